//! `gyro study …`: what-if studies of [`polargen::studies`]; parse, run, print.

use clap::{Args, Subcommand};
use polargen::cli::values;
use polargen::report::ShippedInputs;
use polargen::studies::{contamination::ContaminationOptions, wing::WingOptions};
use polargen::studies::{StudyKind, StudyRequest};
use std::path::PathBuf;

/// Options every study shares.
#[derive(Args)]
pub struct Common {
    /// Aircraft preset (TOML) [default: aircraft/mtosport.toml, built in when absent].
    #[arg(long)]
    aircraft: Option<PathBuf>,
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

/// The studies (comma-separated lists).
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
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, default_value = "0.02,0.05,0.07,0.1,0.2,0.3,0.5",
              value_parser = values::transition)]
        trips: Vec<f64>,
        /// N_crit values of free transition besides the clean 9.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, default_value = "6,3,1", value_parser = values::ncrit)]
        ncrits: Vec<f64>,
        /// Radii r/R outboard of which the blade is tripped at 7 % chord.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, default_value = "0.25,0.5,0.75",
              value_parser = values::unit_interval)]
        outboard: Vec<f64>,
        /// Radii r/R inboard of which the blade is tripped at 7 % chord.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, default_value = "0.5", value_parser = values::unit_interval)]
        inboard: Vec<f64>,
    },
    /// The rotor with each airfoil (names or coordinate files), clean and tripped at 7 % chord.
    Airfoil {
        #[command(flatten)]
        common: Common,
        #[arg(
            long,
            value_delimiter = ',',
            allow_hyphen_values = true,
            default_value = "naca8h12,naca23012"
        )]
        airfoils: Vec<String>,
    },
    /// Contamination penalty against airspeed.
    Speed {
        #[command(flatten)]
        common: Common,
        /// Airfoil name or coordinate file.
        #[arg(long, default_value = "naca8h12")]
        airfoil: String,
        /// Trip location x/c on both surfaces.
        #[arg(long, default_value_t = 0.07, allow_hyphen_values = true, value_parser = values::transition)]
        xtr: f64,
        /// Airspeeds in knots.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, default_value = "30,35,40,45,50,55,60,65,70,75,80,85,90",
              value_parser = values::speed_kt)]
        speeds: Vec<f64>,
    },
    /// What a fixed wing buys: the aircraft's [wing] scaled to each area, trimmed at each speed.
    Wing {
        #[command(flatten)]
        common: Common,
        /// Rotor airfoil name or coordinate file.
        #[arg(long, default_value_t = WingOptions::default().airfoil)]
        airfoil: String,
        /// Wing areas in m² (0 = no wing): the aircraft's [wing] at its span, incidence and
        /// section.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = values::number,
              default_value = values::comma_list(WingOptions::default().areas_m2))]
        areas: Vec<f64>,
        /// Airspeeds in knots.
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true, value_parser = values::speed_kt,
              default_value = values::comma_list(WingOptions::default().speeds_kt))]
        speeds: Vec<f64>,
        /// Trip location x/c on both surfaces of a contaminated rotor [default: the clean rotor].
        #[arg(long, allow_hyphen_values = true, value_parser = values::transition)]
        xtr: Option<f64>,
    },
}

/// The library's request for a parsed `gyro study` command line (the aircraft loaded by
/// `shipped` when not given).
pub fn request(study: Study, shipped: &mut ShippedInputs) -> anyhow::Result<StudyRequest> {
    let (common, kind) = match study {
        Study::Contamination {
            common,
            airfoil,
            trips,
            ncrits,
            outboard,
            inboard,
        } => {
            let options = ContaminationOptions {
                trips,
                ncrits,
                outboard,
                inboard,
            };
            (common, StudyKind::Contamination { airfoil, options })
        }
        Study::Airfoil { common, airfoils } => (common, StudyKind::Airfoil { airfoils }),
        Study::Wing {
            common,
            airfoil,
            areas,
            speeds,
            xtr,
        } => {
            let options = WingOptions {
                airfoil,
                areas_m2: areas,
                speeds_kt: speeds,
                xtr,
            };
            (common, StudyKind::Wing(options))
        }
        Study::Speed {
            common,
            airfoil,
            xtr,
            speeds,
        } => (
            common,
            StudyKind::Speed {
                airfoil,
                xtr,
                speeds_kt: speeds,
            },
        ),
    };
    Ok(StudyRequest {
        kind,
        aircraft: shipped.aircraft(&common.aircraft)?,
        out: common.out,
        cache: common.cache,
        json: common.json,
    })
}
