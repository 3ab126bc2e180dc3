//! One step of the Imperial project's method: move every particle by h,
//! reflect those that overlap a wall, then collide the pairs that overlap.
//! With `approach_check` (the seeds' fix) a wall or pair only bounces while
//! it is approaching; without it (the seeds' first version) an overlap
//! bounces at every step, and pairs that are still overlapping after a bounce
//! bounce back into each other: they stick.

use super::Stepper;
use crate::engine::boundary::Wall;
use crate::engine::collide::bounce;
use crate::engine::observer::{Observer, PairCollision, WallHit};
use crate::engine::thermal;
use crate::engine::vector::{dot, norm2};

impl<const D: usize, O: Observer<D>> Stepper<D, O> {
    /// Advance to `to` (at most dt ahead) and resolve what the step end finds.
    pub(super) fn step(&mut self, to: f64) {
        let h = to - self.time;
        for p in &mut self.particles {
            for k in 0..D {
                p.pos[k] += h * p.vel[k];
            }
        }
        self.time = to;
        self.counts.events += self.particles.len() as u64;
        self.fold_periodic();
        self.walls();
        self.pairs();
        self.tally.end_step();
    }

    fn fold_periodic(&mut self) {
        for k in 0..D {
            if self.sim_box.axes[k].is_periodic() {
                let l = self.sim_box.size[k];
                for p in &mut self.particles {
                    if !(0.0..l).contains(&p.pos[k]) {
                        p.pos[k] = p.pos[k].rem_euclid(l);
                        if p.pos[k] >= l {
                            p.pos[k] = 0.0;
                        }
                    }
                }
            }
        }
    }

    fn walls(&mut self) {
        for i in 0..self.particles.len() {
            for k in 0..D {
                let p = &self.particles[i];
                let high = if p.pos[k] + p.radius > self.sim_box.size[k] {
                    true
                } else if p.pos[k] - p.radius < 0.0 {
                    false
                } else {
                    continue;
                };
                if let Some(wall) = self.sim_box.axes[k].wall(high) {
                    self.bounce_off(i, k, high, wall);
                }
            }
        }
    }

    /// Particle i overlaps the wall `high` of axis k at the step end.
    fn bounce_off(&mut self, i: usize, k: usize, high: bool, wall: Wall) {
        let outward = if high { 1.0 } else { -1.0 };
        let p = &mut self.particles[i];
        let leaving = p.vel[k] * outward > 0.0;
        let hard = matches!(wall, Wall::Hard);
        // A bath always sends the particle back in; a hard wall without the
        // fix reflects whatever the direction.
        if p.is_immovable() || !(leaving || (hard && !self.approach_check)) {
            return;
        }
        let before = p.vel;
        match wall {
            Wall::Hard => p.vel[k] = -p.vel[k],
            Wall::Thermal { temperature } => {
                p.vel = thermal::emit::<D>(&mut self.rng, temperature, p.inv_mass, k, -outward);
            }
        }
        let m = p.mass();
        let event = WallHit {
            time: self.time,
            i,
            axis: k,
            high,
            impulse: std::array::from_fn(|a| m * (p.vel[a] - before[a])),
            energy_gain: 0.5 * m * (norm2(&p.vel) - norm2(&before)),
        };
        self.counts.wall_hits += 1;
        self.observer.wall_hit(&event);
    }

    fn pairs(&mut self) {
        self.cells.fill(&self.particles);
        // The cell list lends the pairs; the particles change as they are
        // collided, so collect the overlapping ones first (few per step).
        let mut found = std::mem::take(&mut self.found);
        found.clear();
        let particles = &self.particles;
        let size = self.sim_box.size;
        let periodic: [bool; D] = std::array::from_fn(|k| self.sim_box.axes[k].is_periodic());
        self.cells.pairs(|i, j| {
            let (i, j) = (i.min(j), i.max(j));
            let (p, q) = (&particles[i], &particles[j]);
            let sigma = p.radius + q.radius;
            let mut r: [f64; D] = std::array::from_fn(|k| q.pos[k] - p.pos[k]);
            for k in 0..D {
                if periodic[k] {
                    r[k] -= size[k] * (r[k] / size[k]).round();
                }
            }
            if norm2(&r) < sigma * sigma {
                found.push((i, j, r));
            }
        });
        // A fixed order (by pair) makes the outcome independent of cells.
        found.sort_unstable_by_key(|&(i, j, _)| (i, j));
        for &(i, j, r) in &found {
            self.collide(i, j, r);
        }
        self.found = found;
    }

    fn collide(&mut self, i: usize, j: usize, r: [f64; D]) {
        let (p, q) = (&self.particles[i], &self.particles[j]);
        let dist = norm2(&r).sqrt();
        let sigma = p.radius + q.radius;
        let speed = norm2(&std::array::from_fn::<f64, D, _>(|k| p.vel[k] - q.vel[k])).sqrt();
        let pass = 2.0 * sigma / speed;
        let repeat = self.tally.overlap(i, j, 1.0 - dist / sigma, pass, self.dt);
        if dist == 0.0 {
            return;
        }
        let n: [f64; D] = std::array::from_fn(|k| r[k] / dist);
        let kick = if self.approach_check {
            bounce(&p.vel, &q.vel, p.inv_mass, q.inv_mass, &n).map(|b| b.impulse_i)
        } else {
            // The seeds' first version: exchange the normal momentum of
            // every overlapping pair, approaching or not.
            let u: f64 = dot(
                &std::array::from_fn::<f64, D, _>(|k| p.vel[k] - q.vel[k]),
                &n,
            );
            let total = p.inv_mass + q.inv_mass;
            (u != 0.0 && total > 0.0).then(|| std::array::from_fn(|k| -2.0 * u / total * n[k]))
        };
        let Some(impulse_i) = kick else { return };
        let (mi, mj) = (p.inv_mass, q.inv_mass);
        for k in 0..D {
            self.particles[i].vel[k] += mi * impulse_i[k];
            self.particles[j].vel[k] -= mj * impulse_i[k];
        }
        self.counts.collisions += 1;
        if repeat {
            self.tally.repeat_collisions += 1;
        }
        let event = PairCollision {
            time: self.time,
            i,
            j,
            impulse_i,
            separation: r,
        };
        self.observer.pair_collision(&event);
    }
}
