//! Free expansion without collisions: particles start uniform in the left
//! half of a box with walls and Maxwellian velocities, and never meet. The
//! fraction left of the middle at time t follows exactly from the starting
//! distribution by unfolding the reflections: a particle at u0 with velocity
//! v is at the image of y = u0 + v t folded into [0, L], and it is on the
//! left when y, modulo 2L, lies within L/2 of a multiple of 2L.
//!
//! Coordinates are those of the centres: a disk of radius a moves in
//! [a, L_box - a], so L = L_box - 2a; it started in [a, L_box/2 - a], so
//! u0 is uniform on [0, c] with c = L/2 - a; the middle is at L/2.

use statrs::function::erf::erfc;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

/// One kind of particle expanding freely.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeExpansion {
    /// Length along x the centres move in (box less a diameter).
    pub length: f64,
    /// The centres start uniform on [0, start] (start <= length / 2).
    pub start: f64,
    /// Standard deviation of v_x: sqrt(kT / m).
    pub spread: f64,
}

/// Image sums below this s / L, mode sums above it: both are exact, each
/// converges fast on its side.
const SWITCH: f64 = 0.5;

impl FreeExpansion {
    /// Disks (or rods, spheres) of `radius` in a box `box_length` long along
    /// x, started in its left half, with mass `mass` at temperature `kt`.
    pub fn new(box_length: f64, radius: f64, mass: f64, kt: f64) -> FreeExpansion {
        let length = box_length - 2.0 * radius;
        FreeExpansion {
            length,
            start: 0.5 * length - radius,
            spread: (kt / mass).sqrt(),
        }
    }

    /// Fraction of the particles in the left half at time t >= 0.
    pub fn left_fraction(&self, t: f64) -> f64 {
        let s = self.spread * t.abs();
        if s == 0.0 {
            1.0
        } else if s < SWITCH * self.length {
            self.by_images(t)
        } else {
            self.by_modes(t)
        }
    }

    /// The sum over images: each image interval [2kL - L/2, 2kL + L/2) of
    /// y = u0 + v t, averaged over u0 uniform on [0, c] and v Gaussian
    /// (spread s = sigma t), in closed form with G(z) = z Phi(z) + phi(z),
    /// the integral of the normal distribution function.
    pub fn by_images(&self, t: f64) -> f64 {
        let (l, c) = (self.length, self.start);
        let s = self.spread * t.abs();
        if s == 0.0 {
            return 1.0;
        }
        // G(z) = max(z, 0) + G(-|z|): the ramps of an image add up to its
        // overlap with the start [0, c] (the answer at t = 0) and only the
        // tails, G(-|z|), remain, which no term cancels. Images more than
        // 40 s away from [0, c] add less than round-off.
        let reach = 40.0 * s + l;
        let first = ((-reach) / (2.0 * l)).floor() as i64;
        let last = ((c + reach) / (2.0 * l)).ceil() as i64;
        let (mut overlap, mut tails) = (0.0, 0.0);
        for k in first..=last {
            let centre = 2.0 * k as f64 * l;
            let (a, b) = (centre - 0.5 * l, centre + 0.5 * l);
            overlap += b.clamp(0.0, c) - a.clamp(0.0, c);
            tails += tail(b / s) - tail((b - c) / s) - tail(a / s) + tail((a - c) / s);
        }
        (overlap + tails * s) / c
    }

    /// The sum over modes: the indicator of the left half, periodic in y
    /// with period 2L, is 1/2 + sum over odd n of (2/(n pi)) sin(n pi/2)
    /// cos(n pi y / L); each mode is damped by exp(-(k s)^2 / 2) (the
    /// Gaussian velocities) and by sin(k c)/(k c) (the uniform start).
    pub fn by_modes(&self, t: f64) -> f64 {
        let (l, c) = (self.length, self.start);
        let s = self.spread * t.abs();
        let mut sum = 0.5;
        let mut n = 1u64;
        loop {
            let k = n as f64 * PI / l;
            let damping = (-0.5 * (k * s).powi(2)).exp();
            if damping < 1e-18 || n > 10_000_000 {
                return sum;
            }
            let sign = if n % 4 == 1 { 1.0 } else { -1.0 };
            sum += sign * 2.0 / (n as f64 * PI) * sinc(k * c) * damping;
            n += 2;
        }
    }

    /// First time the excess over 1/2 falls to 1/e of its start (1/2),
    /// found on a fine grid and refined by bisection.
    pub fn relaxation_time(&self) -> f64 {
        first_below(
            &|t| self.left_fraction(t) - 0.5,
            0.5 / std::f64::consts::E,
            self.length / self.spread,
        )
    }
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
            .map(|(k, _)| k.length / k.spread)
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
fn first_below(f: &dyn Fn(f64) -> f64, level: f64, scale: f64) -> f64 {
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
                let t = r * f.length / f.spread;
                let (a, b) = (f.by_images(t), f.by_modes(t));
                // statrs' erfc is good to ~1e-13 relative; the image sum
                // adds a few dozen of its values (mpmath: the modes' sum at
                // s = L/2 is right to 1e-16, the images' to 4e-12).
                assert!((a - b).abs() < 1e-10, "t = {t}: images {a}, modes {b}");
            }
        }
    }

    #[test]
    fn matches_free_particles_bouncing_between_walls() {
        // Monte Carlo of the same particles, reflected wall by wall.
        let f = FreeExpansion::new(20.0, 0.5, 1.0, 1.0);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(7);
        let n = 200_000;
        for t in [3.0, 8.0, 15.0, 40.0] {
            let mut left = 0usize;
            for _ in 0..n {
                let u0 = f.start * rng.random::<f64>();
                // Box-Muller for a Gaussian velocity.
                let (a, b): (f64, f64) = (rng.random(), rng.random());
                let v = f.spread * (-2.0 * (1.0 - a).ln()).sqrt() * (2.0 * PI * b).cos();
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
                "t = {t}: Monte Carlo {p} +- {se}, theory {exact}"
            );
        }
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
