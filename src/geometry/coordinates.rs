//! Airfoil coordinate-file reader: Selig, Lednicer and plain formats, auto-detected, with
//! validation, converted to XFOIL point order (upper TE → LE → lower TE).
//!
//! Format conventions follow XFOIL's `AREAD` (Drela): a first line that is not a pair of
//! numbers is the airfoil name; a first data pair with both values > 1.5 is a Lednicer
//! point-count header (here: two whole numbers within the point limit, so that a Selig file
//! in millimetres is not taken for one); a clockwise contour is reversed (XFOIL `LOAD`, sign
//! of the area). Line ends may be `\n`, `\r\n` or `\r`; validation: [`super::validation`].

use std::path::Path;

use super::error::{GeometryError, Place};
use super::validation::{signed_area, validate_contour};
use super::Airfoil;
use crate::input::{read_input_or_stdin, text_lines, STDIN_PATH};
use crate::limits::MAX_CONTOUR_POINTS;

/// Layout of a coordinate file.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoordinateFormat {
    /// Name line, then points TE → upper → LE → lower → TE (or the reverse direction).
    Selig,
    /// Name line, a count line like `17. 17.`, then upper LE → TE and lower LE → TE.
    Lednicer,
    /// Points only, no name line, in Selig order.
    Plain,
}

/// One data line: its 1-based line number and its whitespace/comma separated tokens.
struct DataLine<'a> {
    line: usize,
    tokens: Vec<&'a str>,
}

/// Parses one number token, accepting Fortran `D` exponents (`0.15D-02`).
fn parse_number(token: &str, file: &str, line: usize) -> Result<f64, GeometryError> {
    let owned;
    let t = if token.contains(['d', 'D']) {
        owned = token.replace(['d', 'D'], "e");
        owned.as_str()
    } else {
        token
    };
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(GeometryError::NonFinite {
            file: file.to_string(),
            line,
            place: Place::Line,
            token: token.to_string(),
        }),
        Err(_) => Err(GeometryError::BadNumber {
            file: file.to_string(),
            line,
            token: token.to_string(),
        }),
    }
}

/// Parses a data line as exactly two finite numbers.
fn parse_pair(dl: &DataLine, file: &str) -> Result<(f64, f64), GeometryError> {
    if dl.tokens.len() != 2 {
        // A wrong count of *numbers* is reported as such; a non-number is reported first.
        for t in &dl.tokens {
            parse_number(t, file, dl.line)?;
        }
        return Err(GeometryError::ColumnCount {
            file: file.to_string(),
            line: dl.line,
            found: dl.tokens.len(),
        });
    }
    Ok((
        parse_number(dl.tokens[0], file, dl.line)?,
        parse_number(dl.tokens[1], file, dl.line)?,
    ))
}

/// True if the tokens are exactly two numbers (finite or not), i.e. the line is data.
fn looks_like_pair(tokens: &[&str]) -> bool {
    tokens.len() == 2
        && tokens.iter().all(|t| {
            let t = t.replace(['d', 'D'], "e");
            t.parse::<f64>().is_ok()
        })
}

/// Reads and parses an airfoil coordinate file (any supported format), or standard input
/// when `path` is `-` (an airfoil without a name line is then called `stdin`).
pub fn read_airfoil_file(path: &Path) -> Result<Airfoil, GeometryError> {
    let file = path.display().to_string();
    let bytes = read_input_or_stdin(path).map_err(GeometryError::Input)?;
    let fallback = match path.file_stem() {
        _ if path.as_os_str() == STDIN_PATH => "stdin".to_string(),
        Some(s) => s.to_string_lossy().into_owned(),
        None => file.clone(),
    };
    parse_airfoil_bytes(&bytes, &file, &fallback).map(|(a, _)| a)
}

/// Parses coordinate-file bytes. `file` names the source in error messages; `fallback_name`
/// is the airfoil name used when the file has no name line (plain format).
pub fn parse_airfoil_bytes(
    bytes: &[u8],
    file: &str,
    fallback_name: &str,
) -> Result<(Airfoil, CoordinateFormat), GeometryError> {
    let text = std::str::from_utf8(bytes).map_err(|e| GeometryError::NotUtf8 {
        file: file.to_string(),
        offset: e.valid_up_to(),
    })?;
    parse_airfoil_text(text, file, fallback_name)
}

