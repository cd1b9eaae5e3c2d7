//! `polargen`'s command line: the main job (polars and tables) and its subcommands.

use clap::builder::{PossibleValuesParser, TypedValueParser};
use clap::{Args, Parser, Subcommand};
use polargen::cli::values::{self, Alphas};
use polargen::geometry::ShapeOp;
use polargen::table::TableFormat;
use polargen::viscous::ViscousParams;
use std::path::PathBuf;

/// Airfoil polars and Re × Mach × α tables with an XFOIL-class viscous–inviscid solver.
#[derive(Parser, Debug)]
#[command(
    name = "polargen",
    version,
    about,
    args_conflicts_with_subcommands = true,
    subcommand_negates_reqs = true,
    arg_required_else_help = true
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Option<Command>,

    /// No notes, progress or summary lines on stderr (errors are still printed).
    #[arg(long, short, global = true)]
    pub quiet: bool,

    #[command(flatten)]
    pub run: RunArgs,
}

/// Subcommands besides the main job (computing polars and tables).
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Overlay polars from tables (any format convert reads): Cl–α, Cl–Cd, Cl–x_tr
    /// (transition), Cl/Cd–α, Cm–α; SVG or PNG by the extension of --out.
    Plot(PlotArgs),
    /// Convert a table (polargen CSV, JSON or JSONL, XFOIL .pol, C81, OpenFAST AeroDyn,
    /// single-polar CSV) to another format: csv, json, jsonl, xfoil, c81 or aerodyn.
    Convert(ConvertArgs),
    /// Per polar of a table (any format convert reads): α0, lift slope and its fit range,
    /// Cl_max, Cd_min and the Cl there, best L/D, Cm0, and the α range the method trusts.
    Summary(SummaryArgs),
    /// Cp(x) over the airfoil contour and boundary-layer distributions (H, Cf, N) at one α or
    /// Cl, one case per transition setting overlaid (e.g. --xtr 1,0.07: clean vs tripped).
    PlotPoint(PlotPointArgs),
    /// One table per airfoil of files, folders and names, with an index (CSV, JSON); --shard
    /// K/N takes every N-th airfoil (job arrays), --resume keeps finished tables.
    Batch(BatchArgs),
    /// The surface and wake distributions of plot-point as CSV, without an image.
    Point {
        #[command(flatten)]
        case: PointCase,
        /// The distributions (one row per station, surfaces and wake), or - for standard output.
        #[arg(long, value_name = "FILE|-")]
        csv: PathBuf,
    },
    /// Shell completion script on standard output (e.g. `polargen completions bash >
    /// ~/.local/share/bash-completion/completions/polargen`).
    Completions(polargen::cli::CompletionsArgs),
    /// Man pages (roff): the tool's or a subcommand's on standard output (`polargen man
    /// batch > polargen-batch.1; man ./polargen-batch.1`), or all of them with --out DIR.
    Man(polargen::cli::ManArgs),
    /// The airfoil in chord units after the geometry operations (Selig); thickness on stderr.
    Geometry {
        /// Airfoil: a name, a coordinate file or - for standard input.
        #[arg(value_name = "NAME|PATH|-")]
        airfoil: String,
        #[command(flatten)]
        shape: Shape,
        /// Output coordinate file, or - for standard output.
        #[arg(long, value_name = "FILE|-")]
        out: PathBuf,
    },
}

/// `polargen plot-point` options.
#[derive(Args, Debug)]
pub struct PlotPointArgs {
    #[command(flatten)]
    pub case: PointCase,

    /// Output image: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,

    /// Also write the distributions as CSV (one row per station, surfaces and wake).
    #[arg(long, value_name = "FILE")]
    pub csv: Option<PathBuf>,

    /// Figure title (default: airfoil, Re, M, α or Cl).
    #[arg(long)]
    pub title: Option<String>,
}

