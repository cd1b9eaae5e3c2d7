//! Detection of an iteration caught in a cycle, from the sequence of a scalar it produces.

/// The shortest period p ≤ `max_period` with which the end of `history` repeats `repeats`
/// times: each of the last `repeats`·p values equals the value p places before it to a
/// relative tolerance `rtol` (the last (`repeats` + 1)·p values are `repeats` + 1 copies of
/// one block of p values). An iteration whose monitored scalar does this has come back, to
/// round-off, to a state it was in before, and goes round the same loop again.
pub(crate) fn repeating_period(
    history: &[f64],
    max_period: usize,
    repeats: usize,
    rtol: f64,
) -> Option<usize> {
    let n = history.len();
    (1..=max_period).find(|&p| {
        p * (repeats + 1) <= n
            && (0..p * repeats).all(|i| {
                let (now, before) = (history[n - 1 - i], history[n - 1 - i - p]);
                (now - before).abs() <= rtol * now.abs()
            })
    })
}

#[cfg(test)]
mod tests {
    use super::repeating_period;

    #[test]
    fn finds_the_shortest_period() {
        let two = [5.0, 3e-2, 1e-2, 3e-2, 1e-2, 3e-2, 1e-2];
        assert_eq!(repeating_period(&two, 16, 2, 0.0), Some(2));
        // A fixed point is a cycle of period 1.
        assert_eq!(
            repeating_period(&[1.0, 2e-3, 2e-3, 2e-3], 16, 2, 0.0),
            Some(1)
        );
        let three = [9.0, 1.0, 2.0, 3.0, 1.0, 2.0, 3.0, 1.0, 2.0, 3.0];
        assert_eq!(repeating_period(&three, 16, 2, 0.0), Some(3));
        assert_eq!(repeating_period(&three, 2, 2, 0.0), None);
    }

    #[test]
    fn repeats_within_the_tolerance_only() {
        // A period-2 cycle of the viscous solver (NACA 8-H-12), repeating to 1e-11.
        let cycle = [
            1.6351123919823445e-2,
            3.83727004534665e-2,
            1.6351123919784e-2,
            3.837270045331014e-2,
            1.635112391978401e-2,
            3.837270045330505e-2,
        ];
        assert_eq!(repeating_period(&cycle, 16, 2, 1e-6), Some(2));
        assert_eq!(repeating_period(&cycle, 16, 2, 1e-13), None);
        // Only one repeat of the block so far.
        assert_eq!(repeating_period(&[1.0, 2.0, 1.0, 2.0], 16, 2, 0.0), None);
        // A decreasing sequence (a converging iteration) never repeats.
        let converging: Vec<f64> = (0..40).map(|k| 0.7f64.powi(k)).collect();
        assert_eq!(repeating_period(&converging, 16, 2, 1e-6), None);
        assert_eq!(repeating_period(&[], 16, 2, 1e-6), None);
    }
}
