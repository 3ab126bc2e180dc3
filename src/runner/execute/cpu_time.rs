//! CPU time of the calling thread, the cost of a run. Linux reports it in
//! `/proc/thread-self/schedstat` (nanoseconds on a CPU, brought up to date
//! at each scheduler tick, so good to a few milliseconds); where that file
//! does not exist the time is unknown (NaN) and the report shows wall time.

/// Seconds the calling thread has spent on a CPU so far, or NaN.
pub fn thread_cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<u64>().ok())
        .map_or(f64::NAN, |ns| ns as f64 * 1e-9)
}

#[cfg(test)]
mod tests {
    #[test]
    fn grows_with_work_where_known() {
        let before = super::thread_cpu_seconds();
        // Busy for 50 ms of wall time, several scheduler ticks: a fixed
        // count of iterations can be optimised into almost nothing.
        let start = std::time::Instant::now();
        let mut x = 0u64;
        while start.elapsed() < std::time::Duration::from_millis(50) {
            x = std::hint::black_box(x.wrapping_mul(6364136223846793005).wrapping_add(1));
        }
        let after = super::thread_cpu_seconds();
        if before.is_nan() {
            assert!(after.is_nan());
        } else {
            assert!(after > before, "{before} -> {after}");
        }
    }
}
