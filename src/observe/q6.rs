//! Steinhardt bond order of spheres (Steinhardt, Nelson & Ronchetti 1983)
//! from the 12 nearest neighbours (nearest periodic image):
//! q6m(j) = (1/12) Σ_k Y6m(r̂_jk), local q6(j) = √(4π/13 Σ_m |q6m(j)|²),
//! and the global Q6 of the same formula over the bond average
//! (1/N) Σ_j q6m(j) (every sphere has 12 bonds, so this is the average over
//! all bonds). A sphere is crystal-like (ten Wolde, Ruiz-Montero & Frenkel
//! 1996) when at least 7 of its 12 bonds are connected: the normalised
//! Σ_m q6m(j) q6m(k)* / (|q6(j)| |q6(k)|) above 0.7. Only a 3D scene has
//! this order: in any other the values are NaN (validation refuses them).

use super::neighbours::{nearest, periodic, points};
use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;
use std::sync::LazyLock;

/// Neighbours per sphere.
pub const NEIGHBOURS: usize = 12;
/// Connected bonds: normalised dot product above this.
const CONNECTED: f64 = 0.7;
/// Crystal-like: at least this many connected bonds.
const CRYSTAL_BONDS: usize = 7;

const NEEDS: &[Need] = &[
    Need::Sampling,
    Need::Dimension(3),
    Need::Neighbours(NEIGHBOURS),
];
const LABEL: &str = "Steinhardt order q6";
const NAMES: [&str; 3] = ["q6.global", "q6.crystal", "q6.local"];

/// The `q6` series: Q6, the crystal-like fraction and the mean local q6 at
/// each sample.
pub struct Q6Series;

/// The `q6` scalars: their time averages.
pub struct Q6;

impl Observable for Q6Series {
    const ENTRY: Entry = Entry {
        name: "q6",
        kind: Kind::Series,
        writes: "q6.<global|crystal|local>",
        label: LABEL,
        unit: "1",
        needs: NEEDS,
        doc: "Steinhardt bond order of spheres from the 12 nearest neighbours (nearest periodic image): global Q6 over all bonds, fraction of crystal-like spheres (at least 7 of 12 bonds with normalised q6·q6* > 0.7), mean local q6",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(Q6Series))
    }
}

impl Observable for Q6 {
    const ENTRY: Entry = Entry {
        name: "q6",
        kind: Kind::Scalars,
        writes: "q6.<global|crystal|local>",
        label: LABEL,
        unit: "1",
        needs: NEEDS,
        doc: "time averages of the `q6` series",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Mean(Box::new(Q6Series))
    }
}

/// Y6m(r̂) for m = 0..6 as (re, im), r̂ = (x, y, z) a unit vector:
/// K_m (d/dz)^m P6(z) (x + iy)^m, which is K_m P6^m(cos θ) e^{imφ} since
/// sin θ e^{iφ} = x + iy; Y6,-m = (-1)^m Y6m* (the phase convention drops
/// out of every sum over m used here).
pub fn harmonics(r: [f64; 3]) -> [(f64, f64); 7] {
    // K_m = √(13/(4π) (6-m)!/(6+m)!), computed once: this runs per bond.
    static NORMS: LazyLock<[f64; 7]> = LazyLock::new(|| {
        let mut factorials = [1.0; 13];
        for n in 1..13 {
            factorials[n] = factorials[n - 1] * n as f64;
        }
        std::array::from_fn(|m| {
            (13.0 / (4.0 * std::f64::consts::PI) * factorials[6 - m] / factorials[6 + m]).sqrt()
        })
    });
    // P6(z) = (231 z⁶ - 315 z⁴ + 105 z² - 5) / 16, lowest power first.
    let mut p = [-5.0, 0.0, 105.0, 0.0, -315.0, 0.0, 231.0].map(|c| c / 16.0);
    let mut w = (1.0, 0.0);
    let mut out = [(0.0, 0.0); 7];
    for (y, k) in out.iter_mut().zip(NORMS.iter()) {
        let q = p.iter().rev().fold(0.0, |acc, c| acc * r[2] + c);
        *y = (k * q * w.0, k * q * w.1);
        // Next m: differentiate P once more, one more factor of x + iy.
        for n in 0..6 {
            p[n] = (n + 1) as f64 * p[n + 1];
        }
        p[6] = 0.0;
        w = (w.0 * r[0] - w.1 * r[1], w.0 * r[1] + w.1 * r[0]);
    }
    out
}