/// The operating point of `point` and `plot-point`, one case per transition setting.
#[derive(Args, Debug)]
pub struct PointCase {
    /// Airfoil: a name (naca8h12, nacaDDDD, nacaDDDDD), a coordinate file (Selig, Lednicer
    /// or plain x y) or - for standard input.
    #[arg(long, value_name = "NAME|PATH|-")]
    pub airfoil: String,

    #[command(flatten)]
    pub shape: Shape,

    /// Chord Reynolds number (at least 1000).
    #[arg(long, allow_hyphen_values = true, value_parser = values::solver_reynolds)]
    pub re: f64,

    /// Mach number, 0 ≤ M < 1.
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true, value_parser = values::mach)]
    pub mach: f64,

    /// Angle of attack in degrees, within ±180.
    #[arg(
        long,
        allow_hyphen_values = true,
        required_unless_present = "cl",
        conflicts_with = "cl",
        value_parser = values::alpha_deg
    )]
    pub alpha: Option<f64>,

    /// Lift coefficient instead of α: each case is solved at the α giving this Cl.
    #[arg(long, allow_hyphen_values = true, value_parser = values::number)]
    pub cl: Option<f64>,

    /// Transition settings, one case each (overlaid by plot-point): comma-separated x/c on
    /// both surfaces (0 = leading edge, 1 = free); at most 20.
    #[arg(
        long,
        value_name = "LIST",
        default_value = "1",
        allow_hyphen_values = true,
        value_delimiter = ',',
        value_parser = values::transition
    )]
    pub xtr: Vec<f64>,

    #[command(flatten)]
    pub ncrit: Ncrit,

    /// Number of panel nodes.
    #[arg(long, default_value_t = polargen::geometry::DEFAULT_PANEL_NODES, allow_hyphen_values = true, value_parser = values::panels)]
    pub panels: usize,

    #[command(flatten)]
    pub newton: Newton,
}

/// `polargen summary` options.
#[derive(Args, Debug)]
pub struct SummaryArgs {
    /// Table file (any format convert reads).
    #[arg(value_name = "TABLE")]
    pub table: PathBuf,
    /// JSON (an array of flat records) instead of a text table.
    #[arg(long, conflicts_with = "csv")]
    pub json: bool,
    /// CSV instead of a text table.
    #[arg(long)]
    pub csv: bool,
    #[command(flatten)]
    pub read: ReadArgs,
}

/// What to assume where a table file does not say.
#[derive(Args, Debug)]
pub struct ReadArgs {
    /// Reynolds number of a C81 deck whose name gives none (default 1e6; stderr says so).
    #[arg(long, value_name = "RE", allow_hyphen_values = true, value_parser = values::reynolds)]
    pub assume_re: Option<f64>,
    /// Mach number of an AeroDyn file from another tool (it gives none; default 0).
    #[arg(long, value_name = "M", allow_hyphen_values = true, value_parser = values::mach)]
    pub assume_mach: Option<f64>,
    /// The tables to read from an AeroDyn file whose tables differ in UserProp (e.g. flap
    /// angles).
    #[arg(long, value_name = "VALUE", allow_hyphen_values = true, value_parser = values::number)]
    pub user_prop: Option<f64>,
}

/// `polargen convert` options.
#[derive(Args, Debug)]
pub struct ConvertArgs {
    /// Table: polargen CSV (.csv), JSON (.json) or JSON Lines (.jsonl), XFOIL polar file
    /// (.pol), C81 (.c81), OpenFAST AeroDyn airfoil file (any extension), or a CSV of one
    /// polar with columns alpha, cl, cd[, cm].
    #[arg(value_name = "TABLE")]
    pub table: PathBuf,

    /// Output file, or - for standard output (csv, json); the format follows the extension
    /// unless --format is given (xfoil and c81 may write one file per (Re, M) or per Re,
    /// named after it).
    #[arg(long, value_name = "FILE|-")]
    pub out: PathBuf,

