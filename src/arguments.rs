//! Checks of the values a user gives — the command-line tools' flags and the Python package's
//! arguments — made before any computation, with one-line errors that name the argument as the
//! caller calls it (`--re` on the command line, `re` in Python).
//!
//! A leaf module: the flow condition, transition, Newton threshold and panel count of a
//! solution, and lists of them. Checks of rotor quantities (speed, mass, altitude) sit with the
//! aircraft ([`crate::rotor`]) and use the same [`ArgumentError`].

use crate::limits::{short_number, short_text, MAX_NEWTON_TOLERANCE, PANEL_NODES};
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

/// A chord Reynolds number: positive and finite.
pub fn reynolds(name: &str, re: f64) -> Result<(), ArgumentError> {
    require(
        re.is_finite() && re > 0.0,
        name,
        re,
        "the Reynolds number must be positive",
    )
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

/// A forced transition location x/c: in [0, 1], 1 meaning free transition.
pub fn transition(name: &str, xtr: f64) -> Result<(), ArgumentError> {
    require(
        (0.0..=1.0).contains(&xtr),
        name,
        xtr,
        "the transition location must be in [0, 1] (1 = free)",
    )
}

/// The critical amplification ratio N of the e^n criterion: positive.
pub fn ncrit(name: &str, ncrit: f64) -> Result<(), ArgumentError> {
    require(
        ncrit.is_finite() && ncrit > 0.0,
        name,
        ncrit,
        "must be a positive number",
    )
}

/// N_crit of the upper and the lower surface from one value for both (`ncrit`, XFOIL VPAR
/// `N`) and the optional per-side values (`top`, `bottom`: XFOIL `NT`, `NB`); a side not
/// given takes `ncrit`. `names` are the three arguments as the caller names them.
pub fn ncrit_sides(
    names: [&str; 3],
    ncrit_both: f64,
    top: Option<f64>,
    bottom: Option<f64>,
) -> Result<(f64, f64), ArgumentError> {
    ncrit(names[0], ncrit_both)?;
    let side = |name, n: Option<f64>| {
        let n = n.unwrap_or(ncrit_both);
        ncrit(name, n).map(|()| n)
    };
    Ok((side(names[1], top)?, side(names[2], bottom)?))
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
            "--re -1: the Reynolds number must be positive"
        );
        assert_eq!(
            msg(mach("mach", 1.0)),
            "mach 1: the Mach number must be in [0, 1)"
        );
        assert_eq!(
            msg(transition("xtr_top", 1.5)),
            "xtr_top 1.5: the transition location must be in [0, 1] (1 = free)"
        );
        assert_eq!(
            msg(ncrit("ncrit", f64::NAN)),
            "ncrit NaN: must be a positive number"
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
        assert!(mach("m", 0.0).is_ok() && mach("m", -0.0).is_ok() && mach("m", f64::NAN).is_err());
        assert!(transition("x", 0.0).is_ok() && transition("x", 1.0).is_ok());
        assert!(transition("x", -1e-9).is_err() && transition("x", f64::NAN).is_err());
        assert!(ncrit("n", 0.5).is_ok() && ncrit("n", f64::INFINITY).is_err());
        let names = ["n", "top", "bot"];
        assert_eq!(ncrit_sides(names, 9.0, None, Some(3.0)), Ok((9.0, 3.0)));
        assert_eq!(ncrit_sides(names, 9.0, Some(3.0), None), Ok((3.0, 9.0)));
        assert_eq!(
            ncrit_sides(names, 9.0, None, Some(0.0)).unwrap_err().name,
            "bot"
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
