//! Hard disks, Henderson's equation of state (D. Henderson 1975, Mol. Phys.
//! 30, 971): Z = (1 + eta^2 / 8) / (1 - eta)^2. Expanded, it gives
//! B2 exactly and B3, B4 to 0.1 % and 0.2 % (1 + 2 eta + 3.125 eta^2 +
//! 4.25 eta^3 against 3.1280 and 4.2579), and the fluid's simulated pressure to ~1e-3 up to
//! eta ~ 0.4; above it is high (by ~0.5 % at 0.5, where this project's runs
//! give Z = 4.10); it knows nothing of the liquid-hexatic transition
//! (eta ~ 0.70-0.72) and is meaningless above it.

/// Compressibility factor of the hard-disk fluid at packing fraction `eta`.
pub fn z(eta: f64) -> f64 {
    (1.0 + eta * eta / 8.0) / ((1.0 - eta) * (1.0 - eta))
}

#[cfg(test)]
mod tests {
    #[test]
    fn known_values() {
        assert_eq!(super::z(0.0), 1.0);
        // (1 + 0.01125) / 0.49
        assert!((super::z(0.3) - 2.063_775_510_204_08).abs() < 1e-12);
        // Low-density slope: B2 rho = 2 eta, as for the virial series.
        let h = 1e-6;
        assert!(((super::z(h) - 1.0) / h - 2.0).abs() < 1e-5);
    }
}
