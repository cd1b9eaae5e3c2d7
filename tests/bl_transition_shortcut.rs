//! The transition check of a laminar interval used by the solver (`transition_interval`) skips
//! the TRCHEK2 iteration for N2 when one residual evaluation proves that N2 stays below Ncrit.
//! This test sweeps laminar intervals over the whole range the solver meets (attached and
//! separated shape factors, thin and thick layers, short and long intervals, N1 from 0 to just
//! below Ncrit, accelerating and decelerating flow, with and without a trip) and checks that
//! the solver's check decides transition exactly as the full iteration (`amplification_check`)
//! does, with the same transition location.

use polargen::boundary_layer::{BlConditions, BlModel, BlParams, StationVars};

#[test]
fn shortcut_decides_transition_as_the_full_n2_iteration() {
    let mut cases = 0;
    let mut transitions = 0;
    for (re, mach) in [(2.5e5, 0.0), (2.0e6, 0.4)] {
        let m = BlModel::new(
            &BlConditions {
                reynolds: re,
                mach,
                ncrit: 9.0,
            },
            BlParams::default(),
        )
        .expect("valid conditions");
        for x1 in [0.01, 0.05, 0.2, 0.5] {
            for frac in [0.02, 0.1, 0.3] {
                let x2 = x1 * (1.0 + frac);
                for h1 in [2.3, 2.6, 3.2, 4.5, 7.0] {
                    for h_ratio in [0.95, 1.0, 1.1] {
                        for (u1, u_ratio) in [(1.2, 1.02), (1.0, 1.0), (0.9, 0.97)] {
                            for n1 in [0.0, 3.0, 7.0, 8.5, 8.95, 8.999] {
                                for trip in [None, Some(0.5 * (x1 + x2))] {
                                    let th1 = 0.664 * (x1 / re).sqrt();
                                    let th2 = th1 * (x2 / x1).sqrt();
                                    let v1 = StationVars {
                                        x: x1,
                                        u: u1,
                                        theta: th1,
                                        dstar: h1 * th1,
                                        s: n1,
                                        dw: 0.0,
                                    };
                                    let v2 = StationVars {
                                        x: x2,
                                        u: u1 * u_ratio,
                                        theta: th2,
                                        dstar: h1 * h_ratio * th2,
                                        s: 0.03,
                                        dw: 0.0,
                                    };
                                    let full = m
                                        .amplification_check(&v1, &v2, trip)
                                        .expect("valid interval");
                                    let solver = m
                                        .transition_interval(&v1, &v2, trip)
                                        .expect("valid interval");
                                    cases += 1;
                                    match (full.transition, solver) {
                                        (None, None) => {}
                                        (Some((xt, _)), Some(t)) => {
                                            transitions += 1;
                                            assert!(
                                                (t.xi_tr - xt).abs() <= 1e-12 * x2,
                                                "ξ_tr {} vs {xt}",
                                                t.xi_tr
                                            );
                                        }
                                        (a, b) => panic!(
                                            "decisions differ at Re {re}, x1 {x1}, frac {frac}, \
                                             H {h1}×{h_ratio}, u {u1}×{u_ratio}, N1 {n1}, \
                                             trip {trip:?}: full {a:?}, solver {:?}",
                                            b.map(|t| t.xi_tr)
                                        ),
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    // Both outcomes are well represented.
    assert_eq!(cases, 2 * 4 * 3 * 5 * 3 * 3 * 6 * 2);
    assert!(
        transitions > cases / 5 && transitions < 4 * cases / 5,
        "{transitions} of {cases}"
    );
}
