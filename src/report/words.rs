//! The report's words: numbers as printed, verdicts by the report's bands, and the sentences
//! and Markdown tables that compare ours with the paper.

pub(super) use crate::studies::paper::published::change_percent as rel;
use crate::studies::paper::published::Comparison;
use std::fmt::Write as _;

/// Relative differences up to this [%] are called a match in the report's words.
pub(super) const MATCH_PERCENT: f64 = 5.0;

/// Relative differences up to this [%] are called close; larger ones differ.
pub(super) const CLOSE_PERCENT: f64 = 15.0;

/// `v` with `prec` decimals, or "—" when not a number.
pub(super) fn num(v: f64, prec: usize) -> String {
    if v.is_finite() {
        format!("{v:.prec$}")
    } else {
        "—".to_string()
    }
}

/// Signed percentage with one decimal.
pub(super) fn pct(v: f64) -> String {
    if v.is_finite() {
        format!("{v:+.1} %")
    } else {
        "—".to_string()
    }
}

/// How far ours is from the paper, in words, by the report's bands.
pub(super) fn verdict(diff_percent: f64) -> &'static str {
    let d = diff_percent.abs();
    if !d.is_finite() {
        "not computed"
    } else if d <= MATCH_PERCENT {
        "matches"
    } else if d <= CLOSE_PERCENT {
        "close"
    } else {
        "differs"
    }
}

/// Paper-vs-ours counts by verdict: matches, close, differs (names of the latter).
#[derive(Default)]
pub(super) struct Tally {
    matches: usize,
    close: usize,
    differs: Vec<String>,
}

impl Tally {
    fn add(&mut self, name: &str, case: &str, diff_percent: f64) {
        match verdict(diff_percent) {
            "matches" => self.matches += 1,
            "close" => self.close += 1,
            _ => self
                .differs
                .push(format!("{name} {case} ({})", pct(diff_percent))),
        }
    }

    pub(super) fn sentence(&self) -> String {
        let total = self.matches + self.close + self.differs.len();
        // Verb agreeing with a count: "1 matches", "2 match".
        let verb =
            |n: usize, one: &'static str, many: &'static str| if n == 1 { one } else { many };
        let mut s = format!(
            "Of {total} values, {} {} the paper within {MATCH_PERCENT} %, {} {} within \
             {CLOSE_PERCENT} %",
            self.matches,
            verb(self.matches, "matches", "match"),
            self.close,
            verb(self.close, "is", "are"),
        );
        if self.differs.is_empty() {
            s.push_str(" and none differs by more.");
        } else {
            let n = self.differs.len();
            let _ = write!(
                s,
                " and {n} {} by more: {}.",
                verb(n, "differs", "differ"),
                self.differs.join(", ")
            );
        }
        s
    }
}

/// Markdown table of paper vs ours, clean and contaminated, with the contamination changes.
pub(super) fn comparison_table(out: &mut String, rows: &[Comparison]) {
    outln!(
        out,
        "| quantity | paper clean | ours clean | ours vs paper | paper contaminated | ours contaminated | ours vs paper | paper change | ours change |"
    );
    outln!(out, "|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    for r in rows {
        outln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            r.name,
            r.paper.clean,
            num(r.ours.clean, r.decimals),
            pct(rel(r.paper.clean, r.ours.clean)),
            r.paper.contaminated,
            num(r.ours.contaminated, r.decimals),
            pct(rel(r.paper.contaminated, r.ours.contaminated)),
            pct(rel(r.paper.clean, r.paper.contaminated)),
            pct(rel(r.ours.clean, r.ours.contaminated)),
        );
    }
}

/// Paper-vs-ours verdicts of every value (clean and contaminated) of `rows`.
pub(super) fn tally_of(rows: &[Comparison]) -> Tally {
    let mut tally = Tally::default();
    for r in rows {
        tally.add(r.name, "clean", rel(r.paper.clean, r.ours.clean));
        tally.add(
            r.name,
            "contaminated",
            rel(r.paper.contaminated, r.ours.contaminated),
        );
    }
    tally
}

