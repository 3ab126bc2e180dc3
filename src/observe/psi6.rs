//! Hexatic bond order of disks (Nelson & Halperin 1979; the hard-disk
//! phases of Bernard & Krauth 2011): for each disk j,
//! ψ6_j = (1/6) Σ_k exp(6 i θ_jk) over its 6 nearest neighbours k (nearest
//! periodic image), and per sample the global |Ψ6| = |(1/N) Σ_j ψ6_j|. In
//! a liquid |Ψ6| falls as 1/√N; in the hexatic and the solid it stays
//! finite. Only a 2D scene has this order: in any other the values are NaN
//! (validation refuses them first).

use super::neighbours::{nearest, periodic, points};
use super::state::{StateIn, StateOut};
use super::{Context, Entry, Kind, Measure, Observable, Part, Probe, Row, Setup};
use crate::engine::{Observer, Snapshot};
use crate::model::need::Need;
use crate::model::run_output::RunOutput;

/// Neighbours per disk.
pub const NEIGHBOURS: usize = 6;

const NEEDS: &[Need] = &[
    Need::Sampling,
    Need::Dimension(2),
    Need::Neighbours(NEIGHBOURS),
];
const LABEL: &str = "hexatic order ψ6";

/// The `psi6` series: |Ψ6| and the mean |ψ6_j| at each sample.
pub struct Psi6Series;

/// The `psi6` scalars: time averages of |Ψ6| and |ψ6_j|, and the
/// susceptibility χ6 = N (<|Ψ6|²> - <|Ψ6|>²).
#[derive(Default)]
pub struct Psi6 {
    /// Sums over samples of |Ψ6|, |Ψ6|² and the mean |ψ6_j|.
    sums: [f64; 3],
    samples: u64,
    disks: f64,
}

impl Observable for Psi6Series {
    const ENTRY: Entry = Entry {
        name: "psi6",
        kind: Kind::Series,
        writes: "psi6.<global|local>",
        label: LABEL,
        unit: "1",
        needs: NEEDS,
        doc: "hexatic order of disks from the 6 nearest neighbours (nearest periodic image): global |Ψ6| = |(1/N) Σ_j ψ6_j|, ψ6_j = (1/6) Σ_k exp(6iθ_jk), and the mean local |ψ6_j|",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(Psi6Series))
    }
}

impl Observable for Psi6 {
    const ENTRY: Entry = Entry {
        name: "psi6",
        kind: Kind::Scalars,
        writes: "psi6.<global|local|susceptibility>",
        label: LABEL,
        unit: "1",
        needs: NEEDS,
        doc: "time averages of the `psi6` series, and the susceptibility χ6 = N (<|Ψ6|²> - <|Ψ6|>²)",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Observer(Box::new(Psi6::default()))
    }
}

/// ψ6_j of every point, as (re, im); None unless 2D with more than 6 points.
pub fn local<const D: usize>(
    at: &[[f64; D]],
    size: &[f64; D],
    periodic: &[bool; D],
) -> Option<Vec<(f64, f64)>> {
    if D != 2 || at.len() <= NEIGHBOURS {
        return None;
    }
    let bonds = nearest(at, size, periodic, NEIGHBOURS);
    let each = bonds.chunks_exact(NEIGHBOURS).map(|row| {
        let (re, im) = row.iter().fold((0.0, 0.0), |(re, im), (_, d)| {
            let (c, s) = sixfold(d[0], d[1]);
            (re + c, im + s)
        });
        (re / NEIGHBOURS as f64, im / NEIGHBOURS as f64)
    });
    Some(each.collect())
}

/// exp(6iθ) of the direction (x, y), without trigonometry: the sixth power
/// of the unit complex number along it.
fn sixfold(x: f64, y: f64) -> (f64, f64) {
    let r = x.hypot(y);
    let (x, y) = (x / r, y / r);
    let (x2, y2) = (x * x - y * y, 2.0 * x * y);
    let (x3, y3) = (x2 * x - y2 * y, x2 * y + y2 * x);
    (x3 * x3 - y3 * y3, 2.0 * x3 * y3)
}

