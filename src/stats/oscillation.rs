//! The frequency of a damped oscillation, from its turning points.

use std::f64::consts::TAU;

/// The early oscillation: its angular frequency, how many full periods
/// measured it, and the samples at the turning points within them (two per
/// period).
#[derive(Debug, Clone, PartialEq)]
pub struct Oscillation {
    pub omega: f64,
    pub periods: usize,
    pub turning: Vec<usize>,
}

/// Angular frequency of the first `periods` full oscillations of x(t).
///
/// Turning points are found with hysteresis: a maximum counts once the
/// signal has fallen `band` below it (a minimum likewise), so jitter smaller
/// than the band makes no extra turning points, and once the oscillation has
/// decayed into the band it stops counting. Between consecutive turning
/// points the signal crosses their midpoint; same-direction crossings are
/// one period apart (exactly so for an exponentially damped oscillation,
/// whose turning points and midpoints shrink by the same factor each period),
/// and the crossing time is interpolated where the signal is steepest. The
/// band is `band_fraction` of the signal's range, so the window is set by
/// the data, not by a theory's period. None when not even one full period
/// stands out of the band.
pub fn oscillation(
    t: &[f64],
    x: &[f64],
    periods: usize,
    band_fraction: f64,
) -> Option<Oscillation> {
    let (lo, hi) = x
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let band = band_fraction * (hi - lo);
    if band.is_nan() || band <= 0.0 || t.len() != x.len() {
        return None;
    }
    let turning = turning_points(x, band, 2 * periods + 2);
    // Crossing k lies between turning points k and k+1.
    let crossings: Vec<f64> = turning
        .windows(2)
        .filter_map(|w| crossing(t, x, w[0], w[1]))
        .collect();
    let full = (crossings.len().saturating_sub(1) / 2).min(periods);
    if full == 0 {
        return None;
    }
    Some(Oscillation {
        omega: TAU * full as f64 / (crossings[2 * full] - crossings[0]),
        periods: full,
        // Crossings 0 and 2 full bound the periods; between them lie
        // turning points 1 to 2 full.
        turning: turning[1..=2 * full].to_vec(),
    })
}

/// Indices of the first `want` turning points, alternating max and min, each
/// confirmed by a reversal of at least `band`. The start is not a turning
/// point (the motion before it is unknown), so an extreme there is dropped.
fn turning_points(x: &[f64], band: f64, want: usize) -> Vec<usize> {
    let mut found = Vec::new();
    // +1: rising, tracking a maximum at `extreme`; -1: falling; 0: not yet known.
    let mut direction = 0i8;
    let (mut low, mut high, mut extreme) = (0usize, 0usize, 0usize);
    for i in 1..x.len() {
        if found.len() >= want {
            break;
        }
        match direction {
            0 => {
                if x[i] < x[low] {
                    low = i;
                }
                if x[i] > x[high] {
                    high = i;
                }
                if x[i] - x[low] >= band {
                    if low > 0 {
                        found.push(low);
                    }
                    (direction, extreme) = (1, i);
                } else if x[high] - x[i] >= band {
                    if high > 0 {
                        found.push(high);
                    }
                    (direction, extreme) = (-1, i);
                }
            }
            1 => {
                if x[i] > x[extreme] {
                    extreme = i;
                } else if x[extreme] - x[i] >= band {
                    found.push(extreme);
                    (direction, extreme) = (-1, i);
                }
            }
            _ => {
                if x[i] < x[extreme] {
                    extreme = i;
                } else if x[i] - x[extreme] >= band {
                    found.push(extreme);
                    (direction, extreme) = (1, i);
                }
            }
        }
    }
    found
}

