//! Airfoil coordinate-file reader: Selig, Lednicer and plain formats, auto-detected, with
//! validation, converted to XFOIL point order (upper TE → LE → lower TE).
//!
//! Format conventions follow XFOIL's `AREAD` (Drela): a first line that is not a pair of
//! numbers is the airfoil name; a first data pair with both values > 1.5 is a Lednicer
//! point-count header; a clockwise contour is reversed (XFOIL `LOAD`, sign of the area).

use std::path::Path;

use super::error::GeometryError;
use super::Airfoil;

/// Minimum number of contour points accepted from a file.
pub const MIN_POINTS: usize = 10;

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

/// Reads and parses an airfoil coordinate file (any supported format).
pub fn read_airfoil_file(path: &Path) -> Result<Airfoil, GeometryError> {
    let file = path.display().to_string();
    let bytes = std::fs::read(path).map_err(|e| GeometryError::Io {
        file: file.clone(),
        reason: e.to_string(),
    })?;
    let fallback = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| file.clone());
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
    for (k, raw) in text.lines().enumerate() {
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
        let tokens: Vec<&str> = trimmed
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|t| !t.is_empty())
            .collect();
        lines.push(DataLine { line, tokens });
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
    let is_lednicer = has_name && first.0 > 1.5 && first.1 > 1.5;
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
        let count = |v: f64| -> Option<usize> {
            (v.fract().abs() < 1e-9 && (1.0..1.0e6).contains(&v)).then_some(v as usize)
        };
        let (nu, nl) = match (count(first.0), count(first.1)) {
            (Some(a), Some(b)) => (a, b),
            _ => {
                return Err(GeometryError::BadNumber {
                    file: file.to_string(),
                    line: header_line,
                    token: format!("{} {}", first.0, first.1),
                })
            }
        };
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
    validate_contour(&x, &y, &line_of, file)?;

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

/// Signed area enclosed by the contour closed through its end points (positive for
/// counter-clockwise, i.e. XFOIL order), as in XFOIL `LOAD`.
pub(crate) fn signed_area(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len();
    let mut area = 0.0;
    for i in 0..n {
        let j = (i + 1) % n;
        area += 0.5 * (y[i] + y[j]) * (x[i] - x[j]);
    }
    area
}

/// Checks a contour: enough points, all finite, no duplicate consecutive points and no
/// crossing of non-adjacent segments. `line_of[i]` is the line (or point number) reported
/// for point i; `file` names the source.
pub(crate) fn validate_contour(
    x: &[f64],
    y: &[f64],
    line_of: &[usize],
    file: &str,
) -> Result<(), GeometryError> {
    let n = x.len();
    if n < MIN_POINTS {
        return Err(GeometryError::TooFewPoints {
            file: file.to_string(),
            found: n,
            min: MIN_POINTS,
        });
    }
    for i in 0..n {
        if !(x[i].is_finite() && y[i].is_finite()) {
            return Err(GeometryError::NonFinite {
                file: file.to_string(),
                line: line_of[i],
                token: format!("({}, {})", x[i], y[i]),
            });
        }
    }
    let scale = x
        .iter()
        .chain(y.iter())
        .fold(0.0f64, |m, v| m.max(v.abs()))
        .max(f64::MIN_POSITIVE);
    for i in 1..n {
        if (x[i] - x[i - 1]).hypot(y[i] - y[i - 1]) <= 1e-12 * scale {
            return Err(GeometryError::DuplicatePoint {
                file: file.to_string(),
                line: line_of[i],
                x: x[i],
                y: y[i],
            });
        }
    }
    // A closed TE (end points equal up to round-off) makes the first and last segments
    // neighbours, which must not count as a crossing.
    let closed = (x[0] - x[n - 1]).hypot(y[0] - y[n - 1]) <= 1e-9 * scale;
    if let Some((i, j, px, py)) = first_crossing(x, y, closed) {
        return Err(GeometryError::SelfIntersecting {
            file: file.to_string(),
            line_a: line_of[i],
            line_b: line_of[j],
            x: px,
            y: py,
        });
    }
    Ok(())
}

/// First pair of non-adjacent polyline segments (i, i+1), (j, j+1), i < j, that cross
/// properly (each segment's end points strictly on opposite sides of the other), with the
/// crossing point. With `closed`, the first and last segments are treated as adjacent.
fn first_crossing(x: &[f64], y: &[f64], closed: bool) -> Option<(usize, usize, f64, f64)> {
    let n = x.len();
    let orient = |a: usize, b: usize, c: usize| -> f64 {
        (x[b] - x[a]) * (y[c] - y[a]) - (y[b] - y[a]) * (x[c] - x[a])
    };
    for i in 0..n - 1 {
        let (xmin_i, xmax_i) = (x[i].min(x[i + 1]), x[i].max(x[i + 1]));
        let (ymin_i, ymax_i) = (y[i].min(y[i + 1]), y[i].max(y[i + 1]));
        for j in i + 2..n - 1 {
            if closed && i == 0 && j == n - 2 {
                continue;
            }
            if x[j].max(x[j + 1]) < xmin_i
                || x[j].min(x[j + 1]) > xmax_i
                || y[j].max(y[j + 1]) < ymin_i
                || y[j].min(y[j + 1]) > ymax_i
            {
                continue;
            }
            let d1 = orient(i, i + 1, j);
            let d2 = orient(i, i + 1, j + 1);
            let d3 = orient(j, j + 1, i);
            let d4 = orient(j, j + 1, i + 1);
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                let t = d1 / (d1 - d2);
                let px = x[j] + t * (x[j + 1] - x[j]);
                let py = y[j] + t * (y[j + 1] - y[j]);
                return Some((i, j, px, py));
            }
        }
    }
    None
}
