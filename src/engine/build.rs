//! Checks a system before it runs: every request that cannot be simulated is
//! refused here, with what to do instead, so the event loop never sees it.

use super::boundary::SimBox;
use super::neighbours::{Neighbourhood, image_shift, separation};
use super::particle::Particle;
use super::vector::{Vector, norm2};

#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct BuildError(pub String);

fn fail<T>(msg: String) -> Result<T, BuildError> {
    Err(BuildError(msg))
}

/// Validate particles and box; fold positions into periodic boxes.
pub fn validate<const D: usize>(
    particles: &mut [Particle<D>],
    sim_box: &SimBox<D>,
) -> Result<(), BuildError> {
    if !(1..=3).contains(&D) {
        return fail(format!("dimension {D} is not supported; use 1, 2 or 3"));
    }
    for (k, &l) in sim_box.size.iter().enumerate() {
        if !(l.is_finite() && l > 0.0) {
            return fail(format!(
                "box length on axis {k} is {l}; it must be a positive finite number"
            ));
        }
    }
    for (i, p) in particles.iter_mut().enumerate() {
        if p.pos.iter().chain(p.vel.iter()).any(|x| !x.is_finite()) {
            return fail(format!(
                "particle {i} has a position or velocity that is not a finite number"
            ));
        }
        if !(p.radius.is_finite() && p.radius >= 0.0) {
            return fail(format!(
                "particle {i} has radius {}; radii must be finite and >= 0",
                p.radius
            ));
        }
        if !(p.inv_mass.is_finite() && p.inv_mass >= 0.0) {
            return fail(format!(
                "particle {i} has mass {}; masses must be > 0 (infinite for immovable)",
                p.mass()
            ));
        }
        if p.is_immovable() && p.vel.iter().any(|&v| v != 0.0) {
            return fail(format!(
                "particle {i} is immovable (infinite mass) but moving; an immovable particle must be at rest, \
                 since two infinite masses meeting (another immovable particle or a wall) has no defined outcome"
            ));
        }
        // A plane spans every axis but 0, where its other coordinates mean nothing.
        for k in 0..if p.is_plane() { 1 } else { D } {
            let l = sim_box.size[k];
            if sim_box.axes[k].is_periodic() {
                p.pos[k] = p.pos[k].rem_euclid(l);
                if p.pos[k] >= l {
                    p.pos[k] = 0.0;
                }
            } else {
                let slack = 1e-12 * l.max(1.0);
                if p.pos[k] - p.radius < -slack || p.pos[k] + p.radius > l + slack {
                    return fail(format!(
                        "particle {i} at {:?} (radius {}) is outside the box on axis {k}, which spans [0, {l}]",
                        p.pos, p.radius
                    ));
                }
            }
        }
    }
    let planes: Vec<usize> = (0..particles.len())
        .filter(|&i| particles[i].is_plane())
        .collect();
    if let Some(&i) = planes.first() {
        if D == 1 {
            return fail(format!(
                "particle {i} is a plane, but in one dimension a piston is an ordinary particle; make it one"
            ));
        }
        if planes.len() > 1 {
            return fail(format!(
                "particles {planes:?} are planes; a system can have one plane (a piston) at most"
            ));
        }
        if sim_box.axes[0].is_periodic() {
            return fail(
                "a plane (piston) slides along axis 0 between walls, but axis 0 is periodic; put walls on axis 0".into(),
            );
        }
        if particles[i].vel[1..].iter().any(|&v| v != 0.0) {
            return fail(format!(
                "plane {i} moves across axis 0 ({:?}); a plane moves along axis 0 only",
                particles[i].vel
            ));
        }
    }
    if D == 1 && particles.windows(2).any(|w| w[1].pos[0] < w[0].pos[0]) {
        return fail("in one dimension particles must be listed from left to right".into());
    }
    Ok(())
}

/// Refuse overlapping pairs (touching is fine: the engine handles contact).
pub fn check_overlaps<const D: usize, N: Neighbourhood<D>>(
    particles: &[Particle<D>],
    sim_box: &SimBox<D>,
    neighbours: &N,
) -> Result<(), BuildError> {
    let shifts: Vec<Vector<D>> = (0..3u32.pow(D as u32))
        .map(|c| image_shift(c as u8, &sim_box.size))
        .collect();
    for (i, p) in particles.iter().enumerate() {
        let overlapping = neighbours.candidates(i).find_map(|(j, image)| {
            let q = &particles[j];
            let r = separation(&p.pos, &q.pos, image, &shifts, N::PLANES);
            let sigma = p.radius + q.radius;
            (j > i && sigma > 0.0 && norm2(&r) < (sigma * (1.0 - 1e-10)).powi(2))
                .then(|| (j, norm2(&r).sqrt(), sigma))
        });
        if let Some((j, d, sigma)) = overlapping {
            return fail(format!(
                "particles {i} and {j} overlap: their centres are {d:.6} apart but their radii add to {sigma}; \
                 place them further apart, use fewer or smaller particles, or grow the packing by compression"
            ));
        }
    }
    Ok(())
}
