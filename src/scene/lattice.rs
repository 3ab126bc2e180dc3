//! Lattice placement. Sites sit on layers along each axis; "square",
//! "cubic" and "line" use every combination of layers, "hexagonal" and "fcc"
//! those whose layer indices add up to an even number (a centred rectangular
//! cell of aspect sqrt(3), a face-centred cube). Layer spacings are chosen as
//! large as the region allows, so the nearest-neighbour distance is the
//! largest this lattice can give N particles, and every particle lies inside
//! its region radius included (on an axis the region wraps around, the
//! layers are evenly spaced around the period instead).
//!
//! Species with the same region share one lattice; species whose regions
//! overlap otherwise cannot, and are refused.

use super::refusal::{Blame, Refusal};
use super::slots::{Group, singles};
use super::space::{Slot, Space, ball_volume, region_volume};
use rand::seq::SliceRandom;
use rand_chacha::ChaCha8Rng;

struct Kind {
    name: String,
    /// Sites only where the layer indices add up to an even number.
    centred: bool,
    /// Layer spacing per axis for nearest-neighbour distance 1.
    layer: [f64; 3],
}

fn kind(d: usize, name: Option<&str>) -> Result<Kind, String> {
    let name = name.unwrap_or(match d {
        1 => "line",
        2 => "hexagonal",
        _ => "fcc",
    });
    let (centred, layer) = match (d, name) {
        (1, "line") | (2, "square") | (3, "cubic") => (false, [1.0; 3]),
        (2, "hexagonal") => (true, [0.5, 3f64.sqrt() / 2.0, 0.0]),
        (3, "fcc") => (true, [std::f64::consts::FRAC_1_SQRT_2; 3]),
        _ => {
            return Err(format!(
                "lattice `{name}` is not available in {d}D; use {}",
                match d {
                    1 => "\"line\"",
                    2 => "\"square\" or \"hexagonal\"",
                    _ => "\"cubic\" or \"fcc\"",
                }
            ));
        }
    };
    Ok(Kind {
        name: name.to_string(),
        centred,
        layer,
    })
}

/// Positions for every slot, species sharing a region on one lattice with
/// sites assigned at random among them.
pub fn place<const D: usize>(
    slots: &[Slot<D>],
    space: &Space<D>,
    lattice: Option<&str>,
    names: &[String],
    rng: &mut ChaCha8Rng,
) -> Result<Vec<[f64; D]>, String> {
    let kind = kind(D, lattice)?;
    let singles = singles(slots);
    room(&singles, space, lattice, names).map_err(|r| r.to_string())?;
    let mut out = vec![[0.0; D]; slots.len()];
    for mut members in by_region(&singles) {
        let first = slots[members[0]];
        let radius = members.iter().map(|&i| slots[i].radius).fold(0.0, f64::max);
        let fit = Fit::new(&kind, space, &first, radius);
        let sites = fit
            .sites(members.len())
            .map_err(|most| crowded(&kind, space, &singles, &members, most, names).to_string())?;
        if members.iter().any(|&i| slots[i].species != first.species) {
            members.shuffle(rng);
        }
        for (i, x) in members.into_iter().zip(sites) {
            out[i] = x;
        }
    }
    Ok(out)
}

