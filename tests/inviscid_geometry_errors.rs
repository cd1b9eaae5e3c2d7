//! Bad contours are rejected with errors, never panics; sharp/blunt TE detection.

mod xfoil_support;

use polargen::geometry::Airfoil;
use polargen::inviscid::{InviscidError, PanelSystem};
use xfoil_support::paneled;

fn foil(x: Vec<f64>, y: Vec<f64>) -> Airfoil {
    Airfoil {
        name: "test".into(),
        x,
        y,
    }
}

#[test]
fn bad_contours_are_errors() {
    let e = PanelSystem::new(&foil(vec![1.0, 0.0, 1.0], vec![0.0, 0.0, 0.0])).unwrap_err();
    assert_eq!(e, InviscidError::TooFewNodes { got: 3, min: 5 });
    let e = PanelSystem::new(&foil(vec![0.0; 6], vec![0.0; 5])).unwrap_err();
    assert_eq!(e, InviscidError::LengthMismatch { x: 6, y: 5 });

    let mut a = paneled("naca0012");
    a.y[7] = f64::NAN;
    assert_eq!(
        PanelSystem::new(&a).unwrap_err(),
        InviscidError::NonFiniteNode(7)
    );
    let mut a = paneled("naca0012");
    a.x.reverse();
    a.y.reverse();
    assert_eq!(
        PanelSystem::new(&a).unwrap_err(),
        InviscidError::ClockwiseContour
    );
    let mut a = paneled("naca0012");
    a.x[11] = a.x[10];
    a.y[11] = a.y[10];
    assert_eq!(
        PanelSystem::new(&a).unwrap_err(),
        InviscidError::DuplicateNode(10)
    );
}

/// NACA 4/5-digit XFOIL geometry has a 0.00252 c TE gap (blunt); the 8-H-12 file closes at
/// (1, 0) (sharp, TE panel dropped). Chord comes out as ≈ 1 from the spline leading edge.
#[test]
fn trailing_edge_classification() {
    let blunt = PanelSystem::new(&paneled("naca0012")).unwrap();
    let te = blunt.geometry().te;
    assert!(!te.sharp && !te.closed);
    assert!((te.gap - 0.00252).abs() < 1e-6, "gap {}", te.gap);
    assert!((blunt.geometry().chord - 1.0).abs() < 1e-5);
    assert!(blunt.bisector().is_none());

    let sharp = PanelSystem::new(&paneled("naca8h12")).unwrap();
    let te = sharp.geometry().te;
    assert!(te.sharp && te.closed);
    assert!(sharp.bisector().is_some());
    // The paneled 8-H-12 spline leading edge lies ~0.00075 c ahead of x = 0.
    assert!((sharp.geometry().chord - 1.0).abs() < 2e-3);
}

/// The factorised system can be shared across threads (parallel polar sweeps).
#[test]
fn panel_system_is_send_and_sync() {
    fn check<T: Send + Sync>() {}
    check::<PanelSystem>();
}

/// Kutta condition γ₀ + γ_{N−1} = 0 holds for both unit solutions.
#[test]
fn kutta_condition_holds() {
    for name in ["naca2412", "naca8h12"] {
        let sys = PanelSystem::new(&paneled(name)).unwrap();
        let n = sys.n_nodes();
        for k in 0..2 {
            let g = sys.gamma_unit(k);
            assert!((g[0] + g[n - 1]).abs() < 1e-12, "{name} unit {k}");
        }
    }
}

#[test]
fn irregular_contours_never_give_absurd_coefficients() {
    // Contours that give |Cl| up to 1e10 when solved: a contour listed twice (the second pass
    // 0.1 % smaller), one stray point, a fold of the lower surface; each is refused, and no
    // solution of them is returned.
    let p = polargen::geometry::naca("0012", &Default::default())
        .unwrap()
        .repanel(160, &polargen::geometry::PanelingParams::default())
        .unwrap();
    let twice = foil(
        p.x.iter()
            .chain(
                p.x.iter()
                    .map(|x| 0.0005 + 0.999 * x)
                    .collect::<Vec<_>>()
                    .iter(),
            )
            .copied()
            .collect(),
        p.y.iter()
            .chain(p.y.iter().map(|y| 0.999 * y).collect::<Vec<_>>().iter())
            .copied()
            .collect(),
    );
    let mut stray = foil(p.x.clone(), p.y.clone());
    stray.y[40] += 0.3;
    let mut fold = foil(p.x.clone(), p.y.clone());
    fold.x[120] -= 0.2;
    for (name, a) in [("twice", twice), ("stray", stray), ("fold", fold)] {
        match PanelSystem::new(&a) {
            Err(e) => assert!(!e.to_string().is_empty()),
            Ok(s) => {
                for alpha in [-5.0, 0.0, 5.0] {
                    if let Ok(sol) = s.solve(alpha, 0.0) {
                        panic!("{name}: alpha {alpha} gave Cl {}", sol.cl);
                    }
                }
            }
        }
    }
}
