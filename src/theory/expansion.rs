//! Free expansion without collisions: particles start uniform in the left
//! half of a box with walls, with velocities from a known distribution, and
//! never meet. The fraction left of the middle at time t follows exactly
//! from the starting distribution by unfolding the reflections: a particle
//! at u0 with velocity v is at the image of y = u0 + v t folded into
//! [0, L], and it is on the left when y, modulo 2L, lies within L/2 of a
//! multiple of 2L.
//!
//! Coordinates are those of the centres: a disk of radius a moves in
//! [a, L_box - a], so L = L_box - 2a; it started in [a, L_box/2 - a], so
//! u0 is uniform on [0, c] with c = L/2 - a; the middle is at L/2.
//!
//! Two velocity distributions (of v_x; the other axes do not matter):
//! Maxwell's Gaussian, and the Imperial project's momenta uniform in
//! [-p_max, p_max]. The same sum over modes, with other damping, solves the
//! diffusion equation in the same box (`Diffusive`).

use statrs::function::erf::erfc;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// The distribution of v_x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Speeds {
    /// Gaussian with this standard deviation, sqrt(kT / m).
    Maxwell(f64),
    /// Uniform on [-w, w], w = p_max / m.
    Uniform(f64),
}

impl Speeds {
    /// The speed that sets the time scale: the standard deviation, or the
    /// largest speed.
    pub fn scale(&self) -> f64 {
        match *self {
            Speeds::Maxwell(s) | Speeds::Uniform(s) => s,
        }
    }

    /// <v_x^2>: kT / m once the gas has shared its energy.
    pub fn mean_square(&self) -> f64 {
        match *self {
            Speeds::Maxwell(s) => s * s,
            Speeds::Uniform(w) => w * w / 3.0,
        }
    }
}

/// One kind of particle expanding freely.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeExpansion {
    /// Length along x the centres move in (box less a diameter).
    pub length: f64,
    /// The centres start uniform on [0, start] (start <= length / 2).
    pub start: f64,
    pub speeds: Speeds,
}

/// Image sums below this s / L, mode sums above it (Gaussian speeds): both
/// are exact, each converges fast on its side.
const SWITCH: f64 = 0.5;

impl FreeExpansion {
    /// Disks (or rods, spheres) of `radius` in a box `box_length` long along
    /// x, started in its left half, with mass `mass` at temperature `kt`.
    pub fn new(box_length: f64, radius: f64, mass: f64, kt: f64) -> FreeExpansion {
        FreeExpansion::with(box_length, radius, Speeds::Maxwell((kt / mass).sqrt()))
    }

    /// The same with any distribution of v_x.
    pub fn with(box_length: f64, radius: f64, speeds: Speeds) -> FreeExpansion {
        let length = box_length - 2.0 * radius;
        FreeExpansion {
            length,
            start: 0.5 * length - radius,
            speeds,
        }
    }

    /// Fraction of the particles in the left half at time t >= 0.
    pub fn left_fraction(&self, t: f64) -> f64 {
        let s = self.speeds.scale() * t.abs();
        match self.speeds {
            _ if s == 0.0 => 1.0,
            Speeds::Maxwell(_) if s >= SWITCH * self.length => self.by_modes(t),
            _ => self.by_images(t),
        }
    }

    /// The sum over images: the probability that y = u0 + v t lies in an
    /// image interval [2kL - L/2, 2kL + L/2), with u0 uniform on [0, c].
    /// For Gaussian v (spread s = sigma t) in closed form with G(z) = z
    /// Phi(z) + phi(z), the integral of the normal distribution function;
    /// for uniform v on [-w, w] (d = v t uniform on [-s, s], s = w t), the
    /// distribution function of u0 + d is a difference of four parabolas
    /// and only the images within s + c of the start contribute.
    pub fn by_images(&self, t: f64) -> f64 {
        self.below(0.5 * self.length, t)
    }

