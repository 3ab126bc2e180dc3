//! What the catalogue says about an observable, and the part a run builds
//! from it.

use super::sampled::Row;
use super::{Context, Measure};
use crate::engine::Snapshot;
use crate::model::need::Need;

/// The `[observe]` list that names an observable, and the table it fills.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Kind {
    /// Time series: series.parquet.
    Series,
    /// One number per run: a column of runs.parquet.
    Scalars,
    /// Histograms: histograms.parquet.
    Histograms,
}

impl Kind {
    pub const ALL: [Kind; 3] = [Kind::Series, Kind::Scalars, Kind::Histograms];

    /// The key under `[observe]`, as errors and docs spell it.
    pub fn key(self) -> &'static str {
        match self {
            Kind::Series => "series",
            Kind::Scalars => "scalars",
            Kind::Histograms => "histograms",
        }
    }
}

/// One observable as the catalogue lists it.
#[derive(Debug, Clone, Copy)]
pub struct Entry {
    /// The name a descriptor lists.
    pub name: &'static str,
    pub kind: Kind,
    /// The names it writes to its table: its own name, or a pattern whose
    /// `<...>` parts vary (`<low|high>`: one of those words).
    pub writes: &'static str,
    /// Plot axis label; `<...>` parts are those of `writes`, filled in.
    pub label: &'static str,
    /// Unit in reduced units (σ, m, kT); "1" for a pure number.
    pub unit: &'static str,
    /// What the scene and the run must offer (checked before running).
    pub needs: &'static [Need],
    /// One line for `study list` and docs/descriptor.md.
    pub doc: &'static str,
}

/// An observable: its catalogue entry and how a run computes it. Each lives
/// in its own file and has one line in `catalogue.rs`.
pub trait Observable {
    const ENTRY: Entry;
    fn part<const D: usize>(setup: &Setup) -> Part<D>;
}

/// What observables know about a run before it starts.
pub struct Setup {
    /// Index of the piston particle, if the scene has one.
    pub piston: Option<usize>,
}

/// How a run computes one observable.
pub enum Part<const D: usize> {
    /// Read off every sample, in the one pass the sampled observables share;
    /// every value kept, as series.
    Series(Box<dyn Probe<D>>),
    /// Read off every sample like `Series`; only the time averages kept, as
    /// scalars.
    Mean(Box<dyn Probe<D>>),
    /// An observer of its own: it sees the events (or samples) it asks for.
    Observer(Box<dyn Measure<D>>),
}

/// A quantity read off the state at each sample.
pub trait Probe<const D: usize>: Send {
    /// Push this sample's values onto `row`: the same number of values, in
    /// the same order, at every sample.
    fn read(&mut self, s: &Snapshot<D>, row: &mut Row);
    /// The table name of value `k`.
    fn name(&self, k: usize, ctx: &Context) -> String;
}
