//! The elastic collision along the line of centres, written with inverse
//! masses (MacKay's `collide`) so that an infinitely massive partner needs no
//! special case: each particle's velocity along the line is reflected in the
//! centre-of-mass frame.

use super::vector::{Vector, dot};

/// Velocity changes of a colliding pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounce<const D: usize> {
    pub dv_i: Vector<D>,
    pub dv_j: Vector<D>,
    /// Impulse given to `i` (the impulse on `j` is its negative).
    pub impulse_i: Vector<D>,
}

/// Collide `i` and `j` whose centres are joined by the unit vector `n` (from i
/// to j). Returns None for a receding or grazing pair, which must never be
/// collided (the seeds' sticking bug).
#[inline(always)]
pub fn bounce<const D: usize>(
    v_i: &Vector<D>,
    v_j: &Vector<D>,
    inv_mass_i: f64,
    inv_mass_j: f64,
    n: &Vector<D>,
) -> Option<Bounce<D>> {
    let approach: Vector<D> = std::array::from_fn(|k| v_i[k] - v_j[k]);
    let u = dot(&approach, n);
    let total = inv_mass_i + inv_mass_j;
    if u <= 0.0 || total == 0.0 {
        return None;
    }
    // Impulse magnitude 2 u mu with reduced mass mu = 1 / (1/m_i + 1/m_j).
    let j = 2.0 * u / total;
    Some(Bounce {
        dv_i: std::array::from_fn(|k| -inv_mass_i * j * n[k]),
        dv_j: std::array::from_fn(|k| inv_mass_j * j * n[k]),
        impulse_i: std::array::from_fn(|k| -j * n[k]),
    })
}

/// When two spheres with separation `r` (from i to j) and relative velocity
/// `v = v_j - v_i` first touch at distance `sigma`: the time from now, or None
/// if they never do. A pair that round-off left overlapping but approaching
/// collides now; a receding pair never collides (Bannerman et al. 2014).
#[inline(always)]
pub fn contact_time<const D: usize>(r: &Vector<D>, v: &Vector<D>, sigma: f64) -> Option<f64> {
    contact_time_before(r, v, sigma, f64::INFINITY)
}

/// `contact_time`, but only if it comes before `limit`: a prediction that
/// already has an earlier event can skip the square root and the division
/// for most partners, since the time is at least c / (2|b|).
#[inline(always)]
pub fn contact_time_before<const D: usize>(
    r: &Vector<D>,
    v: &Vector<D>,
    sigma: f64,
    limit: f64,
) -> Option<f64> {
    let b = dot(r, v);
    if b >= 0.0 {
        return None;
    }
    let c = dot(r, r) - sigma * sigma;
    if c <= 0.0 {
        return Some(0.0);
    }
    if c >= -2.0 * b * limit {
        return None;
    }
    let v2 = dot(v, v);
    let disc = b * b - v2 * c;
    if disc <= 0.0 {
        return None;
    }
    // The cancellation-free root: c / (-b + sqrt(disc)) rather than (-b - sqrt(disc)) / v2.
    Some(c / (-b + disc.sqrt()))
}

/// On a line the order of particles never changes, so which side the partner
/// is on (`dir` = +1 right, -1 left) is known exactly, even when round-off has
/// put two point rods a hair past each other. Time until contact, or None if
/// they are not closing.
#[inline(always)]
pub fn line_contact_time(
    gap_vector: f64,
    closing_velocity: f64,
    dir: f64,
    sigma: f64,
) -> Option<f64> {
    let closing = dir * closing_velocity;
    if closing <= 0.0 {
        return None;
    }
    Some((dir * gap_vector - sigma).max(0.0) / closing)
}
