//! Value parsers of the tools' flags (`#[arg(value_parser = values::reynolds)]`): each parses
//! the text and checks the value with the library's own check ([`crate::arguments`], the
//! rotor's argument checks), so that every bad value is refused by clap as a usage error
//! (exit 2) before anything runs. The error is an [`ArgumentError`] without a name; clap
//! names the flag and [`Tool::parse`](super::Tool::parse) prints `--flag value: rule`.

use crate::arguments::{self, ArgumentError};
use crate::limits::short_text;
use crate::rotor;
use crate::section::TransitionField;

/// The error of `text`, which breaks `rule` (the flag's name is added by the caller).
fn refused(text: &str, rule: impl Into<std::borrow::Cow<'static, str>>) -> ArgumentError {
    ArgumentError::with_text("", short_text(text.trim()), rule)
}

/// A check of the library, run on a value parsed here (its name is dropped: clap names the
/// flag).
fn nameless(r: Result<(), ArgumentError>) -> Result<(), ArgumentError> {
    r.map_err(|e| ArgumentError {
        name: String::new(),
        ..e
    })
}

/// A finite number.
pub fn number(text: &str) -> Result<f64, ArgumentError> {
    match text.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        _ => Err(refused(text, "not a finite number")),
    }
}

/// A whole number ≥ 0.
pub fn count(text: &str) -> Result<usize, ArgumentError> {
    text.trim()
        .parse::<usize>()
        .map_err(|_| refused(text, "not a whole number ≥ 0"))
}

/// A positive finite number.
pub fn positive(text: &str) -> Result<f64, ArgumentError> {
    let v = number(text)?;
    if v > 0.0 {
        Ok(v)
    } else {
        Err(ArgumentError::new("", v, "must be a positive number"))
    }
}

/// A number `check` accepts (the library's check of one value).
fn checked(
    text: &str,
    check: impl Fn(&str, f64) -> Result<(), ArgumentError>,
) -> Result<f64, ArgumentError> {
    // A number that is not finite still goes to the check, which names its own rule.
    let v = match text.trim().parse::<f64>() {
        Ok(v) => v,
        Err(_) => return Err(refused(text, "not a number")),
    };
    nameless(check("", v)).map(|()| v)
}

/// The broadside drag of the 360° extension (the rule of
/// [`PostStallParams::validate`](crate::table::PostStallParams::validate)).
pub fn cd_max(text: &str) -> Result<f64, ArgumentError> {
    checked(text, |name, v| {
        let params = crate::table::PostStallParams {
            cd_max: v,
            ..Default::default()
        };
        params
            .validate()
            .map_err(|_| ArgumentError::new(name, v, "must be in (0, 3] (docs/limits.md)"))
    })
}

/// A chord Reynolds number ([`arguments::reynolds`]).
pub fn reynolds(text: &str) -> Result<f64, ArgumentError> {
    checked(text, arguments::reynolds)
}

/// One angle of attack in degrees, within ±180° ([`crate::polar::check_alphas`]).
pub fn alpha_deg(text: &str) -> Result<f64, ArgumentError> {
    checked(text, |name, v| crate::polar::check_alphas(name, &[v]))
}

/// A Reynolds number to solve at ([`arguments::solver_reynolds`]).
pub fn solver_reynolds(text: &str) -> Result<f64, ArgumentError> {
    checked(text, arguments::solver_reynolds)
}

/// A Mach number ([`arguments::mach`]).
pub fn mach(text: &str) -> Result<f64, ArgumentError> {
    checked(text, arguments::mach)
}

/// A forced transition location x/c (the rule of [`Transition::check`](crate::section::Transition::check)).
pub fn transition(text: &str) -> Result<f64, ArgumentError> {
    transition_field(text, TransitionField::XtrTop)
}

/// A critical amplification ratio N_crit (the rule of [`Transition::check`](crate::section::Transition::check)).
pub fn ncrit(text: &str) -> Result<f64, ArgumentError> {
    transition_field(text, TransitionField::NcritTop)
}