/// Time at which x first crosses the midpoint of its values at turning
/// points a < b, interpolated linearly between samples.
fn crossing(t: &[f64], x: &[f64], a: usize, b: usize) -> Option<f64> {
    let level = 0.5 * (x[a] + x[b]);
    let rising = x[b] > x[a];
    (a + 1..=b).find_map(|k| {
        let (u, v) = (x[k - 1] - level, x[k] - level);
        let crossed = if rising {
            u < 0.0 && v >= 0.0
        } else {
            u > 0.0 && v <= 0.0
        };
        crossed.then(|| t[k - 1] + (t[k] - t[k - 1]) * u / (u - v))
    })
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// A standard normal draw (Box-Muller).
    pub(crate) fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
        let (u, v): (f64, f64) = (rng.random(), rng.random());
        (-2.0 * (1.0 - u).ln()).sqrt() * (TAU * v).cos()
    }

    /// `n` sample times `step` apart, not starting at zero.
    pub(crate) fn times(step: f64, n: usize) -> Vec<f64> {
        (0..n).map(|k| 3.0 + k as f64 * step).collect()
    }

    /// x = c + a exp(-t/decay) cos(omega t + phase) + noise.
    fn damped(t: &[f64], omega: f64, decay: f64, noise: f64, rng: &mut ChaCha8Rng) -> Vec<f64> {
        t.iter()
            .map(|&s| {
                let s = s - t[0];
                6.0 + 2.0 * (-s / decay).exp() * (omega * s + 0.7).cos() + noise * gaussian(rng)
            })
            .collect()
    }

    /// Noise-free, 20 samples a period, damped by e over three periods: the
    /// sampled turning points miss the true ones by at most a (omega dt)^2/8,
    /// which moves a crossing by dt^2 omega/8 and the frequency by at most
    /// (omega dt)^2 / (8 pi K) relative over K periods (1e-3 here).
    #[test]
    fn damped_oscillation_frequency_within_the_sampling_bound() {
        let omega = 0.3;
        let dt = TAU / omega / 20.0;
        let t = times(dt, 400);
        let mut rng = ChaCha8Rng::seed_from_u64(1);
        let x = damped(&t, omega, 3.0 * TAU / omega, 0.0, &mut rng);
        let got = oscillation(&t, &x, 4, 0.1).expect("oscillates");
        assert_eq!(got.periods, 4);
        let bound = (omega * dt).powi(2) / (8.0 * std::f64::consts::PI * 4.0);
        assert!(
            (got.omega / omega - 1.0).abs() < bound,
            "{got:?}, bound {bound}"
        );
        // The turning points inside the window, half a period apart (to a sample).
        assert_eq!(got.turning.len(), 8);
        for w in got.turning.windows(2) {
            let half = t[w[1]] - t[w[0]];
            assert!((half - 0.5 * TAU / omega).abs() <= dt, "{got:?}");
        }
    }

    /// Strong damping (amplitude down by e every period) and noise of 2% of
    /// the starting amplitude: the band keeps noise from making turning
    /// points, and the estimate stops counting once the oscillation is lost in
    /// the band. Over 200 noise draws the mean is unbiased within 4 standard
    /// errors, and the spread is what crossing-time noise predicts:
    /// sigma_t = noise / slope at each crossing.
    #[test]
    fn noisy_strongly_damped_oscillation_is_unbiased() {
        let omega = 1.0;
        let dt = TAU / omega / 25.0;
        let t = times(dt, 600);
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let draws: Vec<Oscillation> = (0..200)
            .filter_map(|_| {
                let x = damped(&t, omega, TAU / omega, 0.04, &mut rng);
                oscillation(&t, &x, 4, 0.1)
            })
            .collect();
        assert_eq!(draws.len(), 200, "every draw shows at least one period");
        let w: Vec<f64> = draws.iter().map(|d| d.omega / omega).collect();
        let mean = w.iter().sum::<f64>() / w.len() as f64;
        let sd = (w.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (w.len() - 1) as f64).sqrt();
        let se = sd / (w.len() as f64).sqrt();
        assert!((mean - 1.0).abs() < 4.0 * se, "mean {mean} +- {se}");
        // The band (0.1 of a ~2.9 range) lets about two periods count; the
        // last crossing, amplitude ~0.2, moves by noise / slope ~ 0.04 / 0.2
        // time units, i.e. 0.2 / (2 periods * 2 pi) ~ 1.6% of omega.
        assert!(sd < 0.03, "spread {sd}");
        assert!(draws.iter().all(|d| d.periods >= 1 && d.periods <= 4));
        assert!(draws.iter().all(|d| d.turning.len() == 2 * d.periods));
    }

    /// The old estimator's failure: the mean of a strongly damped record is
    /// not the oscillation's centre. A drifting centre and a start far off it
    /// do not bias the turning-point midpoints.
    #[test]
    fn drifting_centre_and_offset_start_do_not_matter() {
        let omega = 0.5;
        let dt = TAU / omega / 30.0;
        let t = times(dt, 500);
        let x: Vec<f64> = t
            .iter()
            .map(|&s| {
                let s = s - t[0];
                2.0 + 0.002 * s + 1.5 * (-s / 60.0).exp() * (omega * s).sin()
            })
            .collect();
        let got = oscillation(&t, &x, 4, 0.1).expect("oscillates");
        assert!((got.omega / omega - 1.0).abs() < 2e-3, "{got:?}");
    }

    #[test]
    fn flat_or_monotone_signals_have_no_frequency() {
        let t = times(1.0, 100);
        assert_eq!(oscillation(&t, &vec![1.0; 100], 4, 0.1), None);
        let ramp: Vec<f64> = t.iter().map(|s| s * 0.1).collect();
        assert_eq!(oscillation(&t, &ramp, 4, 0.1), None);
    }
}
