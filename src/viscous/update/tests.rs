//! The relaxation of the update with the √Cτ clip at the first turbulent station of each
//! surface ([`UpdateLimits::clip_first_turbulent`]), on the marched state of a NACA 0012 at
//! Re 3·10⁶, α 2° (free transition): a Newton step asking the first turbulent station's √Cτ to
//! fall by 95 % — what re-initialising that station turbulent each iteration gives where free
//! transition moves — must not relax the whole update, and must still be bounded there.

use super::{apply_step, UpdateLimits};
use crate::geometry::solver_airfoil;
use crate::inviscid::PanelSystem;
use crate::viscous::march::march;
use crate::viscous::state::BlState;
use crate::viscous::stations::{StationLayout, Surface};
use crate::viscous::{PanelModel, ViscousParams};

const ALPHA: f64 = 2.0;

/// The layout and the marched state, with the closures.
fn marched() -> (StationLayout, BlState, crate::boundary_layer::BlModel) {
    let (foil, _) = solver_airfoil("naca0012", 160, false, &[]).unwrap();
    let system = PanelSystem::new(&foil).unwrap();
    let model = PanelModel::at_alpha(&system, ALPHA).unwrap();
    let q = model.speeds(ALPHA);
    let layout = StationLayout::new(&model, &q[..model.n_airfoil()]).unwrap();
    let params = ViscousParams::at(3e6, 0.0, 1.0);
    let bl = params.boundary_layer().unwrap();
    let free = [Surface::Upper, Surface::Lower]
        .map(|s| layout.range(s).last().map(|k| layout.stations[k].xi));
    let state = march(
        &bl,
        &layout,
        &layout.edge_speed(&q),
        free,
        model.te_gap(),
        &params.march,
    );
    let [closures, _] = bl;
    (layout, state, closures)
}

/// The first and the second turbulent station of the upper surface.
fn turbulent_stations(layout: &StationLayout, state: &BlState) -> (usize, usize) {
    let mut k = layout.range(Surface::Upper).filter(|&k| state.turbulent[k]);
    (k.next().unwrap(), k.next().unwrap())
}

/// A step that changes √Cτ of station `k` by the fraction `change` and θ of every station by
/// `theta_change` (relative), nothing else.
fn step(state: &BlState, k: usize, change: f64, theta_change: f64) -> Vec<[f64; 3]> {
    (0..state.len())
        .map(|j| {
            let ds = if j == k { change * state.s[j] } else { 0.0 };
            [ds, theta_change * state.theta[j], 0.0]
        })
        .collect()
}

#[test]
fn the_first_turbulent_station_does_not_set_the_relaxation() {
    let (layout, state, model) = marched();
    let (first, _) = turbulent_stations(&layout, &state);
    let due = vec![0.0; state.len()];
    let clip = UpdateLimits::default();
    assert!(clip.clip_first_turbulent);
    let xfoil = UpdateLimits {
        clip_first_turbulent: false,
        ..clip
    };
    // √Cτ to fall by 95 % at the first turbulent station, θ to grow by 10 % everywhere.
    let w = step(&state, first, -0.95, 0.1);
    let mut clipped = state.clone();
    let r = apply_step(&model, &layout, &mut clipped, &w, &due, &clip).unwrap();
    // The whole step is taken; that one value is clipped at the largest decrease (DLO).
    assert_eq!(r.rlx, 1.0);
    assert!((clipped.s[first] / state.s[first] - 0.5).abs() < 1e-12);
    for j in 0..state.len() {
        assert!(
            (clipped.theta[j] / state.theta[j] - 1.1).abs() < 1e-12,
            "{j}"
        );
        if j != first {
            assert_eq!(clipped.s[j], state.s[j], "{j}");
        }
    }
    // XFOIL's rule: that change alone relaxes the step for every station to 0.5/0.95.
    let mut relaxed = state.clone();
    let r = apply_step(&model, &layout, &mut relaxed, &w, &due, &xfoil).unwrap();
    assert!((r.rlx - 0.5 / 0.95).abs() < 1e-12, "{}", r.rlx);
    assert!((relaxed.theta[first] / state.theta[first] - (1.0 + 0.1 * r.rlx)).abs() < 1e-12);
    // The RMS change, the convergence measure, counts the full request either way.
    let r_clip = apply_step(&model, &layout, &mut state.clone(), &w, &due, &clip).unwrap();
    assert_eq!(r_clip.rms_change, r.rms_change);
}

#[test]
fn other_stations_still_relax_the_step() {
    let (layout, state, model) = marched();
    let (first, second) = turbulent_stations(&layout, &state);
    let due = vec![0.0; state.len()];
    // The same decrease one station further: it sets the relaxation, as in XFOIL.
    let w = step(&state, second, -0.95, 0.0);
    let mut s = state.clone();
    let r = apply_step(&model, &layout, &mut s, &w, &due, &UpdateLimits::default()).unwrap();
    assert!((r.rlx - 0.5 / 0.95).abs() < 1e-12, "{}", r.rlx);
    assert_eq!(s.s[first], state.s[first]);
    // So does an increase at the first turbulent station beyond DHI (+150 %).
    let w = step(&state, first, 3.0, 0.0);
    let r = apply_step(
        &model,
        &layout,
        &mut state.clone(),
        &w,
        &due,
        &UpdateLimits::default(),
    )
    .unwrap();
    assert!((r.rlx - 1.5 / 3.0).abs() < 1e-12, "{}", r.rlx);
}
