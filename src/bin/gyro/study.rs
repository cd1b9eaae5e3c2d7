//! `gyro study …`: what-if studies of [`polargen::studies`]; parse, run, print.

use anyhow::Result;
use clap::{Args, Subcommand};
use polargen::rotor::Aircraft;
use polargen::studies::{airfoil, contamination, speed};
use polargen::studies::{check_study_out, command_line_cache, parse_list, records_json};
use polargen::studies::{Progress, StudiesError, StudyFiles, TableCache};
use std::path::PathBuf;

/// Options every study shares.
#[derive(Args)]
pub struct Common {
    /// Aircraft preset (TOML).
    #[arg(long)]
    aircraft: PathBuf,
    /// Print JSON records (one per setting) instead of the text table.
    #[arg(long)]
    json: bool,
    /// Write the CSV table and the figures (SVG and PNG) into this folder, all or none.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Table cache folder [default: $XDG_CACHE_HOME/polargen/tables, else ~/.cache/polargen/tables].
    #[arg(long)]
    cache: Option<PathBuf>,
}

/// The studies.
#[derive(Subcommand)]
pub enum Study {
    /// Contamination severity and extent at 60 kt: trip location, one surface, N_crit, coverage.
    Contamination {
        #[command(flatten)]
        common: Common,
        /// Airfoil name or coordinate file.
        #[arg(long, default_value = "naca8h12")]
        airfoil: String,
        /// Trip locations x/c on both surfaces.
        #[arg(long, default_value = "0.02,0.05,0.07,0.1,0.2,0.3,0.5")]
        trips: String,
        /// N_crit values of free transition besides the clean 9.
        #[arg(long, default_value = "6,3,1")]
        ncrits: String,
        /// Radii r/R outboard of which the blade is tripped at 7 % chord.
        #[arg(long, default_value = "0.25,0.5,0.75")]
        outboard: String,
        /// Radii r/R inboard of which the blade is tripped at 7 % chord.
        #[arg(long, default_value = "0.5")]
        inboard: String,
    },
    /// The rotor with each airfoil, clean and tripped at 7 % chord.
    Airfoil {
        #[command(flatten)]
        common: Common,
        /// Airfoil names or coordinate files, comma-separated.
        #[arg(long, default_value = "naca8h12,naca23012")]
        airfoils: String,
    },
    /// Contamination penalty against airspeed.
    Speed {
        #[command(flatten)]
        common: Common,
        /// Airfoil name or coordinate file.
        #[arg(long, default_value = "naca8h12")]
        airfoil: String,
        /// Trip location x/c on both surfaces.
        #[arg(long, default_value_t = 0.07)]
        xtr: f64,
        /// Airspeeds in knots.
        #[arg(long, default_value = "30,35,40,45,50,55,60,65,70,75,80,85,90")]
        speeds: String,
    },
}

/// Run a study, appending its standard output to `buf`; `say` prints a line on stderr.
pub fn run(study: Study, buf: &mut String, say: &dyn Fn(String)) -> Result<()> {
    let progress = Progress::on_terminal();
    match study {
        Study::Contamination {
            common,
            airfoil,
            trips,
            ncrits,
            outboard,
            inboard,
        } => {
            let options = contamination::ContaminationOptions {
                trips: parse_list("trips", &trips)?,
                ncrits: parse_list("ncrits", &ncrits)?,
                outboard: parse_list("outboard", &outboard)?,
                inboard: parse_list("inboard", &inboard)?,
            };
            options.settings()?;
            let (ac, cache) = prepare(
                &common,
                contamination::CSV_STEM,
                &contamination::FIGURE_STEMS,
            )?;
            let s =
                contamination::ContaminationStudy::run(&ac, &airfoil, &options, &cache, &progress)?;
            finish(
                &common,
                buf,
                say,
                records_json(&s.records),
                s.text(),
                || s.files(),
            )
        }
        Study::Airfoil { common, airfoils } => {
            let list: Vec<String> = airfoils
                .split(',')
                .map(str::trim)
                .filter(|s| !s.is_empty())
                .map(String::from)
                .collect();
            if list.is_empty() {
                anyhow::bail!("--airfoils: empty list");
            }
            let (ac, cache) = prepare(&common, airfoil::CSV_STEM, &airfoil::FIGURE_STEMS)?;
            let s = airfoil::AirfoilStudy::run(&ac, &list, &cache, &progress)?;
            finish(
                &common,
                buf,
                say,
                records_json(&s.records),
                s.text(),
                || s.files(),
            )
        }
        Study::Speed {
            common,
            airfoil,
            xtr,
            speeds,
        } => {
            let speeds = parse_list("speeds", &speeds)?;
            let (ac, cache) = prepare(&common, speed::CSV_STEM, &speed::FIGURE_STEMS)?;
            let s = speed::SpeedStudy::run(&ac, &airfoil, xtr, &speeds, &cache, &progress)?;
            s.notes.iter().for_each(|n| say(n.clone()));
            finish(
                &common,
                buf,
                say,
                records_json(&s.records),
                s.text(),
                || s.files(),
            )
        }
    }
}

/// Check the output and cache folders and load the aircraft, before any computation.
fn prepare(common: &Common, csv: &str, figures: &[&str]) -> Result<(Aircraft, TableCache)> {
    if let Some(dir) = &common.out {
        check_study_out(dir, csv, figures)?;
    }
    let cache = command_line_cache(common.cache.clone())?;
    Ok((Aircraft::from_toml_file(&common.aircraft)?, cache))
}

/// Write the files, then print the JSON records or the text table.
fn finish(
    common: &Common,
    buf: &mut String,
    say: &dyn Fn(String),
    json: String,
    text: String,
    files: impl FnOnce() -> Result<StudyFiles, StudiesError>,
) -> Result<()> {
    if let Some(dir) = &common.out {
        for p in files()?.write(dir)? {
            say(format!("wrote {}", p.display()));
        }
    }
    buf.push_str(if common.json { &json } else { &text });
    Ok(())
}