/// Refuses what no lattice can hold: species whose regions overlap without
/// being the same (they cannot share a lattice), and more particles than a
/// region's lattice has sites. The checks ask it species by species, the
/// placement particle by particle.
pub fn room<const D: usize>(
    groups: &[Group<D>],
    space: &Space<D>,
    lattice: Option<&str>,
    names: &[String],
) -> Result<(), Refusal> {
    let Ok(kind) = kind(D, lattice) else {
        // An unknown lattice is the checks' to name, not a matter of room.
        return Ok(());
    };
    let regions = by_region(groups);
    for (a, ga) in regions.iter().enumerate() {
        for gb in &regions[a + 1..] {
            let (s, t) = (&groups[ga[0]].slot, &groups[gb[0]].slot);
            if (0..D).all(|k| s.lo[k] < t.hi[k] && t.lo[k] < s.hi[k]) {
                return Err(Refusal {
                    species: t.species as usize,
                    blame: Blame::Region,
                    message: format!(
                        "species `{}` and `{}` have regions that overlap without being the same, so \
                         they cannot share a lattice",
                        name(names, s),
                        name(names, t)
                    ),
                    hint: "give them the same region (one lattice, sites shared at random) or \
                           regions that do not overlap"
                        .into(),
                });
            }
        }
    }
    for members in &regions {
        let first = groups[members[0]].slot;
        let radius = members
            .iter()
            .map(|&i| groups[i].slot.radius)
            .fold(0.0, f64::max);
        let n: usize = members.iter().map(|&i| groups[i].count).sum();
        // Point particles always fit: the lattice shrinks to hold them.
        if radius > 0.0 {
            let most = Fit::new(&kind, space, &first, radius).count_at(2.0 * radius);
            if most < n {
                return Err(crowded(&kind, space, groups, members, most, names));
            }
        }
    }
    Ok(())
}

/// Groups by region, in order of first appearance: each region's lattice.
fn by_region<const D: usize>(groups: &[Group<D>]) -> Vec<Vec<usize>> {
    let mut regions: Vec<Vec<usize>> = Vec::new();
    for (i, g) in groups.iter().enumerate() {
        match regions
            .iter_mut()
            .find(|r| groups[r[0]].slot.same_region(&g.slot))
        {
            Some(r) => r.push(i),
            None => regions.push(vec![i]),
        }
    }
    regions
}

/// More particles than a region's lattice holds.
fn crowded<const D: usize>(
    kind: &Kind,
    space: &Space<D>,
    groups: &[Group<D>],
    members: &[usize],
    most: usize,
    names: &[String],
) -> Refusal {
    let first = groups[members[0]].slot;
    let radius = members
        .iter()
        .map(|&i| groups[i].slot.radius)
        .fold(0.0, f64::max);
    let n: usize = members.iter().map(|&i| groups[i].count).sum();
    let species: Vec<String> = members.iter().fold(Vec::new(), |mut v, &i| {
        let label = format!("`{}`", name(names, &groups[i].slot));
        if !v.contains(&label) {
            v.push(label);
        }
        v
    });
    let phi = most as f64 * ball_volume(D, radius) / region_volume(&first.lo, &first.hi);
    Refusal {
        species: first.species as usize,
        blame: Blame::Count,
        message: format!(
            "{n} particles of radius {radius} ({}) do not fit on a {} lattice in their region {:?} \
             to {:?}: at most {most} fit, packing fraction {phi:.4}",
            species.join(", "),
            kind.name,
            first.lo,
            first.hi,
        ),
        hint: format!(
            "use fewer or smaller particles or a larger box{}",
            if space.periodic.iter().all(|&p| p) {
                ""
            } else {
                " (walls take room: periodic boundaries fit more)"
            }
        ),
    }
}

/// How many particles of this radius the dimension's default lattice
/// ("line", "hexagonal", "fcc") holds in a slot's region.
pub fn capacity<const D: usize>(space: &Space<D>, slot: &Slot<D>, radius: f64) -> usize {
    match kind(D, None) {
        Ok(kind) => Fit::new(&kind, space, slot, radius).count_at(2.0 * radius),
        Err(_) => 0,
    }
}

fn name<'a, const D: usize>(names: &'a [String], s: &Slot<D>) -> &'a str {
    names.get(s.species as usize).map_or("?", String::as_str)
}

/// One region's lattice geometry.
struct Fit<'a, const D: usize> {
    kind: &'a Kind,
    lo: [f64; D],
    extent: [f64; D],
    wraps: [bool; D],
    radius: f64,
}

