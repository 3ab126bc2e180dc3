//! The error model of the relaxation time of the left fraction, a
//! transient (a longer run buys nothing, exponent 0; only replicas do).
//! The left fraction of N particles fluctuates by about 1/(2√N) about its
//! mean curve, and a crossing time by that over the curve's slope there:
//! one run's relative scatter is k/√N, k set by the curve's shape. k is
//! measured for nearly collisionless disks by the accuracy study's
//! `headline-expansion-n*` cases (radius 0.05 in the 40 x 40 box, seed 15,
//! 32 replicas each). A colliding gas relaxes more steeply and scatters
//! less (k = 0.75 against 1.4 at N = 400 with diameter 1, a one-off check),
//! so the model errs on the wide side there.

use crate::model::descriptor::Descriptor;
use crate::stats::error_model::{ErrorModel, log_interpolate, within};

/// Particles and k = one run's relative scatter times √N, measured.
const PARTICLES: [f64; 3] = [25.0, 100.0, 400.0];
/// (25: two run lengths pooled, 64 runs; 32 at the others.) k falls with
/// N: in small systems the noise brings crossings forward by more.
const K: [f64; 3] = [1.97, 1.66, 1.24];
/// The largest relative ± of those (from each point's fourth moment).
const UNCERTAINTY: f64 = 0.15;

pub fn error_model(d: &Descriptor) -> Option<ErrorModel> {
    let scene = crate::scene::resolve(&d.scene).ok()?;
    let n = scene.species.iter().map(|s| s.count).sum::<usize>() as f64;
    if n < 1.0 || scene.piston.is_some() {
        return None;
    }
    let k = log_interpolate(&PARTICLES, &K, n);
    Some(ErrorModel {
        result: "relaxation_time",
        label: "expansion relaxation time",
        scatter: k / n.sqrt(),
        uncertainty: UNCERTAINTY,
        length_exponent: 0.0,
        basis: format!(
            "one run's scatter k/√N, k = {k:.2} measured for nearly collisionless disks at N = 25–400 \
             (accuracy study){}; a colliding gas scatters less",
            if within(&PARTICLES, n) {
                ""
            } else {
                ", held beyond"
            }
        ),
    })
}
