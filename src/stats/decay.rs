//! How long a decaying excess takes to fall to 1/e of its start, smoothed
//! over a window, and a lower bound on that time when the record ends first.

/// When the excess e(t) (over the level it relaxes to, subtracted by the
/// caller), averaged over a centred window of `window` time units, first
/// falls to 1/e of its starting value, interpolated linearly between
/// samples, from `t[0]`.
///
/// The first passage rather than a fitted exponential: a decay that is not
/// one exponential (fast at first, then ever slower, then wandering) would
/// pull a fit to its late wandering, while the passage is the time to give
/// away 63% of the excess whatever the shape. The window (say one period of
/// an oscillation whose energy this is) removes a ripple within it, and is
/// never longer than the unsmoothed passage; for an exponential it delays
/// the passage by tau ln(sinh(x)/x), x = window/(2 tau): at most 4% of tau.
/// None when the record ends first (see `decay_bound`) or there is no
/// excess to relax.
pub fn relaxation_time(t: &[f64], excess: &[f64], window: f64) -> Option<f64> {
    let start = *excess.first()?;
    if start.is_nan() || start <= 0.0 || t.len() != excess.len() {
        return None;
    }
    // A relaxation faster than the window would be smeared: the window is
    // at most the unsmoothed passage time (ripple makes that early, never late).
    let raw = passage(t, excess, start)?;
    let mut smooth = centred_mean(t, excess, window.min(raw));
    smooth[0] = start;
    passage(t, &smooth, start)
}

/// First time x falls to start/e, interpolated linearly, from t[0].
fn passage(t: &[f64], x: &[f64], start: f64) -> Option<f64> {
    let level = start / std::f64::consts::E;
    (1..t.len()).find_map(|k| {
        let (u, v) = (x[k - 1] - level, x[k] - level);
        (u > 0.0 && v <= 0.0).then(|| t[k - 1] + (t[k] - t[k - 1]) * u / (u - v) - t[0])
    })
}

/// Mean of the samples within window/2 of each sample (fewer at the ends).
fn centred_mean(t: &[f64], x: &[f64], window: f64) -> Vec<f64> {
    let mut prefix = Vec::with_capacity(x.len() + 1);
    prefix.push(0.0);
    for v in x {
        prefix.push(prefix[prefix.len() - 1] + v);
    }
    let half = 0.5 * window.max(0.0);
    let (mut lo, mut hi) = (0, 0);
    (0..t.len())
        .map(|k| {
            while t[lo] < t[k] - half {
                lo += 1;
            }
            while hi < t.len() && t[hi] <= t[k] + half {
                hi += 1;
            }
            (prefix[hi] - prefix[lo]) / (hi - lo) as f64
        })
        .collect()
}

