//! The `gyro` binary: JSON keys, history file, comparison tables and one-line errors.

mod cli_support;

use cli_support::{aircraft, assert_ok, assert_one_line_error, gyro, root};
use std::process::Output;

/// XFOIL 6.99 polars of the NACA 8-H-12 at Re 1.9e6, M 0.41 (free transition / xtr 0.07).
fn table(kind: &str) -> String {
    root()
        .join(format!(
            "tests/data/xfoil/naca8h12_Re1.9e6_M0.41_{kind}.csv"
        ))
        .display()
        .to_string()
}

fn json(out: &Output) -> serde_json::Value {
    assert_ok(out);
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

#[test]
fn trim_json_keys_and_values() {
    let a = aircraft();
    let t = table("free");
    let v = json(&gyro(&[
        "trim",
        "--aircraft",
        &a,
        "--table",
        &t,
        "--speed-kt",
        "60",
        "--mass",
        "450",
        "--json",
    ]));
    for key in [
        "rotor_rpm",
        "rotor_aoa_deg",
        "engine_rpm",
        "rotor_drag_n",
        "parasitic_drag_n",
        "prop_thrust_n",
        "lift_to_drag",
        "rotor_aoa_drag_equivalent_deg",
        "static_thrust_n",
        "table_clamped_fraction",
        "table_supercritical_fraction",
        "table_separated_fraction",
        "static_thrust_post_stall_fraction",
        "static_thrust_supercritical_fraction",
    ] {
        assert!(v[key].is_number(), "{key} missing: {v}");
    }
    let f = |k: &str| v[k].as_f64().unwrap();
    // The drag-equivalent angle is atan(D_R/L_R), L_R = weight at trim; it exceeds the
    // tip-path-plane angle (the in-plane force of the profile drag).
    let weight = 450.0 * 9.80665;
    let equivalent = f("rotor_drag_n").atan2(weight).to_degrees();
    assert!((f("rotor_aoa_drag_equivalent_deg") - equivalent).abs() < 1e-3);
    assert!(f("rotor_aoa_drag_equivalent_deg") > f("rotor_aoa_deg"));
    // A single-node table: nearly every lookup is clamped.
    assert!(f("table_clamped_fraction") > 0.5 && f("static_thrust_n") > 1000.0);
    // XFOIL polars of the paper's airfoil: the paper's trim is 347 rpm, F_prop 1051 N.
    assert!((f("rotor_rpm") - 347.0).abs() < 40.0, "{}", f("rotor_rpm"));
    assert!((f("prop_thrust_n") - f("rotor_drag_n") - f("parasitic_drag_n")).abs() < 1e-6);
    assert!((f("lift_to_drag") - 450.0 * 9.80665 / f("prop_thrust_n")).abs() < 1e-9);
}

#[test]
fn takeoff_json_keys_and_history() {
    let dir = std::env::temp_dir().join(format!("gyro_cli_{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let hist = dir.join("hist.csv");
    let h = hist.display().to_string();
    let v = json(&gyro(&[
        "takeoff",
        "--aircraft",
        &aircraft(),
        "--table",
        &table("free"),
        "--json",
        "--history",
        &h,
    ]));
    for key in ["takeoff_roll_m", "distance_15m_m", "max_flapping_deg"] {
        assert!(v[key].is_number(), "{key} missing: {v}");
    }
    assert!(v["distance_15m_m"].as_f64().unwrap() > v["takeoff_roll_m"].as_f64().unwrap());
    let text = std::fs::read_to_string(&hist).unwrap();
    assert!(text.starts_with("t,x,h,v,rotor_rpm,alpha_r_deg,beta_deg\n"));
    assert!(text.lines().count() > 100);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn compare_prints_both_tables_with_paper_values() {
    let out = gyro(&[
        "compare",
        "--aircraft",
        &aircraft(),
        "--clean",
        &table("free"),
        "--contaminated",
        &table("xtr0.07"),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("Table 3") && text.contains("Table 4"),
        "{text}"
    );
    // The paper's clean and contaminated F_prop and takeoff roll appear beside ours.
    assert!(
        text.contains("1051.0") && text.contains("1197.0") && text.contains("121.0"),
        "{text}"
    );
    let fprop = text.lines().find(|l| l.contains("F_prop")).unwrap();
    assert!(fprop.contains("+13.9%"), "{fprop}");
}

#[test]
fn sweep_gives_a_power_curve() {
    let v = json(&gyro(&[
        "sweep",
        "--aircraft",
        &aircraft(),
        "--table",
        &table("free"),
        "--from-kt",
        "40",
        "--to-kt",
        "80",
        "--step-kt",
        "20",
        "--json",
    ]));
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 3);
    let d_p: Vec<f64> = rows
        .iter()
        .map(|r| r["parasitic_drag_n"].as_f64().unwrap())
        .collect();
    assert!(d_p[0] < d_p[1] && d_p[1] < d_p[2]);
    // D_P ∝ V²: 80 kt has four times the 40 kt value.
    assert!((d_p[2] / d_p[0] - 4.0).abs() < 1e-9);
}

#[test]
fn alpha_distribution_csv() {
    let out = gyro(&[
        "alpha",
        "--aircraft",
        &aircraft(),
        "--table",
        &table("free"),
        "--radius",
        "0.9",
        "--samples",
        "36",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    let mut lines = text.lines();
    assert_eq!(lines.next(), Some("psi_deg,alpha_deg"));
    let rows: Vec<(f64, f64)> = lines
        .map(|l| {
            let (a, b) = l.split_once(',').unwrap();
            (a.parse().unwrap(), b.parse().unwrap())
        })
        .collect();
    assert_eq!(rows.len(), 36);
    // Paper Fig. 10: the blade angle peaks on the retreating side, ψ ≈ 270° (ψ = 0 rear).
    let max = rows
        .iter()
        .cloned()
        .fold((0.0, f64::MIN), |m, r| if r.1 > m.1 { r } else { m });
    assert!((240.0..=300.0).contains(&max.0), "{max:?}");
}

#[test]
fn errors_are_one_line() {
    let t = table("free");
    assert_one_line_error(
        "gyro",
        &gyro(&["trim", "--aircraft", "/nonexistent.toml", "--table", &t]),
        "cannot read aircraft file",
    );
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            "/nonexistent.csv",
        ]),
        "cannot read table",
    );
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &t,
            "--speed-kt=-5",
        ]),
        "--speed-kt",
    );
    // Without --table the shipped clean 8-H-12 table is read (with a note), as gyro report does.
    let shipped = gyro(&["trim", "--aircraft", &aircraft()]);
    assert_ok(&shipped);
    assert!(String::from_utf8_lossy(&shipped.stderr).contains("polars/naca8h12_free.csv"));
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &t,
            "--speed-kt",
            "fast",
        ]),
        "fast",
    );
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &t,
            "--mass",
            "0",
        ]),
        "--mass",
    );
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &t,
            "--mass",
            "5000",
        ]),
        "no trim",
    );
    // A table without the needed columns.
    let bad = std::env::temp_dir().join(format!("gyro_bad_{}.csv", std::process::id()));
    std::fs::write(&bad, "a,b\n1,2\n").unwrap();
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &bad.display().to_string(),
        ]),
        "alpha, cl, cd",
    );
    std::fs::remove_file(&bad).ok();
    // A malformed preset.
    let bad = std::env::temp_dir().join(format!("gyro_bad_{}.toml", std::process::id()));
    std::fs::write(&bad, "name = \"x\"\n").unwrap();
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &bad.display().to_string(),
            "--table",
            &t,
        ]),
        "bad aircraft file",
    );
    std::fs::remove_file(&bad).ok();
    // A table without two converged points in any polar cannot drive the rotor.
    let dead = std::env::temp_dir().join(format!("gyro_dead_{}.csv", std::process::id()));
    std::fs::write(
        &dead,
        "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n\
         x,1e6,0,9,1,1,0,0.1,0.01,0.005,0,1,1,false\n\
         x,1e6,0,9,1,1,1,0.2,0.01,0.005,0,1,1,true\n",
    )
    .unwrap();
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "trim",
            "--aircraft",
            &aircraft(),
            "--table",
            &dead.display().to_string(),
        ]),
        "no polar has at least 2 converged points",
    );
    std::fs::remove_file(&dead).ok();
}

