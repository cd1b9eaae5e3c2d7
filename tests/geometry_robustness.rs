//! Malformed or hostile input must give errors, never panics: random bytes, random
//! numeric files, and random (possibly self-crossing or degenerate) contours through the
//! whole chain reader → validation → spline → LE → repaneling.

use polargen::geometry::{parse_airfoil_bytes, Airfoil, PanelingParams};

#[path = "../src/numerics/test_random.rs"]
mod test_random;
use test_random::Lcg;

#[test]
fn random_bytes_never_panic() {
    let mut r = Lcg::new(1);
    let alphabet = b"0123456789.eEdD+- \t\n,;#naifNACA\x00\xff\r";
    let mut n_err = 0;
    for _ in 0..2000 {
        let len = (r.bits() % 400) as usize;
        let bytes: Vec<u8> = (0..len)
            .map(|_| alphabet[(r.bits() % alphabet.len() as u64) as usize])
            .collect();
        if parse_airfoil_bytes(&bytes, "fuzz", "fuzz").is_err() {
            n_err += 1;
        }
    }
    // Random text is practically never a valid airfoil.
    assert!(n_err > 1900, "only {n_err} of 2000 rejected");
}

#[test]
fn random_contours_never_panic_through_repaneling() {
    let mut r = Lcg::new(7);
    let mut n_ok = 0;
    for k in 0..300 {
        let n = 10 + (r.bits() % 60) as usize;
        // Perturbed ellipse-like loops, from harmless to wildly self-crossing.
        let amp = [0.0, 0.01, 0.1, 1.0][k % 4];
        // Every fifth contour is scaled to extreme magnitudes (overflow of lengths).
        let scale = if k % 5 == 4 { 1e300 } else { 1.0 };
        let (mut x, mut y) = (Vec::new(), Vec::new());
        for i in 0..n {
            let t = 2.0 * std::f64::consts::PI * i as f64 / (n - 1) as f64;
            x.push(scale * (0.5 + 0.5 * t.cos() + amp * (r.unit() - 0.5)));
            y.push(scale * (0.06 * t.sin() + amp * (r.unit() - 0.5)));
        }
        let a = Airfoil {
            name: format!("random {k}"),
            x,
            y,
        };
        match a.panel(80, &PanelingParams::default()) {
            Ok(p) => {
                n_ok += 1;
                assert_eq!(p.len(), 80);
                assert!(p
                    .airfoil
                    .x
                    .iter()
                    .chain(&p.airfoil.y)
                    .all(|v| v.is_finite()));
            }
            Err(e) => assert!(amp > 0.0 || scale > 1.0, "smooth contour {k} rejected: {e}"),
        }
        let _ = a.normalized();
    }
    assert!(n_ok >= 60, "only {n_ok} contours paneled");
}
