//! One relaxation run: a gas started at T0 between walls at T_w. Its
//! temperature against time, the 1/e time, the first stretch against the
//! exact initial exchange rate, and where it settles.

use super::gas::Gas;
use crate::theory::heat::WellMixed;

/// kT = 2K/(d N) from the kinetic energy series (walls: d N free degrees).
pub fn temperatures(gas: &Gas, energy: &[f64]) -> Vec<f64> {
    let f = gas.dimension as f64 * gas.particles;
    energy.iter().map(|k| 2.0 * k / f).collect()
}

/// First time (T - T_w)/(T0 - T_w) falls to `level`, interpolated linearly
/// between the samples around the crossing; NaN if it never does.
pub fn passage(t: &[f64], temp: &[f64], wall: f64, level: f64) -> f64 {
    let Some(&t0) = temp.first() else {
        return f64::NAN;
    };
    let excess = |x: f64| (x - wall) / (t0 - wall);
    for i in 1..temp.len().min(t.len()) {
        let (a, b) = (excess(temp[i - 1]), excess(temp[i]));
        if b <= level {
            let w = (a - level) / (a - b);
            return t[i - 1] + w * (t[i] - t[i - 1]);
        }
    }
    f64::NAN
}

/// The well-mixed model from the run's own start.
pub fn model(gas: &Gas, wall: f64, start: f64) -> WellMixed {
    WellMixed {
        rate: gas.exchange_rate(),
        wall,
        start,
    }
}

/// Change of T over the first samples up to `t1` over the change the model
/// predicts there: its first-order term is exact (the start is a uniform
/// Maxwellian, whatever the density), so this tends to 1 as t1 -> 0.
pub fn initial_ratio(t: &[f64], temp: &[f64], m: &WellMixed, t1: f64) -> f64 {
    // The first sample at or after t1.
    let i = t.iter().position(|&x| x >= t1);
    match (temp.first(), i.and_then(|i| Some((t[i], *temp.get(i)?)))) {
        (Some(&t0), Some((tt, x))) if tt > 0.0 => (x - t0) / (m.temperature(tt) - t0),
        _ => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn passage_is_interpolated_for_cooling_and_heating() {
        let t = [0.0, 1.0, 2.0];
        // Cooling from 2 to 1: excess 1, 0.5, 0.25.
        let e = (-1f64).exp();
        let want = 1.0 + (0.5 - e) / 0.25;
        assert!((passage(&t, &[2.0, 1.5, 1.25], 1.0, e) - want).abs() < 1e-12);
        // Heating from 0.5 to 1: excess 1, 0.5, 0.25 again.
        assert!((passage(&t, &[0.5, 0.75, 0.875], 1.0, e) - want).abs() < 1e-12);
        assert!(passage(&t, &[2.0, 1.9, 1.8], 1.0, e).is_nan());
    }
}
