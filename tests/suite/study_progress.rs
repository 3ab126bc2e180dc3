//! Plain progress lines (logs, CI): runs done, collision rate, failures, ETA.

use bonkers::runner::execute::progress::{human_duration, plain_line};
use std::time::Duration;

#[test]
fn plain_lines_give_the_time_left_at_the_rate_so_far() {
    // A quarter done in 30 s: three quarters left take 90 s.
    assert_eq!(
        plain_line(25, 100, 0, 2.5e6, Duration::from_secs(30)),
        "study: 25/100 runs, 2.50M collisions/s, ETA 2 min"
    );
    assert_eq!(
        plain_line(50, 100, 3, 900.0, Duration::from_secs(10)),
        "study: 50/100 runs, 900 collisions/s, 3 failed, ETA 10 s"
    );
    assert!(plain_line(100, 100, 0, 1.0, Duration::from_secs(1)).ends_with("ETA done"));
    assert!(plain_line(0, 100, 0, 0.0, Duration::ZERO).ends_with("ETA unknown"));
}

#[test]
fn durations_read_as_a_person_would_say_them() {
    assert_eq!(human_duration(0.2), "under a second");
    assert_eq!(human_duration(42.0), "42 s");
    assert_eq!(human_duration(600.0), "10 min");
    assert_eq!(human_duration(3.0 * 3600.0), "3.0 h");
    assert_eq!(human_duration(3.0 * 86_400.0), "3.0 days");
    assert_eq!(human_duration(f64::NAN), "unknown");
}
