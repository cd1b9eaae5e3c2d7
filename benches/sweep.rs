//! Criterion benchmark of one viscous sweep: NACA 8-H-12, Re 1.9e6, M 0.41, α −4…12 step 0.5,
//! free transition and transition fixed at 7 % chord (the paper's two cases), single thread,
//! warm-started march as the `polargen` CLI runs it.

use criterion::{criterion_group, criterion_main, Criterion};
use polargen::geometry::{airfoil_by_name_or_path, PanelingParams};
use polargen::polar::{parse_alpha_range, sweep, SweepParams};
use polargen::viscous::{ViscousParams, ViscousSolver};

fn bench_sweeps(c: &mut Criterion) {
    let foil = airfoil_by_name_or_path("naca8h12")
        .and_then(|a| a.repanel(160, &PanelingParams::default()))
        .expect("8-H-12 geometry");
    let alphas = parse_alpha_range("-4:12:0.5").expect("range");
    let sweep_params = SweepParams::default();
    let mut group = c.benchmark_group("naca8h12_Re1.9e6_M0.41");
    group.sample_size(10);
    for (name, xtr) in [("free", 1.0), ("xtr0.07", 0.07)] {
        let params = ViscousParams::at(1.9e6, 0.41, xtr);
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut solver = ViscousSolver::new(&foil, params).expect("solver");
                let points = sweep(&mut solver, &alphas, &sweep_params);
                assert!(points.iter().filter(|p| p.converged).count() >= 30);
                points
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_sweeps);
criterion_main!(benches);
