//! One particle's velocity in the ensemble an elastic hard-particle run
//! actually samples: energy fixed (and momentum, along periodic axes with
//! nothing immovable), positions and velocities independent. Exact at any
//! N; docs/equilibrium.md derives it.
//!
//! With u = sqrt(m/2) (v - V) (V the centre-of-mass velocity) the fixed
//! energy puts u uniformly on a sphere of radius sqrt(E') in the f free
//! dimensions (E' the energy less the centre of mass's). One component of
//! a uniform point on a sphere in f dimensions, over the radius, has density
//! proportional to (1 - t^2)^((f - 3)/2): (1 + t)/2 is Beta((f-1)/2,
//! (f-1)/2). A fixed momentum along x leaves particle i's component in the
//! free subspace with weight 1 - m/M, which shortens its reach.

use statrs::function::beta::{checked_beta_reg, ln_beta};

/// The marginal of one velocity component v: centre + reach * t, with t
/// distributed as (1 - t^2)^((f - 3)/2) on [-1, 1].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VelocityMarginal {
    pub centre: f64,
    pub reach: f64,
    /// Free degrees of freedom f (at least 2).
    pub dof: f64,
}

impl VelocityMarginal {
    /// A component along which momentum is not conserved (walls): mass m,
    /// total kinetic energy E, f degrees of freedom.
    pub fn free(mass: f64, energy: f64, dof: f64) -> VelocityMarginal {
        VelocityMarginal {
            centre: 0.0,
            reach: (2.0 * energy / mass).sqrt(),
            dof,
        }
    }

    /// A component along which the total momentum P is conserved: M the
    /// total mass, E' the kinetic energy less that of the centre of mass's
    /// motion (along every conserved axis).
    pub fn conserved(
        mass: f64,
        total_mass: f64,
        momentum: f64,
        internal_energy: f64,
        dof: f64,
    ) -> VelocityMarginal {
        VelocityMarginal {
            centre: momentum / total_mass,
            reach: (2.0 * internal_energy * (1.0 - mass / total_mass) / mass).sqrt(),
            dof,
        }
    }

    /// Beta(a, a) of (1 + t)/2.
    fn a(&self) -> f64 {
        0.5 * (self.dof - 1.0)
    }

    fn s(&self, v: f64) -> f64 {
        (0.5 * (1.0 + (v - self.centre) / self.reach)).clamp(0.0, 1.0)
    }

    pub fn pdf(&self, v: f64) -> f64 {
        let s = self.s(v);
        if s <= 0.0 || s >= 1.0 {
            return 0.0;
        }
        let a = self.a();
        ((a - 1.0) * (s * (1.0 - s)).ln() - ln_beta(a, a)).exp() / (2.0 * self.reach)
    }

    pub fn cdf(&self, v: f64) -> f64 {
        let a = self.a();
        checked_beta_reg(a, a, self.s(v)).unwrap_or(f64::NAN)
    }

    /// Standard deviation: reach / sqrt(f), i.e. sqrt(kT/m) with kT = 2E/f
    /// (times sqrt(1 - m/M) when momentum is conserved).
    pub fn std(&self) -> f64 {
        self.reach / self.dof.sqrt()
    }

    /// Probability of [lo, hi).
    pub fn probability(&self, lo: f64, hi: f64) -> f64 {
        self.cdf(hi) - self.cdf(lo)
    }
}

/// The marginal of sqrt(m) |v - V| of one particle in d dimensions: its
/// square over scale = 2 E' (1 - m/M) (M infinite without conserved
/// momentum) is Beta(d/2, (f - d)/2), the share of a sphere's squared
/// radius its d components take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedMarginal {
    pub scale: f64,
    pub dimension: f64,
    pub dof: f64,
}

impl SpeedMarginal {
    pub fn cdf(&self, s: f64) -> f64 {
        let x = (s * s / self.scale).clamp(0.0, 1.0);
        checked_beta_reg(0.5 * self.dimension, 0.5 * (self.dof - self.dimension), x)
            .unwrap_or(f64::NAN)
    }

    pub fn pdf(&self, s: f64) -> f64 {
        let x = s * s / self.scale;
        if s <= 0.0 || x >= 1.0 {
            return 0.0;
        }
        let (a, b) = (0.5 * self.dimension, 0.5 * (self.dof - self.dimension));
        let density = ((a - 1.0) * x.ln() + (b - 1.0) * (1.0 - x).ln() - ln_beta(a, b)).exp();
        density * 2.0 * s / self.scale
    }