    /// Probability that the centre is below `z` (0 <= z <= L, in the
    /// centres' coordinates) at time t: the images of [-z, z) modulo 2L,
    /// summed as in `by_images`.
    pub fn below(&self, z: f64, t: f64) -> f64 {
        let (l, c) = (self.length, self.start);
        if z <= 0.0 {
            return 0.0;
        }
        if z >= l {
            return 1.0;
        }
        let s = self.speeds.scale() * t.abs();
        if s == 0.0 {
            return (z / c).min(1.0);
        }
        match self.speeds {
            Speeds::Maxwell(_) => {
                // G(z) = max(z, 0) + G(-|z|): the ramps of an image add up to
                // its overlap with the start [0, c] (the answer at t = 0) and
                // only the tails, G(-|z|), remain, which no term cancels.
                // Images more than 40 s away from [0, c] add less than
                // round-off.
                let reach = 40.0 * s + l;
                let (first, last) = images(l, c, reach);
                let (mut overlap, mut tails) = (0.0, 0.0);
                for k in first..=last {
                    let centre = 2.0 * k as f64 * l;
                    let (a, b) = (centre - z, centre + z);
                    overlap += b.clamp(0.0, c) - a.clamp(0.0, c);
                    tails += tail(b / s) - tail((b - c) / s) - tail(a / s) + tail((a - c) / s);
                }
                (overlap + tails * s) / c
            }
            Speeds::Uniform(_) => {
                // P(u0 + d < x) = [Q(x + s) - Q(x + s - c) - Q(x - s) + Q(x -
                // s - c)] / (2 s c), Q(x) = max(x, 0)^2 / 2.
                let q = |x: f64| 0.5 * x.max(0.0).powi(2);
                let below =
                    |x: f64| (q(x + s) - q(x + s - c) - q(x - s) + q(x - s - c)) / (2.0 * s * c);
                let (first, last) = images(l, c, s + l);
                (first..=last)
                    .map(|k| {
                        let centre = 2.0 * k as f64 * l;
                        below(centre + z) - below(centre - z)
                    })
                    .sum()
            }
        }
    }

    /// The sum over modes: the indicator of the left half, periodic in y
    /// with period 2L, is 1/2 + sum over odd n of (2/(n pi)) sin(n pi/2)
    /// cos(n pi y / L); each mode is damped by the velocities'
    /// characteristic function at k t (exp(-(k s)^2 / 2) for Gaussian ones,
    /// sin(k w t)/(k w t) for uniform ones) and by sin(k c)/(k c) (the
    /// uniform start). Uniform speeds' modes fall off only as 1/n^3: the
    /// sum stops after `MODES` of them (for tests; `by_images` is exact).
    pub fn by_modes(&self, t: f64) -> f64 {
        let st = self.speeds.scale() * t.abs();
        match self.speeds {
            Speeds::Maxwell(_) => {
                let damping = |k: f64| (-0.5 * (k * st).powi(2)).exp();
                modes(self.length, self.start, &damping, &damping)
            }
            // sinc has zeros: stop on its envelope 1 / (k w t), not on it.
            Speeds::Uniform(_) => modes(self.length, self.start, &|k| sinc(k * st), &|k| {
                (1.0 / (k * st)).min(1.0)
            }),
        }
    }

    /// First time the excess over 1/2 falls to 1/e of its start (1/2),
    /// found on a fine grid and refined by bisection.
    pub fn relaxation_time(&self) -> f64 {
        first_below(
            &|t| self.left_fraction(t) - 0.5,
            0.5 / std::f64::consts::E,
            self.length / self.speeds.scale(),
        )
    }
}

/// The same start spreading by diffusion (coefficient `diffusion`) with no
/// flux through the walls: each mode decays as exp(-D k^2 t).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Diffusive {
    pub length: f64,
    pub start: f64,
    pub diffusion: f64,
}

impl Diffusive {
    /// Particles of `radius` in a box `box_length` long, started in its
    /// left half, diffusing with coefficient `diffusion`.
    pub fn new(box_length: f64, radius: f64, diffusion: f64) -> Diffusive {
        let free = FreeExpansion::with(box_length, radius, Speeds::Maxwell(1.0));
        Diffusive {
            length: free.length,
            start: free.start,
            diffusion,
        }
    }

