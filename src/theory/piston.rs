//! The piston as an oscillator driven by the pressure difference of the two
//! gases (MacKay's question), per unit area of the piston's face.
//!
//! Each gas is an ideal gas in its free volume: P V = (2/d) K. Dividing by
//! the face area its centres reach turns volumes into lengths: a gas with
//! kinetic energy K and free length l pushes the piston with
//! F = (2/d) (K / l) dl/da, where a is the length along x its centres can
//! reach (wall to piston, less a radius at each end), and the face area
//! drops out. The free length is l(a) = a - excluded + edge / a: the reach
//! less what the other particles exclude (exact in 1D, Tonks; in 2D and 3D
//! the second virial term in the box, see `analysis::piston_state`). A
//! polytrope K l^(gamma - 1) = const gives the piston a potential energy:
//! adiabatic gamma = (d + 2)/d (K l^(2/d) fixed), isothermal gamma = 1 (K
//! fixed), and collisionless gamma = 3 (in d > 1, a gas whose particles
//! never collide heats only its x-motion, as a 1D gas does).

/// One gas in the state described.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Gas {
    pub energy: f64,
    /// Total mass of the gas's particles (its inertia, see `with_gas_inertia`).
    pub mass: f64,
    /// Length along x its particles' centres can reach.
    pub reach: f64,
    /// Free length l(a) = a - excluded + edge / a (see `free_length`).
    pub excluded: f64,
    pub edge: f64,
}

impl Gas {
    /// Point particles (nothing excluded) with free length `length`.
    pub fn ideal(energy: f64, mass: f64, length: f64) -> Gas {
        Gas {
            energy,
            mass,
            reach: length,
            excluded: 0.0,
            edge: 0.0,
        }
    }

    /// Free length (free volume over the face area) at reach a.
    pub fn free_length(&self, a: f64) -> f64 {
        a - self.excluded + self.edge / a
    }

    /// The free length in the state described.
    pub fn length(&self) -> f64 {
        self.free_length(self.reach)
    }

    /// P V = (2/d) K.
    fn pv(&self, dimension: usize) -> f64 {
        2.0 * self.energy / dimension as f64
    }

    /// Smallest reach the theory squeezes the gas into: where its free
    /// length vanishes (ideal gases, 1D), or, with an edge term, where that
    /// term stops being a small correction: from a = excluded + 3 sqrt(edge)
    /// on, l > 0 and the push falls monotonically with the reach. Far below
    /// any reach a piston with a few kT of energy gets to.
    fn min_reach(&self) -> f64 {
        self.excluded + 3.0 * self.edge.max(0.0).sqrt()
    }

    /// Pressure times face area (force per unit face) at reach a; infinite
    /// where the gas has no room.
    fn push(&self, law: Law, dimension: usize, a: f64) -> f64 {
        let (l0, l) = (self.length(), self.free_length(a));
        if a <= self.min_reach() || l <= 0.0 {
            return f64::INFINITY;
        }
        let g = law.gamma(dimension);
        self.pv(dimension) / l0 * (l0 / l).powf(g) * (1.0 - self.edge / (a * a))
    }

    /// The gas's energy at reach a along the law (the piston's potential).
    fn energy_at(&self, law: Law, dimension: usize, a: f64) -> f64 {
        let (l0, l) = (self.length(), self.free_length(a));
        if a <= self.min_reach() || l <= 0.0 {
            return f64::INFINITY;
        }
        let g = law.gamma(dimension);
        let pv = self.pv(dimension);
        if g == 1.0 {
            -pv * l.ln()
        } else {
            pv / (g - 1.0) * (l0 / l).powf(g - 1.0)
        }
    }

    /// -d push/da: how much harder the gas pushes when squeezed.
    fn stiffness(&self, law: Law, dimension: usize, a: f64) -> f64 {
        let l = self.free_length(a);
        let slope = 1.0 - self.edge / (a * a);
        let p = self.push(law, dimension, a) / slope;
        p * (law.gamma(dimension) * slope * slope / l - 2.0 * self.edge / (a * a * a))
    }
}

