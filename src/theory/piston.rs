//! The piston as an oscillator driven by the pressure difference of the two
//! gases (MacKay's question). Each gas is an ideal gas of d-dimensional
//! particles in a free length X (box side minus the length its rods occupy):
//! P X = (2/d) E. Compressed slowly (adiabatically) E X^(2/d) stays fixed,
//! i.e. gamma = (d + 2)/d; isothermally E stays fixed (gamma = 1).

/// One gas: its kinetic energy at the start and its free length then.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gas {
    pub energy: f64,
    pub free_length: f64,
}

/// The piston between two gases in a box of length `length` along x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PistonSystem {
    pub dimension: usize,
    pub mass: f64,
    pub x0: f64,
    pub v0: f64,
    pub left: Gas,
    pub right: Gas,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Law {
    Adiabatic,
    Isothermal,
}

impl PistonSystem {
    fn exponent(&self) -> f64 {
        2.0 / self.dimension as f64
    }

    /// Free lengths when the piston is at x.
    fn lengths(&self, x: f64) -> (f64, f64) {
        (
            self.left.free_length + (x - self.x0),
            self.right.free_length - (x - self.x0),
        )
    }

    /// The gases' potential energy for the piston at x.
    pub fn potential(&self, law: Law, x: f64) -> f64 {
        let (xl, xr) = self.lengths(x);
        if xl <= 0.0 || xr <= 0.0 {
            return f64::INFINITY;
        }
        let a = self.exponent();
        match law {
            Law::Adiabatic => {
                self.left.energy * (self.left.free_length / xl).powf(a)
                    + self.right.energy * (self.right.free_length / xr).powf(a)
            }
            Law::Isothermal => -a * (self.left.energy * xl.ln() + self.right.energy * xr.ln()),
        }
    }

    /// Net force on the piston at x: P_left - P_right.
    fn force(&self, law: Law, x: f64) -> f64 {
        let (xl, xr) = self.lengths(x);
        let a = self.exponent();
        let (el, er) = match law {
            Law::Adiabatic => (
                self.left.energy * (self.left.free_length / xl).powf(a),
                self.right.energy * (self.right.free_length / xr).powf(a),
            ),
            Law::Isothermal => (self.left.energy, self.right.energy),
        };
        a * el / xl - a * er / xr
    }

    fn limits(&self) -> (f64, f64) {
        (
            self.x0 - self.left.free_length,
            self.x0 + self.right.free_length,
        )
    }

    /// Angular frequency of small oscillations about the pressure balance:
    /// omega^2 = gamma P (1/X_L + 1/X_R) / M.
    pub fn small_oscillation_omega(&self, law: Law) -> f64 {
        let (lo, hi) = self.limits();
        let x = bisect(
            |x| self.force(law, x),
            lo + 1e-12 * (hi - lo),
            hi - 1e-12 * (hi - lo),
        );
        let (xl, xr) = self.lengths(x);
        let a = self.exponent();
        let gamma = match law {
            Law::Adiabatic => 1.0 + a,
            Law::Isothermal => 1.0,
        };
        let pressure = match law {
            Law::Adiabatic => a * self.left.energy * (self.left.free_length / xl).powf(a) / xl,
            Law::Isothermal => a * self.left.energy / xl,
        };
        (gamma * pressure * (1.0 / xl + 1.0 / xr) / self.mass).sqrt()
    }

    /// Angular frequency of the full nonlinear oscillation with the piston's
    /// actual starting energy: 2 pi / T with T = 2 integral dx / v(x) between
    /// the turning points, v from energy conservation.
    pub fn omega(&self, law: Law) -> f64 {
        let u0 = self.potential(law, self.x0);
        let energy = 0.5 * self.mass * self.v0 * self.v0 + u0;
        let (lo, hi) = self.limits();
        let excess = |x: f64| self.potential(law, x) - energy;
        if 0.5 * self.mass * self.v0 * self.v0 <= 1e-14 * energy.abs().max(1e-300)
            && self.force(law, self.x0).abs() < 1e-12
        {
            return self.small_oscillation_omega(law);
        }
        let eps = 1e-13 * (hi - lo);
        let left = if excess(self.x0) >= 0.0 {
            self.x0
        } else {
            bisect(excess, lo + eps, self.x0)
        };
        let right = if excess(self.x0) >= 0.0 {
            self.x0
        } else {
            bisect(excess, self.x0, hi - eps)
        };
        // If the piston starts at a turning point, find the other one.
        let (a, b) = if left == right {
            if self.force(law, self.x0) > 0.0 {
                (self.x0, bisect(excess, self.x0 + eps, hi - eps))
            } else {
                (bisect(excess, lo + eps, self.x0 - eps), self.x0)
            }
        } else {
            (left, right)
        };
        // x = c + h sin(theta) removes the inverse-square-root ends.
        let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
        let n = 20_000;
        let mut period = 0.0;
        for k in 0..n {
            let theta =
                -std::f64::consts::FRAC_PI_2 + (k as f64 + 0.5) * std::f64::consts::PI / n as f64;
            let x = c + h * theta.sin();
            let kinetic = (energy - self.potential(law, x)).max(0.0);
            if kinetic > 0.0 {
                period += h * theta.cos() / (2.0 * kinetic / self.mass).sqrt();
            }
        }
        period *= 2.0 * std::f64::consts::PI / n as f64;
        2.0 * std::f64::consts::PI / period
    }
}

/// A root of f between a and b, where f changes sign (bisection to round-off).
fn bisect(f: impl Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if m == a || m == b {
            break;
        }
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m
        } else {
            b = m
        }
    }
    0.5 * (a + b)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn symmetric(v0: f64) -> PistonSystem {
        let gas = Gas {
            energy: 2.5,
            free_length: 5.0,
        };
        PistonSystem {
            dimension: 1,
            mass: 1000.0,
            x0: 6.0,
            v0,
            left: gas,
            right: gas,
        }
    }

    #[test]
    fn small_amplitude_nonlinear_period_matches_the_harmonic_one() {
        let s = symmetric(1e-4);
        let small = s.small_oscillation_omega(Law::Adiabatic);
        // gamma = 3, P = 2E/X = 1: omega^2 = 3 * 1 * (2/5) / 1000.
        assert!((small - (3.0 * 0.4 / 1000.0f64).sqrt()).abs() < 1e-12);
        assert!((s.omega(Law::Adiabatic) / small - 1.0).abs() < 1e-4);
        let iso = s.small_oscillation_omega(Law::Isothermal);
        assert!((small / iso - 3f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn large_amplitude_changes_the_period() {
        let s = symmetric(0.2);
        let (small, full) = (
            s.small_oscillation_omega(Law::Adiabatic),
            s.omega(Law::Adiabatic),
        );
        assert!((full / small - 1.0).abs() > 0.01, "{full} vs {small}");
    }
}
