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
//!
//! With `alternating` the order is fixed instead (species in turn, as in the
//! alternating-mass chain); the gaps stay uniform, so the placement is
//! uniform over the configurations with that order.

use super::refusal::{Blame, Refusal};
use super::slots::{Group, singles};
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
    alternating: bool,
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; 1]>, String> {
    let groups = singles(slots);
    room(&groups, obstacle).map_err(|r| r.to_string())?;
    let mut out = vec![[0.0]; slots.len()];
    for cluster in clusters(&groups) {
        let span = Span::of(&groups, &cluster, obstacle);
        let x = match span.segment {
            Some((from, to)) => line_up(slots, &cluster, from, to, alternating, rng),
            None => by_rejection(
                slots,
                &cluster,
                (span.lo, span.hi),
                obstacle,
                alternating,
                rng,
            ),
        }
        .ok_or_else(|| tangled(slots, &cluster, obstacle, span.shared, names))?;
        for (&i, xi) in cluster.iter().zip(x) {
            out[i] = [xi];
        }
    }
    Ok(out)
}

/// Refuses rods that cannot fit where they must go: each set of rods whose
/// regions overlap needs their total length on the line they share, less
/// what the piston takes of it. The checks ask it species by species, the
/// placement rod by rod; both add the lengths in the same order.
pub fn room(groups: &[Group<1>], obstacle: Option<[f64; 2]>) -> Result<(), Refusal> {
    for cluster in clusters(groups) {
        let span = Span::of(groups, &cluster, obstacle);
        let (from, to) = span.segment.unwrap_or((span.lo, span.hi));
        let taken = match (span.segment, span.blocked) {
            (None, Some([a, b])) => b.min(span.hi) - a.max(span.lo),
            _ => 0.0,
        };
        let mut n = 0;
        let mut w = 0.0;
        for &i in &cluster {
            n += groups[i].count;
            for _ in 0..groups[i].count {
                w += 2.0 * groups[i].slot.radius;
            }
        }
        if w > to - from - taken {
            return Err(Refusal {
                species: groups[cluster[0]].slot.species as usize,
                blame: Blame::Count,
                message: format!(
                    "rods of total length {w} do not fit in their region of length {}{}",
                    to - from - taken,
                    if span.blocked.is_some() {
                        " beside the piston"
                    } else {
                        ""
                    }
                ),
                hint: format!(
                    "{n} rods need a length of {w}: use fewer or shorter rods, or a longer box or region"
                ),
            });
        }
    }
    Ok(())
}

/// A set of overlapping regions: the line they cover, the piston if it is in
/// the way, and the one free segment they share, if they share one.
struct Span {
    lo: f64,
    hi: f64,
    blocked: Option<[f64; 2]>,
    shared: bool,
    segment: Option<(f64, f64)>,
}

impl Span {
    fn of(groups: &[Group<1>], members: &[usize], obstacle: Option<[f64; 2]>) -> Span {
        let (lo, hi) = hull(groups, members);
        let blocked = obstacle.filter(|&[a, b]| a < hi && b > lo);
        let first = &groups[members[0]].slot;
        let shared = members.iter().all(|&i| groups[i].slot.same_region(first));
        // An obstacle that only trims an end of a shared region leaves one segment.
        let segment = match blocked {
            _ if !shared => None,
            None => Some((lo, hi)),
            Some([a, b]) if a <= lo => Some((b, hi)),
            Some([a, b]) if b >= hi => Some((lo, a)),
            Some(_) => None,
        };
        Span {
            lo,
            hi,
            blocked,
            shared,
            segment,
        }
    }
}

/// Sets of groups whose regions overlap, directly or through others.
fn clusters(groups: &[Group<1>]) -> Vec<Vec<usize>> {
    let slot = |i: usize| &groups[i].slot;
    let mut order: Vec<usize> = (0..groups.len()).collect();
    order.sort_by(|&a, &b| slot(a).lo[0].total_cmp(&slot(b).lo[0]).then(a.cmp(&b)));
    let mut out: Vec<Vec<usize>> = Vec::new();
    let mut reach = f64::NEG_INFINITY;
    for i in order {
        let s = slot(i);
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

fn hull(groups: &[Group<1>], members: &[usize]) -> (f64, f64) {
    members
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &i| {
            (a.min(groups[i].slot.lo[0]), b.max(groups[i].slot.hi[0]))
        })
}

fn totals(slots: &[Slot<1>], members: &[usize]) -> (usize, f64) {
    let w = members.iter().map(|&i| 2.0 * slots[i].radius).sum();
    (members.len(), w)
}

/// The exact joint placement of `members` on [lo, hi]: a random (or the
/// alternating) order, then uniform gaps. Centres in member order; None if
/// they do not fit.
fn line_up(
    slots: &[Slot<1>],
    members: &[usize],
    lo: f64,
    hi: f64,
    alternating: bool,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<f64>> {
    let (_, occupied) = totals(slots, members);
    let free = hi - lo - occupied;
    if free < 0.0 {
        return None;
    }
    let order = if alternating {
        in_turn(slots, members)
    } else {
        let mut order: Vec<usize> = (0..members.len()).collect();
        order.shuffle(rng);
        order
    };
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

/// Members (as indices into `members`) with the species taking turns in
/// species order; a species that runs out drops out of the turn.
fn in_turn(slots: &[Slot<1>], members: &[usize]) -> Vec<usize> {
    let mut queues: Vec<Vec<usize>> = Vec::new();
    for (m, &i) in members.iter().enumerate() {
        let s = slots[i].species as usize;
        if queues.len() <= s {
            queues.resize(s + 1, Vec::new());
        }
        queues[s].push(m);
    }
    let longest = queues.iter().map(Vec::len).max().unwrap_or(0);
    (0..longest)
        .flat_map(|k| queues.iter().filter_map(move |q| q.get(k).copied()))
        .collect()
}

/// Joint placements on the hull until one keeps every rod in its region and
/// clear of the obstacle: exactly uniform over the allowed configurations.
fn by_rejection(
    slots: &[Slot<1>],
    members: &[usize],
    (lo, hi): (f64, f64),
    obstacle: Option<[f64; 2]>,
    alternating: bool,
    rng: &mut ChaCha8Rng,
) -> Option<Vec<f64>> {
    for _ in 0..TRIES {
        let x = line_up(slots, members, lo, hi, alternating, rng)?;
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
