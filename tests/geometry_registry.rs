//! Name registry: built-in names, NACA designations, file paths and the error listing what
//! is accepted.

use polargen::geometry::{airfoil_by_name_or_path, naca, GeometryError, NacaOptions};
use std::path::Path;

#[test]
fn naca8h12_is_embedded_and_independent_of_cwd() {
    // All other paths in this test binary are absolute, so changing the cwd is safe here.
    std::env::set_current_dir(std::env::temp_dir()).unwrap();
    for name in ["naca8h12", "NACA 8-H-12", "Naca8H12", " naca 8h12 "] {
        let a = airfoil_by_name_or_path(name).unwrap();
        assert_eq!(a.name, "NACA 8-H-12");
        assert_eq!(a.x.len(), 51);
        // Maximum thickness station of TN 1998 Table I (upper surface).
        assert_eq!((a.x[14], a.y[14]), (0.29969, 0.09533));
    }
}

#[test]
fn naca_names_use_the_xfoil_generator() {
    let reference = naca("23012", &NacaOptions::default()).unwrap();
    for name in ["naca23012", "NACA 23012", "naca-23012", "NACA23012"] {
        assert_eq!(airfoil_by_name_or_path(name).unwrap(), reference, "{name}");
    }
    let a = airfoil_by_name_or_path("NACA 2412").unwrap();
    assert_eq!(a.name, "NACA 2412");
    assert_eq!(a.x.len(), 245);
    assert_eq!(
        airfoil_by_name_or_path("naca23112").unwrap().name,
        "NACA 23112"
    );
}

#[test]
fn paths_are_read_as_coordinate_files() {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/geometry/lednicer_naca8h12.dat");
    let a = airfoil_by_name_or_path(p.to_str().unwrap()).unwrap();
    assert_eq!(a, airfoil_by_name_or_path("naca8h12").unwrap());
}

#[test]
fn unknown_names_list_what_is_accepted() {
    for name in ["clarky", "", "/no/such/dir/foil.dat"] {
        let e = airfoil_by_name_or_path(name).unwrap_err();
        assert!(
            matches!(e, GeometryError::UnknownAirfoil { .. }),
            "{name}: {e:?}"
        );
        assert_eq!(
            e.to_string(),
            format!(
                "unknown airfoil '{name}': not a known name and no such file (accepted: naca8h12, \
                 naca23012, nacaDDDD, nacaDDDDD, 'NACA 2412', or a path to a \
                 Selig/Lednicer/plain coordinate file)"
            )
        );
    }
}

#[test]
fn malformed_naca_names_say_why() {
    assert_eq!(
        airfoil_by_name_or_path("naca123").unwrap_err().to_string(),
        "invalid NACA designation 'naca123': expected 4 or 5 digits"
    );
    assert_eq!(
        airfoil_by_name_or_path("NACA 12345")
            .unwrap_err()
            .to_string(),
        "invalid NACA designation 'NACA 12345': third digit must be 0 (normal) or 1 (reflexed)"
    );
    for six in ["naca64-212", "NACA 65A010"] {
        let e = airfoil_by_name_or_path(six).unwrap_err().to_string();
        assert!(e.contains(&format!("'{six}': 6-series sections")), "{e}");
    }
    // a missing file named like a designation is still a missing file
    let e = airfoil_by_name_or_path("naca0012.dat")
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("unknown airfoil"), "{e}");
}

#[test]
fn a_folder_is_named_as_a_folder() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/geometry");
    let name = dir.to_str().unwrap();
    let e = airfoil_by_name_or_path(name).unwrap_err();
    assert!(matches!(e, GeometryError::AirfoilIsFolder { .. }), "{e:?}");
    assert_eq!(
        e.to_string(),
        format!("airfoil '{name}' is a folder, not a coordinate file")
    );
}
