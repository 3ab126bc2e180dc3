//! The frames of `[observe] trajectory`: at every frame time, each
//! particle's position (folded into the box on periodic axes), velocity and
//! image flags (box crossings on periodic axes), handed to a format writer
//! (`gsd.rs`, `xyz.rs`) as it comes, so a long trajectory is never held in
//! memory. Not a catalogue observable: it fills no table; the runner films a
//! chosen run again with it (`runner/execute/trajectory.rs`).
//!
//! Image flags are counted from the folded positions, by the smallest image
//! of each particle's step between two samples. That is exact while no
//! particle moves half a box between samples, so the runner samples often
//! enough for the fastest speed the energy allows (`samples_per_frame`) and
//! writes every few samples; a gas heated past that bound by a thermal wall
//! fails the trajectory instead of giving wrong flags.

pub mod gsd;
pub mod xyz;

use crate::engine::{Observer, Snapshot};

/// What every frame shares, in three dimensions (1D and 2D padded with 0).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Layout {
    /// The scene's dimension, 1 to 3.
    pub dimension: usize,
    /// Box edge per axis; a padded axis has 0.
    pub size: [f64; 3],
    /// Periodic axes.
    pub periodic: [bool; 3],
    /// Species names (the piston, if any, last).
    pub species: Vec<String>,
    /// Per particle: species index, diameter, mass (inf: immovable).
    pub typeid: Vec<u32>,
    pub diameter: Vec<f64>,
    pub mass: Vec<f64>,
}

/// One frame: positions in the box [0, L) of each axis (as the engine has
/// them), velocities and image flags, one row per particle.
#[derive(Debug, Clone, Copy)]
pub struct Frame<'a> {
    /// Its number, from 0.
    pub index: u64,
    /// Simulated time (absolute: 0 is the run's start).
    pub time: f64,
    pub positions: &'a [[f64; 3]],
    pub velocities: &'a [[f64; 3]],
    pub images: &'a [[i32; 3]],
}

/// A trajectory file being written.
pub trait FrameSink {
    /// Append a frame (the layout is the same for every frame).
    fn frame(&mut self, layout: &Layout, frame: &Frame) -> std::io::Result<()>;
    /// Complete the file (the GSD index) after the last frame.
    fn finish(&mut self, layout: &Layout) -> std::io::Result<()>;
}

/// Samples between frames so that no particle can move a fifth of the
/// shortest periodic axis between two: the fastest a particle can move is
/// sqrt(2 E / m) with E all the kinetic energy (`speed_bound`). 1 without
/// periodic axes (no flags to count).
pub fn samples_per_frame(every: f64, speed_bound: f64, shortest_periodic: Option<f64>) -> u64 {
    let Some(l) = shortest_periodic else {
        return 1;
    };
    let n = (every * speed_bound / (SAFE_STEP * l)).ceil();
    if n.is_finite() && n >= 1.0 {
        n.min(u32::MAX as f64) as u64
    } else {
        1
    }
}

/// Largest step between samples, as a fraction of the box, taken as safe
/// (the smallest image is right below one half).
const SAFE_STEP: f64 = 0.2;

/// The observer: every sample updates the image flags, every
/// `per_frame`-th is written, at most `frames` of them.
pub struct Framing<S: FrameSink> {
    sink: S,
    layout: Layout,
    per_frame: u64,
    frames: u64,
    sample_every: f64,
    samples: u64,
    written: u64,
    positions: Vec<[f64; 3]>,
    velocities: Vec<[f64; 3]>,
    images: Vec<[i32; 3]>,
    /// The first write error, or why the flags cannot be counted.
    failed: Option<String>,
}

