//! Section coefficients at scattered operating points: every point a list asks for, solved by
//! the viscous solver. The points of one condition (Re, M and trip locations) form one
//! warm-started polar over their distinct α values, the polars run in parallel on one panel
//! store ([`run_grid`]), and the results come back in the order of the list.

use crate::section::Transition;
use std::collections::HashMap;
use std::sync::atomic::AtomicBool;

use super::build::solve_nodes;
use super::BuildError;
use crate::geometry::Airfoil;
use crate::limits::MAX_GRID_POINTS;
use crate::polar::GridNode;
use crate::section::PolarPoint;
use crate::viscous::ViscousParams;

/// One operating point to solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointQuery {
    /// Angle of attack \[deg\].
    pub alpha_deg: f64,
    /// Chord Reynolds number.
    pub reynolds: f64,
    /// Mach number.
    pub mach: f64,
    /// Forced transition x/c on the upper surface (1 = free).
    pub xtr_top: f64,
    /// Forced transition x/c on the lower surface (1 = free).
    pub xtr_bot: f64,
}

/// The polars a list of queries needs: one per distinct condition, each over its distinct α
/// values in increasing order, and where each query's point is (polar, position in it).
#[derive(Debug, PartialEq)]
pub struct PointPlan {
    /// Per polar: a query of its condition (its α is irrelevant) and its sorted α values.
    polars: Vec<(PointQuery, Vec<f64>)>,
    /// Per query: (polar index, α index within that polar).
    slots: Vec<(usize, usize)>,
}

impl PointPlan {
    /// Groups `queries` by condition (bit-equal Re, M and trips), in order of first
    /// appearance.
    pub fn new(queries: &[PointQuery]) -> Self {
        let key = |q: &PointQuery| {
            [q.reynolds, q.mach, q.xtr_top, q.xtr_bot].map(|v| (v + 0.0).to_bits())
        };
        let mut index: HashMap<[u64; 4], usize> = HashMap::new();
        let mut polars: Vec<(PointQuery, Vec<f64>)> = Vec::new();
        let mut owner = Vec::with_capacity(queries.len());
        for q in queries {
            let i = *index.entry(key(q)).or_insert_with(|| {
                polars.push((*q, Vec::new()));
                polars.len() - 1
            });
            polars[i].1.push(q.alpha_deg + 0.0);
            owner.push(i);
        }
        for (_, alphas) in &mut polars {
            alphas.sort_by(f64::total_cmp);
            alphas.dedup_by(|a, b| a.to_bits() == b.to_bits());
        }
        let slots = queries
            .iter()
            .zip(owner)
            .map(|(q, i)| {
                let alphas = &polars[i].1;
                let at = alphas
                    .binary_search_by(|a| a.total_cmp(&(q.alpha_deg + 0.0)))
                    .unwrap_or_else(|i| i);
                (i, at)
            })
            .collect();
        Self { polars, slots }
    }

    /// Every polar: a query of its condition (its α is any of the polar's) and its α values,
    /// increasing. For checking the values before [`solve_points`].
    pub fn polars(&self) -> impl Iterator<Item = (&PointQuery, &[f64])> {
        self.polars.iter().map(|(q, a)| (q, a.as_slice()))
    }

    /// Number of polars (distinct conditions).
    pub fn polar_count(&self) -> usize {
        self.polars.len()
    }

    /// Number of points to solve (distinct α per condition); at most the number of queries.
    pub fn point_count(&self) -> usize {
        self.polars.iter().map(|(_, a)| a.len()).sum()
    }

    /// Refuses more than [`MAX_GRID_POINTS`] points to solve (a check before any solve).
    pub fn check_size(&self) -> Result<(), BuildError> {
        let points = self.point_count();
        if points <= MAX_GRID_POINTS {
            return Ok(());
        }
        Err(BuildError::TooManyPoints {
            polars: self.polar_count(),
            points,
        })
    }
}

/// Solves the points of `plan` on `foil` (already paneled with `panels` nodes) with the
/// settings of `base` (its Re, M and trips are replaced by each condition's) on at most
/// `threads` threads (0 = all cores), calling `on_points` with the number of points of each
/// finished polar, and stopping as [`build_table_cancellable`](super::build_table_cancellable)
/// does when `cancel` is set. Returns one point per query, in the order of the queries; a
/// point of a polar equals the point of the same α in `polargen --alpha` over that
/// condition's α values (unconverged points are returned flagged, as there).
pub fn solve_points(
    foil: &Airfoil,
    plan: &PointPlan,
    base: &ViscousParams,
    threads: usize,
    on_points: impl Fn(usize) + Sync,
    cancel: &AtomicBool,
) -> Result<Vec<PolarPoint>, BuildError> {
    plan.check_size()?;
    let nodes: Vec<GridNode<'_>> = plan
        .polars
        .iter()
        .enumerate()
        .map(|(i, (q, alphas))| GridNode {
            re: q.reynolds,
            mach: q.mach,
            alphas,
            // Each condition its own series: its points are those of its polar alone.
            series: i,
        })
        .collect();
    let params = |i: usize| {
        let q = &plan.polars[i].0;
        ViscousParams {
            reynolds: q.reynolds,
            mach: q.mach,
            transition: Transition {
                xtr_top: q.xtr_top,
                xtr_bot: q.xtr_bot,
                ..base.transition
            },
            ..*base
        }
    };
    let polars = solve_nodes(foil, &nodes, params, threads, on_points, cancel)?;
    Ok(plan
        .slots
        .iter()
        .map(|&(i, at)| polars[i].points[at])
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn query(alpha_deg: f64, reynolds: f64) -> PointQuery {
        PointQuery {
            alpha_deg,
            reynolds,
            mach: 0.0,
            xtr_top: 1.0,
            xtr_bot: 1.0,
        }
    }

    /// Queries group by condition in order of appearance; repeated α are solved once.
    #[test]
    fn plan_groups_by_condition_and_dedups_alpha() {
        let q = [
            query(4.0, 1e6),
            query(-2.0, 2e6),
            query(0.0, 1e6),
            query(4.0, 1e6),
            query(-0.0, 1e6),
        ];
        let plan = PointPlan::new(&q);
        assert_eq!(plan.polar_count(), 2);
        assert_eq!(plan.point_count(), 3);
        assert_eq!(plan.polars[0].1, vec![0.0, 4.0]);
        assert_eq!(plan.slots, vec![(0, 1), (1, 0), (0, 0), (0, 1), (0, 0)]);
        let mut tripped = query(0.0, 1e6);
        tripped.xtr_top = 0.07;
        assert_eq!(PointPlan::new(&[q[0], tripped]).polar_count(), 2);
    }

    #[test]
    fn too_many_points_are_refused_before_solving() {
        let q: Vec<PointQuery> = (0..=MAX_GRID_POINTS)
            .map(|i| query(0.0, 1e5 + i as f64))
            .collect();
        let plan = PointPlan::new(&q);
        assert!(matches!(
            plan.check_size(),
            Err(BuildError::TooManyPoints { points, .. }) if points == MAX_GRID_POINTS + 1
        ));
    }
}
