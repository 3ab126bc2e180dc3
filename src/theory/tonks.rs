//! Hard rods (Tonks 1936, Phys. Rev. 50, 955): the exact equation of state.
//! N rods of length sigma on a line of length L have the configurational
//! integral of N points on the free length L - N sigma, so at any N
//! beta P (L - N sigma) = N, i.e. Z = beta P / rho = 1 / (1 - eta) with
//! eta = N sigma / L. Between walls this holds for every N when L is the
//! box length (the centres reach L - sigma, the rods exclude (N - 1) sigma
//! more); it holds at every density below close packing (no transition in 1D).

/// Compressibility factor of hard rods at packing fraction `eta` (< 1).
pub fn z(eta: f64) -> f64 {
    1.0 / (1.0 - eta)
}

#[cfg(test)]
mod tests {
    #[test]
    fn known_values() {
        assert_eq!(super::z(0.0), 1.0);
        assert!((super::z(0.5) - 2.0).abs() < 1e-15);
        assert!((super::z(0.8) - 5.0).abs() < 1e-12);
    }
}
