//! The piston as an oscillator driven by the pressure difference of the two
//! gases (MacKay's question). Each gas is an ideal gas of d-dimensional
//! particles in its free volume V (the volume its particles' centres can
//! reach: in 1D the side's length minus the rods' lengths, Tonks):
//! P V = (2/d) K. A polytrope P V^gamma = const gives the piston a potential
//! energy; adiabatic compression has gamma = (d + 2)/d (K V^(2/d) fixed),
//! isothermal gamma = 1 (K fixed), for contrast.

/// One gas: its kinetic energy and free volume in the state described.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gas {
    pub energy: f64,
    pub free_volume: f64,
    /// Total mass of the gas's particles (its inertia, see `with_gas_inertia`).
    pub mass: f64,
}

impl Gas {
    /// P V = (2/d) K.
    fn pv(&self, dimension: usize) -> f64 {
        2.0 * self.energy / dimension as f64
    }
}

/// The piston between two gases, in one state (position x0, speed v0).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PistonSystem {
    pub dimension: usize,
    pub mass: f64,
    /// Area of the piston's face (1 in 1D): a step dx changes the free
    /// volumes by -+ area dx.
    pub area: f64,
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

impl Law {
    /// gamma = (d + 2)/d for an adiabatic ideal gas in d dimensions, 1 isothermal.
    pub fn gamma(self, dimension: usize) -> f64 {
        match self {
            Law::Adiabatic => (dimension as f64 + 2.0) / dimension as f64,
            Law::Isothermal => 1.0,
        }
    }
}

impl PistonSystem {
    /// Free volumes with the piston at x.
    pub fn volumes(&self, x: f64) -> (f64, f64) {
        let dv = self.area * (x - self.x0);
        (self.left.free_volume + dv, self.right.free_volume - dv)
    }

    /// Pressures (left, right) with the piston at x.
    pub fn pressures(&self, law: Law, x: f64) -> (f64, f64) {
        let g = law.gamma(self.dimension);
        let (vl, vr) = self.volumes(x);
        let p = |gas: &Gas, v: f64| {
            gas.pv(self.dimension) / gas.free_volume * (gas.free_volume / v).powf(g)
        };
        (p(&self.left, vl), p(&self.right, vr))
    }

    /// The gases' energy as a function of piston position (the piston's
    /// potential); infinite where a gas would have no room.
    pub fn potential(&self, law: Law, x: f64) -> f64 {
        let (vl, vr) = self.volumes(x);
        if vl <= 0.0 || vr <= 0.0 {
            return f64::INFINITY;
        }
        let g = law.gamma(self.dimension);
        let u = |gas: &Gas, v: f64| {
            let pv = gas.pv(self.dimension);
            if g == 1.0 {
                -pv * v.ln()
            } else {
                pv / (g - 1.0) * (gas.free_volume / v).powf(g - 1.0)
            }
        };
        u(&self.left, vl) + u(&self.right, vr)
    }

    /// Net force on the piston at x: (P_left - P_right) area.
    pub fn force(&self, law: Law, x: f64) -> f64 {
        let (pl, pr) = self.pressures(law, x);
        (pl - pr) * self.area
    }

    /// Where the pressures balance. With P V^gamma fixed on each side and the
    /// total free volume fixed, V_L/V_R = (V_L0/V_R0) (P_L0/P_R0)^(1/gamma).
    pub fn balance(&self, law: Law) -> f64 {
        let g = law.gamma(self.dimension);
        let (l, r) = (&self.left, &self.right);
        let ratio = (l.free_volume / r.free_volume)
            * (l.pv(self.dimension) / l.free_volume / (r.pv(self.dimension) / r.free_volume))
                .powf(1.0 / g);
        let total = l.free_volume + r.free_volume;
        let vl = total * ratio / (1.0 + ratio);
        self.x0 + (vl - l.free_volume) / self.area
    }

    /// Energy of the oscillation: the piston's kinetic energy plus the
    /// potential energy above its minimum (zero at rest at the balance).
    pub fn oscillator_energy(&self, law: Law) -> f64 {
        0.5 * self.mass * self.v0 * self.v0 + self.potential(law, self.x0)
            - self.potential(law, self.balance(law))
    }

    /// Angular frequency of small oscillations about the pressure balance:
    /// omega^2 = gamma P area^2 (1/V_L + 1/V_R) / M.
    pub fn small_oscillation_omega(&self, law: Law) -> f64 {
        let x = self.balance(law);
        let (vl, vr) = self.volumes(x);
        let (p, _) = self.pressures(law, x);
        let g = law.gamma(self.dimension);
        (g * p * self.area * self.area * (1.0 / vl + 1.0 / vr) / self.mass).sqrt()
    }

    /// Angular frequency of the full nonlinear oscillation with the piston's
    /// actual energy: 2 pi / T with T = 2 integral dx / v(x) between the
    /// turning points, v from energy conservation.
    pub fn omega(&self, law: Law) -> f64 {
        let centre = self.balance(law);
        let floor = self.potential(law, centre);
        let energy = self.oscillator_energy(law);
        // Far below round-off of the potential the period is the harmonic one.
        if energy.is_nan() || energy <= 1e-12 * floor.abs().max(1e-300) {
            return self.small_oscillation_omega(law);
        }
        let excess = |x: f64| self.potential(law, x) - floor - energy;
        let (lo, hi) = self.limits();
        let a = bisect(excess, lo, centre);
        let b = bisect(excess, centre, hi);
        // x = c + h sin(theta) removes the inverse-square-root ends.
        let (c, h) = (0.5 * (a + b), 0.5 * (b - a));
        let n = 20_000;
        let mut period = 0.0;
        for k in 0..n {
            let theta =
                -std::f64::consts::FRAC_PI_2 + (k as f64 + 0.5) * std::f64::consts::PI / n as f64;
            let kinetic = -excess(c + h * theta.sin());
            if kinetic > 0.0 {
                period += h * theta.cos() / (2.0 * kinetic / self.mass).sqrt();
            }
        }
        period *= 2.0 * std::f64::consts::PI / n as f64;
        2.0 * std::f64::consts::PI / period
    }

