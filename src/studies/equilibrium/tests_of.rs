//! The statistical tests of one point's replicas: each histogram against
//! its exact finite-N law and its large-N limit, positions against the
//! ordered-rod law, early against late halves. Every replica is set beside
//! its own law (masses are drawn per run); bin errors come from the
//! replicas' spread (`stats::replicas`).

use super::charts::{Name, Runs};
use super::ensemble::Ensemble;
use super::measure::histogram as find;
use crate::model::run_output::RunOutput;
use crate::stats::replicas::{Agreement, fractions, zero_mean};
use crate::theory::maxwell::{MaxwellSpeed, normal_cdf};

/// A bin enters a test when the law puts at least this many counts in it
/// per replica, on average (so that its spread over replicas is near
/// Gaussian).
pub const MIN_EXPECTED: f64 = 20.0;

/// One particle's velocity tests.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Particle {
    /// Engine index and rank from the left (0-based) at the start.
    pub index: usize,
    pub rank: usize,
    /// Mean mass over the replicas.
    pub mass: f64,
    pub exact: Option<Agreement>,
    pub gaussian: Option<Agreement>,
    /// Early half against late half.
    pub halves: Option<Agreement>,
}

#[derive(Debug, Clone, Default, PartialEq)]
pub struct Tests {
    pub particles: Vec<Particle>,
    /// Every rod's position histogram against its order-statistics law,
    /// all ranks' bins in one test.
    pub positions: Option<Agreement>,
    /// Scaled v_x of all particles against the exact law and the Gaussian.
    pub vx_exact: Option<Agreement>,
    pub vx_gaussian: Option<Agreement>,
    /// Scaled speeds against the exact law and Maxwell-Boltzmann.
    pub speed_exact: Option<Agreement>,
    pub speed_mb: Option<Agreement>,
}

/// The probability replica `r`'s law gives the bin [lo, hi].
type Law<'a> = &'a dyn Fn(usize, f64, f64) -> f64;

/// Deviations of each replica's histogram `name(r)` from the law's
/// probabilities `law(r, lo, hi)`, and the bins with enough expected
/// counts; None when a replica lacks the histogram.
fn deviations(runs: &Runs, name: Name, law: Law) -> Option<(Vec<Vec<f64>>, Vec<bool>)> {
    let mut rows = Vec::new();
    let mut expected: Vec<f64> = Vec::new();
    for (r, (_, out)) in runs.iter().enumerate() {
        let h = find(out, &name(r))?;
        let total: f64 = h.count.iter().sum();
        let bins = h.lo.iter().zip(&h.hi);
        let p: Vec<f64> = bins.map(|(a, b)| law(r, *a, *b)).collect();
        if expected.is_empty() {
            expected = vec![0.0; p.len()];
        }
        for (e, p) in expected.iter_mut().zip(&p) {
            *e += p * total;
        }
        let f = fractions(&h.count);
        rows.push(f.iter().zip(&p).map(|(f, p)| f - p).collect());
    }
    let n = runs.len() as f64;
    let keep = expected.iter().map(|e| e / n >= MIN_EXPECTED).collect();
    Some((rows, keep))
}

fn test(runs: &Runs, name: Name, law: Law) -> Option<Agreement> {
    deviations(runs, name, law).and_then(|(rows, keep)| zero_mean(&rows, &keep))
}

pub fn tests_of(runs: &Runs) -> Tests {
    let Some((first, _)) = runs.first() else {
        return Tests::default();
    };
    // Scaled v_x and speeds: each particle's law, averaged over the particles.
    let mixture = |r: usize, law: &dyn Fn(&Ensemble, f64) -> f64| {
        let e = runs[r].0;
        e.balls.iter().map(|b| law(e, b.mass)).sum::<f64>() / e.balls.len() as f64
    };
    let (vx, speed): (Name, Name) = (&|_| "scaled_velocity_x".into(), &|_| "scaled_speed".into());
    let ranked = first.by_rank().into_iter().enumerate();
    Tests {
        particles: ranked
            .filter_map(|(rank, b)| particle(runs, rank, b.index))
            .collect(),
        positions: positions(runs),
        vx_exact: test(runs, vx, &|r, a, b| {
            mixture(r, &|e, m| {
                e.velocity_law(m).probability(a / m.sqrt(), b / m.sqrt())
            })
        }),
        vx_gaussian: test(runs, vx, &|r, a, b| {
            let s = runs[r].0.kt().sqrt();
            normal_cdf(b, 0.0, s) - normal_cdf(a, 0.0, s)
        }),
        speed_exact: test(runs, speed, &|r, a, b| {
            mixture(r, &|e, m| e.speed_law(m).probability(a, b))
        }),
        speed_mb: test(runs, speed, &|r, a, b| {
            let e = runs[r].0;
            MaxwellSpeed {
                kt: e.kt(),
                dimension: e.dimension as f64,
            }
            .probability(a, b)
        }),
    }
}

/// The tests of the particle with engine index `i` (`rank` from the left),
/// if the first replica has its histogram or its halves are tested.
fn particle(runs: &Runs, rank: usize, i: usize) -> Option<Particle> {
    let mass_of = |r: usize| runs[r].0.ball(i).map_or(f64::NAN, |b| b.mass);
    let law = |r: usize| runs[r].0.velocity_law(mass_of(r));
    let exact = |r: usize, a: f64, b: f64| law(r).probability(a, b);
    let gaussian = |r: usize, a: f64, b: f64| {
        let (centre, std) = (law(r).centre, law(r).std());
        normal_cdf(b, centre, std) - normal_cdf(a, centre, std)
    };
    let half = |out: &RunOutput, half: &str| {
        Some(fractions(
            &find(out, &format!("velocity_x_{half}.{i}"))?.count,
        ))
    };
    let differences: Option<Vec<Vec<f64>>> = (runs.iter())
        .map(|(_, out)| {
            let (early, late) = (half(out, "early")?, half(out, "late")?);
            Some(early.iter().zip(&late).map(|(a, b)| a - b).collect())
        })
        .collect();
    let early = deviations(runs, &|_| format!("velocity_x_early.{i}"), &exact);
    let halves = early
        .zip(differences)
        .and_then(|((_, keep), d)| zero_mean(&d, &keep));
    let name = |_: usize| format!("velocity_x.{i}");
    let seen = find(runs[0].1, &name(0)).is_some() || halves.is_some();
    seen.then(|| Particle {
        index: i,
        rank,
        mass: (0..runs.len()).map(mass_of).sum::<f64>() / runs.len() as f64,
        exact: test(runs, &name, &exact),
        gaussian: test(runs, &name, &gaussian),
        halves,
    })
}

/// Every rank's position histogram against its law, in one test.
fn positions(runs: &Runs) -> Option<Agreement> {
    let laws: Option<Vec<_>> = runs.iter().map(|(e, _)| e.rod_laws()).collect();
    let laws = laws?;
    let mut rows: Vec<Vec<f64>> = vec![Vec::new(); runs.len()];
    let mut keep = Vec::new();
    for k in 0..laws.first()?.len() {
        let name = |r: usize| format!("position_x.{}", laws[r][k].0.index);
        let (dev, kept) = deviations(runs, &name, &|r, a, b| laws[r][k].1.probability(a, b))?;
        rows.iter_mut().zip(dev).for_each(|(row, d)| row.extend(d));
        keep.extend(kept);
    }
    zero_mean(&rows, &keep)
}
