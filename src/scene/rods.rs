//! Random rods on a line, exactly uniform over all non-overlapping
//! configurations in which every rod lies in its own region and clear of an
//! obstacle (the 1D piston).
//!
//! Rods that share a segment of free line are placed together: for labelled
//! rods of total length W on a segment of length L, every ordering has the
//! same configuration volume, (L - W)^n / n!, so a uniformly random order
//! followed by n uniform gaps (sorted uniforms in [0, L - W]) is exact. Groups
//! whose regions do not overlap are independent. Anything else (regions that
//! overlap without being equal, a region the obstacle splits in two) is
//! sampled exactly by rejection from the joint placement on the union of the
//! regions, and refused with a clear error when that is hopeless.

use super::space::Slot;
use rand::RngExt;
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

/// Proposals tried before a tangled placement is refused.
const TRIES: usize = 100_000;

pub fn place(
    slots: &[Slot<1>],
    obstacle: Option<[f64; 2]>,
    names: &[String],
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; 1]>, String> {
    let mut out = vec![[0.0]; slots.len()];
    for cluster in clusters(slots) {
        let (lo, hi) = hull(slots, &cluster);
        let blocked = obstacle.filter(|&[a, b]| a < hi && b > lo);
        let shared = cluster
            .iter()
            .all(|&i| slots[i].same_region(&slots[cluster[0]]));
        // An obstacle that only trims an end of a shared region leaves one segment.
        let segment = match blocked {
            _ if !shared => None,
            None => Some((lo, hi)),
            Some([a, b]) if a <= lo => Some((b, hi)),
            Some([a, b]) if b >= hi => Some((lo, a)),
            Some(_) => None,
        };
        let (n, w) = totals(slots, &cluster);
        let (from, to) = segment.unwrap_or((lo, hi));
        let taken = match (segment, blocked) {
            (None, Some([a, b])) => b.min(hi) - a.max(lo),
            _ => 0.0,
        };
        if w > to - from - taken {
            return Err(format!(
                "{n} rods of total length {w} do not fit in [{from}, {to}]{}; use fewer or shorter rods or a longer box",
                if blocked.is_some() {
                    " beside the piston"
                } else {
                    ""
                }
            ));
        }
        let x = match segment {
            Some((from, to)) => line_up(slots, &cluster, from, to, rng),
            None => by_rejection(slots, &cluster, (lo, hi), obstacle, rng),
        }
        .ok_or_else(|| tangled(slots, &cluster, obstacle, shared, names))?;
        for (&i, xi) in cluster.iter().zip(x) {
            out[i] = [xi];
        }
    }
    Ok(out)
}

/// Sets of rods whose regions overlap, directly or through others.
fn clusters(slots: &[Slot<1>]) -> Vec<Vec<usize>> {
    let mut order: Vec<usize> = (0..slots.len()).collect();
    order.sort_by(|&a, &b| slots[a].lo[0].total_cmp(&slots[b].lo[0]).then(a.cmp(&b)));
    let mut out: Vec<Vec<usize>> = Vec::new();
    let mut reach = f64::NEG_INFINITY;
    for i in order {
        let s = &slots[i];
        match out.last_mut() {
            Some(c) if s.lo[0] < reach => {
                c.push(i);
                reach = reach.max(s.hi[0]);
            }
            _ => {
                out.push(vec![i]);
                reach = s.hi[0];
            }
        }
    }
    for c in &mut out {
        c.sort_unstable();
    }
    out
}

fn hull(slots: &[Slot<1>], members: &[usize]) -> (f64, f64) {
    members
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &i| {
            (a.min(slots[i].lo[0]), b.max(slots[i].hi[0]))
        })
}

fn totals(slots: &[Slot<1>], members: &[usize]) -> (usize, f64) {
    let w = members.iter().map(|&i| 2.0 * slots[i].radius).sum();
    (members.len(), w)
}

/// The exact joint placement of `members` on [lo, hi]: a random order, then
/// uniform gaps. Centres in member order; None if they do not fit.
fn line_up(
    slots: &[Slot<1>],
    members: &[usize],
    lo: f64,
    hi: f64,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<f64>> {
    let (_, occupied) = totals(slots, members);
    let free = hi - lo - occupied;
    if free < 0.0 {
        return None;
    }
    let mut order: Vec<usize> = (0..members.len()).collect();
    order.shuffle(rng);
    let mut gaps: Vec<f64> = members.iter().map(|_| free * rng.random::<f64>()).collect();
    gaps.sort_by(f64::total_cmp);
    let mut x = vec![0.0; members.len()];
    let mut used = 0.0;
    for (&m, g) in order.iter().zip(gaps) {
        let r = slots[members[m]].radius;
        x[m] = lo + g + used + r;
        used += 2.0 * r;
    }
    Some(x)
}

/// Joint placements on the hull until one keeps every rod in its region and
/// clear of the obstacle: exactly uniform over the allowed configurations.
fn by_rejection(
    slots: &[Slot<1>],
    members: &[usize],
    (lo, hi): (f64, f64),
    obstacle: Option<[f64; 2]>,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<f64>> {
    for _ in 0..TRIES {
        let x = line_up(slots, members, lo, hi, rng)?;
        let fits = members.iter().zip(&x).all(|(&i, &xi)| {
            let (r, s) = (slots[i].radius, &slots[i]);
            xi - r >= s.lo[0]
                && xi + r <= s.hi[0]
                && obstacle.is_none_or(|[a, b]| xi + r <= a || xi - r >= b)
        });
        if fits {
            return Some(x);
        }
    }
    None
}

fn tangled(
    slots: &[Slot<1>],
    members: &[usize],
    obstacle: Option<[f64; 2]>,
    shared: bool,
    names: &[String],
) -> String {
    let mut regions: Vec<String> = Vec::new();
    for &i in members {
        let s = &slots[i];
        let name = names.get(s.species as usize).map_or("?", String::as_str);
        let text = format!("`{name}` in [{}, {}]", s.lo[0], s.hi[0]);
        if !regions.contains(&text) {
            regions.push(text);
        }
    }
    let why = match obstacle {
        Some([a, b]) if shared => format!("the piston at [{a}, {b}] splits their region"),
        Some([a, b]) => {
            format!("their regions overlap without being the same, around the piston at [{a}, {b}]")
        }
        None => "their regions overlap without being the same".into(),
    };
    format!(
        "cannot place the rods of {} at random: {why}, and no exact uniform placement was found in \
         {TRIES} tries; give species that share space the same region, and keep regions to one side \
         of the piston",
        regions.join(", ")
    )
}
