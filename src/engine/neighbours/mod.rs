//! Who can a particle hit next? 1D needs only its two neighbours in the chain
//! (order never changes); 2D and 3D use a cell grid with crossing events.

mod cells;
mod chain;

pub use cells::CellGrid;
pub use chain::Chain;

use super::boundary::SimBox;
use super::particle::Particle;
use super::vector::Vector;

/// Which periodic image of a partner: per axis an offset in {-1, 0, +1}
/// boxes, packed in base 3 with axis 0 as the lowest digit (so 13 is "no
/// shift" in 3D, 4 in 2D, 1 in 1D).
pub type Image = u8;

pub fn no_shift<const D: usize>() -> Image {
    (0..D).fold(0, |code, _| code * 3 + 1)
}

/// The displacement of image `image` for a box of the given size.
#[inline(always)]
pub fn image_shift<const D: usize>(image: Image, size: &Vector<D>) -> Vector<D> {
    let mut code = image;
    let mut shift = [0.0; D];
    for k in 0..D {
        shift[k] = ((code % 3) as f64 - 1.0) * size[k];
        code /= 3;
    }
    shift
}

/// A cell boundary crossing: which axis, and upwards or downwards.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Crossing {
    pub axis: u8,
    pub up: bool,
}

pub trait Neighbourhood<const D: usize>: Sized + Clone + Send {
    /// Index the particles (already validated and, in 1D, sorted).
    fn build(particles: &[Particle<D>], sim_box: &SimBox<D>) -> Result<Self, String>;
    /// Call `f(j, image)` for every particle j that i could hit before its next crossing.
    fn for_each_candidate(&self, i: usize, f: impl FnMut(usize, Image));
    /// When `p` (particle i) next leaves its cell: absolute time and crossing.
    fn next_crossing(&self, i: usize, p: &Particle<D>) -> Option<(f64, Crossing)>;
    /// Move particle i into its next cell; returns true if it wrapped around a
    /// periodic boundary (its stored position moved by a box length).
    fn cross(&mut self, i: usize, crossing: Crossing, p: &mut Particle<D>) -> bool;
}

/// A neighbourhood's state for a save file: what `build` cannot recompute
/// from the particles. In a cell grid that is each particle's cell and the
/// order of the cell lists, which is the order candidates are tried in and so
/// decides which of two events at the same time a particle schedules.
pub trait Persist<const D: usize>: Neighbourhood<D> {
    /// Tags the kind in a save file, so it is only loaded into the same kind.
    const KIND: u32;
    fn state(&self) -> Vec<u32>;
    /// Rebuild for these particles and box, then take on the saved state.
    fn restore(
        particles: &[Particle<D>],
        sim_box: &SimBox<D>,
        state: &[u32],
    ) -> Result<Self, String>;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn image_codes_put_axis_zero_in_the_lowest_digit() {
        // x one box left, y none, z one box right: digits (0, 1, 2) -> 0 + 3 + 18.
        assert_eq!(
            image_shift::<3>(21, &[10.0, 20.0, 30.0]),
            [-10.0, 0.0, 30.0]
        );
        assert_eq!(image_shift::<3>(no_shift::<3>(), &[1.0; 3]), [0.0; 3]);
    }
}
