//! The successful runs a report is made from, held so that memory does not
//! grow with the number of replicas: every run's scalars, histograms and
//! cost; the full series of the first `KEPT` replicas of each point (the
//! traces and the pictures that show single runs); and, for every point and
//! series, its mean over all the point's replicas at each sample,
//! accumulated as the runs stream past one at a time.

use super::summary::{Stats, t_quantile};
use crate::model::run_output::{RunOutput, Series};
use crate::model::run_spec::RunSpec;
use std::collections::BTreeMap;
use std::ops::Deref;

/// Replicas of each point whose series are kept whole.
pub const KEPT: u32 = 3;

/// The runs, in plan order, and the series means of each point.
#[derive(Debug, Default)]
pub struct Runs {
    runs: Vec<(RunSpec, RunOutput)>,
    means: BTreeMap<(u64, String), Accumulated>,
}

/// Sums at each sample time over the replicas seen so far (runs of a point
/// share their sample times; a shorter record ends the curve). A sample
/// that is not finite is left out of its time's sums.
#[derive(Debug)]
struct Accumulated {
    t: Vec<f64>,
    n: Vec<u64>,
    sum: Vec<f64>,
    /// Welford's running mean and sum of squared deviations.
    running: Vec<f64>,
    ss: Vec<f64>,
}

impl Accumulated {
    fn new(s: &Series) -> Accumulated {
        let len = s.t.len().min(s.value.len());
        Accumulated {
            t: s.t[..len].to_vec(),
            n: vec![0; len],
            sum: vec![0.0; len],
            running: vec![0.0; len],
            ss: vec![0.0; len],
        }
    }

    fn add(&mut self, values: &[f64]) {
        let len = self.sum.len().min(values.len());
        self.t.truncate(len);
        self.n.truncate(len);
        for v in [&mut self.sum, &mut self.running, &mut self.ss] {
            v.truncate(len);
        }
        for (i, &x) in values[..len].iter().enumerate() {
            if !x.is_finite() {
                continue;
            }
            self.n[i] += 1;
            self.sum[i] += x;
            let delta = x - self.running[i];
            self.running[i] += delta / self.n[i] as f64;
            self.ss[i] += delta * (x - self.running[i]);
        }
    }

    /// The times, and the statistics at each (the mean is the plain sum
    /// over n, as `Stats::of` gives it).
    fn curve(&self) -> (Vec<f64>, Vec<Stats>) {
        let mut quantile = (u64::MAX, f64::NAN);
        let stats = (0..self.t.len())
            .map(|i| {
                let n = self.n[i];
                if quantile.0 != n {
                    quantile = (n, t_quantile(n.saturating_sub(1)));
                }
                let mean = if n == 0 {
                    f64::NAN
                } else {
                    self.sum[i] / n as f64
                };
                Stats::from_moments(n, mean, self.ss[i], quantile.1)
            })
            .collect();
        (self.t.clone(), stats)
    }
}

impl Runs {
    /// Take one successful run (in plan order): its series go into its
    /// point's means, and are kept whole only for the first replicas.
    pub fn push(&mut self, spec: RunSpec, mut out: RunOutput) {
        for s in &out.series {
            self.means
                .entry((spec.point_id, s.observable.clone()))
                .or_insert_with(|| Accumulated::new(s))
                .add(&s.value);
        }
        if spec.replica >= KEPT {
            out.series = Vec::new();
        }
        self.runs.push((spec, out));
    }

    /// The mean over every replica of `point` of the series `name` at each
    /// sample time, with its standard error; None if no run of the point
    /// recorded it.
    pub fn mean(&self, point: u64, name: &str) -> Option<(Vec<f64>, Vec<Stats>)> {
        self.means
            .get(&(point, name.to_string()))
            .map(Accumulated::curve)
    }
}

/// Every run, with series only for the first `KEPT` replicas of each point.
impl Deref for Runs {
    type Target = [(RunSpec, RunOutput)];
    fn deref(&self) -> &Self::Target {
        &self.runs
    }
}

impl From<Vec<(RunSpec, RunOutput)>> for Runs {
    fn from(runs: Vec<(RunSpec, RunOutput)>) -> Runs {
        runs.into_iter().collect()
    }
}

impl FromIterator<(RunSpec, RunOutput)> for Runs {
    fn from_iter<I: IntoIterator<Item = (RunSpec, RunOutput)>>(runs: I) -> Runs {
        let mut all = Runs::default();
        for (spec, out) in runs {
            all.push(spec, out);
        }
        all
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accumulated_means_equal_the_statistics_of_all_replicas() {
        let values: Vec<Vec<f64>> = (0..7)
            .map(|r| {
                (0..5)
                    .map(|i| ((r * 7 + i * 3) % 11) as f64 * 0.3)
                    .collect()
            })
            .collect();
        let series = |v: &[f64]| Series {
            observable: "x".into(),
            t: (0..v.len()).map(|i| i as f64).collect(),
            value: v.to_vec(),
        };
        let mut sums = Accumulated::new(&series(&values[0]));
        for (r, v) in values.iter().enumerate() {
            // A shorter record ends the curve.
            sums.add(&v[..if r == 5 { 4 } else { 5 }]);
        }
        // A run whose samples are not finite adds nothing.
        sums.add(&[f64::NAN; 5]);
        let (t, stats) = sums.curve();
        assert_eq!(t, vec![0.0, 1.0, 2.0, 3.0]);
        for (i, s) in stats.iter().enumerate() {
            let column: Vec<f64> = values.iter().map(|v| v[i]).collect();
            let direct = Stats::of(&column);
            assert_eq!((s.n, s.mean), (7, direct.mean));
            assert!((s.std - direct.std).abs() < 1e-14, "{s:?} {direct:?}");
            assert!((s.ci_high - direct.ci_high).abs() < 1e-13);
        }
    }
}
