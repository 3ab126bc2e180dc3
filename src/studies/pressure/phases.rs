//! Where each dimension's fluid is the stable phase: the report labels a
//! point beyond it instead of hiding it.
//! - Rods: no transition at any density (Tonks: the free energy is analytic
//!   below close packing).
//! - Disks: fluid up to 0.700, fluid-hexatic coexistence to 0.716, hexatic
//!   to 0.720, solid above (E. P. Bernard and W. Krauth, Phys. Rev. Lett.
//!   107, 155704 (2011); Engel et al., Phys. Rev. E 87, 042134 (2013)). A
//!   finite periodic box in the coexistence range shows a pressure loop.
//! - Spheres: fluid up to freezing at 0.494, fluid-crystal coexistence to
//!   melting at 0.545, crystal above (Hoover and Ree 1968); a fluid above
//!   0.494 is metastable and may crystallise during a run.

/// Where the disks' fluid ends (Bernard and Krauth 2011).
pub const DISK_FLUID_ENDS: f64 = 0.700;

/// Packing fractions within this of a boundary count as on it (box lengths
/// are written to 10 digits, so a point meant at 0.72 is 0.72 + 1e-10).
const SAME: f64 = 1e-7;

/// The phase a point of dimension `d` at packing fraction `eta` is in at
/// equilibrium, as a short label.
pub fn label(d: usize, eta: f64) -> &'static str {
    let eta = eta - SAME;
    match d {
        1 => "fluid",
        2 if eta <= DISK_FLUID_ENDS => "fluid",
        2 if eta <= 0.716 => "fluid-hexatic coexistence",
        2 if eta <= 0.720 => "hexatic",
        2 => "solid",
        _ if eta <= 0.494 => "fluid",
        _ if eta <= 0.545 => "coexistence (fluid metastable)",
        _ => "crystal (fluid metastable)",
    }
}

/// Whether a fluid equation of state describes the equilibrium state.
pub fn is_fluid(d: usize, eta: f64) -> bool {
    label(d, eta) == "fluid"
}

#[cfg(test)]
mod tests {
    #[test]
    fn boundaries() {
        assert!(super::is_fluid(1, 0.9));
        assert!(super::is_fluid(2, 0.7));
        assert_eq!(super::label(2, 0.71), "fluid-hexatic coexistence");
        assert_eq!(super::label(2, 0.74), "solid");
        assert!(super::is_fluid(3, 0.494));
        assert!(super::is_fluid(2, 0.700_000_000_1));
        assert_eq!(super::label(2, 0.720_000_000_1), "hexatic");
        assert!(!super::is_fluid(3, 0.5));
    }
}