/// Parses coordinate-file text; see [`parse_airfoil_bytes`].
pub fn parse_airfoil_text(
    text: &str,
    file: &str,
    fallback_name: &str,
) -> Result<(Airfoil, CoordinateFormat), GeometryError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut lines: Vec<DataLine> = Vec::new();
    let mut uncounted = 0usize;
    for (k, raw) in text_lines(text).enumerate() {
        let line = k + 1;
        if let Some(b) = raw
            .bytes()
            .find(|&b| (b < 0x20 && b != b'\t' && b != b'\r') || b == 0x7f)
        {
            return Err(GeometryError::Binary {
                file: file.to_string(),
                line,
                byte: b,
            });
        }
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        // Beyond the point limit (and a name and a count line) lines are only counted.
        if lines.len() > MAX_CONTOUR_POINTS + 1 {
            uncounted += 1;
            continue;
        }
        let tokens: Vec<&str> = trimmed
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|t| !t.is_empty())
            .collect();
        lines.push(DataLine { line, tokens });
    }
    if uncounted > 0 {
        let named = !looks_like_pair(&lines[0].tokens);
        return Err(GeometryError::TooManyPoints {
            file: file.to_string(),
            found: lines.len() + uncounted - usize::from(named),
            max: MAX_CONTOUR_POINTS,
        });
    }
    if lines.is_empty() {
        return Err(GeometryError::Empty {
            file: file.to_string(),
        });
    }

    let (name, body) = if looks_like_pair(&lines[0].tokens) {
        (fallback_name.to_string(), &lines[..])
    } else {
        (lines[0].tokens.join(" "), &lines[1..])
    };
    let has_name = body.len() < lines.len();
    if body.is_empty() {
        return Err(GeometryError::Empty {
            file: file.to_string(),
        });
    }

    let first = parse_pair(&body[0], file)?;
    // XFOIL's rule (both values > 1.5), restricted to whole numbers within the point limit,
    // so that a Selig file in millimetres is not taken for a count header.
    let point_count = |v: f64| -> Option<usize> {
        (v > 1.5 && v.fract() == 0.0 && v <= MAX_CONTOUR_POINTS as f64).then_some(v as usize)
    };
    let lednicer_counts = point_count(first.0).zip(point_count(first.1));
    let is_lednicer = has_name && lednicer_counts.is_some();
    let (format, data) = if is_lednicer {
        (CoordinateFormat::Lednicer, &body[1..])
    } else if has_name {
        (CoordinateFormat::Selig, body)
    } else {
        (CoordinateFormat::Plain, body)
    };

    let mut pts: Vec<(f64, f64, usize)> = Vec::with_capacity(data.len());
    for dl in data {
        let (x, y) = parse_pair(dl, file)?;
        pts.push((x, y, dl.line));
    }
    if pts.is_empty() {
        return Err(GeometryError::Empty {
            file: file.to_string(),
        });
    }

    if format == CoordinateFormat::Lednicer {
        let header_line = body[0].line;
        let (nu, nl) = lednicer_counts.unwrap_or((0, 0));
        if nu + nl != pts.len() {
            return Err(GeometryError::LednicerCount {
                file: file.to_string(),
                line: header_line,
                upper: nu,
                lower: nl,
                found: pts.len(),
            });
        }
        let lower = pts.split_off(nu);
        let mut ordered: Vec<(f64, f64, usize)> = pts.into_iter().rev().collect();
        let le = ordered[ordered.len() - 1];
        for (i, p) in lower.into_iter().enumerate() {
            if i == 0 && p.0 == le.0 && p.1 == le.1 {
                continue;
            }
            ordered.push(p);
        }
        pts = ordered;
    }

    let x: Vec<f64> = pts.iter().map(|p| p.0).collect();
    let y: Vec<f64> = pts.iter().map(|p| p.1).collect();
    let line_of: Vec<usize> = pts.iter().map(|p| p.2).collect();
    validate_contour(&x, &y, &line_of, Place::Line, file)?;

    let mut airfoil = Airfoil { name, x, y };
    if signed_area(&airfoil.x, &airfoil.y) < 0.0 {
        airfoil.x.reverse();
        airfoil.y.reverse();
    }
    Ok((airfoil, format))
}

/// Formats an airfoil as a Selig file: the name line, then one `x y` pair per line in
/// XFOIL order, with 8 decimals (enough to round-trip paneled nodes to 1e-8 chord).
pub fn to_selig_string(airfoil: &Airfoil) -> String {
    let mut out = String::with_capacity(24 * (airfoil.x.len() + 1));
    let name = airfoil.name.lines().next().unwrap_or("").trim();
    out.push_str(if name.is_empty() { "airfoil" } else { name });
    out.push('\n');
    for (x, y) in airfoil.x.iter().zip(&airfoil.y) {
        out.push_str(&format!("{x:12.8} {y:12.8}\n"));
    }
    out
}
