//! XFOIL polar text: the layout of the file XFOIL 6.99 writes with `PACC` (a 12-line header
//! with the airfoil name, transition settings, Mach, Re and N_crit — one value, or top and
//! bottom side by side as XFOIL 6.99 writes unequal `NT` and `NB` — then the columns
//! `alpha CL CD CDp CM Top_Xtr Bot_Xtr` in Fortran F8.3, F9.4, F10.5, F10.5, F9.4, F9.4, F9.4
//! fields, and the optional `Cpmin` column XFOIL adds with its minimum-Cp option, F9.4).
//! Only converged points are written, sorted by α, with `Cpmin` and two columns of polargen's
//! own after it, `Top_Xsep` and `Bot_Xsep` (the separation locations x/c, F9.4; XFOIL's
//! `PGET` skips columns it does not know at the end of a row); the supercritical and
//! massive-separation flags are not columns and follow from `Cpmin` and the Mach number of
//! the header, and from the separation locations, when the file is read. The version line names this table's solver instead of XFOIL; for
//! polargen's own tables it ends in `Version <major>.<minor>` as XFOIL's does, so that XFOIL's
//! `PGET` shows the code and its version.
//!
//! **Which CDp.** XFOIL's polar-file column `CDp` is its surface pressure integral (`CLCALC`),
//! not the `CDp = CD − CDf` it prints after each viscous solution. A file written by polargen
//! carries polargen's `cdp` = CD − CDf (the printed quantity) in that column, so reading it
//! back gives `cdf` = CD − CDp; a file from any other code (XFOIL) has no skin-friction drag
//! column, and its points are read with `cdf` = NaN (unknown) and `cdp` as the file gives it.

