//! Input limits: every bound on the size of what a user may hand to polargen or ask it to
//! compute, in one place (the README's "Input limits" table lists the same values). Each bound
//! keeps a run within memory and within seconds-to-minutes, so that a typo or a hostile file
//! gets a one-line error at once instead of a hang. Physical validity ranges (Mach in [0, 1),
//! the ISA troposphere, transition x/c in [0, 1]) are not size limits and stay with the
//! physics that defines them.
//!
//! Times quoted are measured on the 2-core development machine under load (release build).

/// Largest input file read (coordinates, tables, aircraft presets; standard input too)
/// \[bytes\]: 64 MiB, 150 times the largest shipped table (412 kB) and far beyond any airfoil
/// file; a link to `/dev/zero` or a runaway file is refused before it fills memory.
pub const MAX_INPUT_BYTES: u64 = 64 << 20;

/// Most points (rows) one table may hold, read or built: 100 000, twice the most one
/// `polargen` run computes ([`MAX_GRID_POINTS`]). A table this large is about 55 MB as
/// JSON (the most verbose format: ≈ 550 bytes a point), so that what polargen reads it can
/// also write in every format and read back; a writer still measures the file first and
/// refuses one beyond [`MAX_INPUT_BYTES`] (very long airfoil names, say) before writing.
pub const MAX_TABLE_POINTS: usize = 100_000;

/// Most points of an airfoil contour read from a file: 20 000, the most the repaneling spline
/// accepts and 50 times a dense published coordinate file (UIUC files hold 35–400 points).
/// Validation is O(n log n) (a sweep over the segments), so even this many points are
/// checked in milliseconds.
pub const MAX_CONTOUR_POINTS: usize = 20_000;

/// Largest magnitude of a coordinate in a contour file: 10⁹ (a 1 m chord in nanometres). Beyond
/// it squared distances of the spline overflow long before any result could be meaningful.
pub const MAX_COORDINATE: f64 = 1e9;

/// Smallest contour extent (the larger of its x and y spans) accepted: 10⁻⁹, far below a
/// 1 µm chord in metres; below it the relative round-off of the coordinates is of the size of
/// the contour.
pub const MIN_CONTOUR_EXTENT: f64 = 1e-9;

/// Largest Reynolds number of a polar or a table: 10¹⁰, beyond ships' hulls; far above it the
/// text formats' fixed fields no longer hold the value.
pub const MAX_RE: f64 = 1e10;

/// Panel nodes accepted by `--panels` (XFOIL's default is 160; above 1000 the dense influence
/// matrix alone takes seconds per polar with no gain in accuracy).
pub const PANEL_NODES: (usize, usize) = (20, 1000);

/// Most α values one range `A0:A1:DA` may produce.
pub const MAX_ALPHA_POINTS: usize = 100_000;

/// Most points (Re × Mach × α) one `polargen` run may solve: 50 000, 27 times the default rotor
/// grid (1 830 points, 5.5–7.6 s on two cores), i.e. at most a few minutes.
pub const MAX_GRID_POINTS: usize = 50_000;

/// Largest Newton threshold `--tolerance` accepted (RMS relative change of the boundary-layer
/// variables): 10⁻². XFOIL uses 10⁻⁴; at 10⁻² the 8-H-12 at Re 1.9·10⁶, M 0.41, α −4…12°
/// differs from the 10⁻⁴ solution by at most 5·10⁻⁵ in Cl and 0.3 % in Cd, while a looser
/// threshold stops the iteration before the boundary layer has moved from its initial march
/// (`--tolerance 0.999999` gave Cl 0.155 "converged" where the answer is 0.453).
pub const MAX_NEWTON_TOLERANCE: f64 = 1e-2;

/// Radial strips of a rotor preset (`rotor.radial_strips`).
pub const RADIAL_STRIPS: (usize, usize) = (2, 200);

/// Azimuth steps per revolution of a rotor preset (`rotor.azimuth_steps`, even).
pub const AZIMUTH_STEPS: (usize, usize) = (8, 720);

/// Most blade-element cells (radial strips × azimuth steps) of a rotor preset: 2 880, eight
/// times the shipped 10 × 36. The work of every rotor evaluation is proportional to this
/// product: one trim takes 0.5 s at 360 cells and 7.3 s at 5 760 (200 × 720 took 158 s).
pub const MAX_ROTOR_CELLS: usize = 2_880;

/// Most takeoff integration steps (`takeoff.max_time_s / takeoff.time_step_s`).
pub const MAX_TAKEOFF_STEPS: usize = 20_000;

/// Most takeoff steps × rotor cells: 8.64·10⁶, ten times the shipped preset's (2 400 steps of
/// 0.05 s to its 120 s limit × 360 cells), so that a takeoff stays below about 20 s (6 000
/// steps × 360 cells took 4.9 s).
pub const MAX_TAKEOFF_CELL_STEPS: usize = 8_640_000;

/// Most trims one speed sweep (`gyro sweep`, `gyro plot power`) may ask for.
pub const MAX_SWEEP_SPEEDS: usize = 1000;

