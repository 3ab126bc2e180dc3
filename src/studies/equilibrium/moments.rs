//! A Gaussian fit to a histogram by its moments (MacKay's djcmhisto gives
//! "a Gaussian fit ... the mean and standard deviation"), and its excess
//! kurtosis: the number that tells a finite-N law from the Gaussian.
//! Binning adds w^2/12 to the variance; Sheppard's corrections take it out.

use crate::model::run_output::Histogram;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Moments {
    pub mean: f64,
    pub std: f64,
    /// mu4 / mu2^2 - 3: 0 for a Gaussian.
    pub excess_kurtosis: f64,
}

/// Moments of the counts at the bin centres, corrected for the (equal)
/// bin width.
pub fn of(h: &Histogram) -> Moments {
    let centres: Vec<f64> = h.lo.iter().zip(&h.hi).map(|(a, b)| 0.5 * (a + b)).collect();
    let w = h.hi.first().zip(h.lo.first()).map_or(0.0, |(b, a)| b - a);
    let count: f64 = h.count.iter().sum();
    let moment = |f: &dyn Fn(f64) -> f64| {
        let terms = centres.iter().zip(&h.count).map(|(x, c)| c * f(*x));
        terms.sum::<f64>() / count
    };
    let mean = moment(&|x| x);
    let m2 = moment(&|x| (x - mean).powi(2));
    let m4 = moment(&|x| (x - mean).powi(4));
    let var = m2 - w * w / 12.0;
    let m4c = m4 - w * w * m2 / 2.0 + 7.0 * w.powi(4) / 240.0;
    Moments {
        mean,
        std: var.max(0.0).sqrt(),
        excess_kurtosis: m4c / (var * var) - 3.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::theory::maxwell::normal_cdf;

    /// A Gaussian binned into 40 bins of width 0.3 sigma: the corrected
    /// moments are the Gaussian's to well under a percent.
    #[test]
    fn binned_gaussian() {
        let (mu, s, w) = (0.4, 1.3, 0.3 * 1.3);
        let lo: Vec<f64> = (0..60).map(|b| mu - 30.0 * w + b as f64 * w).collect();
        let hi: Vec<f64> = lo.iter().map(|x| x + w).collect();
        let count = lo
            .iter()
            .zip(&hi)
            .map(|(a, b)| 1e6 * (normal_cdf(*b, mu, s) - normal_cdf(*a, mu, s)))
            .collect();
        let m = of(&Histogram {
            observable: "x".into(),
            lo,
            hi,
            count,
        });
        assert!((m.mean - mu).abs() < 1e-9);
        assert!((m.std / s - 1.0).abs() < 1e-3, "{}", m.std);
        assert!(m.excess_kurtosis.abs() < 1e-2, "{}", m.excess_kurtosis);
    }
}
