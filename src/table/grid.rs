//! [`PolarTable`]: one polar per node of a Reynolds × Mach grid, with metadata.

use super::error::TableError;
use super::lookup::{bracket, AlphaCurve};
use super::meta::TableMeta;
use super::post_stall::PostStallParams;
use super::validation::{check_axis, check_meta, check_polar, check_shared_alphas, check_size};
use crate::geometry::ShapeOp;
use crate::limits::MAX_RE;
use crate::section::{massive_separation, FlowCondition, PolarPoint};
use serde::{Deserialize, Deserializer, Serialize, Serializer};

/// A Re × Mach × α table of section coefficients: one polar (list of solved points, converged
/// or not) per (Re, M) node.
///
/// Axes are strictly increasing; polars are stored Re-major (`index = i_re·n_mach + i_mach`)
/// with their points sorted by α. Unconverged points are kept (and written to CSV/JSON) but
/// never used by [`lookup`](crate::section::SectionAero::lookup).
#[derive(Clone, Debug)]
pub struct PolarTable {
    meta: TableMeta,
    re: Vec<f64>,
    mach: Vec<f64>,
    polars: Vec<Vec<PolarPoint>>,
    params: PostStallParams,
    /// ln of the Re axis (lookups interpolate linearly in ln Re).
    ln_re: Vec<f64>,
    /// Prepared α curve per node; a node with < 2 converged points holds a copy of its
    /// nearest usable neighbour's curve, flagged as a substitute.
    curves: Vec<AlphaCurve>,
}

impl PartialEq for PolarTable {
    /// Tables are equal when their metadata, axes, polars and post-stall settings are; a
    /// value unknown (NaN) in both points counts as equal, so that a table read back from its
    /// file equals the table written.
    fn eq(&self, other: &Self) -> bool {
        self.meta == other.meta
            && self.re == other.re
            && self.mach == other.mach
            && self.params == other.params
            && self.polars.len() == other.polars.len()
            && self
                .polars
                .iter()
                .zip(&other.polars)
                .all(|(a, b)| a.len() == b.len() && a.iter().zip(b).all(|(p, q)| same_record(p, q)))
    }
}

/// Two points hold the same values, NaN equal to NaN (every field named: a new one must be
/// compared here too).
fn same_record(p: &PolarPoint, q: &PolarPoint) -> bool {
    let same = |a: f64, b: f64| a == b || (a.is_nan() && b.is_nan());
    let PolarPoint {
        alpha,
        cl,
        cd,
        cdp,
        cdf,
        cm,
        xtr_top,
        xtr_bot,
        converged,
        iterations,
        residual,
        cpmin,
        supercritical,
        xsep_top,
        xsep_bot,
        massive_separation,
    } = *p;
    [
        (alpha, q.alpha),
        (cl, q.cl),
        (cd, q.cd),
        (cdp, q.cdp),
        (cdf, q.cdf),
        (cm, q.cm),
        (xtr_top, q.xtr_top),
        (xtr_bot, q.xtr_bot),
        (residual, q.residual),
        (cpmin, q.cpmin),
        (xsep_top, q.xsep_top),
        (xsep_bot, q.xsep_bot),
    ]
    .into_iter()
    .all(|(a, b)| same(a, b))
        && (converged, iterations, supercritical, massive_separation)
            == (
                q.converged,
                q.iterations,
                q.supercritical,
                q.massive_separation,
            )
}

impl PolarTable {
    /// Build a table from its axes and `re.len()·mach.len()` polars in Re-major order.
    ///
    /// Validates: metadata (N_crit > 0, transition settings in [0, 1], names without control
    /// characters); non-empty, strictly increasing axes; 0 < Re ≤ [`MAX_RE`]; 0 ≤ M < 1; no
    /// empty polar; finite α within ±180°, unique within each polar; finite coefficients,
    /// cd ≥ 0 and the [`COEFFICIENT_BOUNDS`](super::COEFFICIENT_BOUNDS) at converged points; at
    /// most [`MAX_TABLE_POINTS`](crate::limits::MAX_TABLE_POINTS) points. So every table that
    /// exists can be written and read back. (The readers of the formats that keep every
    /// computed point, CSV and JSON, also require one α list in every polar of a table
    /// computed by polargen.) Points are sorted by α. A table in which no polar has two converged points
    /// is accepted (see [`has_lookup`](Self::has_lookup)).
    pub fn new(
        meta: TableMeta,
        re: Vec<f64>,
        mach: Vec<f64>,
        polars: Vec<Vec<PolarPoint>>,
    ) -> Result<Self, TableError> {
        Self::with_params(meta, re, mach, polars, PostStallParams::default())
    }

