//! `gyro autorotate`: the isolated rotor in a tunnel — JSON keys, μ with a reference rpm, the
//! cases CSV over NACA Report 515's Table III, the pitch override and one-line errors.

mod cli_support;

use cli_support::{aircraft, assert_ok, assert_one_line_error, gyro, polars, repo};

fn pca2() -> String {
    repo("aircraft/pca2.toml")
}

fn goe429() -> String {
    polars("goe429_xtr0.07.csv")
}

fn json(args: &[&str]) -> serde_json::Value {
    let out = gyro(args);
    assert_ok(&out);
    serde_json::from_slice(&out.stdout).expect("valid JSON")
}

/// The keys scripts rely on.
const KEYS: [&str; 8] = [
    "rotor_rpm",
    "mu",
    "cl",
    "cd",
    "lift_to_drag",
    "coning_deg",
    "a1_deg",
    "b1_deg",
];

#[test]
fn one_case_json_and_mu_with_a_reference_rpm() {
    let (a, t) = (pca2(), goe429());
    let base = ["autorotate", "--aircraft", &a, "--table", &t, "--json"];
    // Table III row μ .216, α 8.3°, 100.5 rpm: V = 0.216·100.5·π/30·6.858/cos 8.3° = 15.7 m/s.
    let by_mu = json(
        &[
            &base[..],
            &[
                "--alpha-deg",
                "8.3",
                "--mu",
                "0.216",
                "--reference-rpm",
                "100.5",
            ],
        ]
        .concat(),
    );
    for key in KEYS {
        assert!(by_mu[key].is_number(), "{key} missing: {by_mu}");
    }
    let v = by_mu["speed_m_s"].as_f64().unwrap();
    let expected = 0.216 * 100.5 * std::f64::consts::PI / 30.0 * 6.858 / 8.3f64.to_radians().cos();
    assert!((v - expected).abs() < 1e-9, "{v} vs {expected}");
    let speed = format!("{v}");
    let by_speed = json(&[&base[..], &["--alpha-deg", "8.3", "--speed-m-s", &speed]].concat());
    assert_eq!(by_mu, by_speed);
    let f = |k: &str| by_speed[k].as_f64().unwrap();
    // Wind axes: L/D = C_L/C_D; coning of a few degrees, the disc tilted back (a1 > 0) and
    // the blades highest over the retreating side (b1 > 0), as measured on the PCA-2.
    assert!((f("lift_to_drag") - f("cl") / f("cd")).abs() < 1e-9);
    assert!(f("coning_deg") > 3.0 && f("a1_deg") > 0.0 && f("b1_deg") > 0.0);
    // A higher pitch setting turns this rotor faster at a fixed α and wind speed.
    let pitched = json(
        &[
            &base[..],
            &[
                "--alpha-deg",
                "8.3",
                "--speed-m-s",
                &speed,
                "--pitch-deg",
                "2.7",
            ],
        ]
        .concat(),
    );
    assert!(pitched["rotor_rpm"].as_f64().unwrap() > f("rotor_rpm"));
}

/// A cases file runs every row in one command and says so on a start line (a single case
/// runs without one).
#[test]
fn cases_csv_runs_table_iii_in_one_command() {
    let (a, t) = (pca2(), goe429());
    let cases = repo("tests/data/pca2/tr515_table3_pitch1.9_faired.csv");
    let out = gyro(&[
        "autorotate",
        "--aircraft",
        &a,
        "--table",
        &t,
        "--cases",
        &cases,
    ]);
    assert_ok(&out);
    let said = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        said.lines()
            .any(|l| l == "gyro: the rotor in the tunnel: 81 cases"),
        "{said}"
    );
    let one = gyro(&[
        "autorotate",
        "--aircraft",
        &a,
        "--table",
        &t,
        "--alpha-deg",
        "8",
        "--speed-m-s",
        "20",
    ]);
    assert_ok(&one);
    assert!(!String::from_utf8_lossy(&one.stderr).contains("in the tunnel"));
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap();
    let expected = ["alpha_deg", "speed_m_s"]
        .iter()
        .chain(KEYS.iter())
        .map(|s| s.to_string())
        .collect::<Vec<_>>()
        .join(",");
    assert!(header.starts_with(&expected), "{header}");
    assert!(header.ends_with(",error"), "{header}");
    let rows: Vec<&str> = lines.collect();
    assert_eq!(rows.len(), 81);
    // Every row found an autorotation (the error column is empty), in Table III's order.
    assert!(rows.iter().all(|r| r.ends_with(',')), "{rows:?}");
    assert!(rows[0].starts_with("15.9,10.6978,"), "{}", rows[0]);
}