    /// The same system with the gases' inertia added to the piston's: a gas
    /// compressed uniformly moves with a velocity rising linearly from the
    /// wall to the piston, so its kinetic energy is (m_gas / 3) v^2 / 2
    /// (Rayleigh's correction for a spring's own mass). The leading
    /// correction to the frequency when M is not much larger than the gases' mass.
    pub fn with_gas_inertia(&self) -> PistonSystem {
        PistonSystem {
            mass: self.mass + (self.left.mass + self.right.mass) / 3.0,
            ..*self
        }
    }

    /// The piston's path x(t) under the law's force alone (no dissipation),
    /// from its state (x0, v0), every `dt` up to `duration` (RK4).
    pub fn trajectory(&self, law: Law, duration: f64, dt: f64) -> Vec<(f64, f64)> {
        let accel = |x: f64| self.force(law, x) / self.mass;
        let (mut x, mut v) = (self.x0, self.v0);
        let steps = (duration / dt).ceil().max(0.0) as usize;
        let mut path = Vec::with_capacity(steps + 1);
        path.push((0.0, x));
        for k in 1..=steps {
            let (k1x, k1v) = (v, accel(x));
            let (k2x, k2v) = (v + 0.5 * dt * k1v, accel(x + 0.5 * dt * k1x));
            let (k3x, k3v) = (v + 0.5 * dt * k2v, accel(x + 0.5 * dt * k2x));
            let (k4x, k4v) = (v + dt * k3v, accel(x + dt * k3x));
            x += dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            v += dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
            path.push((k as f64 * dt, x));
        }
        path
    }

    /// Piston positions at which one gas has no free volume left.
    fn limits(&self) -> (f64, f64) {
        (
            self.x0 - self.left.free_volume / self.area,
            self.x0 + self.right.free_volume / self.area,
        )
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
            free_volume: 5.0,
            mass: 5.0,
        };
        PistonSystem {
            dimension: 1,
            mass: 1000.0,
            area: 1.0,
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
        // gamma = 3, P = 2K/X = 1: omega^2 = 3 * 1 * (2/5) / 1000.
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

    /// An unbalanced start: the closed-form balance is where the force vanishes.
    #[test]
    fn balance_is_where_the_force_vanishes() {
        let mut s = symmetric(0.0);
        s.left.energy = 7.0;
        for law in [Law::Adiabatic, Law::Isothermal] {
            let x = s.balance(law);
            assert!(x > s.x0, "the hotter left gas pushes the piston right");
            let scale = s.pressures(law, x).0 * s.area;
            assert!(s.force(law, x).abs() < 1e-12 * scale, "{law:?}");
        }
    }

    /// Released from rest off balance, the piston swings to the turning point
    /// on the other side and back in one period; the oscillator energy is the
    /// potential drop to the balance and is conserved along the path.
    #[test]
    fn trajectory_has_the_quadrature_period_and_conserves_energy() {
        let mut s = symmetric(0.0);
        s.left.energy = 4.0;
        let omega = s.omega(Law::Adiabatic);
        let period = std::f64::consts::TAU / omega;
        let dt = period / 4000.0;
        let path = s.trajectory(Law::Adiabatic, 1.5 * period, dt);
        // Returns to its start (a turning point) after one period.
        let back = path
            .iter()
            .min_by(|a, b| (a.0 - period).abs().total_cmp(&(b.0 - period).abs()))
            .map_or(f64::NAN, |p| p.1);
        let swing = path.iter().map(|p| p.1).fold(f64::MIN, f64::max) - s.x0;
        assert!((back - s.x0).abs() < 1e-6 * swing, "{back} vs {}", s.x0);
        let e0 = s.oscillator_energy(Law::Adiabatic);
        let u0 = s.potential(Law::Adiabatic, s.balance(Law::Adiabatic));
        let far = path.iter().map(|p| p.1).fold(f64::MIN, f64::max);
        assert!((s.potential(Law::Adiabatic, far) - u0 - e0).abs() < 1e-6 * e0);
    }

    /// Adiabatic in 2D: gamma = 2, and the face area enters squared.
    #[test]
    fn two_dimensional_gas_has_gamma_two() {
        let gas = Gas {
            energy: 10.0,
            free_volume: 50.0,
            mass: 10.0,
        };
        let s = PistonSystem {
            dimension: 2,
            mass: 500.0,
            area: 10.0,
            x0: 5.0,
            v0: 0.0,
            left: gas,
            right: gas,
        };
        assert_eq!(Law::Adiabatic.gamma(2), 2.0);
        // P = (2/2) K / V = 0.2; omega^2 = 2 * 0.2 * 100 * (2/50) / 500.
        let expected = (2.0 * 0.2 * 100.0 * 0.04 / 500.0f64).sqrt();
        assert!((s.small_oscillation_omega(Law::Adiabatic) - expected).abs() < 1e-12);
    }

    #[test]
    fn gas_inertia_lowers_the_frequency_as_a_spring_mass_does() {
        let s = symmetric(1e-4);
        let heavy = s.with_gas_inertia();
        let ratio = heavy.small_oscillation_omega(Law::Adiabatic)
            / s.small_oscillation_omega(Law::Adiabatic);
        assert!((ratio - (1000.0 / (1000.0 + 10.0 / 3.0f64)).sqrt()).abs() < 1e-12);
    }
}