    /// Output format: csv, json, jsonl (JSON Lines: pandas.read_json(path, lines=True)),
    /// xfoil, c81 or aerodyn (OpenFAST AirfoilInfo file, one table per Re, one file per
    /// Mach number, with the unsteady-aero coefficients from the polar: InclUAdata True).
    #[arg(long, value_enum)]
    pub format: Option<TableFormat>,

    #[command(flatten)]
    pub extension: Extension,

    #[command(flatten)]
    pub read: ReadArgs,
}

/// The 360° extension written into C81 (and AeroDyn) files.
#[derive(Args, Debug)]
pub struct Extension {
    /// Post-stall drag coefficient broadside to the flow (α = ±90°, the flat-plate normal
    /// force) of the 360° extension (Viterna–Corrigan, then a flat plate); default 2.0
    /// (Hoerner's 2-D plate); for a finite blade Viterna–Corrigan give 1.11 + 0.018·AR; at
    /// most 3.
    #[arg(long, value_name = "CD", allow_hyphen_values = true, value_parser = values::cd_max)]
    pub cd_max: Option<f64>,
}

/// `polargen plot` options.
#[derive(Args, Debug)]
pub struct PlotArgs {
    /// Tables: any format convert reads.
    #[arg(required = true, value_name = "TABLE")]
    pub tables: Vec<PathBuf>,

    /// Output image: FILE.svg or FILE.png.
    #[arg(long, value_name = "FILE")]
    pub out: PathBuf,

    /// Reynolds number of the polar to draw from a grid table (nearest node).
    #[arg(long, allow_hyphen_values = true, value_parser = values::reynolds)]
    pub re: Option<f64>,

    /// Mach number of the polar to draw from a grid table (nearest node).
    #[arg(long, allow_hyphen_values = true, value_parser = values::mach)]
    pub mach: Option<f64>,

    /// Figure title (default: airfoils and the Re, M drawn).
    #[arg(long)]
    pub title: Option<String>,

    /// Legend label of a table, once per table in their order (default: airfoil and
    /// transition setting).
    #[arg(long, value_name = "TEXT")]
    pub label: Vec<String>,

    /// Drag-polar Cd axis: auto (0 to 1.5 x the largest attached-flow Cd, rule in
    /// docs/plots.md; drag beyond is marked at the edge), all (all data), or an upper limit.
    #[arg(
        long,
        value_name = "auto|all|CD",
        default_value = "auto",
        allow_hyphen_values = true
    )]
    pub cd_axis: polargen::plot::drag_axis::CdAxis,

    #[command(flatten)]
    pub read: ReadArgs,
}

/// Options of the main job: polars and tables.
#[derive(Args, Debug)]
pub struct RunArgs {
    /// Airfoil: naca8h12, naca23012, nacaDDDD, nacaDDDDD, a coordinate file (Selig,
    /// Lednicer or plain x y), or - for coordinates on standard input.
    #[arg(long, value_name = "NAME|PATH|-", required = true)]
    pub airfoil: Option<String>,

    /// Inviscid panel solution only (cd = 0); output `alpha,cl,cd,cm,converged` as CSV (the
    /// viscous flags --re, --xtr*, --ncrit-top/-bot, --cd-max, --flap-deg and other formats
    /// are refused; --ncrit and --tolerance are not read).
    #[arg(long)]
    pub inviscid: bool,

    #[command(flatten)]
    pub grid: GridArgs,

    /// Output format: csv, json, jsonl (JSON Lines), xfoil (one .pol per Re, M), c81 (one
    /// file per Re) or aerodyn (OpenFAST AirfoilInfo file, one file per Mach number, a table
    /// per Re, with the unsteady-aero coefficients; see convert --help); default: from
    /// --out's extension, else csv.
    #[arg(long, value_enum)]
    pub format: Option<TableFormat>,

    /// Output file; standard output when absent or - (csv and json only).
    #[arg(long, value_name = "FILE|-")]
    pub out: Option<PathBuf>,

    #[command(flatten)]
    pub extension: Extension,

