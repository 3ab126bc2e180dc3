//! Progress of a study: a bar on a terminal, sparse plain lines otherwise
//! (logs, CI), nothing with `--quiet`. Safe to call from many threads.

use indicatif::{ProgressBar, ProgressStyle};
use std::io::IsTerminal;
use std::sync::Mutex;
use std::time::{Duration, Instant};

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ProgressMode {
    /// Bar if stderr is a terminal, plain lines otherwise.
    Auto,
    Plain,
    Quiet,
}

pub struct Progress {
    total: u64,
    bar: Option<ProgressBar>,
    plain: bool,
    state: Mutex<State>,
}

struct State {
    done: u64,
    failed: u64,
    collisions: u64,
    start: Instant,
    last_line: Instant,
    last_tenth: u64,
}

/// Plain mode prints at most this often, and at every tenth of the runs.
const PLAIN_EVERY: Duration = Duration::from_secs(5);

impl Progress {
    /// `total` runs to do in this invocation (resumed runs excluded).
    pub fn new(total: u64, mode: ProgressMode) -> Self {
        let tty = std::io::stderr().is_terminal();
        let bar = (mode == ProgressMode::Auto && tty && total > 0).then(|| {
            let bar = ProgressBar::new(total);
            let style = ProgressStyle::with_template("{bar:30} {pos}/{len} runs  {msg}  ETA {eta}")
                .unwrap_or_else(|_| ProgressStyle::default_bar());
            bar.set_style(style);
            bar
        });
        let now = Instant::now();
        Progress {
            total,
            plain: bar.is_none() && mode != ProgressMode::Quiet,
            bar,
            state: Mutex::new(State {
                done: 0,
                failed: 0,
                collisions: 0,
                start: now,
                last_line: now,
                last_tenth: 0,
            }),
        }
    }

    /// One run finished (`ok` false if it failed) after `collisions` collisions.
    pub fn finished(&self, ok: bool, collisions: u64) {
        let mut s = match self.state.lock() {
            Ok(s) => s,
            Err(poisoned) => poisoned.into_inner(),
        };
        s.done += 1;
        s.failed += u64::from(!ok);
        s.collisions += collisions;
        let rate = s.collisions as f64 / s.start.elapsed().as_secs_f64().max(1e-9);
        if let Some(bar) = &self.bar {
            // Position first: the message update redraws with it.
            bar.set_position(s.done);
            bar.set_message(format!(
                "{} collisions/s{}",
                si(rate),
                failed_note(s.failed)
            ));
        } else if self.plain {
            let tenth = s.done * 10 / self.total.max(1);
            if tenth > s.last_tenth || s.last_line.elapsed() >= PLAIN_EVERY || s.done == self.total
            {
                s.last_tenth = tenth;
                s.last_line = Instant::now();
                eprintln!(
                    "{}",
                    plain_line(s.done, self.total, s.failed, rate, s.start.elapsed())
                );
            }
        }
    }

    pub fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.finish();
        }
    }
}

/// A progress line for logs: runs done, collision rate, failures and the
/// time left if the remaining runs go as fast as the finished ones.
pub fn plain_line(done: u64, total: u64, failed: u64, rate: f64, elapsed: Duration) -> String {
    let eta = if done == 0 {
        "unknown".to_string()
    } else if done >= total {
        "done".to_string()
    } else {
        let left = elapsed.as_secs_f64() * (total - done) as f64 / done as f64;
        human_duration(left)
    };
    format!(
        "study: {done}/{total} runs, {} collisions/s{}, ETA {eta}",
        si(rate),
        failed_note(failed)
    )
}

/// Seconds in the unit a person would use: "40 s", "12 min", "3.5 h".
pub fn human_duration(seconds: f64) -> String {
    match seconds {
        s if !s.is_finite() || s < 0.0 => "unknown".into(),
        s if s < 1.0 => "under a second".into(),
        s if s < 90.0 => format!("{s:.0} s"),
        s if s < 5400.0 => format!("{:.0} min", s / 60.0),
        s if s < 172_800.0 => format!("{:.1} h", s / 3600.0),
        s if s < 8.64e6 => format!("{:.1} days", s / 86_400.0),
        s if s < 3.156e8 => format!("{:.1} years", s / 3.156e7),
        s if s < 3.156e11 => format!("{:.0} years", s / 3.156e7),
        s => format!("{:.1e} years", s / 3.156e7),
    }
}

fn failed_note(failed: u64) -> String {
    if failed == 0 {
        String::new()
    } else {
        format!(", {failed} failed")
    }
}

/// 1234567.0 -> "1.23M".
fn si(x: f64) -> String {
    match x {
        x if x >= 1e9 => format!("{:.2}G", x / 1e9),
        x if x >= 1e6 => format!("{:.2}M", x / 1e6),
        x if x >= 1e3 => format!("{:.2}k", x / 1e3),
        x => format!("{x:.0}"),
    }
}