/// Flags name themselves with their value; impossible ranges, absurd step counts and bad
/// output paths are refused before any computation, and a polargen table with an error is
/// reported as such (not through the XFOIL-polar fallback's complaint).
#[test]
fn bad_values_and_paths_are_refused_up_front() {
    let (a, t) = (aircraft(), table("free"));
    let dir = std::env::temp_dir().join(format!("gyro_paths_{}", std::process::id()));
    std::fs::create_dir_all(dir.join("folder")).unwrap();
    let file = dir.join("plain");
    std::fs::write(&file, "x").unwrap();
    let under_file = format!("{}/h.csv", file.display());
    let folder = dir.join("folder").display().to_string();
    let trim = |extra: &[&str]| {
        let mut args = vec!["trim", "--aircraft", &a, "--table", &t];
        args.extend_from_slice(extra);
        gyro(&args)
    };
    let sweep = |extra: &[&str]| {
        let mut args = vec!["sweep", "--aircraft", &a, "--table", &t];
        args.extend_from_slice(extra);
        gyro(&args)
    };
    let takeoff = |extra: &[&str]| {
        let mut args = vec!["takeoff", "--aircraft", &a, "--table", &t];
        args.extend_from_slice(extra);
        gyro(&args)
    };
    let cases: Vec<(Output, &str)> = vec![
        (
            trim(&["--speed-kt", "-60"]),
            "--speed-kt -60: must be above 0 and below 300 kt",
        ),
        (
            trim(&["--altitude-m", "1e9"]),
            "--altitude-m 1e9: must be within the ISA troposphere",
        ),
        (trim(&["--altitude-m", "-100"]), "--altitude-m -100"),
        (trim(&["--altitude-m", "nan"]), "--altitude-m NaN"),
        (sweep(&["--from-kt", "0"]), "--from-kt 0: must be above 0"),
        (sweep(&["--to-kt", "300"]), "--to-kt 300: must be above 0"),
        (
            sweep(&["--step-kt", "1e-9"]),
            "speeds from 30 to 90 kt (at most 1000)",
        ),
        (
            sweep(&["--step-kt", "-1"]),
            "--step-kt -1: must be a positive number",
        ),
        (
            gyro(&["alpha", "--aircraft", &a, "--table", &t, "--radius", "0.05"]),
            "--radius 0.05: must be a fraction of R on the blade",
        ),
        (takeoff(&["--history", &folder]), "--history: "),
        (
            takeoff(&["--history", &under_file]),
            "plain: is not a folder",
        ),
        (
            gyro(&["takeoff", "--aircraft", &a, "--table", "/dev/null"]),
            "table /dev/null",
        ),
        (
            gyro(&["trim", "--aircraft", &a, "--table", &folder]),
            "is a folder",
        ),
        (
            gyro(&["report", "--aircraft", &a, "--out", file.to_str().unwrap()]),
            "plain: is not a folder",
        ),
    ];
    for (out, needle) in &cases {
        assert_one_line_error("gyro", out, needle);
    }
    // A bad history path is refused before the takeoff is simulated (no ~3 s of work).
    let start = std::time::Instant::now();
    assert_one_line_error(
        "gyro",
        &gyro(&[
            "takeoff",
            "--aircraft",
            &a,
            "--table",
            &t,
            "--history",
            &under_file,
        ]),
        "--history: ",
    );
    assert!(start.elapsed().as_secs_f64() < 2.0);
    // A polargen table with a negative drag is named, not passed to the fallback reader.
    let neg = dir.join("neg.csv");
    std::fs::write(
        &neg,
        "airfoil,re,mach,ncrit,xtr_top_set,xtr_bot_set,alpha,cl,cd,cdp,cm,xtr_top,xtr_bot,converged\n\
         x,1e6,0,9,1,1,0,0.1,-0.01,0.005,0,1,1,true\n\
         x,1e6,0,9,1,1,1,0.2,0.01,0.005,0,1,1,true\n",
    )
    .unwrap();
    let out = trim(&[]);
    assert_ok(&out);
    let out = gyro(&["trim", "--aircraft", &a, "--table", neg.to_str().unwrap()]);
    assert_one_line_error(
        "gyro",
        &out,
        "cd -0.01 < 0 at alpha 0 in polar Re 1000000, M 0",
    );
    assert!(!String::from_utf8_lossy(&out.stderr).contains("XFOIL"));
    std::fs::remove_dir_all(dir).unwrap();
}

