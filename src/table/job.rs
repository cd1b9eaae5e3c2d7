//! The table job of `polargen`: the tables of a [`FlapSweep`] solved one after another on one
//! grid (every section shaped first, every table solved before any is written), each refused
//! when no point converged, given its post-stall Cd_max and written — to its own output, or
//! with the others at the end ([`FlapSweep::write_together`]).

use super::{
    build_table, with_cd_max, write_table, write_table_into, BuildError, FlapSweep, GridSpec,
};
use super::{TableCensus, TableError, TableFormat};
use crate::geometry::{solver_airfoil, GeometryError};
use crate::output::{names_a_file, OutputSet};
use crate::progress::Progress;
use crate::viscous::ViscousParams;
use std::path::PathBuf;
use std::time::Instant;

/// What every table of a [`TableJob`] shares.
#[derive(Clone, Debug)]
pub struct TableJob<'a> {
    /// Airfoil name or coordinate file (flag `--airfoil`).
    pub airfoil: &'a str,
    /// Derotate the airfoil before the geometry operations.
    pub derotate: bool,
    /// Panel count of the solver.
    pub panels: usize,
    /// The Re × M × α grid.
    pub grid: &'a GridSpec,
    /// Solver settings (transition, tolerance) of every point.
    pub base: &'a ViscousParams,
    /// Worker threads (0: all cores).
    pub threads: usize,
    /// Broadside drag of the post-stall extension (flag `--cd-max`), else the default.
    pub cd_max: Option<f64>,
    /// Format of the files written.
    pub format: TableFormat,
}

/// Why a [`TableJob`] stopped.
#[derive(Debug, thiserror::Error)]
pub enum TableJobError {
    /// The airfoil could not be read, shaped or paneled.
    #[error("--airfoil")]
    Airfoil(#[source] GeometryError),
    /// A table could not be solved.
    #[error(transparent)]
    Build(#[from] BuildError),
    /// No point of a table converged: nothing is written.
    #[error("{0}: no point converged; no table written")]
    NoneConverged(TableCensus),
    /// The Cd_max of the extension is refused.
    #[error("--cd-max")]
    CdMax(#[source] TableError),
    /// A table could not be written.
    #[error(transparent)]
    Write(#[from] TableError),
}

impl TableJob<'_> {
    /// Solves and writes every table of `sweep` in its order. Every member's section is
    /// shaped and checked first, and every table solved before any is written, so a
    /// deflection whose contour is refused, or a table without a converged point, leaves no
    /// file. The files of all tables are then written together or not at all (an
    /// [`OutputSet`]; one table may go to a stream). `progress` follows each table's build;
    /// `say` gets the notes of reading the airfoil (`note: …`), each table's census and time
    /// (`… in 1.2 s`, after every file is written) and the file count of a table or set
    /// written as several files (`wrote 4 files`). Returns the files written.
    pub fn run(
        &self,
        sweep: &FlapSweep,
        progress: &dyn Progress,
        say: &dyn Fn(String),
    ) -> Result<Vec<PathBuf>, TableJobError> {
        let mut foils = Vec::with_capacity(sweep.members().len());
        for member in sweep.members() {
            let (foil, notes) =
                solver_airfoil(self.airfoil, self.panels, self.derotate, &member.ops)
                    .map_err(TableJobError::Airfoil)?;
            notes.iter().for_each(|n| say(format!("note: {n}")));
            foils.push(foil);
        }
        let mut tables = Vec::with_capacity(foils.len());
        for (member, foil) in sweep.members().iter().zip(&foils) {
            progress.start(&self.grid.work(&foil.name, self.threads));
            let start = Instant::now();
            let table = build_table(foil, self.panels, self.grid, self.base, self.threads, |n| {
                progress.advance(n)
            })?;
            progress.finish();
            let census = table.census();
            if census.converged == 0 {
                return Err(TableJobError::NoneConverged(census));
            }
            let summary = format!("{census} in {:.1} s", start.elapsed().as_secs_f64());
            let table = with_cd_max(table.with_geometry(&member.ops), self.cd_max)
                .map_err(TableJobError::CdMax)?;
            tables.push((table, summary));
        }
        // The results first: each table's summary after every file is written. Tables with
        // files of their own are staged in one set, so that a failed write (a full disk)
        // leaves none of the sweep's files; one table may go to a stream.
        let mut set = OutputSet::new();
        let mut together = Vec::new();
        let mut summaries = Vec::new();
        let mut streamed = Vec::new();
        for (member, (table, summary)) in sweep.members().iter().zip(tables) {
            match &member.out {
                Some(path) if !names_a_file(path) => {
                    streamed.extend(write_table(&table, path, Some(self.format))?);
                    summaries.push((summary, 1));
                }
                Some(path) => {
                    let files = write_table_into(&table, path, self.format, &mut set)?;
                    summaries.push((summary, files.len()));
                }
                None => {
                    together.push(table);
                    summaries.push((summary, 0));
                }
            }
        }
        let mut written = streamed;
        written.extend(set.commit().map_err(TableError::from)?);
        let files = sweep.write_together(&together)?;
        for (summary, count) in summaries {
            say(summary);
            if count > 1 {
                say(format!("wrote {count} files"));
            }
        }
        if !files.is_empty() {
            say(format!("wrote {} files", files.len()));
        }
        written.extend(files);
        Ok(written)
    }
}