/// (|Ψ6|, mean |ψ6_j|) of the points, NaN where `local` has none.
pub fn order<const D: usize>(at: &[[f64; D]], size: &[f64; D], periodic: &[bool; D]) -> (f64, f64) {
    let Some(psi) = local(at, size, periodic) else {
        return (f64::NAN, f64::NAN);
    };
    let n = psi.len() as f64;
    let (re, im) = psi
        .iter()
        .fold((0.0, 0.0), |(a, b), &(re, im)| (a + re, b + im));
    let mean_local = psi.iter().map(|&(re, im)| re.hypot(im)).sum::<f64>() / n;
    ((re / n).hypot(im / n), mean_local)
}

fn sample_order<const D: usize>(s: &Snapshot<D>) -> (f64, f64, usize) {
    let at = points(s);
    let (global, local) = order(&at, &s.sim_box.size, &periodic(s));
    (global, local, at.len())
}

impl<const D: usize> Probe<D> for Psi6Series {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let (global, local, _) = sample_order(s);
        row.push(global);
        row.push(local);
    }
    fn name(&self, k: usize, _: &Context) -> String {
        ["psi6.global", "psi6.local"][k].into()
    }
}

impl<const D: usize> Observer<D> for Psi6 {
    fn sample(&mut self, s: &Snapshot<D>) {
        let (global, local, n) = sample_order(s);
        for (sum, x) in self.sums.iter_mut().zip([global, global * global, local]) {
            *sum += x;
        }
        self.samples += 1;
        self.disks = n as f64;
    }
}

