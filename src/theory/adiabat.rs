//! The adiabat of a hard-particle fluid: how its temperature follows its
//! density when it expands without exchanging heat, in local equilibrium.
//!
//! The energy of hard particles is all kinetic, so their entropy per
//! particle is the ideal gas's plus an excess that depends on density
//! only: s / k = (d/2) ln kT - ln n - F(eta) + const, with F(eta) the
//! integral of (Z - 1) / eta from 0 to eta. At constant s,
//!
//!   kT / kT0 = (n / n0)^(2/d) exp((2/d) (F(eta) - F(eta0))),
//!
//! the ideal gas's adiabat (gamma = (d + 2) / d) times a factor below 1 on
//! expansion: a dense fluid cools more than an ideal gas, since part of
//! its entropy is in the room the particles have. F from the equations of
//! state the project uses: Tonks (rods, exact: Z = 1/(1 - eta)),
//! Henderson (disks, Z = (1 + eta^2/8)/(1 - eta)^2) and Carnahan-Starling
//! (spheres).

/// F(eta) = integral of (Z - 1) / eta: minus the excess entropy per
/// particle over k (NaN outside dimensions 1 to 3).
pub fn excess_free_energy(dimension: usize, eta: f64) -> f64 {
    match dimension {
        1 => -(1.0 - eta).ln(),
        // (Z - 1)/eta = (2 - 7 eta/8)/(1 - eta)^2, integrated.
        2 => 9.0 / 8.0 * eta / (1.0 - eta) - 7.0 / 8.0 * (1.0 - eta).ln(),
        3 => eta * (4.0 - 3.0 * eta) / (1.0 - eta).powi(2),
        _ => f64::NAN,
    }
}

/// kT / kT0 of a fluid brought adiabatically from packing fraction `eta0`
/// to `eta` (number densities in the same ratio).
pub fn temperature_ratio(dimension: usize, eta0: f64, eta: f64) -> f64 {
    let d = dimension as f64;
    let f = |e: f64| excess_free_energy(dimension, e);
    (eta / eta0).powf(2.0 / d) * ((2.0 / d) * (f(eta) - f(eta0))).exp()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// F' = (Z - 1)/eta for each equation of state, by a central difference.
    #[test]
    fn the_excess_free_energy_integrates_the_equation_of_state() {
        let z = [
            |e: f64| 1.0 / (1.0 - e),
            |e: f64| (1.0 + e * e / 8.0) / (1.0 - e).powi(2),
            |e: f64| (1.0 + e + e * e - e.powi(3)) / (1.0 - e).powi(3),
        ];
        for (i, z) in z.iter().enumerate() {
            let d = i + 1;
            assert_eq!(excess_free_energy(d, 0.0), 0.0);
            for eta in [0.05, 0.2, 0.4] {
                let h = 1e-6;
                let slope =
                    (excess_free_energy(d, eta + h) - excess_free_energy(d, eta - h)) / (2.0 * h);
                assert!((slope - (z(eta) - 1.0) / eta).abs() < 1e-6, "{d}D at {eta}");
            }
        }
    }

    #[test]
    fn dilute_gas_follows_the_ideal_adiabat_and_dense_fluid_cools_more() {
        for d in 1..=3 {
            let ideal = 0.5f64.powf(2.0 / d as f64);
            assert!((temperature_ratio(d, 2e-9, 1e-9) - ideal).abs() < 1e-8);
            assert!(temperature_ratio(d, 0.4, 0.2) < ideal);
        }
    }
}
