//! Hard spheres, Carnahan and Starling (J. Chem. Phys. 51, 635, 1969):
//! Z = (1 + eta + eta^2 - eta^3) / (1 - eta)^3, from rounding the virial
//! coefficients to b_k = k^2 + k - 2 (B4 = 18 v^3 against the exact
//! 18.365). It is 0.258 % below the virial series through B10 with its tail
//! at eta = 0.3 (see `sphere_virial`, `carnahan_starling_kolafa`) and is a fluid
//! equation: above freezing (eta = 0.494) the stable phase is the crystal.

/// Compressibility factor of the hard-sphere fluid at packing fraction `eta`.
pub fn z(eta: f64) -> f64 {
    (1.0 + eta + eta * eta - eta.powi(3)) / (1.0 - eta).powi(3)
}

#[cfg(test)]
mod tests {
    #[test]
    fn known_values() {
        assert_eq!(super::z(0.0), 1.0);
        // 1.363 / 0.343
        assert!((super::z(0.3) - 3.973_760_932_944_606).abs() < 1e-12);
        // B2 rho = 4 eta, B3 rho^2 = 10 eta^2 (exact).
        let h = 1e-4;
        assert!(((super::z(h) - 1.0 - 4.0 * h) / (h * h) - 10.0).abs() < 1e-2);
    }
}
