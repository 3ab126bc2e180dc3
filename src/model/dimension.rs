//! The one place a dimension known only at run time becomes the
//! `const D: usize` that code generic over it needs.

/// Work written once for every dimension: [`in_dimension`] runs it in the
/// dimension a scene asks for.
pub trait ForDimension {
    /// What the work gives back, the same in every dimension.
    type Output;
    /// The work in dimension `D` (1, 2 or 3).
    fn run<const D: usize>(self) -> Self::Output;
}

/// `work` in dimension `d`, or the reason it cannot run (the engine has
/// rods, disks and spheres only).
pub fn in_dimension<W: ForDimension>(d: usize, work: W) -> Result<W::Output, String> {
    match d {
        1 => Ok(work.run::<1>()),
        2 => Ok(work.run::<2>()),
        3 => Ok(work.run::<3>()),
        d => Err(format!("scene.dimension = {d}; use 1, 2 or 3")),
    }
}
