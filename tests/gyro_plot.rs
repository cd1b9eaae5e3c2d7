//! `gyro plot alpha|takeoff|power` on the shipped tables: the figures carry their series and
//! axis labels, PNGs are real images, and errors (of the plots and of `gyro report`) are one
//! line. The report's contents: tests/gyro_report.rs.

mod cli_support;

use cli_support::{aircraft, assert_ok, assert_one_line_error, gyro, polars, scratch};
use std::path::Path;

/// Runs `gyro plot <kind> … --out` once to SVG and once to PNG, checks the PNG is a real image
/// of at least `min_png` bytes and returns the SVG text.
fn plot_both(kind: &str, extra: &[&str], dir: &Path, min_png: usize) -> String {
    let (svg, png) = (
        dir.join(format!("{kind}.svg")),
        dir.join(format!("{kind}.png")),
    );
    let ac = aircraft();
    for out in [&svg, &png] {
        let mut args = vec![
            "plot",
            kind,
            "--aircraft",
            &ac,
            "--out",
            out.to_str().unwrap(),
        ];
        args.extend_from_slice(extra);
        assert_ok(&gyro(&args));
    }
    let bytes = std::fs::read(&png).unwrap();
    assert_eq!(&bytes[..8], b"\x89PNG\r\n\x1a\n");
    assert!(
        bytes.len() > min_png,
        "{kind}: PNG of {} bytes",
        bytes.len()
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.trim_end().ends_with("</svg>"));
    text
}

fn assert_contains(svg: &str, needles: &[&str]) {
    for n in needles {
        assert!(svg.contains(n), "SVG lacks '{n}'");
    }
}

#[test]
fn alpha_plot_has_both_cases_and_azimuth_axis() {
    let dir = scratch("alpha");
    let (c, d) = (polars("naca8h12_free.csv"), polars("naca8h12_xtr0.07.csv"));
    let svg = plot_both(
        "alpha",
        &["--clean", &c, "--contaminated", &d],
        &dir,
        40_000,
    );
    assert_contains(
        &svg,
        &[
            "clean",
            "contaminated",
            "max clean",
            "max contaminated",
            "azimuth ψ [deg] (0 = rear)",
            "local α [deg]",
            "Blade α at r = 0.90 R",
            "NACA 8-H-12",
            ">\n360\n<",
        ],
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn takeoff_plot_has_four_histories_and_lift_off() {
    let dir = scratch("takeoff");
    let (c, d) = (polars("naca8h12_free.csv"), polars("naca8h12_xtr0.07.csv"));
    let svg = plot_both(
        "takeoff",
        &[
            "--clean",
            &c,
            "--contaminated",
            &d,
            "--title",
            "Takeoff test title",
        ],
        &dir,
        80_000,
    );
    assert_contains(
        &svg,
        &[
            "Takeoff test title",
            "speed [kt]",
            "height [m]",
            "rotor speed [rpm]",
            "flapping β [deg]",
            "time [s]",
            "lift-off, clean",
            "lift-off, contaminated",
            "15 m obstacle",
        ],
    );
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn power_plot_has_power_and_thrust_curves() {
    let dir = scratch("power");
    let c = polars("naca8h12_free.csv");
    let svg = plot_both(
        "power",
        &[
            "--clean",
            &c,
            "--from-kt",
            "40",
            "--to-kt",
            "80",
            "--step-kt",
            "10",
        ],
        &dir,
        30_000,
    );
    assert_contains(
        &svg,
        &[
            "clean",
            "power [kW]",
            "propeller thrust [N]",
            "airspeed [kt]",
            "Power required",
        ],
    );
    assert!(!svg.contains("contaminated"), "one case only");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn errors_are_one_line() {
    let dir = scratch("errors");
    let svg = dir.join("e.svg").display().to_string();
    let ac = aircraft();
    let c = polars("naca8h12_free.csv");
    let plot = |extra: &[&str]| {
        let mut args = vec!["plot", "alpha", "--aircraft", &ac];
        args.extend_from_slice(extra);
        gyro(&args)
    };
    assert_one_line_error(
        "gyro",
        &plot(&["--clean", "/nonexistent.csv", "--out", &svg]),
        "cannot read table /nonexistent.csv",
    );
    let bad = dir.join("bad.csv");
    std::fs::write(&bad, "alpha,cl,cd\n0,0.1,zero\n").unwrap();
    assert_one_line_error(
        "gyro",
        &plot(&["--clean", bad.to_str().unwrap(), "--out", &svg]),
        "bad.csv",
    );
    // An output under a regular file: refused before any computation.
    let under_file = format!("{}/a.svg", bad.display());
    assert_one_line_error(
        "gyro",
        &plot(&["--clean", &c, "--out", &under_file]),
        &format!(
            "--out: cannot write plot {under_file}: {}: is not a folder",
            bad.display()
        ),
    );
    assert_one_line_error(
        "gyro",
        &plot(&["--clean", &c, "--out", dir.join("a.pdf").to_str().unwrap()]),
        "unknown file extension",
    );
    assert_one_line_error("gyro", &plot(&["--clean", &c]), "--out");
    assert_one_line_error(
        "gyro",
        &plot(&["--clean", &c, "--radius", "1.5", "--out", &svg]),
        "--radius",
    );
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "plot",
            "power",
            "--aircraft",
            &ac,
            "--clean",
            &c,
            "--from-kt",
            "80",
            "--to-kt",
            "40",
            "--out",
            &svg,
        ]),
        "--to-kt 40: below --from-kt 80",
    );
    // `gyro report` from the tables in `polars_dir` into dir/r
    let report = |polars_dir: &std::path::Path| {
        gyro(&[
            "report",
            "--aircraft",
            &ac,
            "--polars",
            polars_dir.to_str().unwrap(),
            "--out",
            dir.join("r").to_str().unwrap(),
        ])
    };
    assert_one_line_error("gyro", &report(&dir), "naca8h12_free.csv");
    assert!(!dir.join("e.svg").exists() && !dir.join("r").exists());
    // A misnamed table (the 23012 under the 8-H-12's name) is refused, not reported on.
    let polars_dir = dir.join("polars");
    std::fs::create_dir_all(&polars_dir).unwrap();
    for t in ["naca8h12_xtr0.07", "naca23012_free", "naca23012_xtr0.07"] {
        std::fs::copy(
            polars(&format!("{t}.csv")),
            polars_dir.join(format!("{t}.csv")),
        )
        .unwrap();
    }
    std::fs::copy(
        polars("naca23012_free.csv"),
        polars_dir.join("naca8h12_free.csv"),
    )
    .unwrap();
    assert_one_line_error("gyro", 
        &report(&polars_dir),
        "naca8h12_free.csv: holds NACA 23012 with transition at 1/1 (upper/lower), expected naca8h12 at 1",
    );
    assert!(!dir.join("r").exists());
    std::fs::remove_dir_all(dir).unwrap();
}
