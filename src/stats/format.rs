//! Numbers as text: a few significant digits, and a mean with its error bar
//! rounded to the error's precision.

/// `x` with about 4 significant digits; scientific for very small or large
/// magnitudes; "NaN" / "∞" spelled out rather than hidden.
pub fn num(x: f64) -> String {
    if x.is_nan() {
        return "NaN".into();
    }
    if x.is_infinite() {
        return if x > 0.0 { "∞".into() } else { "-∞".into() };
    }
    let a = x.abs();
    if a != 0.0 && !(1e-3..1e6).contains(&a) {
        return format!("{x:.3e}");
    }
    let decimals = if a == 0.0 {
        0
    } else {
        (3 - a.log10().floor() as i32).clamp(0, 6) as usize
    };
    trim(format!("{x:.decimals$}"))
}

/// Drop trailing zeros after a decimal point ("2.500" -> "2.5").
fn trim(s: String) -> String {
    if s.contains('.') && !s.contains('e') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

/// "mean ± stderr" with the error to 2 significant digits and the mean to the
/// same decimal place; just the mean when there is no error bar.
pub fn pm(mean: f64, stderr: f64) -> String {
    if mean.is_finite() && stderr == 0.0 {
        return format!("{} ± 0", num(mean));
    }
    if !mean.is_finite() || !stderr.is_finite() || stderr < 0.0 {
        return num(mean);
    }
    let exp = stderr.log10().floor() as i32;
    let scale = mean.abs().max(stderr);
    if !(1e-3..1e6).contains(&scale) || !(-7..6).contains(&exp) {
        return format!("{mean:.3e} ± {stderr:.1e}");
    }
    let decimals = (1 - exp).max(0) as usize;
    format!("{mean:.decimals$} ± {stderr:.decimals$}")
}

/// An integer with thin thousands separators ("1 234 567"), easier to read in
/// cost tables.
pub fn count(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push('\u{202f}');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats() {
        assert_eq!(num(2.5), "2.5");
        assert_eq!(num(1234.5678), "1235");
        assert_eq!(num(0.012345), "0.01235");
        assert_eq!(num(f64::NAN), "NaN");
        assert_eq!(num(0.0), "0");
        assert_eq!(pm(2.5, 0.645497), "2.50 ± 0.65");
        assert_eq!(pm(123.456, 12.0), "123 ± 12");
        assert_eq!(count(1234567), "1\u{202f}234\u{202f}567");
        assert_eq!(count(12), "12");
        assert_eq!(pm(3.0, 0.0), "3 ± 0");
        assert_eq!(pm(3.0, f64::NAN), "3");
    }
}