    pub fn left_fraction(&self, t: f64) -> f64 {
        if t <= 0.0 {
            return 1.0;
        }
        let dt = self.diffusion * t;
        let damping = |k: f64| (-dt * k * k).exp();
        modes(self.length, self.start, &damping, &damping)
    }

    /// The first passage of the excess to 1/e of its start; about 0.8
    /// L^2 / (pi^2 D) (the slowest mode's time).
    pub fn relaxation_time(&self) -> f64 {
        if self.diffusion.is_nan() || self.diffusion <= 0.0 {
            return f64::NAN;
        }
        first_below(
            &|t| self.left_fraction(t) - 0.5,
            0.5 / std::f64::consts::E,
            self.length * self.length / (PI * PI * self.diffusion),
        )
    }
}

/// Modes of the odd part of the left-half indicator averaged over the
/// start, each damped by `damping(k)`, until `bound(k)` (a decreasing bound
/// on |damping| from k on) says they add less than round-off, or `MODES`.
const MODES: u64 = 2_000_000;

fn modes(l: f64, c: f64, damping: &dyn Fn(f64) -> f64, bound: &dyn Fn(f64) -> f64) -> f64 {
    let mut sum = 0.5;
    let mut n = 1u64;
    loop {
        let k = n as f64 * PI / l;
        if bound(k) < 1e-18 || n > MODES {
            return sum;
        }
        let d = damping(k);
        let sign = if n % 4 == 1 { 1.0 } else { -1.0 };
        sum += sign * 2.0 / (n as f64 * PI) * sinc(k * c) * d;
        n += 2;
    }
}

/// The images k whose interval [2kL - L/2, 2kL + L/2) comes within `reach`
/// of the start [0, c].
fn images(l: f64, c: f64, reach: f64) -> (i64, i64) {
    (
        ((-reach) / (2.0 * l)).floor() as i64,
        ((c + reach) / (2.0 * l)).ceil() as i64,
    )
}

/// A mixture of kinds (in proportion to their counts): its left fraction
/// and relaxation time.
#[derive(Debug, Clone, PartialEq)]
pub struct Mixture {
    pub kinds: Vec<(FreeExpansion, f64)>,
}

impl Mixture {
    pub fn left_fraction(&self, t: f64) -> f64 {
        let total: f64 = self.kinds.iter().map(|(_, w)| w).sum();
        self.kinds
            .iter()
            .map(|(k, w)| w * k.left_fraction(t))
            .sum::<f64>()
            / total
    }

    pub fn relaxation_time(&self) -> f64 {
        let scale = self
            .kinds
            .iter()
            .map(|(k, _)| k.length / k.speeds.scale())
            .fold(0.0, f64::max);
        first_below(
            &|t| self.left_fraction(t) - 0.5,
            0.5 / std::f64::consts::E,
            scale,
        )
    }
}

/// S(0) = kT dn/dP of hard particles at packing fraction `eta`: the
/// variance of the number in half a closed box over the binomial N/4 (a
/// large box). From the equations of state of Tonks (rods, exact),
/// Henderson (disks) and Carnahan-Starling (spheres); 1 for points.
pub fn compressibility(dimension: usize, eta: f64) -> f64 {
    match dimension {
        1 => (1.0 - eta).powi(2),
        2 => {
            // Henderson: Z = (1 + eta^2/8)/(1 - eta)^2, S(0) = 1/d(eta Z)/d eta.
            let e = eta;
            (1.0 - e).powi(3)
                / ((1.0 + 3.0 * e * e / 8.0) * (1.0 - e) + 2.0 * (e + e.powi(3) / 8.0))
        }
        3 => {
            let e = eta;
            (1.0 - e).powi(4) / (1.0 + 4.0 * e + 4.0 * e * e - 4.0 * e.powi(3) + e.powi(4))
        }
        _ => f64::NAN,
    }
}