/// The piston between two gases, in one state (position x0, speed v0).
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
    Collisionless,
}

impl Law {
    /// gamma = (d + 2)/d for an adiabatic ideal gas in d dimensions, 1
    /// isothermal, 3 collisionless (only the x-motion is compressed).
    pub fn gamma(self, dimension: usize) -> f64 {
        match self {
            Law::Adiabatic => (dimension as f64 + 2.0) / dimension as f64,
            Law::Isothermal => 1.0,
            Law::Collisionless => 3.0,
        }
    }
}

impl PistonSystem {
    /// Reaches (left, right) with the piston at x.
    pub fn reaches(&self, x: f64) -> (f64, f64) {
        let dx = x - self.x0;
        (self.left.reach + dx, self.right.reach - dx)
    }

    /// Free lengths (left, right) with the piston at x.
    pub fn lengths(&self, x: f64) -> (f64, f64) {
        let (al, ar) = self.reaches(x);
        (self.left.free_length(al), self.right.free_length(ar))
    }

    /// The gases' energy as a function of piston position (the piston's
    /// potential); infinite where a gas would have no room.
    pub fn potential(&self, law: Law, x: f64) -> f64 {
        let (al, ar) = self.reaches(x);
        self.left.energy_at(law, self.dimension, al) + self.right.energy_at(law, self.dimension, ar)
    }

    /// Net force on the piston at x (per unit face area, as everything here).
    pub fn force(&self, law: Law, x: f64) -> f64 {
        let (al, ar) = self.reaches(x);
        self.left.push(law, self.dimension, al) - self.right.push(law, self.dimension, ar)
    }

    /// Where the pressures balance. Without edge terms the free lengths
    /// move with x one for one and P l^gamma is fixed on each side, so
    /// l_L/l_R = (l_L0/l_R0) (P_L0/P_R0)^(1/gamma) in closed form; the edge
    /// terms' small shift follows by Newton's method on the force (whose
    /// slope is the stiffness), or by bisection should that stray.
    pub fn balance(&self, law: Law) -> f64 {
        let g = law.gamma(self.dimension);
        let (l, r) = (&self.left, &self.right);
        let (ll, lr) = (l.length(), r.length());
        let pressure = |gas: &Gas, length: f64| gas.pv(self.dimension) / length;
        let ratio = ll / lr * (pressure(l, ll) / pressure(r, lr)).powf(1.0 / g);
        let mut x = self.x0 + (ll + lr) * ratio / (1.0 + ratio) - ll;
        if l.edge == 0.0 && r.edge == 0.0 {
            return x;
        }
        let (lo, hi) = self.limits();
        for _ in 0..50 {
            let next = x + self.force(law, x) / self.stiffness_at(law, x);
            if !(next > lo && next < hi) {
                return bisect(|x| self.force(law, x), lo, hi);
            }
            if (next - x).abs() <= 1e-14 * x.abs().max(1.0) {
                return next;
            }
            x = next;
        }
        bisect(|x| self.force(law, x), lo, hi)
    }

    /// -dF/dx with the piston at x.
    fn stiffness_at(&self, law: Law, x: f64) -> f64 {
        let (al, ar) = self.reaches(x);
        self.left.stiffness(law, self.dimension, al) + self.right.stiffness(law, self.dimension, ar)
    }

    /// Energy of the oscillation: the piston's kinetic energy plus the
    /// potential energy above its minimum (zero at rest at the balance).
    pub fn oscillator_energy(&self, law: Law) -> f64 {
        0.5 * self.mass * self.v0 * self.v0 + self.potential(law, self.x0)
            - self.potential(law, self.balance(law))
    }

