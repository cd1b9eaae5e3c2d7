//! Checks of the values a user gives — the command-line tools' flags and the Python package's
//! arguments — made before any computation, with one-line errors that name the argument as the
//! caller calls it (`--re` on the command line, `re` in Python).
//!
//! A leaf module: the flow condition, transition setting, Newton threshold and panel count of a
//! solution, and lists of them. Checks of rotor quantities (speed, mass, altitude) sit with the
//! aircraft ([`crate::rotor`]) and use the same [`ArgumentError`].

use crate::limits::{short_number, short_text, MAX_NEWTON_TOLERANCE, MAX_RE, PANEL_NODES};
use crate::section::{Transition, TransitionField, FREE_XTR};
use std::borrow::Cow;

/// A user-given value outside its range: `<name> <value>: <rule>` on one line (`<name>: <rule>`
/// when the problem is not one value).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{name}{}: {rule}", if value.is_empty() { String::new() } else { format!(" {value}") })]
pub struct ArgumentError {
    /// The argument as the caller names it (`--re`, `re`).
    pub name: String,
    /// The offending value as given (empty when the problem is not one value).
    pub value: String,
    /// What the value must be.
    pub rule: Cow<'static, str>,
}

impl ArgumentError {
    /// The error of argument `name` whose `value` breaks `rule`; the value is echoed in
    /// short form ([`short_number`]: `1e300`, not 301 digits).
    pub fn new(name: &str, value: f64, rule: impl Into<Cow<'static, str>>) -> Self {
        Self::with_text(name, short_number(value), rule)
    }

    /// The error of argument `name` whose value, given as text (empty when the problem is not
    /// one value), breaks `rule`.
    pub fn with_text(
        name: &str,
        value: impl Into<String>,
        rule: impl Into<Cow<'static, str>>,
    ) -> Self {
        Self {
            name: name.to_string(),
            value: value.into(),
            rule: rule.into(),
        }
    }
}

/// Ok when `ok`, else the error of `name` = `value` breaking `rule`.
fn require(
    ok: bool,
    name: &str,
    value: f64,
    rule: impl Into<Cow<'static, str>>,
) -> Result<(), ArgumentError> {
    if ok {
        Ok(())
    } else {
        Err(ArgumentError::new(name, value, rule))
    }
}

/// A chord Reynolds number: positive, at most [`MAX_RE`].
pub fn reynolds(name: &str, re: f64) -> Result<(), ArgumentError> {
    require(
        re > 0.0 && re <= MAX_RE,
        name,
        re,
        format!(
            "the Reynolds number must be positive and at most {}",
            short_number(MAX_RE)
        ),
    )
}

/// A Reynolds number the viscous solver is asked to solve at: as [`reynolds`], and at least
/// [`MIN_SOLVER_RE`](crate::limits::MIN_SOLVER_RE) (below it the boundary layer is no longer
/// thin: Cd of several tenths came out "converged" at Re 100).
pub fn solver_reynolds(name: &str, re: f64) -> Result<(), ArgumentError> {
    reynolds(name, re)?;
    let min = crate::limits::MIN_SOLVER_RE;
    require(
        re >= min,
        name,
        re,
        format!(
            "the viscous solver takes Reynolds numbers from {} (the boundary layer must be thin)",
            short_number(min)
        ),
    )
}

/// The first flag of `given` (name, whether it was given) that was given, refused with `rule`:
/// flags a mode does not read are an error, not ignored.
pub fn refuse_given(given: &[(&str, bool)], rule: &'static str) -> Result<(), ArgumentError> {
    match given.iter().find(|(_, on)| *on) {
        Some((flag, _)) => Err(ArgumentError::with_text(flag, "", rule)),
        None => Ok(()),
    }
}

/// The transition settings of one `point` or `plot-point` run (flag `--xtr`): distinct, and
/// at most [`MAX_POINT_CASES`](crate::limits::MAX_POINT_CASES) cases.
pub fn point_cases(xtr: &[f64]) -> Result<(), ArgumentError> {
    distinct("--xtr", xtr)?;
    let limit = crate::limits::MAX_POINT_CASES;
    if xtr.len() > limit {
        return Err(ArgumentError::with_text(
            "--xtr",
            "",
            format!(
                "{} transition settings: at most {limit} cases per run",
                xtr.len()
            ),
        ));
    }
    Ok(())
}

/// A free-stream Mach number: in [0, 1).
pub fn mach(name: &str, mach: f64) -> Result<(), ArgumentError> {
    require(
        (0.0..1.0).contains(&mach),
        name,
        mach,
        "the Mach number must be in [0, 1)",
    )
}

