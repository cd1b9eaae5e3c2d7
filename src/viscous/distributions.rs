//! Distributions along the surfaces and the wake of one viscous solution, as plots and files
//! show them: pressure coefficient Cp(x/c) (Karman–Tsien at the free-stream Mach number, the
//! correction XFOIL applies when it plots Cp), the shape factor H, the skin friction Cf and the
//! amplification factor N of each station.

use super::solution::{BlStation, ViscousSolution};
use crate::compressibility::KarmanTsien;
use crate::output::{write_output, OutputError};
use std::io::{self, Write};
use std::path::Path;

/// Pressure coefficient at a station of edge speed `ue` (in units of V∞) and free-stream Mach
/// number `mach`: the incompressible Cp = 1 − ue² corrected by Karman–Tsien.
pub fn pressure_coefficient(ue: f64, mach: f64) -> f64 {
    KarmanTsien::new(mach).map_or(f64::NAN, |kt| kt.cp_unchecked(1.0 - ue * ue))
}

/// Plot-ready distributions of one surface (stagnation point → trailing edge): x/c, Cp, H, Cf
/// (free-stream based, as XFOIL plots it) and N on the laminar part (NaN where turbulent).
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceDistributions {
    /// Chordwise station x/c.
    pub x: Vec<f64>,
    /// Pressure coefficient ([`pressure_coefficient`]).
    pub cp: Vec<f64>,
    /// Shape factor H = δ*/θ of the compressible thicknesses (not the kinematic Hk of the
    /// closures, which XFOIL's `DUMP` prints in its "H" column; the two differ when M > 0).
    pub h: Vec<f64>,
    /// Skin-friction coefficient τw/(½ρV∞²).
    pub cf: Vec<f64>,
    /// Amplification factor N (NaN where the layer is turbulent).
    pub n: Vec<f64>,
}

impl SurfaceDistributions {
    /// The distributions of `stations` at free-stream Mach number `mach`.
    pub fn new(stations: &[BlStation], mach: f64) -> Self {
        Self {
            x: stations.iter().map(|s| s.x).collect(),
            cp: stations
                .iter()
                .map(|s| pressure_coefficient(s.ue, mach))
                .collect(),
            h: stations.iter().map(|s| s.h).collect(),
            cf: stations.iter().map(|s| s.cf_inf).collect(),
            n: stations
                .iter()
                .map(|s| if s.turbulent { f64::NAN } else { s.n_or_ctau })
                .collect(),
        }
    }
}

/// The stations of every case as CSV: a header, then one row per station of the upper and the
/// lower surface (stagnation point → trailing edge) and of the wake, for each `(label,
/// solution)` case, at free-stream Mach number `mach`. Columns: `case, alpha, surface, s, x, y,
/// ue, cp, dstar, theta, cf, h, hk, n_or_ctau, turbulent` (`cf` free-stream based).
pub fn write_distributions_csv(
    cases: &[(&str, &ViscousSolution)],
    mach: f64,
    w: &mut dyn Write,
) -> io::Result<()> {
    writeln!(
        w,
        "case,alpha,surface,s,x,y,ue,cp,dstar,theta,cf,h,hk,n_or_ctau,turbulent"
    )?;
    for (label, sol) in cases {
        for (surface, stations) in [
            ("upper", &sol.upper),
            ("lower", &sol.lower),
            ("wake", &sol.wake),
        ] {
            for s in stations.iter() {
                writeln!(
                    w,
                    "{label},{},{surface},{},{},{},{},{},{},{},{},{},{},{},{}",
                    sol.point.alpha,
                    s.s,
                    s.x,
                    s.y,
                    s.ue,
                    pressure_coefficient(s.ue, mach),
                    s.dstar,
                    s.theta,
                    s.cf_inf,
                    s.h,
                    s.hk,
                    s.n_or_ctau,
                    s.turbulent
                )?;
            }
        }
    }
    Ok(())
}

/// [`write_distributions_csv`] to the file `path`, written atomically, or to standard output
/// when `path` is `-` ([`write_output`]).
pub fn write_distributions_file(
    cases: &[(&str, &ViscousSolution)],
    mach: f64,
    path: &Path,
) -> Result<(), OutputError> {
    write_output(path, |w| {
        write_distributions_csv(cases, mach, w).map_err(|e| OutputError::io(path, e))
    })
}