/// A trim outside the table's Re/M range, or beyond the engine, is a result with notes on
/// stderr saying so.
#[test]
fn trim_notes_clamped_lookups_and_engine_limit() {
    let a = aircraft();
    // The XFOIL polar is a single node (Re 1.9e6, M 0.41): most strips lie off it.
    let out = gyro(&["trim", "--aircraft", &a, "--table", &table("free")]);
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("of the blade-element lookups lie outside the table's Reynolds/Mach range"),
        "{err}"
    );
    let out = gyro(&[
        "trim",
        "--aircraft",
        &a,
        "--table",
        &table("free"),
        "--speed-kt",
        "130",
    ]);
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("needs more than the engine's maximum rpm"),
        "{err}"
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("above max"));
}

/// Every command that runs the rotor says where its section data are not to be trusted: the
/// takeoff (the largest share of one rotor solution, also in its JSON), both cases of
/// `compare`, a sweep (with the speeds beyond the engine) and the blade α trim.
#[test]
fn every_rotor_command_says_its_lookup_shares() {
    let a = aircraft();
    let shipped = cli_support::polars("naca8h12_free.csv");
    let stderr_of = |args: &[&str]| {
        let out = gyro(args);
        assert_ok(&out);
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    // The XFOIL polar is a single node (Re 1.9e6, M 0.41): most lookups lie off it.
    let t = table("free");
    let out = gyro(&["takeoff", "--aircraft", &a, "--table", &t, "--json"]);
    assert_ok(&out);
    let v = json(&out);
    assert!(
        v["max_table_clamped_fraction"].as_f64().unwrap() > 0.5,
        "{v}"
    );
    for key in [
        "max_table_supercritical_fraction",
        "max_table_separated_fraction",
    ] {
        assert!(v[key].is_number(), "{key} missing: {v}");
    }
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("note: during the takeoff (the largest share of one rotor solution), ")
            && err.contains("lookups lie outside the table's Reynolds/Mach range"),
        "{err}"
    );
    // The shipped table: some lookups in massive separation during the run, most of them in
    // one solution of the ground roll (13.1 % at 35.2 kt, 6.3 s after brake release; lift-off
    // at 9.6 s).
    let out = gyro(&["takeoff", "--aircraft", &a, "--table", &shipped, "--json"]);
    assert_ok(&out);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("in massive separation"), "{err}");
    let v = json(&out);
    let number = |key: &str| v[key].as_f64().unwrap_or(f64::NAN);
    assert!(
        (number("max_table_separated_fraction") - 0.131).abs() < 0.005,
        "{v}"
    );
    assert!(
        (number("max_table_separated_speed_kt") - 35.2).abs() < 1.0,
        "{v}"
    );
    assert!(
        (number("max_table_separated_time_s") - 6.3).abs() < 0.3,
        "{v}"
    );
    let err = stderr_of(&["compare", "--aircraft", &a, "--clean", &shipped]);
    for case in ["clean", "contaminated"] {
        assert!(
            err.contains(&format!("note: {case}: during the takeoff"))
                && err.contains(&format!("note: {case}: at 60.0 kt, ")),
            "{case}: {err}"
        );
    }
    let err = stderr_of(&[
        "sweep",
        "--aircraft",
        &a,
        "--table",
        &shipped,
        "--from-kt",
        "100",
        "--to-kt",
        "150",
        "--step-kt",
        "25",
    ]);
    assert!(
        err.contains("at 3 of 3 speeds (100.0 to 150.0 kt) the propeller needs more than")
            && err.contains("lean on supercritical table points"),
        "{err}"
    );
    let err = stderr_of(&["alpha", "--aircraft", &a, "--table", &shipped]);
    assert!(err.contains("note: at 60.0 kt, "), "{err}");
}
