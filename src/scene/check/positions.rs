//! Explicit positions: every particle inside the walls and clear of the
//! others and of the piston, with the engine's tolerances (it refuses the
//! same when the run starts). Positions on a periodic axis are folded into
//! the box first, as the builder and the engine fold them.

use crate::model::problem::{Check, bad, compact};
use crate::model::scene::SpeciesSpec;
use crate::scene::slots::Piston;
use crate::scene::space::Space;

/// Closer than this fraction of their contact distance is an overlap.
const OVERLAP: f64 = 1.0 - 1e-10;

pub fn positions<const D: usize>(
    species: &[SpeciesSpec],
    positions: &[Vec<f64>],
    space: &Space<D>,
    piston: Option<Piston>,
) -> Check {
    // Radii particle by particle, species by species (a range at its smallest).
    let radii: Vec<f64> = species
        .iter()
        .flat_map(|sp| std::iter::repeat_n(sp.radius.bounds()[0], sp.count))
        .collect();
    let x: Vec<[f64; D]> = positions
        .iter()
        .map(|p| space.fold(std::array::from_fn(|k| p.get(k).copied().unwrap_or(0.0))))
        .collect();
    for (i, (p, &r)) in x.iter().zip(&radii).enumerate() {
        for k in (0..D).filter(|&k| !space.periodic[k]) {
            let l = space.size[k];
            let slack = 1e-12 * l.max(1.0);
            if p[k] - r < -slack || p[k] + r > l + slack {
                return bad(
                    key(i),
                    format!(
                        "particle {i} at {:?} (radius {}) is outside the box on axis {k}, which \
                         spans [0, {}]",
                        positions[i],
                        compact(r),
                        compact(l)
                    ),
                    Some(
                        "a position is the particle's centre: keep it at least its radius from each wall",
                    ),
                );
            }
        }
    }
    if D == 1 {
        chain(&x, &radii, positions, space, piston)
    } else {
        if let Some(p) = piston {
            for (i, (xi, &r)) in x.iter().zip(&radii).enumerate() {
                let d = (xi[0] - p.x).abs();
                if overlaps(d * d, r + p.half) {
                    return on_piston(i, &positions[i], r, p);
                }
            }
        }
        pairs(&x, &radii, space)
    }
}

fn key(i: usize) -> String {
    format!("scene.placement.positions.{i}")
}

/// Closer than contact, for a squared distance and a contact distance.
fn overlaps(d2: f64, sigma: f64) -> bool {
    sigma > 0.0 && d2 < (sigma * OVERLAP).powi(2)
}

fn overlap(a: usize, b: usize, d: f64, sigma: f64) -> Check {
    bad(
        key(b),
        format!(
            "particles {a} and {b} overlap: their centres are {d:.6} apart but their radii add to {sigma}"
        ),
        Some("place them further apart, or make them smaller"),
    )
}

fn on_piston(i: usize, at: &[f64], r: f64, p: Piston) -> Check {
    bad(
        key(i),
        format!(
            "particle {i} at {at:?} (radius {}) overlaps the piston at x = {} (half thickness {})",
            compact(r),
            compact(p.x),
            compact(p.half)
        ),
        Some("place it clear of the piston, or move the piston"),
    )
}

/// On a line only neighbours can overlap, as the engine's chain sees them:
/// in order along the line (the piston among them), the ends meeting across
/// a periodic boundary.
fn chain<const D: usize>(
    x: &[[f64; D]],
    radii: &[f64],
    positions: &[Vec<f64>],
    space: &Space<D>,
    piston: Option<Piston>,
) -> Check {
    // (position, radius, particle index; None for the piston)
    let mut line: Vec<(f64, f64, Option<usize>)> = x
        .iter()
        .zip(radii)
        .enumerate()
        .map(|(i, (p, &r))| (p[0], r, Some(i)))
        .collect();
    if let Some(p) = piston {
        line.push((p.x, p.half, None));
    }
    line.sort_by(|a, b| a.0.total_cmp(&b.0));
    let n = line.len();
    let wraps = space.periodic[0] && n > 1;
    let pairs = (1..n).map(|k| (k - 1, k, 0.0));
    let across = wraps.then_some((n - 1, 0, space.size[0]));
    for (a, b, shift) in pairs.chain(across) {
        let ((xa, ra, ia), (xb, rb, ib)) = (line[a], line[b]);
        let d = xb + shift - xa;
        if overlaps(d * d, ra + rb) {
            return match (ia, ib, piston) {
                (Some(i), Some(j), _) => overlap(i.min(j), i.max(j), d.abs(), ra + rb),
                (Some(i), None, Some(p)) | (None, Some(i), Some(p)) => {
                    on_piston(i, &positions[i], radii[i], p)
                }
                _ => Ok(()),
            };
        }
    }
    Ok(())
}

/// In 2D and 3D: pairs closer than contact. Particles are counted into
/// cells at least a contact distance wide (and about two per particle at
/// most), so each is compared only with those in its own and the adjacent
/// cells.
fn pairs<const D: usize>(x: &[[f64; D]], radii: &[f64], space: &Space<D>) -> Check {
    let reach = 2.0 * radii.iter().copied().fold(0.0, f64::max);
    if reach <= 0.0 {
        return Ok(());
    }
    let sparse = (space.volume() / (2.0 * x.len() as f64)).powf(1.0 / D as f64);
    let width = reach.max(sparse);
    let n: [usize; D] =
        std::array::from_fn(|k| ((space.size[k] / width).floor() as usize).clamp(1, 1 << 20));
    let cell = |p: &[f64; D]| -> [usize; D] {
        std::array::from_fn(|k| {
            let c = (p[k] / space.size[k] * n[k] as f64).floor().max(0.0) as usize;
            c.min(n[k] - 1)
        })
    };
    let id = |c: &[usize; D]| (0..D).rev().fold(0, |acc, k| acc * n[k] + c[k]);
    // Particles by cell: cell c holds members[start[c]..start[c + 1]].
    let cells: Vec<usize> = x.iter().map(|p| id(&cell(p))).collect();
    let mut start = vec![0usize; n.iter().product::<usize>() + 1];
    for &c in &cells {
        start[c + 1] += 1;
    }
    for c in 1..start.len() {
        start[c] += start[c - 1];
    }
    let mut members = vec![0usize; x.len()];
    let mut next = start.clone();
    for (i, &c) in cells.iter().enumerate() {
        members[next[c]] = i;
        next[c] += 1;
    }
    for (i, xi) in x.iter().enumerate() {
        let home = cell(xi);
        'offsets: for offset in 0..3usize.pow(D as u32) {
            let mut c = home;
            for (k, ck) in c.iter_mut().enumerate() {
                let at = (*ck + (offset / 3usize.pow(k as u32)) % 3) as i64 - 1;
                *ck = match (space.periodic[k], at) {
                    (true, _) => at.rem_euclid(n[k] as i64) as usize,
                    (false, a) if a < 0 || a >= n[k] as i64 => continue 'offsets,
                    (false, a) => a as usize,
                };
            }
            let c = id(&c);
            for &j in &members[start[c]..start[c + 1]] {
                if j >= i {
                    continue;
                }
                let r = space.separation(xi, &x[j]);
                let d2: f64 = r.iter().map(|c| c * c).sum();
                let sigma = radii[i] + radii[j];
                if overlaps(d2, sigma) {
                    return overlap(j, i, d2.sqrt(), sigma);
                }
            }
        }
    }
    Ok(())
}