    /// As [`new`](Self::new), with explicit 360°-extension parameters.
    pub fn with_params(
        meta: TableMeta,
        re: Vec<f64>,
        mach: Vec<f64>,
        mut polars: Vec<Vec<PolarPoint>>,
        params: PostStallParams,
    ) -> Result<Self, TableError> {
        params.validate()?;
        check_meta(&meta)?;
        check_axis("Re", &re)?;
        check_axis("Mach", &mach)?;
        if let Some(&r) = re.iter().find(|r| !(**r > 0.0 && **r <= MAX_RE)) {
            return Err(TableError::BadRe(r));
        }
        if let Some(&m) = mach.iter().find(|m| !((0.0..1.0).contains(*m))) {
            return Err(TableError::BadMach(m));
        }
        let expected = re.len() * mach.len();
        if polars.len() != expected {
            return Err(TableError::Ragged {
                n_re: re.len(),
                n_mach: mach.len(),
                expected,
                got: polars.len(),
            });
        }
        check_size(&polars)?;
        for (k, polar) in polars.iter_mut().enumerate() {
            let (r, m) = (re[k / mach.len()], mach[k % mach.len()]);
            check_polar(r, m, polar)?;
        }
        let ln_re = re.iter().map(|r| r.ln()).collect();
        let curves = build_curves(&re, &mach, &polars, params)?;
        Ok(Self {
            meta,
            re,
            mach,
            polars,
            params,
            ln_re,
            curves,
        })
    }

    /// Build a table from polars given with their flow condition, in any order; the axes are
    /// the sorted distinct Re and M values, and every (Re, M) pair must appear exactly once.
    pub fn from_polars(
        meta: TableMeta,
        polars: Vec<(FlowCondition, Vec<PolarPoint>)>,
    ) -> Result<Self, TableError> {
        let mut re: Vec<f64> = polars.iter().map(|p| p.0.reynolds).collect();
        let mut mach: Vec<f64> = polars.iter().map(|p| p.0.mach).collect();
        if let Some(&r) = re.iter().find(|r| r.is_nan()) {
            return Err(TableError::BadRe(r));
        }
        if let Some(&m) = mach.iter().find(|m| m.is_nan()) {
            return Err(TableError::BadMach(m));
        }
        re.sort_by(f64::total_cmp);
        re.dedup();
        mach.sort_by(f64::total_cmp);
        mach.dedup();
        if re.is_empty() {
            return Err(TableError::EmptyAxis("Re"));
        }
        let mut slots: Vec<Option<Vec<PolarPoint>>> = vec![None; re.len() * mach.len()];
        for (
            FlowCondition {
                reynolds: r,
                mach: m,
            },
            pts,
        ) in polars
        {
            let i = re.partition_point(|&v| v < r);
            let j = mach.partition_point(|&v| v < m);
            let slot = &mut slots[i * mach.len() + j];
            if slot.is_some() {
                return Err(TableError::DuplicatePolar { re: r, mach: m });
            }
            *slot = Some(pts);
        }
        let mut grid = Vec::with_capacity(slots.len());
        for (k, s) in slots.into_iter().enumerate() {
            match s {
                Some(p) => grid.push(p),
                None => {
                    return Err(TableError::MissingPolar {
                        re: re[k / mach.len()],
                        mach: mach[k % mach.len()],
                    })
                }
            }
        }
        Self::new(meta, re, mach, grid)
    }

    /// The table, refused when it was computed by polargen (its solver name starts with
    /// `polargen`) and its polars do not all have one α list: polargen keeps every α of its
    /// grid in every polar, converged or not, so a CSV or JSON file read so is cut short or
    /// edited. A format that keeps only the usable points of each polar (AeroDyn) is not
    /// checked so.
    pub(crate) fn require_every_alpha(self) -> Result<Self, TableError> {
        check_shared_alphas(&self.meta, &self.re, &self.mach, &self.polars)?;
        Ok(self)
    }