impl<'a, const D: usize> Fit<'a, D> {
    fn new(kind: &'a Kind, space: &Space<D>, slot: &Slot<D>, radius: f64) -> Self {
        Fit {
            kind,
            lo: slot.lo,
            extent: std::array::from_fn(|k| slot.hi[k] - slot.lo[k]),
            wraps: std::array::from_fn(|k| space.wraps(&slot.lo, &slot.hi, k)),
            radius,
        }
    }

    /// Layers along axis k for nearest-neighbour distance a.
    fn layers(&self, a: f64, k: usize) -> usize {
        let h = self.kind.layer[k] * a;
        let tol = 1.0 + 1e-9;
        if self.wraps[k] {
            let m = (self.extent[k] / h * tol).floor() as usize;
            // A centred lattice alternates layers, so it needs an even number around a period.
            if self.kind.centred { m - m % 2 } else { m }
        } else {
            let room = self.extent[k] - 2.0 * self.radius;
            if room < 0.0 {
                0
            } else {
                (room / h * tol).floor() as usize + 1
            }
        }
    }

    fn count(&self, m: &[usize; D]) -> usize {
        let all: usize = m.iter().product();
        if self.kind.centred {
            let odd_all: usize = m.iter().map(|x| x % 2).product();
            (all + odd_all) / 2
        } else {
            all
        }
    }

    fn count_at(&self, a: f64) -> usize {
        self.count(&std::array::from_fn(|k| self.layers(a, k)))
    }

    /// n sites, evenly picked from the densest fit that holds them; or the
    /// most that fit, if n do not.
    fn sites(&self, n: usize) -> Result<Vec<[f64; D]>, usize> {
        if n == 0 {
            return Ok(Vec::new());
        }
        // The largest nearest-neighbour distance a with at least n sites.
        let mut lo = 2.0 * self.radius;
        if lo > 0.0 {
            let most = self.count_at(lo);
            if most < n {
                return Err(most);
            }
        } else {
            lo = self.extent.iter().copied().fold(f64::INFINITY, f64::min);
            while self.count_at(lo) < n {
                lo /= 2.0;
            }
        }
        let mut hi = 2.0 * self.extent.iter().copied().fold(0.0, f64::max);
        if self.count_at(hi) >= n {
            lo = hi;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if self.count_at(mid) >= n {
                lo = mid
            } else {
                hi = mid
            }
        }
        let a = lo;
        let m: [usize; D] = std::array::from_fn(|k| self.layers(a, k));
        let coord: Vec<Vec<f64>> = (0..D).map(|k| self.axis(a, k, m[k])).collect();
        let total: usize = m.iter().product();
        let mut all = Vec::with_capacity(self.count(&m));
        for c in 0..total {
            let mut rest = c;
            let j: [usize; D] = std::array::from_fn(|k| {
                let v = rest % m[k];
                rest /= m[k];
                v
            });
            if !self.kind.centred || j.iter().sum::<usize>() % 2 == 0 {
                all.push(std::array::from_fn(|k| coord[k][j[k]]));
            }
        }
        // Vacancies spread evenly through the lattice.
        Ok((0..n).map(|i| all[i * all.len() / n]).collect())
    }

    /// Layer positions along axis k: evenly spaced around a period; in cells
    /// of equal width when that keeps neighbours and walls far enough,
    /// otherwise from wall to wall one radius in.
    fn axis(&self, a: f64, k: usize, m: usize) -> Vec<f64> {
        let (lo, ext, r) = (self.lo[k], self.extent[k], self.radius);
        let h = self.kind.layer[k] * a;
        let cell = ext / m as f64;
        if self.wraps[k] || m == 1 || (cell >= h && cell >= 2.0 * r) {
            (0..m).map(|j| lo + (j as f64 + 0.5) * cell).collect()
        } else {
            let step = (ext - 2.0 * r) / (m - 1) as f64;
            (0..m).map(|j| lo + r + j as f64 * step).collect()
        }
    }
}
