//! Hard spheres, the Carnahan-Starling-Kolafa equation (Kolafa's correction
//! of Carnahan-Starling, published in T. Boublík and I. Nezbeda, Collect.
//! Czech. Chem. Commun. 51, 2301 (1986)):
//! Z = (1 + eta + eta^2 - (2/3)(eta^3 + eta^4)) / (1 - eta)^3.
//! It gives B2 and B3 exactly and B4 = 18.333 v^3 (exact 18.365, Carnahan-
//! Starling 18), and at eta = 0.3 it is within 6e-5 of the virial series
//! through B10 with its tail (`sphere_virial::resummed`), where Carnahan-
//! Starling is 0.258 % low. (It is not the Kolafa-Labik-Malijevsky equation
//! of 2004, a longer fit in eta/(1 - eta).) It is a fluid equation: above freezing
//! (eta = 0.494) the stable phase is the crystal.

/// Compressibility factor of the hard-sphere fluid at packing fraction `eta`.
pub fn z(eta: f64) -> f64 {
    let e2 = eta * eta;
    (1.0 + eta + e2 - 2.0 / 3.0 * (e2 * eta + e2 * e2)) / (1.0 - eta).powi(3)
}

#[cfg(test)]
mod tests {
    use crate::theory::{carnahan_starling, sphere_virial};

    #[test]
    fn known_values() {
        assert_eq!(super::z(0.0), 1.0);
        // (1.39 - (2/3)(0.027 + 0.0081)) / 0.343
        assert!((super::z(0.3) - 3.984_256_559_766_764).abs() < 1e-12);
        // Above Carnahan-Starling by 0.26 % at 0.3.
        let cs = carnahan_starling::z(0.3);
        assert!((super::z(0.3) / cs - 1.0 - 0.002_64).abs() < 1e-4);
        // Within 6e-5 of the resummed virial series there.
        assert!((super::z(0.3) / sphere_virial::resummed(0.3) - 1.0).abs() < 6e-5);
    }

    #[test]
    fn virial_coefficients() {
        // Z = 1 + 4 eta + 10 eta^2 + (55/3) eta^3 + ...: the eta^3
        // coefficient is B4 / v^3 = 18.333 against 18.3648 exact.
        let h: f64 = 1e-3;
        let b4 = (super::z(h) - 1.0 - 4.0 * h - 10.0 * h * h) / h.powi(3);
        assert!((b4 - 55.0 / 3.0).abs() < 0.1, "{b4}");
    }
}