/// A value of the transition setting that `field` accepts.
fn transition_field(text: &str, field: TransitionField) -> Result<f64, ArgumentError> {
    checked(text, |name, v| {
        if field.accepts(v) {
            Ok(())
        } else {
            Err(ArgumentError::new(name, v, field.rule()))
        }
    })
}

/// The Newton threshold ([`arguments::tolerance`]).
pub fn tolerance(text: &str) -> Result<f64, ArgumentError> {
    checked(text, arguments::tolerance)
}

/// A panel-node count ([`arguments::panels`]).
pub fn panels(text: &str) -> Result<usize, ArgumentError> {
    let n = count(text)?;
    nameless(arguments::panels("", n)).map(|()| n)
}

/// An airspeed in knots ([`rotor::check_speed_kt`]).
pub fn speed_kt(text: &str) -> Result<f64, ArgumentError> {
    checked(text, rotor::check_speed_kt)
}

/// A mass in kg ([`rotor::check_mass_kg`]).
pub fn mass_kg(text: &str) -> Result<f64, ArgumentError> {
    checked(text, rotor::check_mass_kg)
}

/// An ISA altitude in metres ([`rotor::check_altitude_m`]).
pub fn altitude_m(text: &str) -> Result<f64, ArgumentError> {
    checked(text, rotor::check_altitude_m)
}

/// An azimuth sample count ([`rotor::check_azimuth_samples`]).
pub fn azimuth_samples(text: &str) -> Result<usize, ArgumentError> {
    let n = count(text)?;
    nameless(rotor::check_azimuth_samples("", n)).map(|()| n)
}

/// A fraction in (0, 1] (a radius r/R; where on the blade is checked against the aircraft).
pub fn fraction(text: &str) -> Result<f64, ArgumentError> {
    let v = number(text)?;
    if v > 0.0 && v <= 1.0 {
        Ok(v)
    } else {
        Err(ArgumentError::new("", v, "must be a fraction in (0, 1]"))
    }
}

/// A fraction in [0, 1] (a coverage radius r/R).
pub fn unit_interval(text: &str) -> Result<f64, ArgumentError> {
    let v = number(text)?;
    if (0.0..=1.0).contains(&v) {
        Ok(v)
    } else {
        Err(ArgumentError::new("", v, "must be a fraction in [0, 1]"))
    }
}

/// An α range `A0:A1:DA` or one value ([`parse_alpha_range`](crate::polar::parse_alpha_range)).
pub fn alpha_range(text: &str) -> Result<Alphas, crate::polar::RangeError> {
    crate::polar::parse_alpha_range(text).map(Alphas)
}

/// The angles of attack of an `--alpha A0:A1:DA` flag, in order \[deg\].
#[derive(Clone, Debug, PartialEq)]
pub struct Alphas(pub Vec<f64>);

/// `values` as a flag's comma-separated list (a default shown in the help).
pub fn comma_list(values: Vec<f64>) -> String {
    let text: Vec<String> = values.iter().map(f64::to_string).collect();
    text.join(",")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_parser_refuses_with_the_value_and_the_rule() {
        let msg = |e: ArgumentError| format!("{} | {}", e.value, e.rule);
        assert_eq!(msg(reynolds("abc").unwrap_err()), "abc | not a number");
        assert_eq!(
            msg(reynolds("0").unwrap_err()),
            "0 | the Reynolds number must be positive and at most 1e10"
        );
        assert_eq!(
            msg(panels("-1").unwrap_err()),
            "-1 | not a whole number ≥ 0"
        );
        assert_eq!(
            msg(panels("5").unwrap_err()),
            "5 | must be between 20 and 1000"
        );
        assert_eq!(reynolds(" 1e6 ").unwrap(), 1e6);
        assert_eq!(mach("1").unwrap_err().name, "");
        assert!(transition("0").is_ok() && transition("1.01").is_err());
        assert!(speed_kt("60").is_ok() && speed_kt("inf").is_err());
        assert!(fraction("0.9").is_ok() && fraction("0").is_err());
        assert_eq!(alpha_range("0:2:1").unwrap(), Alphas(vec![0.0, 1.0, 2.0]));
    }
}
