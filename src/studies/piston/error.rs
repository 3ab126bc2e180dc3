//! The error model of the frequency ratio (measured frequency over the
//! adiabatic prediction along the measured window), for rods (1D).
//!
//! The frequency is measured over the first `window_periods` full periods,
//! however long the run: one run's scatter does not shrink with its length
//! (exponent 0), only replicas buy error. How much one run scatters is not
//! a simple law: the prediction already follows each run's own gas, so what
//! is left is the non-adiabatic part of the motion, which falls steeply
//! with the piston's mass (about as 1/M from M = 1000 on, faster below) and
//! grows with the gas below M ~ 1000. So the model is the scatter measured
//! by the accuracy study's `headline-piston-m*` cases (mackay-piston, piston
//! energy 10 kT, seed 15, 32 replicas each) on a grid of masses and gas
//! sizes, read between them on log-log axes and held at the grid's edges.

use crate::model::descriptor::Descriptor;
use crate::stats::error_model::{ErrorModel, log_interpolate, within};

/// Piston masses and rods per side of the calibration grid.
const MASSES: [f64; 4] = [10.0, 100.0, 1000.0, 10000.0];
const PER_SIDE: [f64; 2] = [5.0, 20.0];
/// One run's relative scatter at each (per side, mass), measured with 32
/// replicas each (64 at M = 100, 5 a side: two run lengths pooled).
const SCATTER: [[f64; 4]; 2] = [
    [0.084, 0.0060, 0.00082, 0.000133],
    [0.182, 0.0085, 0.00099, 0.0000784],
];
/// The largest relative ± of those (from each point's fourth moment).
const UNCERTAINTY: f64 = 0.18;

pub fn error_model(d: &Descriptor) -> Option<ErrorModel> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    if scene.dimension().ok()? != 1 {
        return None;
    }
    let piston = scene.piston.as_ref()?;
    let all = scene.species.iter().map(|s| s.count).sum::<usize>() as f64;
    let side = piston.per_side.map_or(all / 2.0, |k| k as f64);
    if side < 1.0 || piston.mass.is_nan() || piston.mass <= 0.0 {
        return None;
    }
    let rows: Vec<f64> = SCATTER
        .iter()
        .map(|row| log_interpolate(&MASSES, row, piston.mass))
        .collect();
    let scatter = log_interpolate(&PER_SIDE, &rows, side);
    let inside = within(&MASSES, piston.mass) && within(&PER_SIDE, side);
    Some(ErrorModel {
        result: "frequency_ratio",
        label: "piston frequency ratio",
        scatter,
        uncertainty: UNCERTAINTY,
        length_exponent: 0.0,
        basis: format!(
            "one run's scatter measured for MacKay's rods at M = 10–10⁴, 5 and 20 a side (accuracy study), \
             read at M = {}, {side} a side{}",
            piston.mass,
            if inside {
                ""
            } else {
                " (outside the grid: its nearest edge)"
            }
        ),
    })
}
