//! Subprocesses under bounds, for the hostile tests: at most 2 GB of
//! address space (`ulimit -v`, so a runaway allocation fails instead of
//! swapping), killed and failed past a time limit, output read as it comes
//! (a long message must not fill a pipe and stall the child); and the
//! fixed-seed proptest configuration the fuzz tests share.
#![allow(dead_code)]

use proptest::test_runner::{Config, RngSeed};
use std::ffi::OsStr;
use std::io::Read;
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// `program` under `sh -c "ulimit -v ..."`; add arguments, environment and
/// working folder, then `finish` it.
pub fn limited(program: impl AsRef<OsStr>) -> Command {
    let mut command = Command::new("sh");
    command
        .arg("-c")
        .arg("ulimit -v 2000000; exec \"$0\" \"$@\"")
        .arg(program);
    command
}

/// How a bounded child ended: its exit code (-1 if a signal ended it) and
/// what it wrote.
pub struct Finished {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

fn reader(pipe: Option<impl Read + Send + 'static>) -> std::thread::JoinHandle<String> {
    std::thread::spawn(move || {
        let mut text = Vec::new();
        if let Some(mut pipe) = pipe {
            let _ = pipe.read_to_end(&mut text);
        }
        String::from_utf8_lossy(&text).into_owned()
    })
}

/// Run `command` to its end; panics (naming `what`) past `limit`.
pub fn finish(mut command: Command, what: &str, limit: Duration) -> Finished {
    let mut child = command
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let (out, err) = (reader(child.stdout.take()), reader(child.stderr.take()));
    let clock = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap() {
            break status;
        }
        if clock.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("{what} ran past {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(10));
    };
    Finished {
        code: status.code().unwrap_or(-1),
        stdout: out.join().unwrap(),
        stderr: err.join().unwrap(),
    }
}

/// The study command with `args` in `cwd`, bounded: exit code and stderr.
pub fn study<S: AsRef<OsStr> + std::fmt::Debug>(
    args: &[S],
    cwd: &Path,
    limit: Duration,
) -> (i32, String) {
    let mut command = limited(env!("CARGO_BIN_EXE_study"));
    command.args(args).current_dir(cwd);
    let done = finish(command, &format!("study {args:?}"), limit);
    (done.code, done.stderr)
}

/// The names in folder `p`, sorted (lossy: for messages and comparisons).
pub fn names(p: &Path) -> Vec<String> {
    let mut n: Vec<String> = std::fs::read_dir(p)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    n.sort();
    n
}

/// `cases` cases from a fixed seed: the same inputs in every CI run, no
/// failure files.
pub fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(18),
        failure_persistence: None,
        ..Config::default()
    }
}
