//! Criterion benchmarks of the rotor model with the shipped contaminated NACA 8-H-12 table
//! (transition at 7 % chord): one takeoff from brake release to 15 m (about 1 000 fourth-order
//! Runge–Kutta steps, four warm-started rotor solutions each) and one 60 kt cruise trim, as
//! `gyro takeoff` and `gyro trim` run them. Run with `cargo bench --bench rotor`.

use criterion::{criterion_group, criterion_main, Criterion};
use polargen::rotor::{simulate_takeoff, trim_aircraft, Aircraft, TrimParams};
use polargen::table::read_lookup_table;
use std::path::Path;

fn bench_rotor(c: &mut Criterion) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let aircraft = Aircraft::from_toml_file(&root.join("aircraft/mtosport.toml")).expect("preset");
    let table = read_lookup_table(&root.join("polars/naca8h12_xtr0.07.csv")).expect("table");
    let mut group = c.benchmark_group("mtosport_naca8h12_xtr0.07");
    group.sample_size(10);
    group.bench_function("takeoff", |b| {
        b.iter(|| {
            let r = simulate_takeoff(&aircraft, &table).expect("takeoff");
            assert!(r.distance_15m_m > r.takeoff_roll_m);
            r
        })
    });
    group.bench_function("trim_60kt", |b| {
        b.iter(|| {
            trim_aircraft(
                &aircraft,
                &table,
                60.0,
                aircraft.mass_kg,
                0.0,
                &TrimParams::default(),
            )
            .expect("trim")
        })
    });
    group.finish();
}

criterion_group!(benches, bench_rotor);
criterion_main!(benches);
