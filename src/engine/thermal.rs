//! Thermal walls: a particle leaves with a velocity drawn from the wall's
//! flux-weighted Maxwellian, so the normal speed has density
//! (m v / kT) exp(-m v^2 / 2kT) (a Rayleigh law, not a Gaussian) and each
//! tangential component is Gaussian with variance kT / m.

use rand::RngExt;
use rand_chacha::ChaCha8Rng;

/// A standard normal deviate (Box–Muller; one of the pair is enough here).
pub fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    let u: f64 = 1.0 - rng.random::<f64>(); // (0, 1]
    let v: f64 = rng.random::<f64>();
    (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
}

/// New velocity for a particle of inverse mass `inv_mass` leaving a wall at
/// temperature `kt` across axis `axis`, into the box (`inward` = +1 or -1).
pub fn emit<const D: usize>(
    rng: &mut ChaCha8Rng,
    kt: f64,
    inv_mass: f64,
    axis: usize,
    inward: f64,
) -> [f64; D] {
    let scale = (kt * inv_mass).sqrt();
    let mut v = [0.0; D];
    for (k, vk) in v.iter_mut().enumerate() {
        if k == axis {
            let u: f64 = 1.0 - rng.random::<f64>();
            *vk = inward * scale * (-2.0 * u.ln()).sqrt();
        } else {
            *vk = scale * gaussian(rng);
        }
    }
    v
}