    /// The same adiabatic oscillation where it passes the balance: the
    /// piston there with all the oscillator energy as kinetic energy, each
    /// gas moved along its adiabat (K l^(2/d) fixed). The neutral state to
    /// ask another law from: at a turning point one gas is hot and the other
    /// cold only because the swing compressed them.
    pub fn at_balance(&self) -> PistonSystem {
        let x = self.balance(Law::Adiabatic);
        let (al, ar) = self.reaches(x);
        let energy = self.oscillator_energy(Law::Adiabatic).max(0.0);
        let exponent = 2.0 / self.dimension as f64;
        let moved = |gas: Gas, a: f64| Gas {
            energy: gas.energy * (gas.length() / gas.free_length(a)).powf(exponent),
            reach: a,
            ..gas
        };
        PistonSystem {
            x0: x,
            v0: (2.0 * energy / self.mass).sqrt(),
            left: moved(self.left, al),
            right: moved(self.right, ar),
            ..*self
        }
    }

    /// Stiffness -dF/dx of each gas (left, right) at the balance.
    pub fn stiffnesses(&self, law: Law) -> (f64, f64) {
        let (al, ar) = self.reaches(self.balance(law));
        (
            self.left.stiffness(law, self.dimension, al),
            self.right.stiffness(law, self.dimension, ar),
        )
    }

