//! Contours at the edges of what a coordinate file may hold (`tests/data/contours`; XFOIL 6.99
//! references on them in `tests/data/xfoil`): chord units with an inclined chord line or a deflected flap are used as given;
//! any other contour is scaled by its chord, the distance from the leading edge to the
//! trailing-edge midpoint, never by its x-extent; CAD exports with many points and few decimals
//! pass the spike test while real spikes and sawtooth contours do not; messages give the numbers
//! (a contour of 1e-12, a Reynolds number above the cap).

mod cli_support;
mod xfoil_support;

use polargen::geometry::{
    parse_airfoil_text, read_airfoil_file, solver_airfoil, Airfoil, GeometryError,
};
use polargen::inviscid::PanelSystem;
use polargen::section::PolarPoint;
use polargen::viscous::{ViscousParams, ViscousSolver};
use std::path::{Path, PathBuf};

const DATA: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/contours/");

fn data(name: &str) -> String {
    format!("{DATA}{name}")
}

/// The solver's nodes of `spec` (as `polargen --airfoil` prepares them) and the notes.
fn nodes(spec: &str) -> (Airfoil, Vec<String>) {
    solver_airfoil(spec, 160, false, &[]).unwrap()
}

/// Fresh viscous solutions at Re 10⁶, free transition.
fn viscous(foil: &Airfoil, alpha: f64) -> PolarPoint {
    let mut solver = ViscousSolver::new(foil, ViscousParams::at(1e6, 0.0, 1.0)).unwrap();
    solver.solve(alpha).point
}

/// Inviscid (Cl, Cm) at M 0.
fn inviscid(foil: &Airfoil, alpha: f64) -> (f64, f64) {
    let s = PanelSystem::new(foil).unwrap().solve(alpha, 0.0).unwrap();
    (s.cl, s.cm)
}

#[test]
fn inclined_and_flapped_contours_in_chord_units_are_used_as_given() {
    // A contour already in chord units keeps its size: taking its x-extent for the chord would
    // scale the NACA 0012 rotated 10° (leading edge to trailing edge exactly 1) by 1/cos 10°,
    // the one rotated 30° by 1/cos 30° (inviscid Cl 3.997 against XFOIL's 3.4616), the flap
    // (20° at 75 % chord, leading edge to trailing edge 0.9887) by 1/0.985. Measured: viscous
    // |ΔCl| ≤ 5e-5, |ΔCd|/Cd ≤ 0.02 %, |Δx_tr| ≤ 1e-4 (x/c along the inclined chord line);
    // inviscid |ΔCl|, |ΔCm| ≤ 5e-5.
    for (file, viscous_ref, inviscid_ref) in [
        (
            "n0012_tilt10.dat",
            Some("n0012_tilt10_Re1e6_M0_free.csv"),
            "n0012_tilt10_inviscid_M0.csv",
        ),
        ("n0012_tilt30.dat", None, "n0012_tilt30_inviscid_M0.csv"),
        (
            "n0012_flap20.dat",
            Some("n0012_flap20_Re1e6_M0_free.csv"),
            "n0012_flap20_inviscid_M0.csv",
        ),
    ] {
        let (foil, notes) = nodes(&data(file));
        assert!(
            notes.iter().all(|n| !n.contains("scaled")),
            "{file}: {notes:?}"
        );
        assert!(
            notes.iter().any(|n| n.contains("inclined")),
            "{file}: {notes:?}"
        );
        for r in xfoil_support::polar(inviscid_ref) {
            let (cl, cm) = inviscid(&foil, r.alpha);
            assert!(
                (cl - r.cl).abs() <= 1.5e-4 && (cm - r.cm).abs() <= 1.5e-4,
                "{file} α {}: cl {cl} cm {cm} vs XFOIL {r:?}",
                r.alpha
            );
        }
        for r in viscous_ref.map(xfoil_support::polar).unwrap_or_default() {
            let p = viscous(&foil, r.alpha);
            assert!(p.converged, "{file} α {}", r.alpha);
            assert!(
                (p.cl - r.cl).abs() <= 1.5e-4
                    && (p.cd / r.cd - 1.0).abs() <= 1e-3
                    && (p.xtr_top - r.xtr_top).abs() <= 3e-4
                    && (p.xtr_bot - r.xtr_bot).abs() <= 3e-4,
                "{file} α {}: {p:?} vs XFOIL {r:?}",
                r.alpha
            );
        }
    }
}

