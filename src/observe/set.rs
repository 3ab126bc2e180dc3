//! The observers of one run behind the engine's one observer: each hook is
//! only called on the observers that use it, so an observable nobody asked
//! for costs nothing per event.

use super::{Context, Measure, StateIn, StateOut};
use crate::engine::{Observer, PairCollision, Snapshot, WallHit};
use crate::model::run_output::RunOutput;

/// The observers of one run, split by the hooks they use.
pub struct ObserverSet<const D: usize> {
    measures: Vec<Box<dyn Measure<D>>>,
    on_collision: Vec<usize>,
    on_wall: Vec<usize>,
    on_sample: Vec<usize>,
    /// Off during equilibration.
    pub recording: bool,
}

impl<const D: usize> ObserverSet<D> {
    pub fn new(measures: Vec<Box<dyn Measure<D>>>) -> Self {
        let pick = |f: &dyn Fn(&dyn Measure<D>) -> bool| {
            (0..measures.len())
                .filter(|&i| f(measures[i].as_ref()))
                .collect()
        };
        ObserverSet {
            on_collision: pick(&|m| m.uses_collisions()),
            on_wall: pick(&|m| m.uses_walls()),
            on_sample: pick(&|m| m.uses_samples()),
            measures,
            recording: false,
        }
    }

    /// Everything the observers accumulated, and whether they record: the
    /// observers' part of a checkpoint. None if one of them cannot be saved.
    pub fn save_state(&self) -> Option<Vec<f64>> {
        let mut out = StateOut::default();
        out.number(f64::from(u8::from(self.recording)));
        for m in &self.measures {
            if !m.save(&mut out) {
                return None;
            }
        }
        Some(out.0)
    }

    /// Take on a state `save_state` wrote for the same observers.
    pub fn restore_state(&mut self, state: &[f64]) -> Result<(), String> {
        let mut from = StateIn::new(state);
        self.recording = from.number()? != 0.0;
        for m in &mut self.measures {
            m.restore(&mut from)?;
        }
        from.done()
    }

    pub fn finish(self, ctx: &Context, out: &mut RunOutput) {
        for m in self.measures {
            m.finish(ctx, out);
        }
    }
}

impl<const D: usize> Observer<D> for ObserverSet<D> {
    fn pair_collision(&mut self, e: &PairCollision<D>) {
        if self.recording {
            for &i in &self.on_collision {
                self.measures[i].pair_collision(e);
            }
        }
    }
    fn wall_hit(&mut self, e: &WallHit<D>) {
        if self.recording {
            for &i in &self.on_wall {
                self.measures[i].wall_hit(e);
            }
        }
    }
    fn sample(&mut self, s: &Snapshot<D>) {
        if self.recording {
            for &i in &self.on_sample {
                self.measures[i].sample(s);
            }
        }
    }
}
