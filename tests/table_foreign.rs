//! Tables written by other tools (tests/data/foreign, provenance in its README): OpenFAST's
//! example AeroDyn airfoil files and C81 decks of MBDyn and c81utils, read by the one table
//! reader whatever their extension, every tabulated value kept, and the reader saying what it
//! assumed.

use polargen::section::SectionAero;
use polargen::table::{read_table_with, ReadOptions, TableRead};
use std::path::{Path, PathBuf};

fn foreign(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/foreign")
        .join(name)
}

fn read_foreign(name: &str, options: &ReadOptions) -> TableRead {
    read_table_with(&foreign(name), options).unwrap()
}

/// The value rows `alpha cl cd cm` after the `NumAlf` line of an AeroDyn file.
fn aerodyn_rows(name: &str) -> Vec<[f64; 4]> {
    let text = std::fs::read_to_string(foreign(name)).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    let at = lines.iter().position(|l| l.contains("NumAlf")).unwrap();
    let n: usize = lines[at]
        .split_whitespace()
        .next()
        .unwrap()
        .parse()
        .unwrap();
    lines[at + 1..]
        .iter()
        .filter(|l| !l.trim_start().starts_with('!'))
        .take(n)
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|w| w.parse().unwrap()).collect();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

#[test]
fn openfast_examples_read_whole_at_the_assumed_mach() {
    for (name, rows, thickness) in [
        ("openfast_ad_polar_example.dat", 143, Some(0.30)),
        ("openfast_ad_airfoil_example.dat", 63, None),
    ] {
        let read = read_foreign(name, &ReadOptions::default());
        let t = &read.table;
        assert_eq!((t.re(), t.mach()), (&[0.75e6][..], &[0.0][..]), "{name}");
        assert_eq!(
            read.notes,
            [
                "the AeroDyn file does not give its Mach number: M 0 assumed (set it with \
              --assume-mach)"
            ]
        );
        // Metadata a file does not give is unknown, not invented.
        let m = t.meta();
        assert!(
            m.transition.ncrit_top.is_nan() && m.transition.xtr_top.is_nan(),
            "{m:?}"
        );
        assert_eq!(m.thickness.is_nan(), thickness.is_none());
        if let Some(tc) = thickness {
            assert_eq!(m.thickness, tc);
        }
        // Every row, as written.
        let expect = aerodyn_rows(name);
        assert_eq!(expect.len(), rows);
        let polar = t.polar_at(0, 0).unwrap();
        let got: Vec<[f64; 4]> = polar.iter().map(|p| [p.alpha, p.cl, p.cd, p.cm]).collect();
        assert_eq!(got, expect, "{name}");
        assert!(polar.iter().all(|p| p.converged));
    }
    // The Mach number of the options, without a note.
    let at = read_foreign(
        "openfast_ad_polar_example.dat",
        &ReadOptions {
            mach: Some(0.3),
            ..ReadOptions::default()
        },
    );
    assert_eq!((at.table.mach(), at.notes.len()), (&[0.3][..], 0));
}

/// MBDyn's deck: CL on 11 Mach numbers × 39 angles, CD on 11 × 65, CM on 9 × 47. Each
/// tabulated value is kept at its own (α, M); the Mach 1 column is dropped, and said.
#[test]
fn mbdyn_deck_reads_each_block_on_its_own_lists() {
    let read = read_foreign("mbdyn_naca0012.c81", &ReadOptions::default());
    let t = &read.table;
    assert_eq!(
        t.mach(),
        &[0.0, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.75, 0.8, 0.9]
    );
    assert_eq!(t.re(), &[1e6]);
    assert_eq!(
        read.notes,
        [
            "C81 deck: the column at Mach 1 dropped (tables hold 0 <= M < 1)",
            "C81 deck: it gives no Reynolds number; Re 1000000 assumed (set it with --assume-re)"
        ]
    );
    // Values read off the deck (var/naca0012.c81): CL at α −11°, M 0.2 (row "-11." second
    // field, no blank before it), CD at −175°, M 0.9, CM at its own α rows.
    let at = |alpha: f64, mach: f64| {
        let polar = t.polar(1e6, mach).unwrap();
        *polar.iter().find(|p| p.alpha == alpha).unwrap()
    };
    assert_eq!(at(-11.0, 0.2).cl, -1.161);
    assert_eq!(at(-11.0, 0.3).cl, -1.19);
    assert_eq!(at(-175.0, 0.9).cd, 0.062);
    assert_eq!(at(-180.0, 0.0).cl, 0.0);
    // Every α of the three blocks is a row of every polar (union: 39, 65, 47 angles).
    let n = t.polar_at(0, 0).unwrap().len();
    assert!((65..=39 + 65 + 47).contains(&n), "{n}");
    // The metadata a deck does not carry is unknown.
    assert!(t.meta().transition.ncrit_top.is_nan() && t.meta().transition.xtr_bot.is_nan());
    // The Reynolds number of the options, said as assumed.
    let at_re = read_foreign(
        "mbdyn_naca0012.c81",
        &ReadOptions {
            re: Some(3e6),
            ..ReadOptions::default()
        },
    );
    assert_eq!(at_re.table.re(), &[3e6]);
    assert!(
        at_re.notes[1].ends_with("Re 3000000 assumed"),
        "{:?}",
        at_re.notes
    );
}

/// The VR-8 deck of c81utils: CL at 12 Mach numbers, CD at 14, CM at 13. A CD value at a
/// Mach number the CL block does not have is kept exactly; CL there is interpolated in M.
#[test]
fn vr8_deck_with_different_mach_lists() {
    let read = read_foreign("c81utils_vr8.c81", &ReadOptions::default());
    let t = &read.table;
    assert!(t.mach().len() >= 13, "{:?}", t.mach());
    assert_eq!(t.meta().airfoil, "VR8TM6 VR8 -6 tab C81 format");
    // The deck's first CL row: α −180°, −0.005 at every Mach number.
    for (k, _) in t.mach().iter().enumerate() {
        let first = t.polar_at(0, k).unwrap()[0];
        assert_eq!((first.alpha, first.cl), (-180.0, -0.005));
    }
    // Lookups stay within the deck's CL range everywhere (no wild extrapolation).
    for a in [-20.0, -5.0, 0.0, 5.0, 12.0, 60.0] {
        for m in [0.0, 0.35, 0.7] {
            let l = t.lookup(a, 1e6, m);
            assert!(
                l.cl.abs() < 2.0 && l.cd > 0.0 && l.cd < 2.5,
                "α {a} M {m}: {l:?}"
            );
        }
    }
}
