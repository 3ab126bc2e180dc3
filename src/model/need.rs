//! What a study or an observable needs from the scene and the run; the
//! descriptor checks say what to add when one is missing.

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Need {
    /// A piston in the scene.
    Piston,
    /// `[run] sample_every`: the quantity is read off samples.
    Sampling,
    /// At least one axis with walls (not periodic).
    Walls,
    /// At least one thermal wall.
    ThermalWalls,
    /// A scene of this dimension (bond orders are defined in one).
    Dimension(usize),
    /// More particles than this many nearest neighbours of each.
    Neighbours(usize),
}