/// `foil` with every coordinate multiplied by `scale` and shifted by (`dx`, `dy`), written to a
/// scratch file.
fn moved(foil: &Airfoil, scale: f64, dx: f64, dy: f64, name: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("polargen-contour-{}-{name}", std::process::id()));
    let mut text = format!("{name}\n");
    for (x, y) in foil.x.iter().zip(&foil.y) {
        text.push_str(&format!("{:.12} {:.12}\n", scale * x + dx, scale * y + dy));
    }
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn a_contour_not_in_chord_units_is_scaled_by_its_chord_and_not_rotated() {
    // The 10° contour in millimetres of a 250 mm chord, shifted: scaled by 1/250 (its leading
    // edge to trailing edge), translated, not rotated; same solution as in chord units.
    let given = read_airfoil_file(Path::new(&data("n0012_tilt10.dat"))).unwrap();
    let mm = moved(&given, 250.0, 40.0, -7.0, "tilt10_mm.dat");
    let (foil, notes) = nodes(mm.to_str().unwrap());
    let note = notes.iter().find(|n| n.contains("scaled")).expect("a note");
    assert!(
        note.contains("scaled by 0.004 ")
            && note.contains("is 250;")
            && note.contains("-10.000 deg")
            && note.contains("not rotated"),
        "{note}"
    );
    let (unit, _) = nodes(&data("n0012_tilt10.dat"));
    for alpha in [0.0, 4.0] {
        let (a, b) = (inviscid(&foil, alpha).0, inviscid(&unit, alpha).0);
        assert!((a - b).abs() < 1e-6, "α {alpha}: {a} vs {b}");
    }
    // A level contour in percent of the chord: scaled by 0.01.
    let level = xfoil_support::nodes("naca0012_buffer.dat");
    let percent = moved(&level, 100.0, 0.0, 0.0, "percent.dat");
    let (_, notes) = nodes(percent.to_str().unwrap());
    assert!(
        notes
            .iter()
            .any(|n| n.contains("scaled by 0.01 ") && n.contains("0.000 deg")),
        "{notes:?}"
    );
    let _ = std::fs::remove_file(mm);
    let _ = std::fs::remove_file(percent);
}

/// A NACA 0012 as a CAD export: `n` points evenly spaced in x, printed with `decimals` decimals
/// (as `tests/data/contours/cad.py`); `None` decimals prints every digit.
fn cad_export(n: usize, decimals: Option<usize>) -> String {
    let m = (n - 1) / 2;
    let half: Vec<(f64, f64)> = (0..=m)
        .map(|i| {
            let x = i as f64 / m as f64;
            let t = 0.6
                * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x.powi(2) + 0.2843 * x.powi(3)
                    - 0.1015 * x.powi(4));
            (x, t)
        })
        .collect();
    let points = half
        .iter()
        .rev()
        .copied()
        .chain(half[1..].iter().map(|&(x, y)| (x, -y)));
    let mut text = format!("NACA 0012 {n} points\n");
    for (x, y) in points {
        text.push_str(&match decimals {
            Some(d) => format!("{x:.d$} {y:.d$}\n"),
            None => format!("{x:e} {y:e}\n"),
        });
    }
    text
}

fn parse(text: &str) -> Result<Airfoil, GeometryError> {
    parse_airfoil_text(text, "cad.dat", "cad").map(|(a, _)| a)
}

/// Viscous Cl and Cd at α 4°, Re 10⁶ of a contour as `polargen --airfoil` prepares it.
fn cl_cd_at_4(foil: &Airfoil) -> (f64, f64) {
    let (unit, _) = foil.in_chord_units().unwrap();
    let paneled = unit
        .repanel(160, &polargen::geometry::PanelingParams::default())
        .unwrap();
    let p = viscous(&paneled, 4.0);
    assert!(p.converged);
    (p.cl, p.cd)
}