#[test]
fn a_whole_aircraft_preset_autorotates_too() {
    let t = polars("naca8h12_free.csv");
    let v = json(&[
        "autorotate",
        "--aircraft",
        &aircraft(),
        "--table",
        &t,
        "--alpha-deg",
        "2.8",
        "--speed-m-s",
        "30.87",
        "--json",
    ]);
    // The MTOsport rotor at 60 kt and α_H 5°: a teetering rotor, coning its precone (3°).
    assert!(
        (v["coning_deg"].as_f64().unwrap() - 3.0).abs() < 1e-12,
        "{v}"
    );
    assert!(
        (300.0..420.0).contains(&v["rotor_rpm"].as_f64().unwrap()),
        "{v}"
    );
}

#[test]
fn bad_arguments_are_one_line_errors() {
    let (a, t) = (pca2(), goe429());
    let run = |extra: &[&str]| {
        gyro(&[&["autorotate", "--aircraft", &a, "--table", &t][..], extra].concat())
    };
    assert_one_line_error(
        "gyro",
        &run(&["--alpha-deg", "95", "--speed-m-s", "20"]),
        "--alpha-deg",
    );
    assert_one_line_error(
        "gyro",
        &run(&["--alpha-deg", "5", "--speed-m-s", "-3"]),
        "--speed-m-s",
    );
    assert_one_line_error(
        "gyro",
        &run(&["--alpha-deg", "5", "--speed-m-s", "NaN"]),
        "--speed-m-s",
    );
    assert_one_line_error(
        "gyro",
        &run(&["--alpha-deg", "5", "--mu", "0.2", "--reference-rpm", "0"]),
        "--reference-rpm",
    );
    assert_one_line_error(
        "gyro",
        &run(&["--alpha-deg", "5", "--speed-m-s", "20", "--pitch-deg", "30"]),
        "rotor.incidence_deg",
    );
    // Neither a wind speed nor cases: a usage error.
    let out = run(&["--alpha-deg", "5"]);
    assert_eq!(out.status.code(), Some(2));
    // A cases file without the columns, and one with a bad row (named by its line).
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "alpha,speed\n5,20\n").unwrap();
    let bad = bad.display().to_string();
    assert_one_line_error("gyro", &run(&["--cases", &bad]), "alpha_deg");
    let row = dir.path().join("row.csv");
    std::fs::write(&row, "alpha_deg,speed_m_s\n5,20\n5,1e6\n").unwrap();
    let row = row.display().to_string();
    let out = run(&["--cases", &row]);
    assert_one_line_error("gyro", &out, "line 3");
    // A bad file, not a bad command line: exit status 1 as for a file without the columns.
    assert_eq!(out.status.code(), Some(1));
    // The rotor-only preset cannot be trimmed as an aircraft.
    let out = gyro(&["trim", "--aircraft", &a, "--table", &t]);
    assert_one_line_error("gyro", &out, "describes a rotor alone");
}

/// A case without an autorotation is an error that says why (the rotor near broadside to
/// the wind: the inflow/flapping iteration does not converge), not only that none was found.
#[test]
fn a_failed_case_says_why() {
    let o = gyro(&[
        "-q",
        "autorotate",
        "--aircraft",
        &pca2(),
        "--table",
        &goe429(),
        "--alpha-deg",
        "85",
        "--speed-m-s",
        "30",
    ]);
    assert_one_line_error(
        "gyro",
        &o,
        "no autorotating rotor speed: rotor inflow/flapping",
    );
    assert_eq!(o.status.code(), Some(1));
}
