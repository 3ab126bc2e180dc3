//! Why a run stopped short of where it was asked to stop: its clock stood
//! still, or it spent the events it was allowed. Either way it cannot go on,
//! and the run loop fails the run with this as the reason.

use std::fmt;

/// A run that cannot reach its `Stop`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Halt {
    /// `events` events in a row at absolute time `time` (NaN when the next
    /// event's time was not a number): a particle caged with no room to
    /// move, or a scene whose numbers the clock cannot resolve, repeats
    /// events at one instant forever.
    Stalled { time: f64, events: u64 },
    /// The `limit` of events allowed was spent (a run stopped by a
    /// collision count whose pairs meet far more rarely than expected).
    Spent { limit: u64, collisions: u64 },
    /// No event will ever come (nothing moves), with only `collisions` pair
    /// collisions of those a `Stop::Collisions` asked for.
    Still { collisions: u64 },
}

/// Events in a row at one instant that a system of `n` particles may take
/// before its clock counts as stalled. Simultaneous events are legitimate
/// (a lattice started with equal speeds, a chain of rods in contact passing
/// an impulse along), but they come in numbers of the order of `n`; a
/// million more is ~0.1 s of events.
pub fn stall_bound(n: usize) -> u64 {
    1_000_000 + 100 * n as u64
}

impl fmt::Display for Halt {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            Halt::Stalled { time, events } if time.is_nan() => write!(
                f,
                "the clock failed: the next event's time is not a number (after {events} \
                 events at one instant); the box is too large or too small for the \
                 particles' sizes and speeds to be resolved"
            ),
            Halt::Stalled { time, events } => write!(
                f,
                "the clock stopped at t = {time}: {events} events in a row at that instant \
                 (a particle caged with no room to move, e.g. between immovable particles \
                 in contact, or sizes and speeds the clock cannot resolve)"
            ),
            Halt::Spent { limit, collisions } => write!(
                f,
                "stopped after {limit} events with only {collisions} pair collisions: its \
                 particles meet far more rarely than expected, so the collision count it \
                 asks for may never come"
            ),
            Halt::Still { collisions } => write!(
                f,
                "nothing moves any more: no event will ever come, after only {collisions} \
                 pair collisions of those asked for"
            ),
        }
    }
}