    pub fn probability(&self, lo: f64, hi: f64) -> f64 {
        self.cdf(hi) - self.cdf(lo)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    fn gauss(rng: &mut ChaCha8Rng) -> f64 {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }

    /// Midpoint rule over [lo, hi] with n steps.
    fn integrate(f: impl Fn(f64) -> f64, lo: f64, hi: f64, n: usize) -> f64 {
        let h = (hi - lo) / n as f64;
        (0..n).map(|i| f(lo + (i as f64 + 0.5) * h)).sum::<f64>() * h
    }

    #[test]
    fn pdf_integrates_to_the_cdf_and_the_variance_is_kt_over_m() {
        for (m, e, f) in [
            (1.0, 5.0, 10.0),
            (4.0, 5.0, 10.0),
            (2.0, 3.0, 4.0),
            (1.0, 50.0, 100.0),
        ] {
            let law = VelocityMarginal::free(m, e, f);
            let a = law.reach;
            assert!((integrate(|v| law.pdf(v), -a, a, 200_000) - 1.0).abs() < 1e-6);
            for x in [-0.7, -0.2, 0.0, 0.3, 0.9] {
                let v = x * a;
                let numeric = integrate(|v| law.pdf(v), -a, v, 200_000);
                assert!((numeric - law.cdf(v)).abs() < 1e-6, "{m} {f} {x}");
            }
            let var = integrate(|v| v * v * law.pdf(v), -a, a, 200_000);
            let kt = 2.0 * e / f;
            assert!((var - kt / m).abs() < 1e-6 * kt / m);
            assert!((law.std() - (kt / m).sqrt()).abs() < 1e-12);
        }
    }

    /// Walls: draw velocities uniformly on the energy shell (a Gaussian
    /// vector in u = sqrt(m/2) v, scaled to |u|^2 = E); the fraction of the
    /// draws below each quantile is the law's, within 4 binomial errors.
    /// Periodic: project the Gaussian vector onto total momentum zero first.
    #[test]
    fn monte_carlo_on_the_energy_shell() {
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let masses = [1.0, 1.3, 2.0, 3.1, 4.0, 6.0, 9.0];
        let energy = 3.5;
        let draws = 40_000;
        for conserved in [false, true] {
            let n = masses.len();
            let total: f64 = masses.iter().sum();
            let dof = if conserved { n - 1 } else { n } as f64;
            let mut below = vec![[0usize; 3]; n];
            let laws: Vec<VelocityMarginal> = masses
                .iter()
                .map(|&m| {
                    if conserved {
                        VelocityMarginal::conserved(m, total, 0.0, energy, dof)
                    } else {
                        VelocityMarginal::free(m, energy, dof)
                    }
                })
                .collect();
            let at = [-0.5, 0.1, 0.8];
            for _ in 0..draws {
                let mut v: Vec<f64> = masses.iter().map(|m| gauss(&mut rng) / m.sqrt()).collect();
                if conserved {
                    let p: f64 = v.iter().zip(&masses).map(|(v, m)| v * m).sum();
                    v.iter_mut().for_each(|v| *v -= p / total);
                }
                let k: f64 = v.iter().zip(&masses).map(|(v, m)| 0.5 * m * v * v).sum();
                let scale = (energy / k).sqrt();
                for i in 0..n {
                    for (j, x) in at.iter().enumerate() {
                        if v[i] * scale < x * laws[i].reach {
                            below[i][j] += 1;
                        }
                    }
                }
            }
            for i in 0..n {
                for (j, x) in at.iter().enumerate() {
                    let p = laws[i].cdf(x * laws[i].reach);
                    let got = below[i][j] as f64 / draws as f64;
                    let se = (p * (1.0 - p) / draws as f64).sqrt();
                    assert!(
                        (got - p).abs() < 4.0 * se,
                        "{conserved} {i} {x}: {got} vs {p}"
                    );
                }
            }
        }
    }

    #[test]
    fn speed_marginal_against_monte_carlo() {
        // 2D, 12 disks of mass 1, walls (f = 24) and periodic (f = 22).
        let mut rng = ChaCha8Rng::seed_from_u64(8);
        let (n, energy, draws) = (12usize, 12.0, 40_000);
        for conserved in [false, true] {
            let dof = if conserved { 2 * (n - 1) } else { 2 * n } as f64;
            let scale = 2.0 * energy * if conserved { 1.0 - 1.0 / n as f64 } else { 1.0 };
            let law = SpeedMarginal {
                scale,
                dimension: 2.0,
                dof,
            };
            let s_max = scale.sqrt();
            assert!((integrate(|s| law.pdf(s), 0.0, s_max, 200_000) - 1.0).abs() < 1e-6);
            let at = [0.5, 1.0, 2.0];
            let mut below = [0usize; 3];
            for _ in 0..draws {
                let mut v: Vec<[f64; 2]> =
                    (0..n).map(|_| [gauss(&mut rng), gauss(&mut rng)]).collect();
                if conserved {
                    for k in 0..2 {
                        let p: f64 = v.iter().map(|v| v[k]).sum::<f64>() / n as f64;
                        v.iter_mut().for_each(|v| v[k] -= p);
                    }
                }
                let kin: f64 = v.iter().map(|v| 0.5 * (v[0] * v[0] + v[1] * v[1])).sum();
                let s = (v[0][0] * v[0][0] + v[0][1] * v[0][1]).sqrt() * (energy / kin).sqrt();
                for (j, x) in at.iter().enumerate() {
                    below[j] += (s < *x) as usize;
                }
            }
            for (j, x) in at.iter().enumerate() {
                let p = law.cdf(*x);
                let got = below[j] as f64 / draws as f64;
                let se = (p * (1.0 - p) / draws as f64).sqrt();
                assert!((got - p).abs() < 4.0 * se, "{conserved} {x}: {got} vs {p}");
            }
        }
    }
}