/// Σ over m = -6..6 of a_m b_m*, from the m >= 0 halves (real: the -m
/// terms are the conjugates of the +m ones).
fn dot(a: &[(f64, f64); 7], b: &[(f64, f64); 7]) -> f64 {
    a[0].0 * b[0].0
        + 2.0
            * (1..7)
                .map(|m| a[m].0 * b[m].0 + a[m].1 * b[m].1)
                .sum::<f64>()
}

/// √(4π/13 Σ_m |a_m|²).
fn magnitude(a: &[(f64, f64); 7]) -> f64 {
    (4.0 * std::f64::consts::PI / 13.0 * dot(a, a)).sqrt()
}

/// (Q6, crystal-like fraction, mean local q6) of the points with `k`
/// neighbours each (12 for the observable); NaN unless 3D with more than
/// `k` points.
pub fn order<const D: usize>(
    at: &[[f64; D]],
    size: &[f64; D],
    periodic: &[bool; D],
    k: usize,
) -> [f64; 3] {
    let n = at.len();
    if D != 3 || n <= k {
        return [f64::NAN; 3];
    }
    let bonds = nearest(at, size, periodic, k);
    let q: Vec<[(f64, f64); 7]> = bonds
        .chunks_exact(k)
        .map(|row| {
            let mut sum = [(0.0, 0.0); 7];
            for (_, d) in row {
                let r = (0..D).map(|a| d[a] * d[a]).sum::<f64>().sqrt();
                let y = harmonics([d[0] / r, d[1] / r, d[2] / r]);
                for (s, y) in sum.iter_mut().zip(y) {
                    *s = (s.0 + y.0 / k as f64, s.1 + y.1 / k as f64);
                }
            }
            sum
        })
        .collect();
    let norm: Vec<f64> = q.iter().map(|a| dot(a, a).sqrt()).collect();
    let crystal = bonds
        .chunks_exact(k)
        .enumerate()
        .filter(|(j, row)| {
            let connected = row
                .iter()
                .filter(|(i, _)| dot(&q[*j], &q[*i]) > CONNECTED * norm[*j] * norm[*i])
                .count();
            connected >= CRYSTAL_BONDS
        })
        .count();
    let mut total = [(0.0, 0.0); 7];
    for a in &q {
        for (t, x) in total.iter_mut().zip(a) {
            *t = (t.0 + x.0 / n as f64, t.1 + x.1 / n as f64);
        }
    }
    let local = q.iter().map(magnitude).sum::<f64>() / n as f64;
    [magnitude(&total), crystal as f64 / n as f64, local]
}