    /// Flap sweep: one table per deflection [deg], comma-separated, about the hinge of --flap
    /// X:Y; each file named <stem>_flap<DEG><ext> (the deflection is the table's flap_deg;
    /// one deflection may go to standard output). Every section is checked and every table
    /// solved before any file is written, and the files appear all together or not at all;
    /// the tables together count against the points limit of a run. With --format aerodyn
    /// several deflections go together: one file per Re and Mach (<stem>_Re<RE>_M<MACH><ext>;
    /// --out itself for one), holding one table per deflection in increasing order, its
    /// UserProp the deflection (OpenFAST's AFTabMod 3).
    #[arg(
        long,
        value_name = "LIST",
        allow_hyphen_values = true,
        requires = "flap"
    )]
    pub flap_deg: Option<String>,
}

/// `polargen batch` options (the grid flags as the main job's).
#[derive(Args, Debug)]
pub struct BatchArgs {
    /// Airfoils: coordinate files, folders (their *.dat files) or names (naca2412); each
    /// table is named after the file stem.
    #[arg(long, value_name = "DIR|FILE|NAME", num_args = 1.., required = true)]
    pub airfoils: Vec<String>,

    /// Output folder: <name>.csv (or .json) per airfoil and index.csv + index.json
    /// (index-K-of-N.* for a shard).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,

    /// Table format: csv or json.
    #[arg(long, default_value = "csv", value_parser = PossibleValuesParser::new(["csv", "json"])
        .map(|f| if f == "json" { TableFormat::Json } else { TableFormat::Csv }))]
    pub format: TableFormat,

    /// Only every N-th airfoil of the list sorted by name, from the K-th (1 ≤ K ≤ N).
    #[arg(long, value_name = "K/N")]
    pub shard: Option<polargen::table::Shard>,

    /// Keep tables that read back complete for the same grid and settings (what is compared:
    /// docs/batch.md).
    #[arg(long)]
    pub resume: bool,

    /// Airfoils solved at the same time, each on --threads workers (0 = one per core).
    #[arg(long, default_value_t = 1, allow_hyphen_values = true, value_parser = values::count)]
    pub jobs: usize,

    #[command(flatten)]
    pub grid: GridArgs,
}

/// The grid and solver flags shared by the main job and `batch`.
#[derive(Args, Debug)]
pub struct GridArgs {
    #[command(flatten)]
    pub shape: Shape,

    /// Chord Reynolds numbers, comma-separated. Without --re and --mach: the rotor grid of
    /// 8 Re 1e5…3e6 × 8 M 0…0.65; --re alone runs at M 0 (as XFOIL). At least 1000.
    #[arg(long, value_name = "LIST", allow_hyphen_values = true, value_delimiter = ',', value_parser = values::solver_reynolds)]
    pub re: Option<Vec<f64>>,

    /// Mach numbers, comma-separated, 0 ≤ M < 1 (needs --re; inviscid: one value, default 0).
    #[arg(long, value_name = "LIST", allow_hyphen_values = true, value_delimiter = ',', value_parser = values::mach)]
    pub mach: Option<Vec<f64>>,

    /// Angles of attack in degrees: A0:A1:DA (inclusive) or one value (default −10:20:0.5).
    #[arg(long, allow_hyphen_values = true, value_parser = values::alpha_range)]
    pub alpha: Option<Alphas>,

    /// Forced transition x/c on both surfaces, along the chord line from the leading edge
    /// (0 = leading edge, 1 = free transition, e^n).
    #[arg(long, value_name = "X", allow_hyphen_values = true, conflicts_with_all = ["xtr_top", "xtr_bot"], value_parser = values::transition)]
    pub xtr: Option<f64>,

    /// Forced transition x/c on the upper surface (0 = leading edge, 1 = free).
    #[arg(long, value_name = "X", allow_hyphen_values = true, value_parser = values::transition)]
    pub xtr_top: Option<f64>,

    /// Forced transition x/c on the lower surface (0 = leading edge, 1 = free).
    #[arg(long, value_name = "X", allow_hyphen_values = true, value_parser = values::transition)]
    pub xtr_bot: Option<f64>,

