//! How much room a gas of hard particles has beside the piston: its free
//! length l(a) = a - excluded + edge / a as a function of its reach a (the
//! length along x its centres can reach), per unit of the face area its
//! centres reach.
//!
//! A particle's centre keeps a radius from every wall and from the piston,
//! so it reaches a = X - 2r along x and L_k - 2r across. The free volume is
//! the N-th root of the configurational integral, Q^(1/N) (so that
//! S = N k ln V_free + (d/2) N k ln T, and the adiabat is K V_free^(2/d)
//! fixed), taken to first order in the pair overlaps:
//! V_free = A - sum over pairs I_ij / (N A), where A is the region the
//! centres reach and I_ij the measure of placements of a pair that overlap
//! (contact distance sigma_ij = r_i + r_j). For a box region with sides L_k,
//! I = integral over |h| < sigma of prod_k (L_k - |h_k|) dh, which is linear
//! in the reach: bulk term (the second virial coefficient) and edge terms
//! (the box's faces cut the excluded regions of particles near them).
//!
//! In 1D this is exact with the edge term dropped: l = X - sum sigma_i
//! (Tonks). In 2D and 3D it is the second virial order; what it leaves out
//! is of order (B2 rho)^2 (the third virial coefficient of disks is 0.782
//! B2^2, the free-volume form gives B2^2) and must be small where it is used.

/// A gas's room beside the piston (see the module notes).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Room {
    /// Mean radius of its particles: its reach is X - 2 radius.
    pub radius: f64,
    /// Face area its centres reach: prod over k > 0 of (L_k - 2 radius); 1 in 1D.
    pub face: f64,
    /// l(a) = a - excluded + edge / a.
    pub excluded: f64,
    pub edge: f64,
}

impl Room {
    /// The room of a gas of particles with these radii in a box whose
    /// lengths across x are `across` (none in 1D).
    pub fn of(radii: &[f64], across: &[f64]) -> Room {
        let n = radii.len();
        let dimension = across.len() + 1;
        let radius = radii.iter().sum::<f64>() / n.max(1) as f64;
        let sides: Vec<f64> = across.iter().map(|l| l - 2.0 * radius).collect();
        let face: f64 = sides.iter().product();
        // I(a) = a P - Q summed over pairs.
        let (mut p, mut q) = (0.0, 0.0);
        for i in 0..n {
            for j in i + 1..n {
                let (pi, qi) = overlap(dimension, radii[i] + radii[j], &sides);
                p += pi;
                q += qi;
            }
        }
        let per = if n == 0 {
            0.0
        } else {
            1.0 / (n as f64 * face * face)
        };
        Room {
            radius,
            face,
            excluded: p * per,
            // Tonks: the exact 1D free length has no edge term.
            edge: if dimension == 1 { 0.0 } else { q * per },
        }
    }
}

/// The overlap measure of a pair with contact distance sigma in a box region
/// of reach a along x and sides `across`: I = a P - Q; returns (P, Q).
/// prod_k (L_k - |h_k|) expands over the subsets S of axes with a factor |h_k|:
/// P collects those without x, Q (negated) those with it.
fn overlap(dimension: usize, sigma: f64, across: &[f64]) -> (f64, f64) {
    let (mut p, mut q) = (0.0, 0.0);
    for subset in 0u32..(1 << across.len()) {
        let size = subset.count_ones() as usize;
        let rest: f64 = (0..across.len())
            .filter(|k| subset & (1 << k) == 0)
            .map(|k| across[k])
            .product();
        let sign = if size.is_multiple_of(2) { 1.0 } else { -1.0 };
        p += sign * moment(dimension, size, sigma) * rest;
        q += sign * moment(dimension, size + 1, sigma) * rest;
    }
    (p, q)
}

/// The integral of |h_1| |h_2| ... |h_j| (j of the d coordinates) over the
/// d-ball of radius sigma.
fn moment(dimension: usize, j: usize, sigma: f64) -> f64 {
    use std::f64::consts::PI;
    let s = sigma;
    match (dimension, j) {
        (1, 0) => 2.0 * s,
        (1, 1) => s * s,
        (2, 0) => PI * s * s,
        (2, 1) => 4.0 / 3.0 * s.powi(3),
        (2, 2) => 0.5 * s.powi(4),
        (3, 0) => 4.0 / 3.0 * PI * s.powi(3),
        (3, 1) => 0.5 * PI * s.powi(4),
        (3, 2) => 8.0 / 15.0 * s.powi(5),
        (3, 3) => s.powi(6) / 6.0,
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};

    /// 1D: the Tonks free length X - sum sigma_i, whatever the radii.
    #[test]
    fn one_dimension_is_tonks() {
        let radii = [0.5, 0.2, 0.3, 0.0];
        let room = Room::of(&radii, &[]);
        let x = 12.0;
        let reach = x - 2.0 * room.radius;
        let tonks = x - radii.iter().map(|r| 2.0 * r).sum::<f64>();
        assert!((reach - room.excluded + room.edge / reach - tonks).abs() < 1e-12);
        assert_eq!(room.face, 1.0);
    }

    /// Disks: the bulk term is the second virial coefficient pi sigma^2 / 2
    /// per pair and particle, (N - 1) pi sigma^2 / 2 over the face.
    #[test]
    fn disks_exclude_their_second_virial_area() {
        let room = Room::of(&[0.5; 5], &[41.0]);
        let face = 40.0;
        assert_eq!(room.face, face);
        // P = pi sigma^2 b - (4/3) sigma^3, per pair; 10 pairs over N b^2.
        let p = std::f64::consts::PI * face - 4.0 / 3.0;
        assert!((room.excluded - 10.0 * p / (5.0 * face * face)).abs() < 1e-12);
        let q = 4.0 / 3.0 * face - 0.5;
        assert!((room.edge - 10.0 * q / (5.0 * face * face)).abs() < 1e-12);
    }

    /// The overlap measure of a pair in a rectangle and in a box, against a
    /// Monte Carlo count of overlapping placements (seeded; 4 standard errors).
    #[test]
    fn overlap_measure_matches_a_count() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
        for sides in [vec![3.0, 2.0], vec![3.0, 2.0, 2.5]] {
            let d = sides.len();
            let sigma = 0.8;
            let (p, q) = overlap(d, sigma, &sides[1..]);
            let exact = sides[0] * p - q;
            let draws = 400_000;
            let hits = (0..draws)
                .filter(|_| {
                    let r2: f64 = sides
                        .iter()
                        .map(|l| (l * rng.random::<f64>() - l * rng.random::<f64>()).powi(2))
                        .sum();
                    r2 < sigma * sigma
                })
                .count() as f64;
            let volume: f64 = sides.iter().product();
            let f = hits / draws as f64;
            let estimate = f * volume * volume;
            let se = (f * (1.0 - f) / draws as f64).sqrt() * volume * volume;
            assert!(
                (estimate - exact).abs() < 4.0 * se,
                "{d}D: {exact} vs {estimate} +- {se}"
            );
        }
    }
}
