//! Error handling and file writing of the renderer: one-line errors for bad paths and bad
//! figures, atomic replacement of existing plots, no temporary files left behind.

use std::path::{Path, PathBuf};

use polargen::plot::{
    check_image_path, render, render_svg_string, Figure, Marker, Panel, PlotError, Series, Style,
};

/// A fresh, empty directory for one test.
fn fresh_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "polargen-plot-errors-{}-{name}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Names of the files in `dir`.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("read dir")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

/// A small valid figure: y = x² on [0, 2].
fn parabola(title: &str) -> Figure {
    let x: Vec<f64> = (0..=20).map(|k| 0.1 * k as f64).collect();
    let y: Vec<f64> = x.iter().map(|x| x * x).collect();
    Figure::new(title).with_panel(
        Panel::new("parabola", "x [m]", "y [m²]").with_series(Series::new(
            "y = x²",
            x,
            y,
            Style::solid(0),
        )),
    )
}

/// Asserts that an error message is one non-empty line containing `needle`.
fn assert_one_line(err: &PlotError, needle: &str) {
    let msg = err.to_string();
    assert!(
        !msg.is_empty() && !msg.contains('\n'),
        "not one line: {msg:?}"
    );
    assert!(msg.contains(needle), "{msg:?} does not mention {needle:?}");
}

#[test]
fn unknown_extension_is_rejected() {
    let dir = fresh_dir("ext");
    for name in ["plot.jpg", "plot", "plot.svg.bak"] {
        let err = render(&parabola("t"), dir.join(name)).expect_err(name);
        assert!(matches!(err, PlotError::UnknownExtension { .. }), "{err:?}");
        assert_one_line(&err, name);
    }
    assert!(listing(&dir).is_empty(), "files left: {:?}", listing(&dir));
    // Upper-case extensions are accepted.
    render(&parabola("t"), dir.join("PLOT.SVG")).expect("upper-case .SVG");
    assert_eq!(listing(&dir), vec!["PLOT.SVG"]);
}

#[test]
fn missing_folders_are_created() {
    let dir = fresh_dir("missing");
    for name in ["no/such/dir/plot.svg", "no/such/dir/plot.png"] {
        render(&parabola("t"), dir.join(name)).expect(name);
    }
    assert_eq!(
        listing(&dir.join("no/such/dir")),
        vec!["plot.png", "plot.svg"]
    );
}

#[test]
fn path_under_a_file_or_a_folder_gives_unwritable_error() {
    let dir = fresh_dir("unwritable");
    std::fs::write(dir.join("file"), b"x").expect("seed file");
    std::fs::create_dir_all(dir.join("folder.svg")).expect("seed folder");
    for name in ["file/plot.svg", "file/sub/plot.png", "folder.svg"] {
        let path = dir.join(name);
        let err = render(&parabola("t"), &path).expect_err(name);
        assert!(matches!(err, PlotError::Output { .. }), "{err:?}");
        assert_one_line(&err, &path.display().to_string());
        assert_eq!(
            err.to_string(),
            check_image_path(&path).unwrap_err().to_string()
        );
    }
    assert_eq!(listing(&dir), vec!["file", "folder.svg"]);
}

#[test]
fn existing_plots_are_replaced_without_leftovers() {
    let dir = fresh_dir("replace");
    for ext in ["svg", "png"] {
        let path = dir.join(format!("plot.{ext}"));
        std::fs::write(&path, b"old contents").expect("seed file");
        render(&parabola("first title"), &path).expect("render");
        let bytes = std::fs::read(&path).expect("read");
        assert!(bytes.len() > 5_000, "{ext}: {} bytes", bytes.len());
        assert_ne!(&bytes[..], b"old contents");
    }
    assert_eq!(listing(&dir), vec!["plot.png", "plot.svg"]);
    let svg = std::fs::read_to_string(dir.join("plot.svg")).expect("svg");
    assert!(svg.contains("first title") && svg.contains("y = x²") && svg.contains("y [m²]"));
}