    /// The same table with other 360°-extension parameters.
    pub fn with_post_stall(self, params: PostStallParams) -> Result<Self, TableError> {
        Self::with_params(self.meta, self.re, self.mach, self.polars, params)
    }

    /// The same table recording `ops` as the geometry operations its section was made with
    /// ([`TableMeta::geometry`]).
    pub fn with_geometry(mut self, ops: &[ShapeOp]) -> Self {
        self.meta.geometry = ops.to_vec();
        self
    }

    /// Metadata.
    pub fn meta(&self) -> &TableMeta {
        &self.meta
    }

    /// Reynolds-number axis (strictly increasing).
    pub fn re(&self) -> &[f64] {
        &self.re
    }

    /// Mach-number axis (strictly increasing).
    pub fn mach(&self) -> &[f64] {
        &self.mach
    }

    /// ln of the Re axis.
    pub(crate) fn ln_re(&self) -> &[f64] {
        &self.ln_re
    }

    /// 360°-extension parameters.
    pub fn post_stall_params(&self) -> &PostStallParams {
        &self.params
    }

    /// The polar at grid indices (`i_re`, `i_mach`), sorted by α; `None` outside the grid.
    pub fn polar_at(&self, i_re: usize, i_mach: usize) -> Option<&[PolarPoint]> {
        if i_re < self.re.len() && i_mach < self.mach.len() {
            Some(&self.polars[i_re * self.mach.len() + i_mach])
        } else {
            None
        }
    }

    /// The polar at exactly this (Re, M) node (relative tolerance 1e-9), if there is one.
    pub fn polar(&self, re: f64, mach: f64) -> Option<&[PolarPoint]> {
        let i = self
            .re
            .iter()
            .position(|&r| (r - re).abs() <= 1e-9 * r.abs())?;
        let j = self
            .mach
            .iter()
            .position(|&m| (m - mach).abs() <= 1e-9 * m.abs().max(1.0))?;
        self.polar_at(i, j)
    }

    /// The node nearest to (Re, M) — nearest in ln Re and in M separately — with its flow
    /// condition.
    pub fn nearest_polar(&self, re: f64, mach: f64) -> (FlowCondition, &[PolarPoint]) {
        let ln = if re > 0.0 { re.ln() } else { f64::NEG_INFINITY };
        let nearest = |axis: &[f64], x: f64| {
            let (i, w, _) = bracket(axis, x);
            if w > 0.5 {
                i + 1
            } else {
                i
            }
        };
        let i = nearest(&self.ln_re, ln);
        let j = nearest(&self.mach, mach);
        (
            FlowCondition::new(self.re[i], self.mach[j]),
            &self.polars[i * self.mach.len() + j],
        )
    }

    /// All polars with their flow condition, Re-major.
    pub fn polars(&self) -> impl Iterator<Item = (FlowCondition, &[PolarPoint])> {
        let nm = self.mach.len();
        self.polars.iter().enumerate().map(move |(k, p)| {
            (
                FlowCondition::new(self.re[k / nm], self.mach[k % nm]),
                p.as_slice(),
            )
        })
    }

    /// Total number of points (converged or not).
    pub fn point_count(&self) -> usize {
        self.polars.iter().map(Vec::len).sum()
    }

    /// Number of converged points.
    pub fn converged_count(&self) -> usize {
        self.polars.iter().flatten().filter(|p| p.converged).count()
    }

    /// First and last converged α (deg) of the curve used at node (`i_re`, `i_mach`) (that of
    /// the nearest usable neighbour if the node's own polar has < 2 converged points).
    pub fn alpha_range(&self, i_re: usize, i_mach: usize) -> Option<(f64, f64)> {
        (i_re < self.re.len() && i_mach < self.mach.len() && self.has_lookup())
            .then(|| self.curves[i_re * self.mach.len() + i_mach].alpha_range())
    }

    /// Whether lookups are possible: at least one polar has two converged points. A table
    /// without (e.g. a single-α polar, or a grid where everything failed) is still a valid
    /// record of what was computed and can be written, but [`lookup`](crate::section::SectionAero::lookup)
    /// returns NaN coefficients on it.
    pub fn has_lookup(&self) -> bool {
        !self.curves.is_empty()
    }

