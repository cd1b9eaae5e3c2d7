//! The library's errors as Python exceptions, with the command-line tools' one-line messages
//! (`polargen::diagnostics::error_line`): `ValueError` for bad input, `OSError` (or its
//! `FileNotFoundError`, `PermissionError`, `IsADirectoryError` subclasses) for files, and
//! `NotConvergedError` where a computation found no solution. A panic inside the library never
//! crosses into Python: [`shielded`] turns it into a `RuntimeError`.

use std::error::Error;
use std::io::ErrorKind;
use std::panic::{catch_unwind, AssertUnwindSafe};

use polargen::arguments::ArgumentError;
use polargen::diagnostics::error_line;
use polargen::geometry::GeometryError;
use polargen::input::{InputError, InputProblem};
use polargen::output::OutputError;
use polargen::polar::{OperatingPointError, RangeError, TargetClError};
use polargen::rotor::{AircraftError, TakeoffError, TrimError};
use polargen::studies::paper::StudyError;
use polargen::studies::StudiesError;
use polargen::table::{BuildError, TableError};
use polargen::viscous::ViscousError;
use pyo3::exceptions::{
    PyFileNotFoundError, PyIsADirectoryError, PyOSError, PyPermissionError, PyRuntimeError,
    PyValueError,
};
use pyo3::{create_exception, PyErr};

create_exception!(
    polargen,
    NotConvergedError,
    PyRuntimeError,
    "No converged solution: a viscous point, a target lift coefficient, a trim or a takeoff."
);

/// Which Python exception an error becomes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// Bad input: `ValueError`.
    Input,
    /// A file could not be read or written: `OSError` or the subclass of the I/O error kind.
    File(Option<ErrorKind>),
    /// No converged solution: `NotConvergedError`.
    NotConverged,
}

/// The exception of `kind` with `message`.
pub fn exception(kind: Kind, message: String) -> PyErr {
    match kind {
        Kind::Input => PyValueError::new_err(message),
        Kind::NotConverged => NotConvergedError::new_err(message),
        Kind::File(Some(ErrorKind::NotFound)) => PyFileNotFoundError::new_err(message),
        Kind::File(Some(ErrorKind::PermissionDenied)) => PyPermissionError::new_err(message),
        Kind::File(Some(ErrorKind::IsADirectory)) => PyIsADirectoryError::new_err(message),
        Kind::File(_) => PyOSError::new_err(message),
    }
}

/// A library error that knows which exception it is.
pub trait Classify: Error + 'static {
    /// The exception kind of this error.
    fn kind(&self) -> Kind;
}

/// The exception of `e`, its message the CLI's error line; `context` (an argument name, as the
/// CLI's `--name`) is put in front when given.
pub fn raise<E: Classify>(context: Option<&str>, e: E) -> PyErr {
    let line = error_line(&e);
    let message = match context {
        Some(c) => format!("{c}: {line}"),
        None => line,
    };
    exception(e.kind(), message)
}

/// The kind of the first I/O error in the chain of `e`.
fn io_kind(e: &(dyn Error + 'static)) -> Option<ErrorKind> {
    let mut next = Some(e);
    while let Some(err) = next {
        if let Some(io) = err.downcast_ref::<std::io::Error>() {
            return Some(io.kind());
        }
        next = err.source();
    }
    None
}

impl Classify for InputError {
    fn kind(&self) -> Kind {
        Kind::File(match self.problem {
            InputProblem::NotFound => Some(ErrorKind::NotFound),
            InputProblem::Folder => Some(ErrorKind::IsADirectory),
            InputProblem::NotRegular(_) | InputProblem::TooLarge { .. } | InputProblem::Os(_) => {
                None
            }
        })
    }
}

impl Classify for ArgumentError {
    fn kind(&self) -> Kind {
        Kind::Input
    }
}

impl Classify for RangeError {
    fn kind(&self) -> Kind {
        Kind::Input
    }
}

impl Classify for GeometryError {
    fn kind(&self) -> Kind {
        match self {
            GeometryError::Input(e) => e.kind(),
            _ => Kind::Input,
        }
    }
}

impl Classify for OutputError {
    fn kind(&self) -> Kind {
        Kind::File(io_kind(self))
    }
}

impl Classify for TableError {
    fn kind(&self) -> Kind {
        match self {
            TableError::Input(e) => e.kind(),
            TableError::Io { source, .. } => Kind::File(Some(source.kind())),
            TableError::Output(o) => o.kind(),
            TableError::File { source, .. } => source.kind(),
            _ => Kind::Input,
        }
    }
}

impl Classify for AircraftError {
    fn kind(&self) -> Kind {
        match self {
            AircraftError::Input(e) => e.kind(),
            _ => Kind::Input,
        }
    }
}

impl Classify for ViscousError {
    fn kind(&self) -> Kind {
        Kind::Input
    }
}

impl Classify for BuildError {
    fn kind(&self) -> Kind {
        match self {
            BuildError::Table(t) => t.kind(),
            _ => Kind::Input,
        }
    }
}

impl Classify for TargetClError {
    fn kind(&self) -> Kind {
        match self {
            TargetClError::BadTarget(_) => Kind::Input,
            _ => Kind::NotConverged,
        }
    }
}

impl Classify for OperatingPointError {
    fn kind(&self) -> Kind {
        match self {
            OperatingPointError::BadAlpha(_) => Kind::Input,
            OperatingPointError::TargetCl(t) => t.kind(),
            _ => Kind::NotConverged,
        }
    }
}

impl Classify for TrimError {
    fn kind(&self) -> Kind {
        match self {
            TrimError::Input(_) | TrimError::Altitude | TrimError::Propeller(_) => Kind::Input,
            _ => Kind::NotConverged,
        }
    }
}

impl Classify for TakeoffError {
    fn kind(&self) -> Kind {
        match self {
            TakeoffError::Propeller(_) => Kind::Input,
            _ => Kind::NotConverged,
        }
    }
}

impl Classify for StudyError {
    fn kind(&self) -> Kind {
        match self {
            StudyError::Trim { source, .. } => source.kind(),
            StudyError::Takeoff { source, .. } => source.kind(),
            _ => Kind::NotConverged,
        }
    }
}

impl Classify for StudiesError {
    fn kind(&self) -> Kind {
        match self {
            StudiesError::Aircraft(e) => e.kind(),
            StudiesError::Rotor(e) => e.kind(),
            StudiesError::Output(e) => e.kind(),
            StudiesError::Cache(e) => e.kind(),
            StudiesError::Build { source, .. } => source.kind(),
            StudiesError::Csv(_) => Kind::File(io_kind(self)),
            _ => Kind::Input,
        }
    }
}

/// Runs `f`, turning a panic inside the library into a `RuntimeError` that says so (a bug to
/// report, never a result).
pub fn shielded<T>(f: impl FnOnce() -> T) -> Result<T, PyErr> {
    catch_unwind(AssertUnwindSafe(f)).map_err(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        PyRuntimeError::new_err(format!("polargen internal error (please report): {what}"))
    })
}