impl<const D: usize> Probe<D> for Q6Series {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let at = points(s);
        for x in order(&at, &s.sim_box.size, &periodic(s), NEIGHBOURS) {
            row.push(x);
        }
    }
    fn name(&self, k: usize, _: &Context) -> String {
        NAMES[k].into()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use std::f64::consts::PI;

    fn unit(theta: f64, phi: f64) -> [f64; 3] {
        [
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
            theta.cos(),
        ]
    }

    /// The addition theorem: Σ_m |Y6m|² = 13/(4π) in every direction.
    #[test]
    fn the_harmonics_sum_to_thirteen_over_four_pi() {
        for (theta, phi) in [(0.0, 0.0), (0.3, 1.1), (1.5, -2.0), (2.9, 4.0), (PI, 0.5)] {
            let y = harmonics(unit(theta, phi));
            let sum = dot(&y, &y);
            assert!(
                (sum - 13.0 / (4.0 * PI)).abs() < 1e-12,
                "{theta} {phi}: {sum}"
            );
        }
    }

    /// Each Y6m has unit norm on the sphere, and they are orthogonal:
    /// midpoint sums in cos θ and φ (exact in φ for these frequencies).
    #[test]
    fn the_harmonics_are_orthonormal() {
        let (nz, nphi) = (4000, 16);
        let mut gram = [[0.0; 7]; 7];
        for a in 0..nz {
            let z = -1.0 + (a as f64 + 0.5) * 2.0 / nz as f64;
            for b in 0..nphi {
                let phi = (b as f64 + 0.5) * 2.0 * PI / nphi as f64;
                let y = harmonics(unit(z.acos(), phi));
                let weight = (2.0 / nz as f64) * (2.0 * PI / nphi as f64);
                for m in 0..7 {
                    for l in 0..7 {
                        gram[m][l] += weight * (y[m].0 * y[l].0 + y[m].1 * y[l].1);
                    }
                }
            }
        }
        for m in 0..7 {
            for l in 0..7 {
                let want = if m == l { 1.0 } else { 0.0 };
                assert!(
                    (gram[m][l] - want).abs() < 1e-5,
                    "<Y6{m}, Y6{l}> = {}",
                    gram[m][l]
                );
            }
        }
    }

    /// An `n`³ cubic lattice of spacing 1 with the given basis, in the
    /// periodic box it fills.
    fn lattice(n: usize, basis: &[[f64; 3]]) -> (Vec<[f64; 3]>, [f64; 3]) {
        let mut at = Vec::new();
        for i in 0..n {
            for j in 0..n {
                for k in 0..n {
                    for b in basis {
                        at.push([
                            i as f64 + b[0] + 0.1,
                            j as f64 + b[1] + 0.1,
                            k as f64 + b[2] + 0.1,
                        ]);
                    }
                }
            }
        }
        (at, [n as f64; 3])
    }

    const FCC: [[f64; 3]; 4] = [[0.0; 3], [0.5, 0.5, 0.0], [0.5, 0.0, 0.5], [0.0, 0.5, 0.5]];

    /// FCC: every sphere has q6 = 0.57452 (Steinhardt et al.: 0.575), all
    /// alike, so Q6 is the same and every sphere is crystal-like.
    #[test]
    fn fcc_is_all_crystal_with_its_q6() {
        let (at, size) = lattice(4, &FCC);
        let [global, crystal, local] = order(&at, &size, &[true; 3], NEIGHBOURS);
        assert!((local - 0.574524).abs() < 1e-6, "{local}");
        assert!((global - local).abs() < 1e-12, "{global}");
        assert_eq!(crystal, 1.0);
    }

    /// Simple cubic, with its 6 nearest neighbours (the 12 nearest are not
    /// defined there): q6 = 1/√8 = 0.35355.
    #[test]
    fn simple_cubic_with_six_neighbours() {
        let (at, size) = lattice(4, &[[0.0; 3]]);
        let [global, crystal, local] = order(&at, &size, &[true; 3], 6);
        let want = 1.0 / 8f64.sqrt();
        assert!(
            (local - want).abs() < 1e-12 && (global - want).abs() < 1e-12,
            "{local}"
        );
        // Crystal-like asks 7 connected bonds: more than 6 neighbours give.
        assert_eq!(crystal, 0.0);
    }

    /// Points at random: the 12 bonds of a point go in independent uniform
    /// directions, so <Σ_m |q6m(j)|²> = (13/4π)/12 and a sum over N points
    /// gives N <Q6²> = 1/12 for independent points; bonds two points share
    /// can at most double it. Tested at 4 standard errors at two N (the
    /// 1/√N law). Almost no point is crystal-like: a connected bond needs
    /// a normalised dot of two near-random 13-component vectors above 0.7
    /// (about 2.5 standard deviations), and 7 of 12 of them at once.
    #[test]
    fn random_points_have_order_of_one_over_root_n() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(12);
        for n in [200usize, 1600] {
            let side = (n as f64).cbrt() * 1.5;
            let runs = 30;
            let mut crystal = 0.0;
            let values: Vec<f64> = (0..runs)
                .map(|_| {
                    let at: Vec<[f64; 3]> = (0..n)
                        .map(|_| std::array::from_fn(|_| side * rng.random::<f64>()))
                        .collect();
                    let [global, fraction, _] = order(&at, &[side; 3], &[true; 3], NEIGHBOURS);
                    crystal += fraction / runs as f64;
                    n as f64 * global * global
                })
                .collect();
            let mean = values.iter().sum::<f64>() / runs as f64;
            let sd =
                (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (runs - 1) as f64).sqrt();
            let error = sd / (runs as f64).sqrt();
            assert!(
                mean + 4.0 * error > 1.0 / 12.0 && mean - 4.0 * error < 1.0 / 6.0,
                "N = {n}: N<Q6²> = {mean} ± {error}"
            );
            assert!(crystal < 0.01, "N = {n}: crystal-like fraction {crystal}");
        }
    }
}