impl<S: FrameSink> Framing<S> {
    /// `species` names the particles' species indices; `frames` at most are
    /// written, one every `per_frame` samples taken `sample_every` apart.
    pub fn new(
        sink: S,
        species: Vec<String>,
        per_frame: u64,
        frames: u64,
        sample_every: f64,
    ) -> Self {
        Framing {
            sink,
            layout: Layout {
                species,
                ..Layout::default()
            },
            per_frame: per_frame.max(1),
            frames,
            sample_every,
            samples: 0,
            written: 0,
            positions: Vec::new(),
            velocities: Vec::new(),
            images: Vec::new(),
            failed: None,
        }
    }

    /// Complete the file; an error if any write failed or the image flags
    /// could not be counted.
    pub fn finish(mut self) -> Result<S, String> {
        if let Some(why) = self.failed {
            return Err(why);
        }
        self.sink
            .finish(&self.layout)
            .map_err(|e| format!("cannot write the trajectory: {e}"))?;
        Ok(self.sink)
    }

    fn start<const D: usize>(&mut self, s: &Snapshot<D>) {
        let layout = &mut self.layout;
        layout.dimension = D;
        for k in 0..D {
            layout.size[k] = s.sim_box.size[k];
            layout.periodic[k] = s.sim_box.axes[k].is_periodic();
        }
        layout.typeid = s.particles.iter().map(|p| u32::from(p.species)).collect();
        layout.diameter = s.particles.iter().map(|p| 2.0 * p.radius).collect();
        layout.mass = s.particles.iter().map(|p| p.mass()).collect();
        let n = s.particles.len();
        self.positions = (0..n).map(|i| pad(s.position(i))).collect();
        self.velocities = vec![[0.0; 3]; n];
        self.images = vec![[0; 3]; n];
    }

    /// Count the crossings since the last sample; false if a step could be
    /// too long to tell (a gas heated beyond the bound sampled for).
    fn follow<const D: usize>(&mut self, s: &Snapshot<D>) -> bool {
        let periodic = self.layout.periodic;
        let size = self.layout.size;
        let fastest = s
            .particles
            .iter()
            .filter(|p| !p.is_immovable())
            .map(|p| p.vel.iter().map(|v| v * v).sum::<f64>())
            .fold(0.0, f64::max)
            .sqrt();
        for k in 0..D {
            if periodic[k] && fastest * self.sample_every >= 0.5 * size[k] {
                return false;
            }
        }
        for i in 0..self.positions.len() {
            let x = pad(s.position(i));
            for k in 0..D {
                if periodic[k] {
                    let step = x[k] - self.positions[i][k];
                    if step < -0.5 * size[k] {
                        self.images[i][k] += 1;
                    } else if step > 0.5 * size[k] {
                        self.images[i][k] -= 1;
                    }
                }
            }
            self.positions[i] = x;
        }
        true
    }
}

/// Zero-padded to three axes.
fn pad<const D: usize>(x: [f64; D]) -> [f64; 3] {
    std::array::from_fn(|k| if k < D { x[k] } else { 0.0 })
}

impl<const D: usize, S: FrameSink> Observer<D> for Framing<S> {
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.failed.is_some() || self.written >= self.frames {
            return;
        }
        if self.samples == 0 {
            self.start(s);
        } else if !self.follow(s) {
            self.failed = Some(format!(
                "at time {}, a particle moves fast enough to cross half the box between two \
                 samples, so its box crossings cannot be counted (a thermal wall heated the gas \
                 past the speed sampled for)",
                s.time
            ));
            return;
        }
        let take = self.samples.is_multiple_of(self.per_frame);
        self.samples += 1;
        if !take {
            return;
        }
        for (i, p) in s.particles.iter().enumerate() {
            self.velocities[i] = pad(p.vel);
        }
        let frame = Frame {
            index: self.written,
            time: s.time,
            positions: &self.positions,
            velocities: &self.velocities,
            images: &self.images,
        };
        if let Err(e) = self.sink.frame(&self.layout, &frame) {
            self.failed = Some(format!("cannot write the trajectory: {e}"));
        }
        self.written += 1;
    }
}
