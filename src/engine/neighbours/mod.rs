//! Who can a particle hit next? 1D needs only its two neighbours in the chain
//! (order never changes); 2D and 3D keep a neighbour list per particle,
//! renewed when the particle has moved a shell's width.

mod centres;
mod chain;
mod grid;
mod lists;
mod store;

pub use chain::Chain;
pub use lists::{NeighbourList, layout};

use super::bodies::Body;
use super::boundary::SimBox;
use super::particle::Particle;
use super::prefetch::{Lines, Read};
use super::vector::Vector;

/// Which periodic image of a partner: per axis an offset in {-1, 0, +1}
/// boxes, packed in base 3 with axis 0 as the lowest digit (so 13 is "no
/// shift" in 3D, 4 in 2D, 1 in 1D). `PLANE` marks a pair with a plane.
pub type Image = u8;

/// The image code of a pair one of which is a plane perpendicular to axis 0.
pub const PLANE: Image = 31;

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

/// The vector from a point at `x_i` to one at `x_j` seen as image `image`
/// (`shifts` by image code). A plane spans every axis but 0, so a pair with a
/// plane is separated along axis 0 only; `planes` says whether that case can
/// arise at all, and compiles it out when it cannot.
#[inline(always)]
pub fn separation<const D: usize>(
    x_i: &Vector<D>,
    x_j: &Vector<D>,
    image: Image,
    shifts: &[Vector<D>],
    planes: bool,
) -> Vector<D> {
    if planes && image == PLANE {
        std::array::from_fn(|k| if k == 0 { x_j[0] - x_i[0] } else { 0.0 })
    } else {
        let s = &shifts[image as usize];
        std::array::from_fn(|k| x_j[k] + s[k] - x_i[k])
    }
}

pub trait Neighbourhood<const D: usize>: Sized + Clone + Send {
    /// Whether a plane (a piston wall) can take part. A neighbourhood without
    /// planes compiles every plane branch of the event loop away.
    const PLANES: bool = false;
    /// Index the particles (already validated and, in 1D, sorted).
    fn build(particles: &[Particle<D>], sim_box: &SimBox<D>) -> Result<Self, String>;
    /// Every particle j (as image `image`) that i could hit before its next renewal.
    fn candidates(&self, i: usize) -> impl Iterator<Item = (usize, Image)>;
    /// Whether i could reach the wall on the high (or low) side of an axis
    /// before anything else. Only a chain knows better than "yes": on a line
    /// only its end particles can.
    #[inline(always)]
    fn can_reach_wall(&self, _i: usize, _high: bool) -> bool {
        true
    }
    /// Start loading i's neighbourhood, which will be read `when` (a hint).
    #[inline(always)]
    fn prefetch(&self, _i: usize, _when: Read) {}
    /// Start loading what renewing `p` (particle i) at time `t` will read
    /// (a hint; what it works out to ask may be kept for the renewal).
    #[inline(always)]
    fn prefetch_renewal(&mut self, _i: usize, _p: &Body<D>, _t: f64) {}
    /// When `p` (particle i) next needs its neighbourhood renewed (absolute time).
    fn next_renewal(&self, i: usize, p: &Body<D>) -> Option<f64>;
    /// Whether `p` (particle i) is still inside its neighbourhood at time `t`:
    /// then its renewal comes later (a line leaves a ball only once), and
    /// need not be computed. "No" when unsure.
    #[inline(always)]
    fn inside_at(&self, _i: usize, _p: &Body<D>, _t: f64) -> bool {
        false
    }
    /// Make the changes to other particles' lists that the last renewal
    /// left undone, so that the lines they write load meanwhile. Until
    /// then only the renewed particle's own neighbourhood is up to date.
    #[inline(always)]
    fn catch_up(&mut self) {}
    /// Renew particle i's neighbourhood at time `now` (moving `p` there);
    /// returns true if its stored position jumped by a box length. With
    /// `bodies`, ask for the new partners' bodies as soon as they are found,
    /// so that they load while the other lists change (a hint).
    fn renew(&mut self, i: usize, p: &mut Body<D>, now: f64, bodies: Option<Lines>) -> bool;
}

/// A neighbourhood's state for a save file: what `build` cannot recompute
/// from the particles.
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
