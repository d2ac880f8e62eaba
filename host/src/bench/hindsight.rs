//! What a per-triangle choice of strategy could reach on a row at best, with hindsight: the
//! yardstick `uvt auto-rule` measures `auto`'s rule against (its source's last table,
//! `docs/bounds.md`).
//!
//! Each triangle of a row offers a [`Choice`] per strategy: its modelled instructions and the
//! samples it tests. A rule picks one choice per triangle from what setup knows; hindsight picks
//! from the figures themselves, so no rule does better than:
//!
//! - [`least_cost`]: every triangle's cheapest choice. No per-triangle choice costs less; where
//!   it is not below Laine 2011's alone, no rule over these strategies is.
//! - [`least_tested_within`]: the fewest samples tested by any choice whose instructions stay
//!   within a budget. It solves the linear relaxation of that multiple-choice knapsack (a
//!   triangle may mix two choices), whose optimum is at most the optimum of whole choices: a
//!   lower bound on the samples tested, so the sample-test efficiency it gives is an **upper**
//!   bound on any rule's. The relaxation is solved exactly by the greedy rule of Sinha and
//!   Zoltners (1979): per triangle the lower convex hull of its (instructions, tested) points,
//!   from the cheapest point on; the hull's steps taken across all triangles in order of samples
//!   saved per instruction, the last one in part. Within one triangle the steps' rates fall
//!   (convexity), so the global order never takes a step before its predecessor.

/// One strategy on one triangle: modelled instructions and tested samples.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice {
    /// modelled instructions
    pub cost: f64,
    /// tested samples
    pub tested: f64,
}

/// The least instructions of any per-triangle choice: every triangle's cheapest (0 for no
/// triangle or a triangle without choices).
pub fn least_cost(tris: &[Vec<Choice>]) -> f64 {
    tris.iter()
        .map(|c| c.iter().map(|x| x.cost).fold(f64::INFINITY, f64::min))
        .filter(|c| c.is_finite())
        .sum()
}

/// The lower convex hull of `pts` from the cheapest point (the fewest tested among the
/// cheapest) on, through points each cheaper in tests and dearer in instructions than the last.
fn lower_hull(pts: &[Choice]) -> Vec<Choice> {
    let mut p: Vec<Choice> = pts.to_vec();
    p.sort_by(|a, b| {
        a.cost
            .total_cmp(&b.cost)
            .then(a.tested.total_cmp(&b.tested))
    });
    let mut hull: Vec<Choice> = Vec::with_capacity(p.len());
    for x in p {
        // Dominated: no fewer tests than the last hull point, at no lower cost.
        if hull.last().is_some_and(|l| x.tested >= l.tested) {
            continue;
        }
        // Pop while the last point lies on or above the chord from the one before it to x.
        while hull.len() >= 2 {
            let (a, b) = (hull[hull.len() - 2], hull[hull.len() - 1]);
            let cross = (b.cost - a.cost) * (x.tested - a.tested)
                - (b.tested - a.tested) * (x.cost - a.cost);
            if cross <= 0.0 {
                hull.pop();
            } else {
                break;
            }
        }
        hull.push(x);
    }
    hull
}

/// The fewest samples tested (the linear relaxation's optimum, module docs) by any choice of one
/// [`Choice`] per triangle (or a mix of two) whose instructions total at most `budget`; `None`
/// when even every triangle's cheapest choice is over it, or a triangle has no choice.
pub fn least_tested_within(tris: &[Vec<Choice>], budget: f64) -> Option<f64> {
    let mut cost = 0.0;
    let mut tested = 0.0;
    // (samples saved per instruction, instructions, samples saved) of every hull step.
    let mut steps: Vec<(f64, f64, f64)> = Vec::new();
    for t in tris {
        let hull = lower_hull(t);
        let first = hull.first()?;
        cost += first.cost;
        tested += first.tested;
        for w in hull.windows(2) {
            let (dc, dt) = (w[1].cost - w[0].cost, w[0].tested - w[1].tested);
            steps.push((dt / dc, dc, dt));
        }
    }
    if cost > budget {
        return None;
    }
    steps.sort_by(|a, b| b.0.total_cmp(&a.0));
    for (_, dc, dt) in steps {
        let room = budget - cost;
        if room <= 0.0 {
            break;
        }
        let f = (room / dc).min(1.0);
        cost += f * dc;
        tested -= f * dt;
    }
    Some(tested)
}