/// Clean → contaminated change of the paper (`pch`) and ours (`och`) [%] are both "changing"
/// when the paper's is at least this large [%]; smaller paper changes have no direction to
/// compare.
const CHANGE_THRESHOLD_PERCENT: f64 = 1.0;

/// Sentence on how often the clean → contaminated change has the paper's sign.
pub(super) fn direction_sentence(rows: &[Comparison]) -> String {
    let changes: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| {
            (
                rel(r.paper.clean, r.paper.contaminated),
                rel(r.ours.clean, r.ours.contaminated),
            )
        })
        .filter(|(pch, _)| pch.abs() >= CHANGE_THRESHOLD_PERCENT)
        .collect();
    let agree = changes
        .iter()
        .filter(|(pch, och)| pch.signum() == och.signum())
        .count();
    format!(
        "The direction of the clean → contaminated change agrees with the paper for {agree} of \
         the {} quantities the paper shows changing by {CHANGE_THRESHOLD_PERCENT} % or more.",
        changes.len()
    )
}

/// Our contamination change of each row over the paper's, (ours contaminated − ours clean) /
/// (paper contaminated − paper clean), for the rows the paper shows changing by
/// [`CHANGE_THRESHOLD_PERCENT`] or more: (name, ratio).
pub(super) fn change_ratios(rows: &[Comparison]) -> Vec<(&'static str, f64)> {
    rows.iter()
        .filter(|r| rel(r.paper.clean, r.paper.contaminated).abs() >= CHANGE_THRESHOLD_PERCENT)
        .map(|r| {
            let ratio =
                (r.ours.contaminated - r.ours.clean) / (r.paper.contaminated - r.paper.clean);
            (r.name, ratio)
        })
        .collect()
}

/// Bullet list stating each row's agreement and its contamination change in words, then the
/// tally and direction sentences.
pub(super) fn comparison_words(out: &mut String, rows: &[Comparison]) {
    for r in rows {
        let (dc, dd) = (
            rel(r.paper.clean, r.ours.clean),
            rel(r.paper.contaminated, r.ours.contaminated),
        );
        let (pch, och) = (
            rel(r.paper.clean, r.paper.contaminated),
            rel(r.ours.clean, r.ours.contaminated),
        );
        let change = if pch.abs() < CHANGE_THRESHOLD_PERCENT {
            format!(
                "Contamination changes it by {} in the paper and {} here.",
                pct(pch),
                pct(och)
            )
        } else {
            let ratio = och / pch;
            let size = if pch.signum() != och.signum() {
                "the opposite direction".to_string()
            } else if (ratio - 1.0).abs() <= 0.2 {
                "about the same size".to_string()
            } else if ratio > 1.0 {
                format!("{ratio:.1}× the paper's change")
            } else {
                format!("{:.0} % of the paper's change", 100.0 * ratio)
            };
            format!(
                "Contamination: paper {}, ours {} ({size}).",
                pct(pch),
                pct(och)
            )
        };
        outln!(
            out,
            "- **{}** — clean: ours {} vs paper {} ({}, {}); contaminated: ours {} vs paper {} ({}, {}). {change}",
            r.name,
            num(r.ours.clean, r.decimals),
            r.paper.clean,
            pct(dc),
            verdict(dc),
            num(r.ours.contaminated, r.decimals),
            r.paper.contaminated,
            pct(dd),
            verdict(dd),
        );
    }
    outln!(out);
    outln!(
        out,
        "{} {}",
        tally_of(rows).sentence(),
        direction_sentence(rows)
    );
}

/// The larger of two values, NaN if either is NaN (a missing value must not hide).
pub(super) fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// Unsigned percentage with one decimal, "—" when not a number.
pub(super) fn num_pct(v: f64) -> String {
    if v.is_finite() {
        format!("{v:.1} %")
    } else {
        "— (a value is missing)".to_string()
    }
}
