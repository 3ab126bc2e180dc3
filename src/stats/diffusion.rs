//! A self-diffusion coefficient from a mean-squared displacement.

use super::line::line;

/// The fit of the mean-squared displacement starts at this fraction of the
/// longest lag measured.
pub const FIT_FROM: f64 = 0.25;

/// Self-diffusion coefficient from a mean-squared displacement along one
/// axis against lag: the slope of the straight line through the lags from
/// `FIT_FROM` of the longest on, over 2 (MSD = 2 D (t - t_memory) once the
/// velocity has forgotten its start). NaN without enough finite points.
pub fn diffusion(lag: &[f64], msd: &[f64]) -> (f64, f64) {
    let longest = lag.iter().copied().fold(0.0, f64::max);
    let (x, y): (Vec<f64>, Vec<f64>) = lag
        .iter()
        .zip(msd)
        .filter(|(t, m)| **t >= FIT_FROM * longest && m.is_finite())
        .map(|(t, m)| (*t, *m))
        .unzip();
    if x.len() < 3 {
        return (f64::NAN, f64::NAN);
    }
    let (slope, _, _) = line(&x, &y, None);
    (slope / 2.0, x[0])
}