impl<const D: usize> Measure<D> for Psi6 {
    fn uses_samples(&self) -> bool {
        true
    }
    fn save(&self, out: &mut StateOut) -> bool {
        out.list(&self.sums);
        out.number(self.samples as f64);
        out.number(self.disks);
        true
    }
    fn restore(&mut self, from: &mut StateIn) -> Result<(), String> {
        let sums = from.list()?;
        self.sums = sums
            .try_into()
            .map_err(|_| "psi6: a state of three sums expected".to_string())?;
        self.samples = from.number()? as u64;
        self.disks = from.number()?;
        Ok(())
    }
    fn finish(self: Box<Self>, _: &Context, out: &mut RunOutput) {
        let [g, g2, l] = self.sums.map(|x| x / self.samples as f64);
        out.scalars.push(("psi6.global".into(), g));
        out.scalars.push(("psi6.local".into(), l));
        out.scalars
            .push(("psi6.susceptibility".into(), self.disks * (g2 - g * g)));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// A triangular lattice of spacing 1, `nx` by `ny` (even) points, and
    /// the periodic box it fills.
    fn triangular(nx: usize, ny: usize) -> (Vec<[f64; 2]>, [f64; 2]) {
        let h = 3f64.sqrt() / 2.0;
        let at = (0..ny)
            .flat_map(|j| {
                (0..nx).map(move |i| [i as f64 + 0.5 * (j % 2) as f64 + 0.25, (j as f64 + 0.5) * h])
            })
            .collect();
        (at, [nx as f64, ny as f64 * h])
    }

    #[test]
    fn a_triangular_lattice_has_perfect_order() {
        for (nx, ny) in [(4, 4), (12, 14)] {
            let (at, size) = triangular(nx, ny);
            for psi in local(&at, &size, &[true; 2]).unwrap() {
                assert!((psi.0.hypot(psi.1) - 1.0).abs() < 1e-12, "{psi:?}");
            }
            let (global, mean) = order(&at, &size, &[true; 2]);
            assert!((global - 1.0).abs() < 1e-12 && (mean - 1.0).abs() < 1e-12);
        }
    }

    /// Turning every bond by α turns every ψ6_j by 6α: |Ψ6| stays. A patch
    /// between walls, turned about its centre; its inner disks are perfect.
    #[test]
    fn turning_the_lattice_keeps_its_order() {
        let (patch, _) = triangular(16, 16);
        let size = [40.0, 40.0];
        let turned = |alpha: f64| -> Vec<[f64; 2]> {
            let (c, s) = (alpha.cos(), alpha.sin());
            patch
                .iter()
                .map(|p| {
                    let (x, y) = (p[0] - 8.0, p[1] - 7.0);
                    [20.0 + c * x - s * y, 20.0 + s * x + c * y]
                })
                .collect()
        };
        let (flat, _) = order(&turned(0.0), &size, &[false; 2]);
        for alpha in [0.3, 1.0, 2.5] {
            let at = turned(alpha);
            let (global, _) = order(&at, &size, &[false; 2]);
            assert!((global - flat).abs() < 1e-12, "{alpha}: {global} vs {flat}");
            let inner = 8 * 16 + 8;
            let psi = local(&at, &size, &[false; 2]).unwrap()[inner];
            let angle = psi.1.atan2(psi.0);
            assert!((psi.0.hypot(psi.1) - 1.0).abs() < 1e-12);
            // The phase turns by 6α (mod 2π).
            let turn = (angle - 6.0 * alpha).rem_euclid(std::f64::consts::TAU);
            assert!(
                turn.min(std::f64::consts::TAU - turn) < 1e-9,
                "{alpha}: {angle}"
            );
        }
    }

    /// A rectangular lattice of sides 1 and 2.5: the 6 nearest are ±x at 1
    /// and 2, ±y at 2.5 (next: 2.69), so ψ6_j = (4 - 2)/6 = 1/3 exactly.
    #[test]
    fn a_stretched_lattice_has_its_exact_order() {
        let (nx, ny) = (10, 6);
        let at: Vec<[f64; 2]> = (0..ny)
            .flat_map(|j| (0..nx).map(move |i| [i as f64 + 0.5, 2.5 * (j as f64 + 0.5)]))
            .collect();
        let size = [nx as f64, 2.5 * ny as f64];
        for psi in local(&at, &size, &[true; 2]).unwrap() {
            assert!(
                (psi.0 - 1.0 / 3.0).abs() < 1e-12 && psi.1.abs() < 1e-12,
                "{psi:?}"
            );
        }
    }

    /// Points at random (an ideal gas): |Ψ6| is of order 1/√N. Each ψ6_j
    /// averages 6 independent random phases, so <|ψ6_j|²> = 1/6; bonds two
    /// disks share at most double the sum's variance: N <|Ψ6|²> between
    /// 1/6 and 1/3 in expectation; tested at 4 standard errors, at two N
    /// (the 1/√N law: N <|Ψ6|²> does not grow with N).
    #[test]
    fn random_points_have_order_of_one_over_root_n() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        for n in [200usize, 1600] {
            let side = (n as f64).sqrt() * 1.5;
            let runs = 40;
            let values: Vec<f64> = (0..runs)
                .map(|_| {
                    let at: Vec<[f64; 2]> = (0..n)
                        .map(|_| [side * rng.random::<f64>(), side * rng.random::<f64>()])
                        .collect();
                    let (global, mean) = order(&at, &[side; 2], &[true; 2]);
                    assert!(mean > 0.2 && mean < 0.6, "mean local {mean}");
                    n as f64 * global * global
                })
                .collect();
            let mean = values.iter().sum::<f64>() / runs as f64;
            let sd =
                (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (runs - 1) as f64).sqrt();
            let error = sd / (runs as f64).sqrt();
            assert!(
                mean + 4.0 * error > 1.0 / 6.0 && mean - 4.0 * error < 1.0 / 3.0,
                "N = {n}: N<|Ψ6|²> = {mean} ± {error}"
            );
        }
    }
}