/// A lower bound on the relaxation time of a record too short to show it:
/// with a fraction `left` of the excess still there after `span`, and a
/// decay rate that does not speed up (-ln of the excess concave in t, as
/// the piston's is), 1/e is reached no sooner than span / -ln(left).
pub fn decay_bound(span: f64, left: f64) -> f64 {
    if left >= 1.0 {
        f64::INFINITY
    } else {
        span / -left.ln()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stats::oscillation::tests::{gaussian, times};
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;
    use std::f64::consts::TAU;

    /// An oscillation whose energy decays exactly exponentially, x = a
    /// exp(-t/2tau) cos(omega t), v = -a omega exp(-t/2tau) sin(omega t),
    /// sampled a few times a period in any phase: the kinetic part swings
    /// between 0 and all of it, but K + U decays smoothly and its passage to
    /// 1/e is at tau. Linear interpolation of exp(-t/tau) between samples dt
    /// apart misplaces the passage by at most dt^2 / (8 tau).
    #[test]
    fn exact_exponential_decay_of_an_oscillation_is_recovered() {
        let (tau, omega) = (37.0, 0.9);
        for step in [0.5, 1.7, 4.0, 9.0] {
            let t = times(step, (3.0 * tau / step) as usize);
            let e: Vec<f64> = t
                .iter()
                .map(|s| {
                    let s = s - t[0];
                    let envelope = 3.0 * (-s / (2.0 * tau)).exp();
                    let (x, v) = (
                        envelope * (omega * s).cos(),
                        -envelope * omega * (omega * s).sin(),
                    );
                    0.5 * v * v + 0.5 * omega * omega * x * x
                })
                .collect();
            let got = relaxation_time(&t, &e, 0.0).expect("decays");
            let bound = step * step / (8.0 * tau);
            assert!(
                (got - tau).abs() <= bound,
                "step {step}: {got}, bound {bound}"
            );
        }
    }

    /// The oscillator energy of a fast, large swing ripples within each
    /// period (here by 30%, at twice the oscillation frequency, as at the
    /// turning points): unsmoothed, a ripple trough crosses 1/e early;
    /// averaged over one period the passage is at tau, delayed by the
    /// window's known tau ln(sinh(x)/x), x = period/(2 tau), within the
    /// sampling and edge error (1% of tau here).
    #[test]
    fn ripple_within_a_period_is_averaged_out() {
        let (tau, period, step) = (60.0, 20.0, 0.25);
        let t = times(step, (4.0 * tau / step) as usize);
        let e: Vec<f64> = t
            .iter()
            .map(|s| {
                let s = s - t[0];
                (-s / tau).exp() * (1.0 + 0.3 * (2.0 * TAU * s / period).sin())
            })
            .collect();
        let raw = relaxation_time(&t, &e, 0.0).expect("decays");
        assert!(raw < 0.9 * tau, "a ripple trough passes early: {raw}");
        let got = relaxation_time(&t, &e, period).expect("decays");
        let x = period / (2.0 * tau);
        let expected = tau * (1.0 + (x.sinh() / x).ln());
        assert!((got - expected).abs() < 0.01 * tau, "{got} vs {expected}");
    }

    /// A decay much faster than the window (an overdamped light piston):
    /// the window shrinks to the passage time, so the delay stays within
    /// its 4% bound (plus 1% for averaging discrete samples).
    #[test]
    fn window_never_smears_a_fast_decay() {
        let (tau, step) = (3.0, 0.05);
        let t = times(step, 2000);
        let e: Vec<f64> = t.iter().map(|s| (-(s - t[0]) / tau).exp()).collect();
        let got = relaxation_time(&t, &e, 40.0).expect("decays");
        assert!(got >= tau && got <= 1.052 * tau, "{got}");
    }

    /// Noise on every sample (std sigma = 0.05 of the starting excess A):
    /// near the passage the excess falls at A/(e tau) per unit time, so the
    /// passage moves by about sigma e tau / A (the first of several noisy
    /// passages comes a little early). Over 100 draws the mean lies within
    /// that scale, and within 4 standard errors of it, of tau.
    #[test]
    fn noisy_decay_passage_is_within_its_noise_scale() {
        let (tau, step, sigma, amp) = (20.0, 0.5, 0.1, 2.0);
        let t = times(step, (6.0 * tau / step) as usize);
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let got: Vec<f64> = (0..100)
            .filter_map(|_| {
                let mut e: Vec<f64> = t
                    .iter()
                    .map(|s| amp * (-(s - t[0]) / tau).exp() + sigma * gaussian(&mut rng))
                    .collect();
                e[0] = amp;
                relaxation_time(&t, &e, 0.0)
            })
            .collect();
        assert_eq!(got.len(), 100);
        let mean = got.iter().sum::<f64>() / 100.0;
        let sd = (got.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 99.0).sqrt();
        let scale = sigma * std::f64::consts::E * tau / amp;
        assert!(
            (mean - tau).abs() < scale + 4.0 * sd / 10.0,
            "mean {mean}, sd {sd}"
        );
        assert!(sd < scale, "sd {sd} vs {scale}");
    }

    /// The bound is exact for an exponential and below the truth for a decay
    /// that slows down.
    #[test]
    fn decay_bound_is_a_lower_bound() {
        let tau = 50.0;
        assert!((decay_bound(10.0, (-10.0f64 / tau).exp()) - tau).abs() < 1e-9);
        // exp(-sqrt(t)): slower and slower; reaches 1/e at t = 1.
        assert!(decay_bound(0.25, (-0.5f64).exp()) < 1.0);
        assert_eq!(decay_bound(10.0, 1.2), f64::INFINITY);
    }

    #[test]
    fn records_that_show_no_passage_give_none() {
        let t = times(1.0, 100);
        assert_eq!(relaxation_time(&t, &vec![1.0; 100], 5.0), None);
        let slow: Vec<f64> = t.iter().map(|s| (-(s - 3.0) / 500.0).exp()).collect();
        assert_eq!(relaxation_time(&t, &slow, 5.0), None);
        let negative: Vec<f64> = t.iter().map(|s| -(-(s - 3.0) / 10.0).exp()).collect();
        assert_eq!(relaxation_time(&t, &negative, 5.0), None);
    }
}