    #[command(flatten)]
    pub ncrit: Ncrit,

    /// Number of panel nodes after curvature-based repaneling (XFOIL PANE).
    #[arg(long, default_value_t = polargen::geometry::DEFAULT_PANEL_NODES, allow_hyphen_values = true, value_parser = values::panels)]
    pub panels: usize,

    #[command(flatten)]
    pub newton: Newton,

    /// Worker threads (0 = all cores); a polar's two α branches run in parallel, so more
    /// than two threads per polar are not started.
    #[arg(long, default_value_t = 0, allow_hyphen_values = true, value_parser = values::count)]
    pub threads: usize,
}

/// N_crit of the e^n transition criterion (XFOIL VPAR N, NT, NB).
#[derive(Args, Debug)]
pub struct Ncrit {
    /// Critical amplification ratio N of the e^n transition criterion, both surfaces.
    #[arg(long, default_value_t = 9.0, allow_hyphen_values = true, value_parser = values::ncrit)]
    pub ncrit: f64,
    /// N_crit on the upper surface (default: --ncrit).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = values::ncrit)]
    pub ncrit_top: Option<f64>,
    /// N_crit on the lower surface and the wake (default: --ncrit).
    #[arg(long, value_name = "N", allow_hyphen_values = true, value_parser = values::ncrit)]
    pub ncrit_bot: Option<f64>,
}

/// The Newton threshold of the viscous solver.
#[derive(Args, Debug)]
pub struct Newton {
    /// Newton convergence threshold on the RMS relative change of the boundary-layer
    /// variables (XFOIL uses 1e-4).
    #[arg(long, default_value_t = ViscousParams::default().tolerance, allow_hyphen_values = true, value_parser = values::tolerance)]
    pub tolerance: f64,
}

/// How a coordinate file's shape is taken, and the geometry operations on it (XFOIL GDES;
/// applied in chord units in the order blend, thickness and camber, te-gap, flap).
#[derive(Args, Debug)]
pub struct Shape {
    /// Rotate the coordinates so that the chord line (leading edge to trailing-edge midpoint)
    /// lies along x, measuring α from the chord line; without it α is measured from the x
    /// axis of the file (a contour not in chord units is only scaled and translated).
    #[arg(long)]
    pub derotate: bool,
    /// Maximum thickness, chord units (XFOIL TSET: thickness line scaled, camber kept).
    #[arg(long, value_name = "T", allow_hyphen_values = true, value_parser = ShapeOp::thickness)]
    pub thickness: Option<ShapeOp>,
    /// Maximum camber, chord units, signed (XFOIL TSET: camber line scaled, thickness kept).
    #[arg(long, value_name = "C", allow_hyphen_values = true, value_parser = ShapeOp::camber)]
    pub camber: Option<ShapeOp>,
    /// Trailing-edge gap G, blended over BLEND (0…1, default 1) of the chord (XFOIL TGAP).
    #[arg(long, value_name = "G[:BLEND]", allow_hyphen_values = true, value_parser = ShapeOp::te_gap)]
    pub te_gap: Option<ShapeOp>,
    /// Plain flap, hinge x/c X, y/c Y, deflection DEG, + down (XFOIL FLAP; α, Cm unflapped).
    #[arg(long, value_name = "X:Y[:DEG]", allow_hyphen_values = true, value_parser = ShapeOp::flap)]
    pub flap: Option<ShapeOp>,
    /// Blend: F of airfoil OTHER, 1 − F of this one, paired by chord station (XFOIL INTX).
    #[arg(long, value_name = "OTHER:F", value_parser = ShapeOp::blend)]
    pub blend: Option<ShapeOp>,
}

impl Shape {
    /// The operations, in the order they are applied.
    pub fn ops(&self) -> Vec<ShapeOp> {
        let all = [
            &self.blend,
            &self.thickness,
            &self.camber,
            &self.te_gap,
            &self.flap,
        ];
        all.into_iter().flatten().cloned().collect()
    }
}
