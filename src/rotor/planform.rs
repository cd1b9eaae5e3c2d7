//! The blade's chord and pitch along the span: piecewise-linear stations in r/R (a station
//! repeated at the same r/R is a step), or a constant chord and an untwisted blade.

/// One station of a [`Planform`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PlanformStation {
    /// Radius fraction r/R.
    pub r_over_r: f64,
    /// Chord relative to the rotor's reference chord.
    pub chord_ratio: f64,
    /// Pitch relative to the blade's pitch setting \[rad\].
    pub twist: f64,
}

/// Chord and twist along the blade, linear between stations ordered by r/R; a repeated r/R
/// is a step (the outer value holds from that radius on). Outside the stations the end values
/// hold. No stations: chord ratio 1, no twist.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Planform {
    /// The stations, r/R non-decreasing.
    pub stations: Vec<PlanformStation>,
}

impl Planform {
    /// Chord ratio and twist \[rad\] at radius fraction `x`.
    pub fn at(&self, x: f64) -> (f64, f64) {
        let s = &self.stations;
        let (Some(first), Some(last)) = (s.first(), s.last()) else {
            return (1.0, 0.0);
        };
        if x < first.r_over_r {
            return (first.chord_ratio, first.twist);
        }
        if x >= last.r_over_r {
            return (last.chord_ratio, last.twist);
        }
        // The last segment with a positive length that starts at or inboard of x.
        let i = s
            .windows(2)
            .rposition(|w| w[0].r_over_r <= x && w[1].r_over_r > w[0].r_over_r)
            .unwrap_or(0);
        let (a, b) = (s[i], s[i + 1]);
        let t = ((x - a.r_over_r) / (b.r_over_r - a.r_over_r)).clamp(0.0, 1.0);
        (
            a.chord_ratio + t * (b.chord_ratio - a.chord_ratio),
            a.twist + t * (b.twist - a.twist),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn station(r_over_r: f64, chord_ratio: f64, twist: f64) -> PlanformStation {
        PlanformStation {
            r_over_r,
            chord_ratio,
            twist,
        }
    }

    #[test]
    fn steps_and_linear_segments() {
        // A narrow untwisted root to 0.4 R, then a wide blade twisted from −1 to +2.
        let p = Planform {
            stations: vec![
                station(0.0, 0.5, 0.0),
                station(0.4, 0.5, 0.0),
                station(0.4, 1.0, -1.0),
                station(1.0, 1.0, 2.0),
            ],
        };
        assert_eq!(p.at(0.2), (0.5, 0.0));
        assert_eq!(p.at(0.399), (0.5, 0.0));
        assert_eq!(p.at(0.4), (1.0, -1.0));
        let (c, t) = p.at(0.7);
        assert_eq!(c, 1.0);
        assert!((t - 0.5).abs() < 1e-12, "{t}");
        assert_eq!(p.at(1.0), (1.0, 2.0));
        assert_eq!(p.at(1.2), (1.0, 2.0));
        assert_eq!(Planform::default().at(0.5), (1.0, 0.0));
    }
}
