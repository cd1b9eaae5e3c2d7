//! Station topology (XFOIL STFIND/IBLPAN/XICALC).

use super::*;
use crate::inviscid::{PanelGeometry, PanelParams};

#[test]
fn stagnation_point_is_interpolated_sign_change() {
    let q = [1.0, 0.5, -0.5, -1.0];
    let s = [0.0, 1.0, 2.0, 3.0];
    let st = find_stagnation(&q, &s).unwrap();
    assert_eq!(st.ist, 1);
    assert!((st.sst - 1.5).abs() < 1e-12);
    // Asymmetric: zero crossing at 1/4 of the interval.
    let st = find_stagnation(&[1.0, 0.25, -0.75], &[0.0, 1.0, 3.0]).unwrap();
    assert!((st.sst - 1.5).abs() < 1e-12, "{}", st.sst);
    assert_eq!(
        find_stagnation(&[1.0, 1.0, 1.0], &[0.0, 1.0, 2.0]),
        Err(ViscousError::NoStagnationPoint)
    );
}

/// Diamond-like closed contour of 9 nodes with a 3-node wake (no speeds or influence needed).
fn geometry() -> PanelModel {
    let x = [1.0, 0.7, 0.4, 0.1, 0.0, 0.1, 0.4, 0.7, 1.0];
    let y = [0.0, 0.03, 0.05, 0.03, 0.0, -0.03, -0.05, -0.03, 0.0];
    PanelModel {
        airfoil: PanelGeometry::new(&x, &y, &PanelParams::default()).unwrap(),
        wake_x: vec![1.0, 1.3, 1.8],
        wake_y: vec![0.0; 3],
        q_unit: [vec![0.0; 12], vec![0.0; 12]],
        dij: crate::inviscid::SourceInfluence::zeros(9, 3),
    }
}

#[test]
fn layout_orders_stations_and_xi() {
    let g = geometry();
    // Stagnation between nodes 4 and 5 (slightly on the lower side).
    let q = [1.0, 1.1, 1.2, 0.8, 0.2, -0.6, -1.1, -1.0, -0.9];
    let layout = StationLayout::new(&g, &q).unwrap();
    assert_eq!(layout.n_upper, 5);
    assert_eq!(layout.n_lower, 4);
    assert_eq!(layout.n_wake, 3);
    let upper: Vec<usize> = layout
        .range(Surface::Upper)
        .map(|k| layout.stations[k].node)
        .collect();
    assert_eq!(upper, vec![4, 3, 2, 1, 0]);
    let lower: Vec<usize> = layout
        .range(Surface::Lower)
        .map(|k| layout.stations[k].node)
        .collect();
    assert_eq!(lower, vec![5, 6, 7, 8]);
    for surface in [Surface::Upper, Surface::Lower, Surface::Wake] {
        let xi: Vec<f64> = layout
            .range(surface)
            .map(|k| layout.stations[k].xi)
            .collect();
        assert!(xi.windows(2).all(|w| w[1] >= w[0]), "{surface:?}: {xi:?}");
        assert!(xi[0] >= 0.0);
    }
    // Wake ξ starts at the lower TE ξ and then adds the wake arc length.
    let w0 = layout.wake_start();
    assert_eq!(
        layout.stations[w0].xi,
        layout.stations[layout.lower_te()].xi
    );
    assert!((layout.stations[w0 + 2].xi - layout.stations[w0].xi - 0.8).abs() < 1e-12);
    // Sharp TE: no wake gap.
    assert!(layout.stations[w0..].iter().all(|s| s.wake_gap == 0.0));
    // Edge speed sign convention Ue = vti·q.
    let ue = layout.edge_speed(&[q.as_slice(), &[-1.0, -1.0, -1.0]].concat());
    assert!(ue.iter().all(|u| *u > 0.0));
    // Moving the stagnation point one node down: node 5 changes surface and maps to the first
    // old upper station; every other station maps to the same node.
    let q2 = [1.0, 1.1, 1.2, 0.8, 0.4, 0.1, -1.1, -1.0, -0.9];
    let layout2 = StationLayout::new(&g, &q2).unwrap();
    let map = layout2.map_from(&layout);
    for (k, &o) in map.iter().enumerate() {
        let (new, old) = (layout2.stations[k], layout.stations[o]);
        if new.node == 5 {
            assert_eq!(o, 0);
        } else {
            assert_eq!(new.node, old.node);
        }
    }
}