#[test]
fn invalid_figures_are_rejected() {
    let err = render_svg_string(&Figure::new("nothing")).expect_err("empty");
    assert!(matches!(err, PlotError::EmptyFigure { .. }));
    assert_one_line(&err, "nothing");

    let bad = Figure::new("t").with_panel(Panel::new("p", "x", "y").with_series(Series::new(
        "uneven",
        vec![1.0, 2.0, 3.0],
        vec![1.0, 2.0],
        Style::solid(0),
    )));
    let err = render_svg_string(&bad).expect_err("mismatch");
    assert!(matches!(
        err,
        PlotError::LengthMismatch { nx: 3, ny: 2, .. }
    ));
    assert_one_line(&err, "uneven");

    for (min, max) in [(1.0, 1.0), (2.0, 1.0), (f64::NAN, 1.0)] {
        let fig =
            Figure::new("t").with_panel(Panel::new("ranged", "x", "y").with_y_range(min, max));
        let err = render_svg_string(&fig).expect_err("range");
        assert!(
            matches!(err, PlotError::InvalidRange { axis: "y", .. }),
            "{err:?}"
        );
        assert_one_line(&err, "ranged");
    }
    let fig = Figure::new("t").with_panel(Panel::new("stepped", "x", "y").with_x_tick_step(0.0));
    let err = render_svg_string(&fig).expect_err("step");
    assert!(
        matches!(err, PlotError::InvalidTickStep { axis: "x", .. }),
        "{err:?}"
    );
}

#[test]
fn degenerate_data_still_renders() {
    // Empty panel, gaps (NaN), infinities, a constant series, data outside a fixed range.
    let fig = Figure::new("degenerate")
        .with_panel(Panel::new("empty", "x", "y"))
        .with_panel(Panel::new("gaps", "x", "y").with_series(Series::new(
            "gappy",
            vec![0.0, 1.0, f64::NAN, 3.0, 4.0, f64::INFINITY],
            vec![0.0, 1.0, 2.0, 3.0, f64::NAN, 1.0],
            Style::dashed(1),
        )))
        .with_panel(
            Panel::new("constant", "x", "y")
                .with_series(Series::new(
                    "flat",
                    vec![0.0, 1.0],
                    vec![2.0, 2.0],
                    Style::solid(2),
                ))
                .with_marker(Marker::vline(0.5, "mark", 3)),
        )
        .with_panel(
            Panel::new("clipped", "x", "y")
                .with_x_range(0.0, 1.0)
                .with_y_range(0.0, 1.0)
                .with_series(Series::new(
                    "steep",
                    vec![-5.0, 5.0],
                    vec![-5.0, 5.0],
                    Style::solid(0),
                ))
                .with_marker(Marker::point(3.0, 3.0, "outside point", 1)),
        );
    let svg = render_svg_string(&fig).expect("renders");
    for t in ["gappy", "flat", "mark", "steep", "outside point"] {
        assert!(svg.contains(t), "legend lacks {t}");
    }
    // The steep line is clipped to the panel's plotting rectangle: its polyline (palette
    // colour 0, the only one in that colour) has exactly two points, both inside the 4th cell.
    let line = svg
        .split("<polyline")
        .find(|p| p.contains("stroke=\"#1F77B4\""))
        .expect("steep line drawn");
    let pts: Vec<(f64, f64)> = line
        .split("points=\"")
        .nth(1)
        .expect("points")
        .split('"')
        .next()
        .expect("points end")
        .split_whitespace()
        .map(|p| {
            let (x, y) = p.split_once(',').expect("pair");
            (x.parse().expect("x"), y.parse().expect("y"))
        })
        .collect();
    assert_eq!(pts.len(), 2, "{pts:?}");
    // 4th panel of a 2 × 2 grid of 720 × 520 cells below a 50 px title.
    for (x, y) in pts {
        assert!(
            (720.0..1440.0).contains(&x) && (570.0..1090.0).contains(&y),
            "({x}, {y})"
        );
    }
}

#[test]
fn parallel_renders_do_not_interfere() {
    let dir = fresh_dir("parallel");
    std::thread::scope(|scope| {
        for k in 0..6 {
            let dir = &dir;
            scope.spawn(move || {
                // Threads k and k + 3 write the same file: both must leave a complete plot.
                let file = k % 3;
                let ext = if file == 1 { "png" } else { "svg" };
                render(
                    &parabola(&format!("figure {file}")),
                    dir.join(format!("p{file}.{ext}")),
                )
                .expect("parallel render");
            });
        }
    });
    assert_eq!(listing(&dir), vec!["p0.svg", "p1.png", "p2.svg"]);
    for name in ["p0.svg", "p2.svg"] {
        let svg = std::fs::read_to_string(dir.join(name)).expect("svg");
        assert!(svg.trim_end().ends_with("</svg>"), "{name} incomplete");
    }
    let png = std::fs::read(dir.join("p1.png")).expect("png");
    assert_eq!(&png[1..4], b"PNG");
    assert!(png.len() > 5_000);
}
