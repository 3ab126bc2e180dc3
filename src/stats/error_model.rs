//! What a study expects the error bar of its headline result to be, before
//! anything runs: one run's relative scatter over replicas at a descriptor,
//! and how that scatter changes with the run's length. Each study that
//! gives one (`Study::error_model`) derives it in its own folder (`error.rs`)
//! from what the descriptor sets, with constants measured by the accuracy
//! study's seeded `headline-*` cases (studies/accuracy.toml); the accuracy
//! report measures them again beside the model, and `study validate`
//! prints the error bars the plan will have.

/// One run's relative scatter of a result and how it scales.
#[derive(Debug, Clone, PartialEq)]
pub struct ErrorModel {
    /// The run result (column of runs.parquet) it is about.
    pub result: &'static str,
    /// How reports and `study validate` name it.
    pub label: &'static str,
    /// Standard deviation of one run's value over replicas, relative to
    /// the mean, at this descriptor.
    pub scatter: f64,
    /// Relative uncertainty of `scatter` itself (from the calibration runs'
    /// count; the model's own assumptions come on top where it extrapolates).
    pub uncertainty: f64,
    /// One run's scatter goes as (run length)^exponent: −1/2 for a time
    /// average over runs longer than its correlation time, 0 for a result
    /// read off a transient (longer runs buy nothing; only replicas do).
    pub length_exponent: f64,
    /// Where the numbers come from and where they stop holding.
    pub basis: String,
}

impl ErrorModel {
    /// Relative standard error of the mean over `replicas` runs.
    pub fn stderr(&self, replicas: u32) -> f64 {
        self.scatter / f64::from(replicas.max(1)).sqrt()
    }

    /// Replicas for a relative standard error `target` (at least 2, for an
    /// error bar).
    pub fn replicas_for(&self, target: f64) -> f64 {
        (self.scatter / target).powi(2).ceil().max(2.0)
    }
}

/// Relative uncertainty of a standard deviation estimated from `n`
/// independent values of a normal variable: 1/sqrt(2(n − 1)).
pub fn scatter_uncertainty(n: usize) -> f64 {
    if n < 2 {
        f64::INFINITY
    } else {
        1.0 / (2.0 * (n as f64 - 1.0)).sqrt()
    }
}

/// Relative uncertainty of the standard deviation of `values`, from their
/// own fourth moment: Var(s²) ≈ (μ₄ − σ⁴ (n − 3)/(n − 1)) / n, so
/// δs/s ≈ ½ √((κ − (n − 3)/(n − 1)) / n) with κ = μ₄/σ⁴. For a normal
/// variable (κ = 3) it is about 1/√(2(n − 1)); a heavy tail (a few long
/// mixing times, a run whose piston swung oddly) makes it larger, which the
/// normal formula would hide.
pub fn scatter_uncertainty_of(values: &[f64]) -> f64 {
    let n = values.len();
    if n < 4 {
        return scatter_uncertainty(n);
    }
    let nf = n as f64;
    let mean = values.iter().sum::<f64>() / nf;
    let m2 = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / nf;
    let m4 = values.iter().map(|v| (v - mean).powi(4)).sum::<f64>() / nf;
    if m2 <= 0.0 {
        return scatter_uncertainty(n);
    }
    let kurtosis = m4 / (m2 * m2);
    let excess = (kurtosis - (nf - 3.0) / (nf - 1.0)).max(0.0);
    // Never below the normal variable's.
    (0.5 * (excess / nf).sqrt()).max(scatter_uncertainty(n))
}

/// Linear interpolation of `ys` at `x` between the nodes `xs` (increasing),
/// on log-log axes, held at the end values outside them: measured scatters
/// at a few calibration points, read between them.
pub fn log_interpolate(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let n = xs.len().min(ys.len());
    if n == 0 {
        return f64::NAN;
    }
    if x <= xs[0] || n == 1 {
        return ys[0];
    }
    if x >= xs[n - 1] {
        return ys[n - 1];
    }
    let i = xs[..n].iter().rposition(|&a| a <= x).unwrap_or(0);
    if xs[i] == x {
        return ys[i];
    }
    let w = (x / xs[i]).ln() / (xs[i + 1] / xs[i]).ln();
    (ys[i].ln() * (1.0 - w) + ys[i + 1].ln() * w).exp()
}

/// Whether `x` lies within the nodes (else the model holds the nearest).
pub fn within(xs: &[f64], x: f64) -> bool {
    xs.first().is_some_and(|&a| x >= a * 0.999) && xs.last().is_some_and(|&b| x <= b * 1.001)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_power_laws_exactly_and_holds_the_ends() {
        let xs = [10.0, 100.0, 1000.0];
        let ys = [1.0, 0.1, 0.05];
        assert!(
            (log_interpolate(&xs, &ys, 31.622776601683793) - 0.31622776601683794).abs() < 1e-12
        );
        assert_eq!(log_interpolate(&xs, &ys, 1.0), 1.0);
        assert_eq!(log_interpolate(&xs, &ys, 1e6), 0.05);
        assert_eq!(log_interpolate(&xs, &ys, 100.0), 0.1);
        assert!(within(&xs, 500.0) && !within(&xs, 5.0));
    }

    #[test]
    fn standard_error_falls_as_root_replicas() {
        let m = ErrorModel {
            result: "x",
            label: "x",
            scatter: 0.04,
            uncertainty: 0.1,
            length_exponent: 0.0,
            basis: String::new(),
        };
        assert!((m.stderr(16) - 0.01).abs() < 1e-15);
        assert_eq!(m.replicas_for(0.01), 16.0);
        assert_eq!(m.replicas_for(1.0), 2.0);
    }
}