/// Most speeds × rotor cells of one speed sweep: 36 000, 100 speeds at the shipped 360 cells
/// (about a minute), or the default 13 speeds at 2 770 cells.
pub const MAX_SWEEP_CELL_SPEEDS: usize = 36_000;

/// Lowest Reynolds number the viscous solver is asked to solve at (`--re`, Python's `re`):
/// the thin-boundary-layer equations need δ/c ≪ 1, and a laminar layer is δ/c ≈ 5/√Re thick
/// at the trailing edge (Blasius), 0.16 at 10³. Tables read from other codes may have lower
/// Reynolds numbers.
pub const MIN_SOLVER_RE: f64 = 1e3;

/// Most transition settings (cases) of one `polargen point` or `plot-point` run (`--xtr`):
/// the cases are overlaid in one figure.
pub const MAX_POINT_CASES: usize = 20;

/// Most cases of one tunnel cases file (`gyro autorotate --cases`): with the PCA-2 preset's
/// 960 rotor cells a case takes about 15 ms of CPU (NACA Report 515's Table III, 81 rows,
/// 1.2 s), so the largest file runs for about 2.5 min on one core.
pub const MAX_TUNNEL_CASES: usize = 10_000;

/// Largest broadside drag coefficient `cd_max` of the 360° extension (`--cd-max`, a table's
/// `post_stall`): a two-dimensional flat plate has about 2.0 (Hoerner 1965, ch. 3) and
/// Viterna & Corrigan's finite-blade rule at most 2.01; 3 leaves room for a measured value.
pub const MAX_CD_MAX: f64 = 3.0;

/// Azimuth samples of a blade α(ψ) curve (`--samples`).
pub const AZIMUTH_SAMPLES: (usize, usize) = (4, 3600);

/// Largest accepted aircraft mass \[kg\] (a sanity bound far above any gyroplane).
pub const MAX_MASS_KG: f64 = 100_000.0;

/// Largest accepted airspeed \[kt\] (of a preset, and of the `gyro` commands, which take it as
/// an exclusive bound).
pub const MAX_SPEED_KT: f64 = 300.0;

/// A number as a user reads it back in an error: at most 6 significant digits, an exponent
/// for very large or small magnitudes (`1e200`, not 201 digits), `NaN` and `inf` as such.
pub fn short_number(v: f64) -> String {
    if !v.is_finite() || v == 0.0 {
        return format!("{v}");
    }
    let a = v.abs();
    if (1e-4..1e7).contains(&a) {
        let s = format!(
            "{:.*}",
            6usize.saturating_sub(a.log10().floor() as usize + 1),
            v
        );
        trim_zeros(&s)
    } else {
        let s = format!("{v:.5e}");
        match s.split_once('e') {
            Some((m, e)) => format!("{}e{e}", trim_zeros(m)),
            None => s,
        }
    }
}

/// A number written so that it reads back as the same `f64` and stays short: the plain decimal
/// (`10`, `0.75`) when it has at most 24 characters, else the shortest exponent form that reads
/// back exactly (`1e-300`, not a 300-digit decimal). For text that is parsed again, such as the
/// geometry operations a table records.
pub fn exact_number(v: f64) -> String {
    let plain = format!("{v}");
    if plain.len() <= 24 {
        plain
    } else {
        format!("{v:e}")
    }
}

/// A decimal without trailing zeros (and without a trailing point).
fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s.to_string()
    }
}

/// A user's text as it is echoed back in an error: at most 40 characters, longer text cut with
/// `…` (a 300-digit token is not printed whole).
pub fn short_text(s: &str) -> String {
    const MAX_CHARS: usize = 40;
    if s.chars().count() <= MAX_CHARS {
        s.to_string()
    } else {
        let head: String = s.chars().take(MAX_CHARS - 1).collect();
        format!("{head}…")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(short_number(1e200), "1e200");
        assert_eq!(short_number(-1.23456789e-12), "-1.23457e-12");
        assert_eq!(short_number(0.5), "0.5");
        assert_eq!(short_number(1.9e6), "1900000");
        assert_eq!(short_number(123.456789), "123.457");
        assert_eq!(short_number(0.0), "0");
        assert_eq!(short_number(f64::NAN), "NaN");
        assert_eq!(short_text(&"9".repeat(300)).chars().count(), 40);
        assert_eq!(short_text("0.25"), "0.25");
    }

    #[test]
    fn exact_numbers_read_back_and_stay_short() {
        assert_eq!(exact_number(10.0), "10");
        assert_eq!(exact_number(-0.75), "-0.75");
        assert_eq!(exact_number(1e-300), "1e-300");
        for v in [
            1e-300,
            0.1 + 0.2,
            -7.3e-9,
            1.23456789012345e20,
            5e-324,
            f64::MAX,
        ] {
            let text = exact_number(v);
            assert!(text.len() <= 24, "{text}");
            assert_eq!(
                text.parse::<f64>().unwrap().to_bits(),
                v.to_bits(),
                "{text}"
            );
        }
    }
}
