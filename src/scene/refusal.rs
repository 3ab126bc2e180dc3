//! Why particles cannot be placed, found the same way by the scene's checks
//! (from the spec, before anything runs) and by the placements (from the
//! particles drawn): the species at fault, whether its count or its region
//! is to blame, what is wrong and what would be right.

use std::fmt;

#[derive(Debug, Clone, PartialEq)]
pub struct Refusal {
    /// Index of the species at fault.
    pub species: usize,
    pub blame: Blame,
    pub message: String,
    pub hint: String,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Blame {
    /// Too many particles (or too large) for the room they have.
    Count,
    /// The region: too small for a particle, or where it cannot be.
    Region,
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}; {}", self.message, self.hint)
    }
}
