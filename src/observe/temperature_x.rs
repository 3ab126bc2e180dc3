//! Temperature and number of particles in slabs along x at each sample: the
//! profiles of a gas out of equilibrium (an expansion cools where it thins
//! fast; a gas between a hot and a cold wall carries a gradient). The
//! temperature is that of the motion about the slab's own mean velocity,
//! so a slab flowing as a whole is not counted hot: kT = sum m |v - u|^2 /
//! (d (n - 1)), u the slab's mass-weighted mean velocity (d degrees of
//! freedom go to u), NaN with fewer than two particles. Ensemble means of
//! the slabs' values give the profiles; a probe keeps no state of its own.

use super::{Context, Entry, Kind, Observable, Part, Probe, Row, Setup};
use crate::engine::Snapshot;
use crate::model::need::Need;

/// Slabs across the box along x.
pub const SLABS: usize = 16;

pub struct TemperatureX;

impl Observable for TemperatureX {
    const ENTRY: Entry = Entry {
        name: "temperature_x",
        kind: Kind::Series,
        writes: "<count|temperature>_x.<slab>",
        label: "<count|temperature> in slab <slab> of 16 along x",
        unit: "1 or kT",
        needs: &[Need::Sampling],
        doc: "number of movable particles and their kT about the slab's mean velocity in each of 16 equal slabs along x (slab 0 at x = 0), at each sample",
    };
    fn part<const D: usize>(_: &Setup) -> Part<D> {
        Part::Series(Box::new(TemperatureX))
    }
}

impl<const D: usize> Probe<D> for TemperatureX {
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row) {
        let length = s.sim_box.size[0];
        // Per slab: count, mass, momentum, twice the kinetic energy.
        let mut count = [0usize; SLABS];
        let mut mass = [0.0; SLABS];
        let mut momentum = [[0.0; D]; SLABS];
        let mut twice_energy = [0.0; SLABS];
        for (i, p) in s.particles.iter().enumerate() {
            if p.is_immovable() || p.is_plane() {
                continue;
            }
            let b = (s.position(i)[0] / length * SLABS as f64).floor();
            if !(0.0..SLABS as f64).contains(&b) {
                continue;
            }
            let b = b as usize;
            let m = p.mass();
            count[b] += 1;
            mass[b] += m;
            for k in 0..D {
                momentum[b][k] += m * p.vel[k];
                twice_energy[b] += m * p.vel[k] * p.vel[k];
            }
        }
        for b in 0..SLABS {
            row.push(count[b] as f64);
            let flow: f64 = momentum[b].iter().map(|q| q * q).sum::<f64>() / mass[b];
            row.push(if count[b] >= 2 {
                (twice_energy[b] - flow) / (D as f64 * (count[b] - 1) as f64)
            } else {
                f64::NAN
            });
        }
    }
    fn name(&self, k: usize, _: &Context) -> String {
        let what = if k.is_multiple_of(2) {
            "count"
        } else {
            "temperature"
        };
        format!("{what}_x.{}", k / 2)
    }
}