    /// `Ok` when lookups are possible, else [`TableError::Empty`] (for consumers such as the
    /// rotor model and the C81 writer).
    pub fn require_lookup(&self) -> Result<(), TableError> {
        if self.has_lookup() {
            Ok(())
        } else {
            Err(TableError::Empty)
        }
    }

    /// Prepared α curve of a node.
    #[inline]
    pub(crate) fn curve(&self, i_re: usize, i_mach: usize) -> &AlphaCurve {
        &self.curves[i_re * self.mach.len() + i_mach]
    }
}

/// Weight of a (normalised) Re distance relative to a Mach distance when a polar without two
/// converged points borrows the curve of its nearest usable neighbour.
const SAME_RE_PREFERENCE: f64 = 10.0;

/// Prepare the α curve of every node; a node without two converged points borrows the curve
/// of the nearest usable node (first along M in the same Re row, then along Re), flagged.
fn build_curves(
    re: &[f64],
    mach: &[f64],
    polars: &[Vec<PolarPoint>],
    params: PostStallParams,
) -> Result<Vec<AlphaCurve>, TableError> {
    let nm = mach.len();
    let own: Vec<Option<AlphaCurve>> = polars.iter().map(|p| AlphaCurve::new(p, params)).collect();
    if own.iter().all(Option::is_none) {
        // Kept as a record of what was computed (all points flagged); lookups need
        // `require_lookup` to pass first.
        return Ok(Vec::new());
    }
    let ln_re: Vec<f64> = re.iter().map(|r| r.ln()).collect();
    // Distance in grid-normalised units; a step along Re counts SAME_RE_PREFERENCE times a
    // step along M, so that a neighbour at the same Re is preferred.
    let span_re = (ln_re[ln_re.len() - 1] - ln_re[0]).max(1e-300);
    let span_m = (mach[nm - 1] - mach[0]).max(1e-300);
    let mut curves = Vec::with_capacity(own.len());
    for k in 0..own.len() {
        if let Some(c) = &own[k] {
            curves.push(c.clone());
            continue;
        }
        let (i, j) = (k / nm, k % nm);
        let best = (0..own.len())
            .filter(|&q| own[q].is_some())
            .min_by(|&p, &q| {
                let d = |q: usize| {
                    let dr = (ln_re[q / nm] - ln_re[i]) / span_re;
                    let dm = (mach[q % nm] - mach[j]) / span_m;
                    SAME_RE_PREFERENCE * dr.abs() + dm.abs()
                };
                d(p).total_cmp(&d(q))
            })
            .ok_or(TableError::Empty)?;
        let mut c = own[best].clone().ok_or(TableError::Empty)?;
        c.substitute = true;
        curves.push(c);
    }
    Ok(curves)
}

/// Serde form of one point: like [`PolarPoint`] but NaN/∞ (possible in unconverged points)
/// are written as the strings `"NaN"`, `"inf"`, `"-inf"` so that JSON can hold them.
#[derive(Serialize, Deserialize)]
struct PointRecord {
    #[serde(with = "nonfinite")]
    alpha: f64,
    #[serde(with = "nonfinite")]
    cl: f64,
    #[serde(with = "nonfinite")]
    cd: f64,
    #[serde(with = "nonfinite")]
    cdp: f64,
    #[serde(with = "nonfinite")]
    cdf: f64,
    #[serde(with = "nonfinite")]
    cm: f64,
    #[serde(with = "nonfinite")]
    xtr_top: f64,
    #[serde(with = "nonfinite")]
    xtr_bot: f64,
    converged: bool,
    iterations: u32,
    #[serde(with = "nonfinite")]
    residual: f64,
    /// Absent in files written before the field existed: unknown (NaN).
    #[serde(with = "nonfinite", default = "unknown_cpmin")]
    cpmin: f64,
    /// Absent (or null): unknown.
    #[serde(default)]
    supercritical: Option<bool>,
    /// Absent in files written before the field existed: unknown (NaN).
    #[serde(with = "nonfinite", default = "unknown_x")]
    xsep_top: f64,
    /// As `xsep_top`.
    #[serde(with = "nonfinite", default = "unknown_x")]
    xsep_bot: f64,
    /// Absent (or null): follows from `xsep_top` and `xsep_bot`, unknown when they are.
    #[serde(default)]
    massive_separation: Option<bool>,
}