/// First t at which `f(t)` falls to `level`, scanning in steps of scale/400
/// up to 100 scales (NaN if it never does), then bisecting.
pub fn first_below(f: &dyn Fn(f64) -> f64, level: f64, scale: f64) -> f64 {
    let step = scale / 400.0;
    let mut lo = 0.0;
    for i in 1..=40_000 {
        let hi = i as f64 * step;
        if f(hi) <= level {
            let mut hi = hi;
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if f(mid) <= level {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return 0.5 * (lo + hi);
        }
        lo = hi;
    }
    f64::NAN
}

/// The normal distribution function.
fn phi_cdf(z: f64) -> f64 {
    0.5 * erfc(-z * FRAC_1_SQRT_2)
}

/// G(-|z|), G(z) = z Phi(z) + phi(z) the integral of Phi from -infinity
/// to z (G(z) = z + G(-z)).
fn tail(z: f64) -> f64 {
    let z = -z.abs();
    let density = (-0.5 * z * z).exp() / (2.0 * PI).sqrt();
    z * phi_cdf(z) + density
}

fn sinc(x: f64) -> f64 {
    if x == 0.0 { 1.0 } else { x.sin() / x }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    fn disks() -> FreeExpansion {
        FreeExpansion::new(40.0, 0.5, 1.0, 1.0)
    }

    #[test]
    fn starts_all_left_and_ends_even() {
        let f = disks();
        assert_eq!(f.left_fraction(0.0), 1.0);
        // Before the fastest particles (within ~8 sigma) reach the middle.
        assert!((f.left_fraction(0.01) - 1.0).abs() < 1e-12);
        assert!((f.left_fraction(1e4) - 0.5).abs() < 1e-12);
        // Point particles filling the half: the mode sum at t -> 0 is the
        // indicator's Fourier series, 1 at the start.
        let points = FreeExpansion::new(10.0, 0.0, 1.0, 1.0);
        assert!((points.by_modes(1e-3) - 1.0).abs() < 1e-3);
    }

    #[test]
    fn images_and_modes_agree() {
        for f in [disks(), FreeExpansion::new(20.0, 0.05, 2.0, 1.5)] {
            for r in [0.1, 0.3, 0.5, 1.0, 2.0] {
                let t = r * f.length / f.speeds.scale();
                let (a, b) = (f.by_images(t), f.by_modes(t));
                // statrs' erfc is good to ~1e-13 relative; the image sum
                // adds a few dozen of its values (mpmath: the modes' sum at
                // s = L/2 is right to 1e-16, the images' to 4e-12).
                assert!((a - b).abs() < 1e-10, "t = {t}: images {a}, modes {b}");
            }
        }
        // Uniform speeds: the modes fall off as 1/n^3, so the sum cut after
        // MODES of them is right to ~1e-12 at these times.
        for f in [
            FreeExpansion::with(40.0, 0.5, Speeds::Uniform(1.0)),
            FreeExpansion::with(20.0, 0.05, Speeds::Uniform(0.3)),
        ] {
            for r in [0.2, 0.5, 1.0, 3.0, 7.3] {
                let t = r * f.length / f.speeds.scale();
                let (a, b) = (f.by_images(t), f.by_modes(t));
                assert!((a - b).abs() < 1e-9, "t = {t}: images {a}, modes {b}");
            }
        }
    }

    /// Monte Carlo of the same particles, reflected wall by wall, for both
    /// velocity distributions: within 4 standard errors of the exact sum.
    #[test]
    fn matches_free_particles_bouncing_between_walls() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let n = 200_000;
        for speeds in [Speeds::Maxwell(1.0), Speeds::Uniform(1.5)] {
            let f = FreeExpansion::with(20.0, 0.5, speeds);
            for t in [3.0, 8.0, 15.0, 40.0] {
                let mut left = 0usize;
                for _ in 0..n {
                    let u0 = f.start * rng.random::<f64>();
                    let (a, b): (f64, f64) = (rng.random(), rng.random());
                    let v = match speeds {
                        // Box-Muller for a Gaussian velocity.
                        Speeds::Maxwell(s) => {
                            s * (-2.0 * (1.0 - a).ln()).sqrt() * (2.0 * PI * b).cos()
                        }
                        Speeds::Uniform(w) => w * (2.0 * a - 1.0),
                    };
                    let mut x = u0 + v * t;
                    // Fold: reflect off 0 and L until inside.
                    while !(0.0..=f.length).contains(&x) {
                        x = if x < 0.0 { -x } else { 2.0 * f.length - x };
                    }
                    left += usize::from(x < 0.5 * f.length);
                }
                let p = left as f64 / n as f64;
                let se = (p * (1.0 - p) / n as f64).sqrt();
                let exact = f.left_fraction(t);
                assert!(
                    (p - exact).abs() < 4.0 * se,
                    "{speeds:?}, t = {t}: Monte Carlo {p} +- {se}, theory {exact}"
                );
            }
        }
    }

    /// Free flight has no time scale but L / w: the relaxation time is
    /// inversely proportional to p_max.
    #[test]
    fn uniform_relaxation_time_is_inverse_in_p_max() {
        let at = |w: f64| FreeExpansion::with(40.0, 0.5, Speeds::Uniform(w)).relaxation_time();
        let tau = at(1.0);
        for w in [0.25, 0.5, 2.0, 4.0] {
            assert!((at(w) * w / tau - 1.0).abs() < 1e-9, "w = {w}");
        }
        // Nothing crosses the middle before the fastest particle can.
        let f = FreeExpansion::with(40.0, 0.5, Speeds::Uniform(1.0));
        let gap = f.length / 2.0 - f.start;
        assert!((f.left_fraction(0.99 * gap) - 1.0).abs() < 1e-12);
        assert!(f.left_fraction(1.01 * gap) < 1.0 - 1e-9);
    }

    /// With points filling the half exactly, the diffusive curve is the
    /// mixing study's step (the same modes), and its time is L^2 / D over
    /// a number.
    #[test]
    fn diffusive_curve_is_the_cosine_series_of_a_step() {
        let d = Diffusive::new(30.0, 0.0, 0.7);
        let tau = super::super::mixing::slowest_mode_time(30.0, 0.7);
        for t in [1.0, 20.0, 100.0, 400.0] {
            let step = super::super::mixing::step_excess(t, tau);
            assert!((d.left_fraction(t) - 0.5 - step).abs() < 1e-12, "t = {t}");
        }
        let ratio = d.relaxation_time() / tau;
        assert!((ratio - super::super::mixing::step_mixing_time(1.0)).abs() < 1e-6);
        let slow = Diffusive::new(30.0, 0.0, 0.35);
        assert!((slow.relaxation_time() / d.relaxation_time() - 2.0).abs() < 1e-9);
    }

    #[test]
    fn compressibility_limits() {
        for d in 1..=3 {
            assert_eq!(compressibility(d, 0.0), 1.0);
            // Dilute: S(0) = 1 - 2 B2 n = 1 - 2^d eta to first order.
            let eta = 1e-6;
            let slope = (1.0 - compressibility(d, eta)) / eta;
            assert!((slope - 2f64.powi(d as i32)).abs() < 1e-4, "{d}D: {slope}");
        }
        // Henderson at eta = 0.2, by a numerical derivative of eta Z.
        let p = |e: f64| e * (1.0 + e * e / 8.0) / (1.0 - e).powi(2);
        let h = 1e-6;
        let s = 2.0 * h / (p(0.2 + h) - p(0.2 - h));
        assert!((compressibility(2, 0.2) - s).abs() < 1e-8);
    }

    #[test]
    fn relaxation_time_is_the_first_passage() {
        let f = disks();
        let tau = f.relaxation_time();
        let level = 0.5 / std::f64::consts::E;
        assert!((f.left_fraction(tau) - 0.5 - level).abs() < 1e-9);
        // Monotone decay: nothing crosses earlier on a fine grid.
        for i in 1..1000 {
            let t = tau * i as f64 / 1000.0;
            assert!(f.left_fraction(t) - 0.5 > level);
        }
        // Slower particles (heavier) take longer in proportion to sqrt(m).
        let heavy = FreeExpansion::new(40.0, 0.5, 4.0, 1.0);
        assert!((heavy.relaxation_time() / tau - 2.0).abs() < 1e-9);
        // A mixture of one kind is that kind.
        let one = Mixture {
            kinds: vec![(f, 3.0)],
        };
        assert!((one.relaxation_time() - tau).abs() < 1e-9);
    }
}
