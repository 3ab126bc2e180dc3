//! A collisionless gas between two thermal walls at T_w across x (any other
//! axes periodic), started as a uniform Maxwellian at T0: each particle
//! keeps its velocity until it first reaches a wall, then carries the
//! velocity a wall emitted until the next. Exact for point particles, the
//! dilute limit (Kn -> infinity) of the relaxation. docs/heat.md derives it.
//!
//! Per particle, with free length L (the centres' range along x):
//! - the first hit comes at t1 = U L / |v_x|, U uniform: until then the
//!   particle has its starting energy;
//! - after an emission at time 0 its expected energy h(t) obeys the renewal
//!   equation h(t) = a(t) + int_0^t h(t - s) dF(s), with F the law of a
//!   flight time L / u (u the emitted normal speed, a Rayleigh law) and
//!   a(t) = E[energy; flight longer than t];
//! - so E(t) = A0(t) + int_0^t h(t - s) dG(s), G the law of t1 and
//!   `A0(t) = E[starting energy; t1 > t]`.

/// Mean energy per particle at times 0, dt, 2 dt, ... (`steps` + 1 values),
/// the renewal equation solved on that grid (error O(dt)).
#[derive(Debug, Clone, PartialEq)]
pub struct FreeRelaxation {
    pub dt: f64,
    pub energy: Vec<f64>,
}

/// Half-normal quadrature nodes for |v_x| of a Maxwellian at `kt`:
/// (speed, weight), trapezoid over [0, 9 sd].
fn half_normal(kt: f64, mass: f64) -> Vec<(f64, f64)> {
    let sd = (kt / mass).sqrt();
    let n = 4000;
    let h = 9.0 * sd / n as f64;
    (0..=n)
        .map(|i| {
            let v = i as f64 * h;
            let density =
                2.0 / (sd * (2.0 * std::f64::consts::PI).sqrt()) * (-0.5 * (v / sd).powi(2)).exp();
            let end = if i == 0 || i == n { 0.5 } else { 1.0 };
            (v, density * h * end)
        })
        .collect()
}

impl FreeRelaxation {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        dimension: usize,
        length: f64,
        mass: f64,
        wall: f64,
        start: f64,
        dt: f64,
        steps: usize,
    ) -> FreeRelaxation {
        let tangential = (dimension as f64 - 1.0) / 2.0;
        let nodes = half_normal(start, mass);
        // G(s) = P(t1 <= s) = E[min(1, |v| s / L)].
        let g = |s: f64| -> f64 {
            nodes
                .iter()
                .map(|&(v, w)| w * (v * s / length).min(1.0))
                .sum()
        };
        // A0(t) = E[(m v^2/2 + tangential kT0) max(0, 1 - |v| t / L)].
        let a0 = |t: f64| -> f64 {
            nodes
                .iter()
                .map(|&(v, w)| {
                    w * (0.5 * mass * v * v + tangential * start) * (1.0 - v * t / length).max(0.0)
                })
                .sum()
        };
        // Emitted normal speed u: P(u < c) = 1 - exp(-w_c), w_c = m c^2 / 2 kT_w;
        // a flight lasts L/u, so P(flight > t) = P(u < L/t).
        let a = |t: f64| -> f64 {
            if t <= 0.0 {
                return wall * (1.0 + tangential);
            }
            let wc = mass * (length / t).powi(2) / (2.0 * wall);
            let e = (-wc).exp();
            wall * (1.0 - (1.0 + wc) * e) + tangential * wall * (1.0 - e)
        };
        let f = |s: f64| -> f64 {
            if s <= 0.0 {
                0.0
            } else {
                (-mass * length * length / (2.0 * wall * s * s)).exp()
            }
        };
        let at = |k: usize| k as f64 * dt;
        // Probabilities of a flight (p) and of a first hit (q) in each step,
        // taken to end at its midpoint's grid point.
        let p: Vec<f64> = (0..=steps)
            .map(|j| if j == 0 { 0.0 } else { f(at(j)) - f(at(j - 1)) })
            .collect();
        let q: Vec<f64> = (0..=steps)
            .map(|j| if j == 0 { 0.0 } else { g(at(j)) - g(at(j - 1)) })
            .collect();
        let mut h = vec![0.0; steps + 1];
        for k in 0..=steps {
            let renewed: f64 = (1..=k).map(|j| p[j] * h[k - j]).sum();
            h[k] = a(at(k)) + renewed;
        }
        let energy = (0..=steps)
            .map(|k| a0(at(k)) + (1..=k).map(|j| q[j] * h[k - j]).sum::<f64>())
            .collect();
        FreeRelaxation { dt, energy }
    }

    /// Mean energy per particle at time `t` (linear between grid points;
    /// NaN beyond the grid).
    pub fn energy_at(&self, t: f64) -> f64 {
        let x = t / self.dt;
        let k = x.floor() as usize;
        if k + 1 >= self.energy.len() {
            return if k + 1 == self.energy.len() {
                self.energy[k]
            } else {
                f64::NAN
            };
        }
        let w = x - k as f64;
        self.energy[k] * (1.0 - w) + self.energy[k + 1] * w
    }

    /// First time the excess energy falls to 1/e of its start.
    pub fn relaxation_time(&self, equilibrium: f64) -> f64 {
        let e0 = self.energy[0] - equilibrium;
        let level = e0 / std::f64::consts::E;
        for k in 1..self.energy.len() {
            let (a, b) = (
                self.energy[k - 1] - equilibrium,
                self.energy[k] - equilibrium,
            );
            if (b - level) * e0.signum() <= 0.0 {
                return (k as f64 - 1.0 + (a - level) / (a - b)) * self.dt;
            }
        }
        f64::NAN
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn walls_at_the_gas_temperature_change_nothing() {
        // An equilibrium gas stays at kT per particle (2D) at every time.
        let r = FreeRelaxation::new(2, 10.0, 1.0, 1.0, 1.0, 0.05, 2000);
        for e in &r.energy {
            assert!((e - 1.0).abs() < 5e-3, "{e}");
        }
    }

    #[test]
    fn a_hot_gas_cools_to_the_walls_with_the_exact_first_slope() {
        let (l, tw, t0) = (20.0, 1.0, 2.0);
        let r = FreeRelaxation::new(2, l, 1.0, tw, t0, 0.02, 20000);
        assert!((r.energy[0] - t0).abs() < 1e-6);
        // Late: toward the wall's equilibrium, kT_w per particle in 2D, but
        // slowly: particles with v_x -> 0 take ever longer to reach a wall
        // (an algebraic tail).
        let (e100, e390) = (r.energy_at(100.0) - tw, r.energy_at(390.0) - tw);
        assert!(
            0.0 < e390 && e390 < 0.5 * e100 && e100 < 0.1,
            "{e100} {e390}"
        );
        // Early: per particle, (2/L) sqrt(kT0 / 2 pi m) hits per unit time
        // each moving (3/2)(T_w - T0).
        let rate = 2.0 / l * (t0 / (2.0 * std::f64::consts::PI)).sqrt() * 1.5 * (tw - t0);
        let slope = (r.energy_at(0.2) - r.energy[0]) / 0.2;
        assert!((slope / rate - 1.0).abs() < 0.02, "{slope} {rate}");
        assert!(r.relaxation_time(tw) > 0.0);
    }
}