use super::{stem_or, supercritical_from_cpmin};
use crate::output::OutputSet;
use crate::section::{massive_separation, FlowCondition, PolarPoint, Transition};
use crate::table::{PolarTable, TableError, TableMeta};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Width and decimals of the point columns `alpha CL CD CDp CM Top_Xtr Bot_Xtr Cpmin` (XFOIL's
/// F8.3, F9.4, F10.5, F10.5, F9.4, F9.4, F9.4, F9.4) and `Top_Xsep Bot_Xsep` (F9.4).
const POLAR_FIELDS: [(usize, usize); 10] = [
    (8, 3),
    (9, 4),
    (10, 5),
    (10, 5),
    (9, 4),
    (9, 4),
    (9, 4),
    (9, 4),
    (9, 4),
    (9, 4),
];

/// Index of the `Cpmin` field in [`POLAR_FIELDS`]; the fields from it on may be unknown.
const CPMIN_FIELD: usize = 7;

/// Write one polar in XFOIL's polar-file layout to `w`; a value wider than its field is
/// refused ([`TableError::FieldOverflow`]), and so is metadata the header needs but the table
/// does not know (N_crit and the trips of a table read from a C81 deck).
pub fn write_polar_to(
    meta: &TableMeta,
    re: f64,
    mach: f64,
    points: &[PolarPoint],
    w: &mut dyn Write,
) -> Result<(), TableError> {
    let header = [
        ("ncrit_top", meta.transition.ncrit_top),
        ("ncrit_bot", meta.transition.ncrit_bot),
        ("xtr_top_set", meta.transition.xtr_top),
        ("xtr_bot_set", meta.transition.xtr_bot),
    ];
    if let Some((field, _)) = header.iter().find(|(_, v)| v.is_nan()) {
        return Err(TableError::UnknownInHeader {
            field,
            format: "an XFOIL polar file",
        });
    }
    let solver = if meta.solver.is_empty() {
        "polargen"
    } else {
        meta.solver.as_str()
    };
    let version = if solver.starts_with("polargen") {
        let mut v = env!("CARGO_PKG_VERSION").split('.');
        format!(
            "   Version {}.{}",
            v.next().unwrap_or("0"),
            v.next().unwrap_or("0")
        )
    } else {
        String::new()
    };
    let mut s = String::new();
    s.push_str(" \n");
    s.push_str(&format!("       {solver}{version}\n"));
    s.push_str(" \n");
    s.push_str(&format!(" Calculated polar for: {}\n", meta.airfoil));
    s.push_str(" \n");
    s.push_str(" 1 1 Reynolds number fixed          Mach number fixed         \n");
    s.push_str(" \n");
    s.push_str(&format!(
        " xtrf = {:7.3} (top)      {:7.3} (bottom)  \n",
        meta.transition.xtr_top, meta.transition.xtr_bot
    ));
    let re_field = format!("{:9.3}", re / 1e6);
    // One N_crit, or top and bottom side by side as XFOIL 6.99 writes unequal NT and NB.
    let t = &meta.transition;
    let ncrit = match t.common_ncrit() {
        Some(n) => vec![("ncrit", n)],
        None => vec![("ncrit_top", t.ncrit_top), ("ncrit_bot", t.ncrit_bot)],
    };
    let mut fields = vec![("Re", re, re_field.clone())];
    fields.extend(ncrit.iter().map(|&(f, n)| (f, n, format!("{n:7.3}"))));
    // Re and N_crit must stay positive when read back (Re 2.5e-7 would print as 0.000 e 6);
    // two N_crit fields need a blank between them.
    for (field, value, text) in &fields {
        if text.trim().parse::<f64>().map_or(true, |v| v <= 0.0) {
            return Err(TableError::HeaderResolution {
                field,
                value: *value,
            });
        }
        if ncrit.len() == 2 && !text.starts_with(' ') {
            return Err(TableError::FieldOverflow {
                value: *value,
                width: 6,
            });
        }
    }
    let ncrit_field: String = fields[1..].iter().map(|f| f.2.as_str()).collect();
    s.push_str(&format!(
        " Mach = {mach:7.3}     Re = {re_field} e 6     Ncrit = {ncrit_field}\n"
    ));
    s.push_str(" \n");
    s.push_str(
        "   alpha    CL        CD       CDp       CM     Top_Xtr  Bot_Xtr   Cpmin   Top_Xsep \
         Bot_Xsep\n",
    );
    s.push_str(
        "  ------ -------- --------- --------- -------- -------- -------- -------- -------- \
         --------\n",
    );
    for p in points.iter().filter(|p| p.converged) {
        let values = [
            p.alpha, p.cl, p.cd, p.cdp, p.cm, p.xtr_top, p.xtr_bot, p.cpmin, p.xsep_top, p.xsep_bot,
        ];
        for (k, (value, (width, decimals))) in values.into_iter().zip(POLAR_FIELDS).enumerate() {
            let field = format!("{value:width$.decimals$}");
            // A wider value would merge with its neighbour and not read back; a minimum
            // pressure that is unknown (NaN) or beyond Karman–Tsien (−∞), or an unknown
            // separation location, is written as such.
            let unknown = k >= CPMIN_FIELD && !value.is_finite();
            if field.len() > width || !(value.is_finite() || unknown) {
                return Err(TableError::FieldOverflow { value, width });
            }
            s.push_str(&field);
        }
        s.push('\n');
    }
    w.write_all(s.as_bytes()).map_err(TableError::Write)
}

/// File name of the polar at (Re, M) for output stem `stem`: `<stem>_Re<re>_M<mach>.pol`,
/// with Re as mantissa and exponent (`1.9e6`) and M in shortest decimal form (`0.41`).
pub fn polar_file_name(stem: &str, re: f64, mach: f64) -> String {
    format!("{stem}_Re{}_M{mach}.pol", re_label(re))
}

/// Re as `<mantissa>e<exponent>` with at most 6 significant digits, e.g. `2.5e5`, `1.9e6`.
pub fn re_label(re: f64) -> String {
    let mut exp = re.abs().log10().floor();
    let mut m = format!("{:.5}", re / 10f64.powf(exp));
    if m.starts_with("10") {
        exp += 1.0;
        m = format!("{:.5}", re / 10f64.powf(exp));
    }
    while m.ends_with('0') {
        m.pop();
    }
    if m.ends_with('.') {
        m.pop();
    }
    format!("{m}e{exp}")
}

/// Write the converged points of every polar of `table` as XFOIL polar files: `path` itself
/// when the table has one polar, otherwise `<dir>/<stem>_Re<re>_M<mach>.pol` for each
/// (Re, M), where `<stem>` is `path` without extension, all together or none
/// ([`OutputSet`]). Two α that the F8.3 field would merge are refused. Returns the files
/// written.
pub fn write_xfoil_polars(table: &PolarTable, path: &Path) -> Result<Vec<PathBuf>, TableError> {
    let mut set = OutputSet::new();
    stage_xfoil_polars(table, path, &mut set)?;
    Ok(set.commit()?)
}

/// The files of [`write_xfoil_polars`], staged in `set` (written when it is committed).
/// Returns the files staged.
pub(crate) fn stage_xfoil_polars(
    table: &PolarTable,
    path: &Path,
    set: &mut OutputSet,
) -> Result<Vec<PathBuf>, TableError> {
    let polars = table.re().len() * table.mach().len();
    let mut files = Vec::with_capacity(polars);
    for (FlowCondition { reynolds: re, mach }, points) in table.polars() {
        check_alpha_resolution(re, mach, points)?;
        let file = polar_path(path, polars, re, mach);
        set.write(&file, |w| {
            write_polar_to(table.meta(), re, mach, points, w).map_err(|e| e.in_output(&file))
        })?;
        files.push(file);
    }
    Ok(files)
}

/// The file of the polar at (`re`, `mach`) of a table of `polars` polars written to `path`:
/// `path` itself for one polar, else [`polar_file_name`] beside it.
pub(super) fn polar_path(path: &Path, polars: usize, re: f64, mach: f64) -> PathBuf {
    if polars == 1 {
        return path.to_path_buf();
    }
    path.with_file_name(polar_file_name(&stem_or(path, "polar"), re, mach))
}

/// The α of converged points must stay distinct in the F8.3 field, or reading the file back
/// would merge two points into one.
fn check_alpha_resolution(re: f64, mach: f64, points: &[PolarPoint]) -> Result<(), TableError> {
    let mut written: Vec<String> = points
        .iter()
        .filter(|p| p.converged)
        .map(|p| format!("{:8.3}", p.alpha))
        .collect();
    written.sort();
    match written.windows(2).find(|w| w[0] == w[1]) {
        Some(w) => Err(TableError::DuplicateAlpha {
            re,
            mach,
            alpha: w[0].trim().parse().unwrap_or(f64::NAN),
        }),
        None => Ok(()),
    }
}

/// Read an XFOIL polar file (as written by XFOIL's `PACC` or by
/// [`write_xfoil_polars`]) as a one-polar table.
///
/// The header gives the airfoil name, `xtrf` (top, bottom), Mach, Re (`1.900 e 6`) and
/// N_crit; the column-title line locates `alpha CL CD CDp CM Top_Xtr Bot_Xtr` and, if
/// present, `Cpmin`, `Top_Xsep` and `Bot_Xsep` among any other columns (XFOIL may add
/// `Xcpmin`, `Chinge`). Without `Cpmin` the minimum pressure and the supercritical flag are
/// unknown, without the separation columns the separation locations and the massive-separation
/// flag. Every row is a converged point
/// (XFOIL writes no others); a repeated α (XFOIL sweeps that revisit a point) keeps the first
/// row. The panel count is unknown (0) and the solver is the file's first text line (the
/// version line).
pub fn parse_xfoil_polar(text: &str) -> Result<PolarTable, TableError> {
    let err = |line: usize, message: &str| TableError::Polar {
        line,
        message: message.to_string(),
    };
    let num = |line: usize, s: &str| -> Result<f64, TableError> {
        s.parse()
            .map_err(|_| err(line, &format!("'{s}' is not a number")))
    };
    let mut name = None;
    let mut solver = String::new();
    // Whether polargen wrote the file: its CDp column is then CD − CDf (module docs).
    let mut ours = false;
    let mut xtr = None;
    let mut cond = None;
    let mut columns: Option<Vec<String>> = None;
    let mut points: Vec<PolarPoint> = Vec::new();
    for (i, raw) in crate::input::text_lines(text).enumerate() {
        let line = i + 1;
        let t = raw.trim();
        if let Some(cols) = columns.as_deref() {
            // Skip blank lines and the dashed rule under the column titles.
            if t.is_empty() || t.contains("--") {
                continue;
            }
            let v: Vec<&str> = t.split_whitespace().collect();
            if v.len() < cols.len() {
                return Err(err(
                    line,
                    &format!("{} columns, expected {}", v.len(), cols.len()),
                ));
            }
            let get = |name: &str| -> Result<f64, TableError> {
                let k = cols
                    .iter()
                    .position(|c| c.eq_ignore_ascii_case(name))
                    .ok_or_else(|| TableError::MissingColumn(name.to_string()))?;
                num(line, v[k])
            };
            let (cd, cdp) = (get("CD")?, get("CDp")?);
            let optional = |name: &str| match cols.iter().any(|c| c.eq_ignore_ascii_case(name)) {
                true => get(name),
                false => Ok(f64::NAN),
            };
            let (cpmin, xsep_top, xsep_bot) = (
                optional("Cpmin")?,
                optional("Top_Xsep")?,
                optional("Bot_Xsep")?,
            );
            let p = PolarPoint {
                alpha: get("alpha")?,
                cl: get("CL")?,
                cd,
                cdp,
                cdf: if ours { cd - cdp } else { f64::NAN },
                cm: get("CM")?,
                xtr_top: get("Top_Xtr")?,
                xtr_bot: get("Bot_Xtr")?,
                converged: true,
                iterations: 0,
                residual: 0.0,
                cpmin,
                supercritical: None,
                xsep_top,
                xsep_bot,
                massive_separation: massive_separation(xsep_top, xsep_bot),
            };
            if !points.iter().any(|q| q.alpha == p.alpha) {
                points.push(p);
            }
        } else if let Some(rest) = t.strip_prefix("Calculated polar for:") {
            name = Some(rest.trim().to_string());
        } else if solver.is_empty() && name.is_none() && !t.is_empty() {
            solver = t.split_whitespace().collect::<Vec<_>>().join(" ");
            ours = solver.starts_with("polargen");
            if ours {
                // The version suffix this writer adds to its own solver name.
                solver = solver.split(" Version").next().unwrap_or("").to_string();
            }
        } else if t.starts_with("xtrf") {
            let v: Vec<&str> = t.split_whitespace().collect();
            match (v.get(2), v.get(4)) {
                (Some(a), Some(b)) => xtr = Some((num(line, a)?, num(line, b)?)),
                _ => return Err(err(line, "xtrf line lacks the top and bottom values")),
            }
        } else if t.starts_with("Mach") {
            // "Mach = 0.410 Re = 1.900 e 6 Ncrit = 9.000", or "… Ncrit = 9.000 3.000" (top, bottom)
            let v: Vec<&str> = t.split_whitespace().collect();
            if v.len() < 11 {
                return Err(err(line, "Mach/Re/Ncrit line is incomplete"));
            }
            let re = num(line, v[5])? * 10f64.powf(num(line, v[7])?);
            let top = num(line, v[10])?;
            let bot = v.get(11).map_or(Ok(top), |b| num(line, b))?;
            cond = Some((num(line, v[2])?, re, (top, bot)));
        } else if t.starts_with("alpha") {
            columns = Some(t.split_whitespace().map(str::to_string).collect());
        }
    }
    let name = name.ok_or_else(|| err(1, "no 'Calculated polar for:' line"))?;
    let (xt, xb) = xtr.ok_or_else(|| err(1, "no 'xtrf =' line"))?;
    let (mach, re, (ncrit_top, ncrit_bot)) =
        cond.ok_or_else(|| err(1, "no 'Mach = … Re = … Ncrit = …' line"))?;
    if columns.is_none() {
        return Err(err(1, "no column-title line starting with 'alpha'"));
    }
    for p in &mut points {
        p.supercritical = supercritical_from_cpmin(p.cpmin, mach);
    }
    let meta = TableMeta {
        airfoil: name,
        transition: Transition::sides(ncrit_top, ncrit_bot, xt, xb),
        thickness: f64::NAN,
        panels: 0,
        solver,
        geometry: Vec::new(),
    };
    PolarTable::new(meta, vec![re], vec![mach], vec![points])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_names_carry_re_and_mach() {
        assert_eq!(re_label(1e6), "1e6");
        assert_eq!(re_label(999_999.9999999), "1e6");
        assert_eq!(re_label(2.5e5), "2.5e5");
        assert_eq!(polar_file_name("x", 2.5e5, 0.3), "x_Re2.5e5_M0.3.pol");
    }
}