    /// Angular frequency of small oscillations about the pressure balance:
    /// omega^2 = -dF/dx / M, gamma P (1/l_L + 1/l_R) / M for ideal gases.
    pub fn small_oscillation_omega(&self, law: Law) -> f64 {
        let (kl, kr) = self.stiffnesses(law);
        ((kl + kr) / self.mass).sqrt()
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
        let n = 2_000;
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
    /// (Rayleigh's correction for a spring's own mass; in 2D and 3D the same
    /// for the gas's motion along x). That flow energy is part of each gas's
    /// measured kinetic energy but not of its heat, so it moves from the
    /// gases to the oscillator: the state must be one where the gases
    /// already flow with the piston (not a gas at rest behind a piston set
    /// moving). The leading correction to the frequency when M is not much
    /// larger than the gases' mass.
    pub fn with_gas_inertia(&self) -> PistonSystem {
        let flowing = |gas: Gas| Gas {
            energy: gas.energy - gas.mass * self.v0 * self.v0 / 6.0,
            ..gas
        };
        PistonSystem {
            mass: self.mass + (self.left.mass + self.right.mass) / 3.0,
            left: flowing(self.left),
            right: flowing(self.right),
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

    /// Piston positions at which one gas has no room left.
    fn limits(&self) -> (f64, f64) {
        (
            self.x0 + self.left.min_reach() - self.left.reach,
            self.x0 + self.right.reach - self.right.min_reach(),
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
        let gas = Gas::ideal(2.5, 5.0, 5.0);
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

    /// An unbalanced start: the balance is where the force vanishes, on the
    /// side of the cooler gas, and for ideal gases where the closed form
    /// (P V^gamma fixed, total length fixed) puts it:
    /// l_L/l_R = (l_L0/l_R0) (P_L0/P_R0)^(1/gamma).
    #[test]
    fn balance_is_where_the_force_vanishes() {
        let mut s = symmetric(0.0);
        s.left.energy = 7.0;
        for law in [Law::Adiabatic, Law::Isothermal] {
            let x = s.balance(law);
            assert!(x > s.x0, "the hotter left gas pushes the piston right");
            let scale = s.left.pv(1) / s.left.length();
            assert!(s.force(law, x).abs() < 1e-12 * scale, "{law:?}");
            let ratio = (7.0f64 / 2.5).powf(1.0 / law.gamma(1));
            let (ll, lr) = s.lengths(x);
            assert!((ll / lr / ratio - 1.0).abs() < 1e-12, "{law:?}");
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

    /// Adiabatic in 2D: gamma = 2; collisionless: 3, as in 1D.
    #[test]
    fn two_dimensional_gas_has_gamma_two() {
        // Per unit face: K = 10 over free length 5, so P l = (2/2) K = 10.
        let gas = Gas::ideal(10.0, 10.0, 5.0);
        let s = PistonSystem {
            dimension: 2,
            mass: 500.0,
            x0: 5.0,
            v0: 0.0,
            left: gas,
            right: gas,
        };
        assert_eq!(Law::Adiabatic.gamma(2), 2.0);
        // omega^2 = gamma (P l) (1/l^2 + 1/l^2) / M = 2 * 10 * (2/25) / 500.
        let expected = (2.0 * 10.0 * 2.0 / 25.0 / 500.0f64).sqrt();
        assert!((s.small_oscillation_omega(Law::Adiabatic) - expected).abs() < 1e-12);
        let ratio = s.small_oscillation_omega(Law::Collisionless)
            / s.small_oscillation_omega(Law::Adiabatic);
        assert!((ratio - 1.5f64.sqrt()).abs() < 1e-12);
    }

    /// The edge term: the force is the derivative of the potential, and the
    /// stiffness the derivative of the force (central differences).
    #[test]
    fn force_and_stiffness_are_derivatives_with_an_edge_term() {
        let gas = |energy| Gas {
            energy,
            mass: 1.0,
            reach: 10.0,
            excluded: 0.8,
            edge: 0.3,
        };
        let s = PistonSystem {
            dimension: 2,
            mass: 100.0,
            x0: 10.0,
            v0: 0.0,
            left: gas(12.0),
            right: gas(9.0),
        };
        let h = 1e-5;
        for law in [Law::Adiabatic, Law::Isothermal, Law::Collisionless] {
            for x in [8.0, 10.0, 11.5] {
                let dudx = (s.potential(law, x + h) - s.potential(law, x - h)) / (2.0 * h);
                assert!((s.force(law, x) + dudx).abs() < 1e-7, "{law:?} at {x}");
            }
            let c = s.balance(law);
            let k = -(s.force(law, c + h) - s.force(law, c - h)) / (2.0 * h);
            let (kl, kr) = s.stiffnesses(law);
            assert!(
                ((kl + kr) / k - 1.0).abs() < 1e-7,
                "{law:?}: {} vs {k}",
                kl + kr
            );
        }
    }

    /// Moved along its adiabat to the balance, the oscillation is the same:
    /// same oscillator energy, same frequency, no force there.
    #[test]
    fn at_balance_is_the_same_oscillation() {
        let mut s = symmetric(0.0);
        s.left.energy = 4.0;
        s.left.excluded = 0.5;
        s.right.edge = 0.2;
        let b = s.at_balance();
        let e = s.oscillator_energy(Law::Adiabatic);
        assert!((b.oscillator_energy(Law::Adiabatic) / e - 1.0).abs() < 1e-9);
        assert!((b.omega(Law::Adiabatic) / s.omega(Law::Adiabatic) - 1.0).abs() < 1e-6);
        assert!(b.force(Law::Adiabatic, b.x0).abs() < 1e-12);
    }

    #[test]
    fn gas_inertia_lowers_the_frequency_as_a_spring_mass_does() {
        // At a turning point (no flow), only the inertia changes.
        let s = symmetric(0.0);
        let heavy = s.with_gas_inertia();
        let ratio = heavy.small_oscillation_omega(Law::Adiabatic)
            / s.small_oscillation_omega(Law::Adiabatic);
        assert!((ratio - (1000.0 / (1000.0 + 10.0 / 3.0f64)).sqrt()).abs() < 1e-12);
        // Moving, the gases' flow energy moves to the oscillator: the total
        // is the same.
        let s = symmetric(0.05);
        let heavy = s.with_gas_inertia();
        let total = |t: &PistonSystem| 0.5 * t.mass * t.v0 * t.v0 + t.left.energy + t.right.energy;
        assert!((total(&heavy) - total(&s)).abs() < 1e-12);
        assert!(heavy.left.energy < s.left.energy);
    }
}
