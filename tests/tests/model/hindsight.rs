//! The hindsight bounds of `uvt auto-rule` (`host/src/bench/hindsight.rs`) against brute force:
//! named cases (the edges of the budget, dominated and collinear choices, no triangle, a
//! triangle without a choice) and seeded-random rows (`UVT_SEED`, printed on failure;
//! `UVT_EXTENSIVE=1` for many more), where the cheapest per-triangle cost must equal the least
//! over every whole choice, and the fewest tested samples within a budget must equal the
//! relaxation's optimum found by enumerating its basic solutions (every triangle on one choice
//! but at most one, which mixes two) and be at most every whole choice's within the budget.

use uvt_host::bench::hindsight::{least_cost, least_tested_within, Choice};
use uvt_tests::{cases, seed, Rng};

fn ch(cost: f64, tested: f64) -> Choice {
    Choice { cost, tested }
}

/// Every whole choice (one index per triangle).
fn assignments(tris: &[Vec<Choice>]) -> Vec<Vec<usize>> {
    let mut all = vec![vec![]];
    for t in tris {
        all = all
            .into_iter()
            .flat_map(|a| {
                (0..t.len()).map(move |k| {
                    let mut b = a.clone();
                    b.push(k);
                    b
                })
            })
            .collect();
    }
    all
}

fn totals(tris: &[Vec<Choice>], a: &[usize]) -> (f64, f64) {
    tris.iter().zip(a).fold((0.0, 0.0), |(c, t), (x, &k)| {
        (c + x[k].cost, t + x[k].tested)
    })
}

/// The relaxation's optimum by its basic solutions: whole choices, and whole choices with one
/// triangle mixing two of its choices so that the budget is met exactly.
fn relaxation_brute(tris: &[Vec<Choice>], budget: f64) -> Option<f64> {
    let mut best: Option<f64> = None;
    let mut take = |t: f64| best = Some(best.map_or(t, |b: f64| b.min(t)));
    for a in assignments(tris) {
        let (c, t) = totals(tris, &a);
        if c <= budget {
            take(t);
        }
        for (j, tri) in tris.iter().enumerate() {
            let (rc, rt) = (c - tri[a[j]].cost, t - tri[a[j]].tested);
            for x in tri {
                for y in tri {
                    // f·x + (1 − f)·y with the cost exactly the budget.
                    if x.cost == y.cost {
                        continue;
                    }
                    let f = (budget - rc - y.cost) / (x.cost - y.cost);
                    if (0.0..=1.0).contains(&f) {
                        take(rt + f * x.tested + (1.0 - f) * y.tested);
                    }
                }
            }
        }
    }
    best
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-9 * (1.0 + a.abs().max(b.abs()))
}

#[test]
fn named_cases() {
    let tri = vec![ch(10.0, 100.0), ch(20.0, 50.0), ch(40.0, 40.0)];
    let one = vec![tri.clone()];
    // Under the cheapest choice: nothing fits.
    assert_eq!(least_tested_within(&one, 9.999), None);
    // Exactly the cheapest: it alone.
    assert_eq!(least_tested_within(&one, 10.0), Some(100.0));
    // Halfway to the second hull point: half its saving.
    assert_eq!(least_tested_within(&one, 15.0), Some(75.0));
    // Unbounded: the fewest tests of any choice.
    assert_eq!(least_tested_within(&one, f64::INFINITY), Some(40.0));
    assert_eq!(least_cost(&one), 10.0);
    // A dominated choice (dearer and testing more) and a collinear one change nothing.
    let more = vec![vec![
        ch(10.0, 100.0),
        ch(15.0, 75.0),
        ch(20.0, 50.0),
        ch(30.0, 90.0),
        ch(40.0, 40.0),
    ]];
    for b in [10.0, 12.5, 15.0, 20.0, 30.0, 40.0, 50.0] {
        assert_eq!(
            least_tested_within(&more, b),
            least_tested_within(&one, b),
            "budget {b}"
        );
    }
    // The steps go by samples saved per instruction across triangles: the second triangle's
    // 10 per instruction before the first's 5.
    let two = vec![tri, vec![ch(5.0, 60.0), ch(6.0, 50.0)]];
    assert_eq!(least_tested_within(&two, 16.0), Some(150.0));
    assert_eq!(least_tested_within(&two, 21.0), Some(125.0));
    // No triangle: nothing tested, nothing spent; a triangle without a choice: no bound.
    assert_eq!(least_tested_within(&[], 0.0), Some(0.0));
    assert_eq!(least_cost(&[]), 0.0);
    assert_eq!(least_tested_within(&[vec![]], 1e9), None);
}

#[test]
fn seeded_rows_against_brute_force() {
    let seed = seed();
    let mut rng = Rng(seed);
    for case in 0..cases(400, 20_000) {
        let n = 1 + rng.below(4) as usize;
        let tris: Vec<Vec<Choice>> = (0..n)
            .map(|_| {
                (0..1 + rng.below(4))
                    .map(|_| {
                        // Integral figures a third of the time: ties and collinear steps.
                        if rng.below(3) == 0 {
                            ch(rng.int_range(1, 6) as f64, rng.int_range(0, 6) as f64)
                        } else {
                            ch(rng.range(1.0, 100.0), rng.range(0.0, 100.0))
                        }
                    })
                    .collect()
            })
            .collect();
        let whole = assignments(&tris);
        let cheapest = whole
            .iter()
            .map(|a| totals(&tris, a).0)
            .fold(f64::INFINITY, f64::min);
        let lc = least_cost(&tris);
        assert!(
            close(lc, cheapest),
            "UVT_SEED={seed} case {case}: {tris:?}\n least_cost {lc} ({:#x}), brute force {cheapest} ({:#x})",
            lc.to_bits(),
            cheapest.to_bits()
        );
        let budget = cheapest * rng.range(0.9, 1.6);
        let got = least_tested_within(&tris, budget);
        let want = relaxation_brute(&tris, budget);
        let ok = match (got, want) {
            (Some(g), Some(w)) => close(g, w),
            (None, None) => true,
            _ => false,
        };
        assert!(
            ok,
            "UVT_SEED={seed} case {case}: {tris:?} budget {budget}\n least_tested_within {got:?}, brute force {want:?}"
        );
        // A bound: at most the fewest tests of any whole choice within the budget.
        if let Some(g) = got {
            for a in &whole {
                let (c, t) = totals(&tris, a);
                assert!(
                    c > budget || g <= t + 1e-9 * t.abs().max(1.0),
                    "UVT_SEED={seed} case {case}: {tris:?} budget {budget}\n bound {g} over whole choice {a:?} testing {t}"
                );
            }
        }
    }
}
