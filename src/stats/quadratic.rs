//! A least-squares quadratic through points, read at x = 0: the contact
//! value of a profile extrapolated from its first bins.

/// Least-squares quadratic through the points, at x = 0.
pub fn quadratic_at_zero(points: &[(f64, f64)]) -> f64 {
    // Normal equations for y = c0 + c1 x + c2 x^2.
    let mut a = [[0.0; 3]; 3];
    let mut b = [0.0; 3];
    for &(x, y) in points {
        let p = [1.0, x, x * x];
        for i in 0..3 {
            for j in 0..3 {
                a[i][j] += p[i] * p[j];
            }
            b[i] += p[i] * y;
        }
    }
    solve3(a, b)[0]
}

fn solve3(mut a: [[f64; 3]; 3], mut b: [f64; 3]) -> [f64; 3] {
    for col in 0..3 {
        let pivot = (col..3)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .unwrap_or(col);
        a.swap(col, pivot);
        b.swap(col, pivot);
        for row in col + 1..3 {
            let f = a[row][col] / a[col][col];
            for k in col..3 {
                a[row][k] -= f * a[col][k];
            }
            b[row] -= f * b[col];
        }
    }
    let mut x = [0.0; 3];
    for row in (0..3).rev() {
        let s: f64 = (row + 1..3).map(|k| a[row][k] * x[k]).sum();
        x[row] = (b[row] - s) / a[row][row];
    }
    x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_is_recovered() {
        let pts: Vec<(f64, f64)> = (0..8)
            .map(|i| {
                let x = 0.01 + 0.02 * i as f64;
                (x, 2.5 - 3.0 * x + 7.0 * x * x)
            })
            .collect();
        assert!((quadratic_at_zero(&pts) - 2.5).abs() < 1e-10);
    }
}