/// The transition values a user gives ([`Transition`]), each with its name as the caller
/// names it: N_crit for both surfaces (XFOIL VPAR `N`) and optionally per surface (`NT`,
/// `NB`; a surface not given takes the common value), and the trip x/c of each surface.
#[derive(Clone, Copy, Debug)]
pub struct TransitionArgs<'a> {
    /// N_crit of both surfaces (`--ncrit`).
    pub ncrit: (&'a str, f64),
    /// N_crit of the upper surface if given (`--ncrit-top`).
    pub ncrit_top: (&'a str, Option<f64>),
    /// N_crit of the lower surface if given (`--ncrit-bot`).
    pub ncrit_bot: (&'a str, Option<f64>),
    /// Trip x/c of the upper surface (`--xtr` or `--xtr-top`).
    pub xtr_top: (&'a str, f64),
    /// Trip x/c of the lower surface (`--xtr` or `--xtr-bot`).
    pub xtr_bot: (&'a str, f64),
}

/// The trips of `--xtr` (both surfaces), else of `--xtr-top` and `--xtr-bot` (a surface not
/// given is free): the flag and value of each surface, as [`TransitionArgs`] takes them.
pub fn trip_flags(
    xtr: Option<f64>,
    xtr_top: Option<f64>,
    xtr_bot: Option<f64>,
) -> [(&'static str, f64); 2] {
    match xtr {
        Some(x) => [("--xtr", x), ("--xtr", x)],
        None => [("--xtr-top", xtr_top), ("--xtr-bot", xtr_bot)]
            .map(|(flag, x)| (flag, x.unwrap_or(FREE_XTR))),
    }
}

/// The transition setting of `args`, every value checked by the setting's own rule
/// ([`Transition::check`]), the common N_crit first even where both surfaces override it; an
/// error names the value as the caller does.
pub fn transition<'a>(args: &TransitionArgs<'a>) -> Result<Transition, ArgumentError> {
    let field = TransitionField::NcritTop;
    let (name, ncrit) = args.ncrit;
    require(field.accepts(ncrit), name, ncrit, field.rule())?;
    let side = |given: (&'a str, Option<f64>)| match given.1 {
        Some(v) => (given.0, v),
        None => (name, ncrit),
    };
    let (top, bot) = (side(args.ncrit_top), side(args.ncrit_bot));
    let setting = Transition::sides(top.1, bot.1, args.xtr_top.1, args.xtr_bot.1);
    setting.check().map(|()| setting).map_err(|e| {
        let name = match e.field {
            TransitionField::NcritTop => top.0,
            TransitionField::NcritBot => bot.0,
            TransitionField::XtrTop => args.xtr_top.0,
            TransitionField::XtrBot => args.xtr_bot.0,
        };
        ArgumentError::new(name, e.value, e.field.rule())
    })
}

/// The Newton threshold of the viscous solver: in (0, [`MAX_NEWTON_TOLERANCE`]].
pub fn tolerance(name: &str, tolerance: f64) -> Result<(), ArgumentError> {
    require(
        tolerance > 0.0 && tolerance <= MAX_NEWTON_TOLERANCE,
        name,
        tolerance,
        format!(
            "must be above 0 and at most {MAX_NEWTON_TOLERANCE} (a looser threshold stops \
             before the boundary layer has converged)"
        ),
    )
}

/// A panel-node count within [`PANEL_NODES`].
pub fn panels(name: &str, panels: usize) -> Result<(), ArgumentError> {
    let (lo, hi) = PANEL_NODES;
    if (lo..=hi).contains(&panels) {
        return Ok(());
    }
    Err(ArgumentError::with_text(
        name,
        panels.to_string(),
        format!("must be between {lo} and {hi}"),
    ))
}

/// A list of values for one axis (Re, Mach, α): not empty, every value finite, none twice.
pub fn distinct(name: &str, values: &[f64]) -> Result<(), ArgumentError> {
    if values.is_empty() {
        return Err(ArgumentError::with_text(name, "", "no values given"));
    }
    for (k, &v) in values.iter().enumerate() {
        require(v.is_finite(), name, v, "not a finite number")?;
        require(!values[..k].contains(&v), name, v, "given twice")?;
    }
    Ok(())
}

/// A comma-separated list of distinct finite numbers given as `text` (a command-line list
/// such as `--re 1e6,2e6`).
pub fn number_list(name: &str, text: &str) -> Result<Vec<f64>, ArgumentError> {
    let error = |item: &str, rule: &str| {
        let value = format!("'{}'", short_text(text));
        ArgumentError::with_text(name, value, format!("'{}' {rule}", short_text(item)))
    };
    let mut out: Vec<f64> = Vec::new();
    for item in text.split(',').map(str::trim) {
        match item.parse::<f64>() {
            Ok(v) if v.is_finite() && out.contains(&v) => {
                return Err(error(item, "is given twice"))
            }
            Ok(v) if v.is_finite() => out.push(v),
            _ => return Err(error(item, "is not a finite number")),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_the_argument_and_the_value() {
        let msg = |r: Result<(), ArgumentError>| r.unwrap_err().to_string();
        assert_eq!(
            msg(reynolds("--re", -1.0)),
            "--re -1: the Reynolds number must be positive and at most 1e10"
        );
        assert_eq!(
            msg(mach("mach", 1.0)),
            "mach 1: the Mach number must be in [0, 1)"
        );
        let trip = |xtr_top: f64, ncrit: f64| {
            transition(&TransitionArgs {
                ncrit: ("ncrit", ncrit),
                ncrit_top: ("ncrit_top", None),
                ncrit_bot: ("ncrit_bot", None),
                xtr_top: ("xtr_top", xtr_top),
                xtr_bot: ("xtr_bot", 1.0),
            })
            .map(|_| ())
        };
        assert_eq!(
            msg(trip(1.5, 9.0)),
            "xtr_top 1.5: the transition location must be in [0, 1] (0 = leading edge, 1 = free)"
        );
        assert_eq!(
            msg(trip(0.5, f64::NAN)),
            "ncrit NaN: N_crit must be a positive number"
        );
        assert_eq!(
            msg(tolerance("tolerance", 0.5)),
            "tolerance 0.5: must be above 0 and at most 0.01 (a looser threshold stops before \
             the boundary layer has converged)"
        );
        assert_eq!(
            msg(panels("panels", 5)),
            "panels 5: must be between 20 and 1000"
        );
        assert_eq!(msg(distinct("re", &[])), "re: no values given");
        assert_eq!(
            msg(distinct("re", &[1e6, 2e6, 1e6])),
            "re 1000000: given twice"
        );
        assert_eq!(
            msg(distinct("alpha", &[0.0, f64::INFINITY])),
            "alpha inf: not a finite number"
        );
    }

    #[test]
    fn values_in_range_pass() {
        assert!(reynolds("re", 1e-3).is_ok() && reynolds("re", 0.0).is_err());
        assert!(reynolds("re", 1e10).is_ok() && reynolds("re", 1.0001e10).is_err());
        assert!(mach("m", 0.0).is_ok() && mach("m", -0.0).is_ok() && mach("m", f64::NAN).is_err());
        let setting = |ncrit: f64, top: Option<f64>, bot: Option<f64>, xtr: f64| {
            transition(&TransitionArgs {
                ncrit: ("n", ncrit),
                ncrit_top: ("top", top),
                ncrit_bot: ("bot", bot),
                xtr_top: ("x", xtr),
                xtr_bot: ("x", xtr),
            })
        };
        assert!(setting(9.0, None, None, 0.0).is_ok() && setting(9.0, None, None, 1.0).is_ok());
        for bad in [-1e-9, 1.0 + 1e-9, f64::NAN, f64::INFINITY] {
            assert_eq!(setting(9.0, None, None, bad).unwrap_err().name, "x");
        }
        assert!(setting(0.5, None, None, 1.0).is_ok());
        assert_eq!(
            setting(f64::INFINITY, None, None, 1.0).unwrap_err().name,
            "n"
        );
        assert_eq!(
            setting(9.0, None, Some(3.0), 1.0),
            Ok(Transition::sides(9.0, 3.0, 1.0, 1.0))
        );
        assert_eq!(
            setting(9.0, Some(3.0), None, 0.07),
            Ok(Transition::sides(3.0, 9.0, 0.07, 0.07))
        );
        assert_eq!(setting(9.0, None, Some(0.0), 1.0).unwrap_err().name, "bot");
        // The common value is checked even where both surfaces override it.
        assert_eq!(
            setting(0.0, Some(3.0), Some(3.0), 1.0).unwrap_err().name,
            "n"
        );
        assert_eq!(number_list("l", "1, 2e6").unwrap(), [1.0, 2e6]);
        assert_eq!(
            number_list("--re", "1,x").unwrap_err().to_string(),
            "--re '1,x': 'x' is not a finite number"
        );
        assert!(number_list("l", "1,1").is_err() && number_list("l", "").is_err());
        assert!(tolerance("t", 1e-4).is_ok() && tolerance("t", 0.0).is_err());
        assert!(panels("p", 20).is_ok() && panels("p", 1000).is_ok() && panels("p", 1001).is_err());
        assert!(distinct("a", &[-1.0, 0.0, 1.0]).is_ok());
    }
}