#[test]
fn cad_exports_with_few_decimals_are_read() {
    // The rounding staircase of a CAD export turns its vertices back and forth by degrees; the
    // file is read, not refused as folding back (a stray point or a spike). XFOIL solves the
    // 501-point file: Cl 0.4268, Cd 0.00733 at 4°; measured 0.42680, 0.007331.
    let (cl, cd) = cl_cd_at_4(&read_airfoil_file(Path::new(&data("n0012_cad501.dat"))).unwrap());
    let r = xfoil_support::polar("n0012_cad501_Re1e6_M0_free_a4.csv")[0];
    assert!(
        (cl - r.cl).abs() <= 1.5e-4 && (cd / r.cd - 1.0).abs() <= 2e-3,
        "{cl} {cd}"
    );
    // More points and decimals (XFOIL's buffer takes at most a few hundred points). Against
    // the same points printed in full, the rounding moves Cl and Cd by 1.2e-3 and 0.6 % at 4
    // decimals (the leading edge, 0.016 chord in radius, resolved to 1e-4), 4.9e-4 and 0.1 %
    // at 5, 4.7e-4 and 0.2 % at 7 (19 999 points 1e-4 apart: the noise of the spline's
    // curvature moves the repaneled nodes).
    for (n, d, tol) in [
        (501, 4, [4e-3, 1.7e-2]),
        (2001, 5, [1.5e-3, 3e-3]),
        (19_999, 7, [1.5e-3, 6e-3]),
    ] {
        let rounded = cl_cd_at_4(&parse(&cad_export(n, Some(d))).unwrap());
        let full = cl_cd_at_4(&parse(&cad_export(n, None)).unwrap());
        assert!(
            (rounded.0 - full.0).abs() < tol[0] && (rounded.1 / full.1 - 1.0).abs() < tol[1],
            "{n} points, {d} decimals: {rounded:?} vs {full:?}"
        );
    }
}

/// The points of a contour text (first line the name).
fn points(text: &str) -> Vec<(f64, f64)> {
    text.lines()
        .skip(1)
        .map(|l| {
            let mut f = l.split_whitespace().map(|v| v.parse::<f64>().unwrap());
            (f.next().unwrap(), f.next().unwrap())
        })
        .collect()
}

fn print(points: &[(f64, f64)], decimals: usize) -> String {
    let mut text = String::from("edited\n");
    for (x, y) in points {
        text.push_str(&format!("{x:.decimals$} {y:.decimals$}\n"));
    }
    text
}

#[test]
fn real_spikes_and_sawtooth_contours_are_still_refused() {
    let cad = points(&cad_export(501, Some(4)));
    // One point of the 4-decimal export 0.01 chord off the surface: a spike.
    let mut spike = cad.clone();
    spike[120].1 += 0.01;
    let e = parse(&print(&spike, 4)).unwrap_err().to_string();
    assert!(
        e.contains("folds back at point") && e.contains(":122:"),
        "{e}"
    );
    // Every other point 5e-4 chord off the surface (five units of the last decimal): a sawtooth,
    // refused as one, not as a turn of a few degrees somewhere.
    let saw = |amplitude: f64| -> Vec<(f64, f64)> {
        cad.iter()
            .enumerate()
            .map(|(k, &(x, y))| {
                let off = if k % 2 == 0 { amplitude } else { -amplitude };
                (x, if x > 0.05 { y + off } else { y })
            })
            .collect()
    };
    let e = parse(&print(&saw(5e-4), 4)).unwrap_err().to_string();
    assert!(e.contains("zigzags") && e.contains("sawtooth"), "{e}");
    // The same with 1e-6 chord teeth printed with 12 decimals (no "a turn of 0°").
    let e = parse(&print(&saw(1e-6), 12)).unwrap_err().to_string();
    assert!(
        e.contains("zigzags") && e.contains("turns against its sense") && !e.contains("0°)"),
        "{e}"
    );
    // Teeth below the printed precision are rounding: read.
    assert!(parse(&print(&saw(2e-5), 4)).is_ok());
}

/// `polargen` run with `args` (`cli_support::polargen`): success, stderr.
fn polargen(args: &[&str]) -> (bool, String) {
    let out = cli_support::polargen(args);
    (out.status.success(), cli_support::stderr(&out))
}

#[test]
fn messages_give_the_numbers() {
    let level = xfoil_support::nodes("naca0012_buffer.dat");
    // A contour 1e-12 across, printed in full: its size is printed.
    let mut text = String::from("tiny\n");
    for (x, y) in level.x.iter().zip(&level.y) {
        text.push_str(&format!("{:e} {:e}\n", 1e-12 * x, 1e-12 * y));
    }
    let e = parse(&text).unwrap_err().to_string();
    assert!(e.contains("spans only 1e-12, less than 1e-9"), "{e}");
    // The same printed with 9 decimals: every point is (0, 0); before, "spans only 0".
    let flat = print(&points(&text), 9);
    let e = parse(&flat).unwrap_err().to_string();
    assert!(
        e.contains("all 245 points are the point (0, 0)") && e.contains("too few decimals"),
        "{e}"
    );
    // The Reynolds number cap (docs/limits.md), before any solve.
    let (ok, err) = polargen(&["--airfoil", "naca0012", "--re", "2e10", "--alpha", "0:10:1"]);
    assert!(
        !ok && err.contains("--re 2e10: the Reynolds number must be positive and at most 1e10"),
        "{err}"
    );
}