/// The `cpmin` of a point whose record does not hold one.
fn unknown_cpmin() -> f64 {
    f64::NAN
}

/// The separation location of a point whose record does not hold one.
fn unknown_x() -> f64 {
    f64::NAN
}

impl From<&PolarPoint> for PointRecord {
    fn from(p: &PolarPoint) -> Self {
        Self {
            alpha: p.alpha,
            cl: p.cl,
            cd: p.cd,
            cdp: p.cdp,
            cdf: p.cdf,
            cm: p.cm,
            xtr_top: p.xtr_top,
            xtr_bot: p.xtr_bot,
            converged: p.converged,
            iterations: p.iterations,
            residual: p.residual,
            cpmin: p.cpmin,
            supercritical: p.supercritical,
            xsep_top: p.xsep_top,
            xsep_bot: p.xsep_bot,
            massive_separation: p.massive_separation,
        }
    }
}

impl From<PointRecord> for PolarPoint {
    fn from(p: PointRecord) -> Self {
        Self {
            alpha: p.alpha,
            cl: p.cl,
            cd: p.cd,
            cdp: p.cdp,
            cdf: p.cdf,
            cm: p.cm,
            xtr_top: p.xtr_top,
            xtr_bot: p.xtr_bot,
            converged: p.converged,
            iterations: p.iterations,
            residual: p.residual,
            cpmin: p.cpmin,
            supercritical: p.supercritical,
            xsep_top: p.xsep_top,
            xsep_bot: p.xsep_bot,
            massive_separation: p
                .massive_separation
                .or_else(|| massive_separation(p.xsep_top, p.xsep_bot)),
        }
    }
}

/// The serde form of a table (what JSON files hold).
#[derive(Serialize, Deserialize)]
struct TableRecord {
    meta: TableMeta,
    re: Vec<f64>,
    mach: Vec<f64>,
    #[serde(default)]
    post_stall: Option<PostStallParams>,
    /// Re-major, one list of points per (Re, M).
    polars: Vec<Vec<PointRecord>>,
}

impl Serialize for PolarTable {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        TableRecord {
            meta: self.meta.clone(),
            re: self.re.clone(),
            mach: self.mach.clone(),
            post_stall: Some(self.params),
            polars: self
                .polars
                .iter()
                .map(|p| p.iter().map(PointRecord::from).collect())
                .collect(),
        }
        .serialize(s)
    }
}

impl<'de> Deserialize<'de> for PolarTable {
    /// Deserialise and validate (the same checks as [`PolarTable::new`]).
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let r = TableRecord::deserialize(d)?;
        let polars = r
            .polars
            .into_iter()
            .map(|p| p.into_iter().map(PolarPoint::from).collect())
            .collect();
        Self::with_params(
            r.meta,
            r.re,
            r.mach,
            polars,
            r.post_stall.unwrap_or_default(),
        )
        .map_err(serde::de::Error::custom)
    }
}

/// Serde helpers: finite floats as numbers, NaN and ±∞ as strings.
pub(super) mod nonfinite {
    use serde::{de, Deserialize, Deserializer, Serializer};

    /// Write a finite value as a number, otherwise as `"NaN"`, `"inf"` or `"-inf"`.
    pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
        if v.is_finite() {
            s.serialize_f64(*v)
        } else if v.is_nan() {
            s.serialize_str("NaN")
        } else if *v > 0.0 {
            s.serialize_str("inf")
        } else {
            s.serialize_str("-inf")
        }
    }

    #[derive(Deserialize)]
    #[serde(untagged)]
    enum NumOrText {
        Num(f64),
        Text(String),
    }

    /// Read a number, or one of the strings written by [`serialize`].
    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
        match NumOrText::deserialize(d)? {
            NumOrText::Num(v) => Ok(v),
            NumOrText::Text(t) => match t.as_str() {
                "NaN" => Ok(f64::NAN),
                "inf" => Ok(f64::INFINITY),
                "-inf" => Ok(f64::NEG_INFINITY),
                _ => Err(de::Error::custom(format!("'{t}' is not a number"))),
            },
        }
    }
}
