//! Hostile output folders (issue 18, items 5, 6 and 9): links planted in
//! OUT are never followed, files bonkers did not make are never removed, a
//! folder that is not a study's output is refused unless `--force`, and a
//! record is trusted only if its checksum holds; a record that is a link to
//! /dev/zero, a pipe or a folder neither hangs a run nor fails it with exit 1.

use crate::study_common::{
    PISTON, assert_same, fake, run_into, run_options, tables, write_descriptor,
};
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::cluster::shard::Shard;
use bonkers::runner::execute::checkpoint::{self, Place};
use bonkers::runner::pipeline::{Slice, StudyOptions, run_slice, run_study};
use bonkers::runner::store::lock::OutLock;
use bonkers::runner::store::read_parquet;
use polars::prelude::DataFrame;
use std::os::unix::fs::symlink;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Longer than any of these commands takes; a hang fails the test.
const LIMIT: Duration = Duration::from_secs(60);

/// The `study` binary with `args`: exit code and stderr, or a failed test
/// if it runs longer than `LIMIT` (it is killed then).
fn study(args: &[&str]) -> (i32, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_study"))
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            panic!("`study {}` hung (killed after {LIMIT:?})", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// A simulator that counts its calls.
struct Counting(AtomicUsize);

impl Counting {
    fn simulate(&self, spec: &RunSpec) -> anyhow::Result<RunOutput> {
        self.0.fetch_add(1, Ordering::SeqCst);
        fake(spec)
    }
    fn take(&self) -> usize {
        self.0.swap(0, Ordering::SeqCst)
    }
}

/// Every file under `dir` (links as links) with its bytes, or a folder mark.
fn snapshot(dir: &Path) -> Vec<(PathBuf, Option<Vec<u8>>)> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let t = e.file_type().unwrap();
            if t.is_dir() {
                stack.push(e.path());
                found.push((e.path(), None));
            } else if t.is_symlink() {
                found.push((
                    e.path(),
                    Some(
                        std::fs::read_link(e.path())
                            .unwrap()
                            .into_os_string()
                            .into_encoded_bytes(),
                    ),
                ));
            } else {
                found.push((e.path(), Some(std::fs::read(e.path()).unwrap())));
            }
        }
    }
    found.sort();
    found
}

/// The record files of `out` (their names), sorted.
fn records(out: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(out.join("runs"))
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("run-") && n.ends_with(".json"))
        .collect();
    names.sort();
    names
}

fn is_link(p: &Path) -> bool {
    std::fs::symlink_metadata(p).is_ok_and(|m| m.file_type().is_symlink())
}

/// runs.parquet and summary.parquet of `dir` without the timings (the real
/// piston records no histograms).
fn run_tables(dir: &Path) -> Vec<(String, DataFrame)> {
    ["runs.parquet", "summary.parquet"]
        .iter()
        .map(|name| {
            let mut df = read_parquet(&dir.join(name)).unwrap();
            for col in ["wall_seconds", "cpu_seconds", "prepare_seconds"] {
                if df.column(col).is_ok() {
                    df = df.drop(col).unwrap();
                }
            }
            (name.to_string(), df)
        })
        .collect()
}

/// Item 5: a link where bonkers keeps a lock, its plan or one of its folders
/// is refused with exit 2 naming it, and whatever it points at (or would
/// create, for a dangling link) is left exactly as it was; `--force` does
/// not change that.
#[test]
fn links_where_bonkers_keeps_its_own_state_are_refused() {
    // (name in OUT, the link points at a folder, the target exists, extra flags)
    let cases: [(&str, bool, bool, &[&str]); 7] = [
        (".study.lock", false, true, &[]),
        (".study.lock", false, false, &[]),
        (".study.json", false, true, &[]),
        ("runs", true, true, &[]),
        ("runs", true, true, &["--fresh"]),
        ("slurm", true, true, &[]),
        (".shard-1-of-2.lock", false, true, &["--shard", "1/2"]),
    ];
    for (name, folder, exists, flags) in cases {
        let dir = tempfile::tempdir().unwrap();
        let file = write_descriptor(dir.path(), PISTON);
        let victim = dir.path().join("victim");
        if folder {
            std::fs::create_dir(&victim).unwrap();
            std::fs::write(victim.join("important.txt"), "mine").unwrap();
            std::fs::write(victim.join("run-1.json"), "mine too").unwrap();
            std::fs::write(victim.join(".run-1.json.1-2.tmp"), "and this").unwrap();
        } else if exists {
            std::fs::write(&victim, "precious").unwrap();
        }
        let out = dir.path().join("out");
        std::fs::create_dir(&out).unwrap();
        symlink(&victim, out.join(name)).unwrap();
        let before = snapshot(dir.path());
        for force in [false, true] {
            let mut args = vec!["run", s(&file), "--out", s(&out), "--quick"];
            args.extend(flags);
            if force {
                args.push("--force");
            }
            let (code, err) = study(&args);
            assert_eq!(code, 2, "{name} {flags:?}: {err}");
            assert!(err.contains(s(&out.join(name))), "{name}: {err}");
            assert!(err.contains("symbolic link"), "{name}: {err}");
            assert_eq!(snapshot(dir.path()), before, "{name} {flags:?}");
        }
        // A dangling link: the lock must not create its target either.
        assert_eq!(victim.exists(), folder || exists, "{name}");
    }
}

/// The locks themselves do not write through a link, whoever calls them,
/// nor use a pipe.
#[test]
fn a_lock_file_that_is_a_link_is_not_written_through() {
    let dir = tempfile::tempdir().unwrap();
    let victim = dir.path().join("victim");
    std::fs::write(&victim, "precious").unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    symlink(&victim, out.join(".study.lock")).unwrap();
    symlink(&victim, out.join(".shard-1-of-2.lock")).unwrap();
    let err = OutLock::acquire(&out).unwrap_err().to_string();
    assert!(err.contains("symbolic link"), "{err}");
    assert!(OutLock::shared(&out, None).is_err());
    std::fs::remove_file(out.join(".study.lock")).unwrap();
    let err = OutLock::shared(&out, Some("1-of-2"))
        .unwrap_err()
        .to_string();
    assert!(err.contains(".shard-1-of-2.lock"), "{err}");
    assert_eq!(std::fs::read_to_string(&victim).unwrap(), "precious");

    // Nor is a pipe used as a lock: refused, with exit 2 from a study.
    let piped = dir.path().join("piped");
    std::fs::create_dir(&piped).unwrap();
    let lock = piped.join(".study.lock");
    assert!(
        Command::new("mkfifo")
            .arg(&lock)
            .status()
            .unwrap()
            .success()
    );
    assert!(OutLock::acquire(&piped).is_err());
    let file = write_descriptor(dir.path(), PISTON);
    let err = run_into(&file, &piped, 2, &fake).unwrap_err();
    assert_eq!(err.exit_code(), 2, "{err}");
    assert!(err.to_string().contains("is not a regular file"), "{err}");
}

/// Item 5 and 9: links where bonkers replaces a file (records, checkpoints,
/// tables, the report, the manifest, a staging folder) are replaced or
/// removed, never followed: a record linked to /dev/zero, to a pipe's
/// stand-in or to a file outside does not hang the run, the targets are
/// untouched, the runs are made again (saying why) and the tables are
/// those of the first run.
#[test]
fn links_where_bonkers_replaces_a_file_are_replaced_not_followed() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick", "--quiet"]);
    assert_eq!(code, 0, "{err}");
    let first = run_tables(&out);
    let names = records(&out);
    assert_eq!(names.len(), 4);

    let outside = dir.path().join("outside");
    std::fs::create_dir(&outside).unwrap();
    std::fs::write(outside.join("file"), "precious").unwrap();
    std::fs::write(outside.join("dir-content"), "mine").unwrap();
    // The run whose record is a link to /dev/zero is made again, and finds
    // its checkpoint a link to /dev/zero too.
    let ckpt = names[1].replace(".json", ".ckpt");
    let planted: [(PathBuf, PathBuf); 7] = [
        (out.join("runs").join(&names[0]), outside.join("file")),
        (out.join("runs").join(&names[1]), "/dev/zero".into()),
        (out.join("runs").join(&ckpt), "/dev/zero".into()),
        (out.join("report.md"), outside.join("file")),
        (out.join("runs.parquet"), outside.join("file")),
        (out.join("manifest.json"), "/dev/zero".into()),
        (out.join(".staging-999999"), outside.clone()),
    ];
    for (link, target) in &planted {
        std::fs::remove_file(link).ok();
        symlink(target, link).unwrap();
    }
    let before = snapshot(&outside);
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("2 saved runs cannot be used and run again") && err.contains("symbolic link"),
        "{err}"
    );
    assert!(err.contains("4 runs (2 run now, 2 resumed"), "{err}");
    assert_eq!(snapshot(&outside), before);
    for (link, _) in &planted[..3] {
        assert!(!is_link(link), "{} is still a link", link.display());
    }
    // The published names are bonkers' own links into the current set.
    for (link, _) in &planted[3..6] {
        let name = link.file_name().unwrap();
        let own = Path::new(".outputs").join(name);
        assert_eq!(std::fs::read_link(link).unwrap(), own, "{}", link.display());
    }
    assert!(!out.join(".staging-999999").exists());
    assert!(!out.join("runs").join(&ckpt).exists());
    assert_same(&first, &run_tables(&out));

    // `study status` reads the Slurm script: a link there does not hang it.
    std::fs::create_dir(out.join("slurm")).unwrap();
    symlink("/dev/zero", out.join("slurm").join("shards.sbatch")).unwrap();
    let (code, err) = study(&["status", s(&out)]);
    assert_eq!(code, 0, "{err}");
}

/// Item 9: what sits where a record belongs but is no file: a pipe is not
/// read (no hang) and is replaced by the run's record; a folder is refused
/// with exit 2 naming it, and left as it was, by `run` and `collect`.
#[test]
fn a_record_that_is_a_pipe_or_a_folder() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick", "--quiet"]);
    assert_eq!(code, 0, "{err}");
    let names = records(&out);
    let record = |i: usize| out.join("runs").join(&names[i]);

    std::fs::remove_file(record(0)).unwrap();
    let made = Command::new("mkfifo").arg(record(0)).status().unwrap();
    assert!(made.success());
    let (code, err) = study(&["collect", s(&out)]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("not a regular file"), "{err}");
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick"]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("1 saved runs cannot be used"), "{err}");
    assert!(std::fs::symlink_metadata(record(0)).unwrap().is_file());

    std::fs::remove_file(record(1)).unwrap();
    std::fs::create_dir(record(1)).unwrap();
    std::fs::write(record(1).join("notes.txt"), "mine").unwrap();
    let before = snapshot(&out);
    for args in [
        vec!["run", s(&file), "--out", s(&out), "--quick"],
        vec!["run", s(&file), "--out", s(&out), "--quick", "--fresh"],
        vec!["collect", s(&out)],
    ] {
        let (code, err) = study(&args);
        assert_eq!(code, 2, "{args:?}: {err}");
        assert!(err.contains(s(&record(1))), "{err}");
        assert!(err.contains("is a folder named like a run's file"), "{err}");
        assert_eq!(snapshot(&out), before, "{args:?}");
    }
}

/// A checkpoint linked to /dev/zero, or a pipe, is not read (no hang).
#[test]
fn a_checkpoint_that_is_a_link_or_a_pipe_is_not_read() {
    let dir = tempfile::tempdir().unwrap();
    let link = dir.path().join("run-1.ckpt");
    symlink("/dev/zero", &link).unwrap();
    let pipe = dir.path().join("run-2.ckpt");
    assert!(
        Command::new("mkfifo")
            .arg(&pipe)
            .status()
            .unwrap()
            .success()
    );
    for path in [link, pipe] {
        let place = Place {
            path,
            every: Duration::from_secs(1),
            fingerprint: "f".into(),
            continued: false,
        };
        let start = Instant::now();
        assert!(checkpoint::read(&place).is_none());
        assert!(start.elapsed() < Duration::from_secs(5));
    }
}

/// User files planted in OUT, and bonkers' own leftovers beside them.
const USERS: [&str; 6] = [
    "thesis.tmp",
    "runs/cache.tmp",
    "runs/run-notes.json",
    "runs/important.txt",
    "runs/run-5.json.bak",
    ".staging-backup/notes.txt",
];
const LEFTOVERS: [&str; 6] = [
    ".runs.parquet.123-4.tmp",
    "runs/.run-1.json.5-6.tmp",
    "runs/run-7.json",
    "runs/run-7.ckpt",
    ".staging-123456/runs.parquet",
    ".staging-123456/.bonkers",
];

fn plant(out: &Path, names: &[&str]) {
    for name in names {
        let path = out.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, format!("{name} as planted")).unwrap();
    }
}

/// Item 6: a resumed run, `--fresh`, a shard and a collect remove their own
/// leftovers (exact names; a staging folder only with its marker) and
/// nothing of the user's; records of runs the plan does not have stay
/// (only `--prune` deletes them: `hostile_outdir.rs`).
#[test]
fn only_names_bonkers_makes_are_removed() {
    type Step = fn(&Path, &Path, &Counting) -> usize;
    let steps: [(&str, Step, usize); 4] = [
        (
            "resume",
            |f, o, c| {
                run_into(f, o, 2, &|s| c.simulate(s)).unwrap();
                c.take()
            },
            0,
        ),
        (
            "fresh",
            |f, o, c| {
                let fresh = StudyOptions {
                    fresh: true,
                    ..run_options(o, 2)
                };
                run_study(f, &fresh, &|s| c.simulate(s), &AtomicBool::new(false)).unwrap();
                c.take()
            },
            18,
        ),
        (
            "shard",
            |f, o, c| {
                let shard = Slice::Shard(Shard { index: 1, count: 2 });
                run_slice(
                    f,
                    &run_options(o, 2),
                    &shard,
                    &|s| c.simulate(s),
                    &AtomicBool::new(false),
                )
                .unwrap();
                c.take()
            },
            0,
        ),
        (
            "collect",
            |f, o, c| {
                let collect = bonkers::runner::pipeline::CollectOptions {
                    out: Some(o.to_path_buf()),
                    replicas: None,
                    quick: false,
                    yes: false,
                    command_line: vec!["study".into(), "collect".into()],
                };
                bonkers::runner::pipeline::collect_study(f, &collect).unwrap();
                c.take()
            },
            0,
        ),
    ];
    for (what, step, ran) in steps {
        let dir = tempfile::tempdir().unwrap();
        let file = write_descriptor(dir.path(), PISTON);
        let out = dir.path().join("out");
        run_into(&file, &out, 2, &fake).unwrap();
        let made = tables(&out);
        plant(&out, &USERS);
        plant(&out, &LEFTOVERS);
        let counting = Counting(AtomicUsize::new(0));
        assert_eq!(step(&file, &out, &counting), ran, "{what}");
        for name in USERS {
            let text = std::fs::read_to_string(out.join(name));
            assert_eq!(
                text.ok(),
                Some(format!("{name} as planted")),
                "{what}: {name}"
            );
        }
        // A shard removes nothing: the leftovers may be another part's work.
        for name in LEFTOVERS {
            // Collect tidies OUT, not the runs folder (it makes no runs).
            let stays = what == "shard"
                || name.starts_with("runs/run-7")
                || (what == "collect" && name.starts_with("runs/"));
            assert_eq!(out.join(name).exists(), stays, "{what}: {name}");
        }
        assert_same(&made, &tables(&out));
    }
}

/// Item 6: a non-empty folder that no study made is refused (exit 2, naming
/// it, a file of it and `--force`) and left as it was, by `run` and `slurm`;
/// `--force` writes there and keeps the user's files (names bonkers makes,
/// like `report.md`, are then its own). Empty folders and folders holding
/// only bonkers' lock files are fine; names alone (`runs/`, `.staging-12/`)
/// are no proof that a study made a folder.
#[test]
fn a_folder_no_study_made_is_refused_unless_forced() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    // (what the folder holds, accepted without --force)
    let cases: [(&[&str], bool); 5] = [
        (&[], true),
        (&[".study.lock"], true),
        (&["runs/notes.txt", ".staging-12/x"], false),
        (&["thesis.tex"], false),
        (&["report.md", "runs/run-1.json"], false),
    ];
    for (i, (holds, accepted)) in cases.into_iter().enumerate() {
        let out = dir.path().join(format!("out{i}"));
        std::fs::create_dir(&out).unwrap();
        plant(&out, holds);
        let before = snapshot(&out);
        let result = run_into(&file, &out, 2, &fake);
        assert_eq!(result.is_ok(), accepted, "{holds:?}: {result:?}");
        if accepted {
            assert!(out.join("summary.parquet").is_file());
            continue;
        }
        let err = result.unwrap_err();
        assert_eq!(err.exit_code(), 2, "{err}");
        let msg = err.to_string();
        let top = holds[0].split('/').next().unwrap();
        assert!(msg.contains(s(&out)) && msg.contains(top), "{msg}");
        assert!(msg.contains("--force"), "{msg}");
        assert_eq!(snapshot(&out), before, "{holds:?}");
        for args in [
            vec!["run", s(&file), "--out", s(&out), "--quick"],
            vec!["slurm", s(&file), "--out", s(&out), "--shards", "2"],
        ] {
            let (code, err) = study(&args);
            assert_eq!(code, 2, "{args:?}: {err}");
            assert!(err.contains("--force"), "{err}");
            assert_eq!(snapshot(&out), before, "{args:?}");
        }
        let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick", "--force"]);
        assert_eq!(code, 0, "{err}");
        assert!(out.join("summary.parquet").is_file());
        if holds.contains(&"thesis.tex") {
            let text = std::fs::read_to_string(out.join("thesis.tex")).unwrap();
            assert_eq!(text, "thesis.tex as planted");
        }
    }
    // A file is not a folder.
    let not_a_folder = dir.path().join("file");
    std::fs::write(&not_a_folder, "x").unwrap();
    let err = run_into(&file, &not_a_folder, 2, &fake).unwrap_err();
    assert_eq!(err.exit_code(), 2, "{err}");
    assert!(err.to_string().contains("is not a folder"), "{err}");
}

/// Change the first digit of the first scalar result of a record's text,
/// keeping it valid JSON.
fn tamper(text: &str) -> String {
    let at = text.find("\"scalars\":[[\"").unwrap() + "\"scalars\":[[\"".len();
    let value = at + text[at..].find("\",\"").unwrap() + 3;
    let i = value + text[value..].find(|c: char| c.is_ascii_digit()).unwrap();
    let digit = text.as_bytes()[i] - b'0';
    let changed = format!("{}{}{}", &text[..i], (digit + 1) % 10, &text[i + 1..]);
    serde_json::from_str::<serde_json::Value>(&changed).expect("still valid JSON");
    changed
}

/// Item 9: a record whose result was changed (valid JSON still) is not
/// reused: its run is made again and the tables are those of the first
/// run; one without a checksum likewise; `study run` says why, `study
/// collect` lists the run as unusable.
#[test]
fn a_record_changed_after_it_was_written_is_made_again() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let counting = Counting(AtomicUsize::new(0));
    let stop = AtomicBool::new(false);
    run_study(
        &file,
        &run_options(&out, 2),
        &|s| counting.simulate(s),
        &stop,
    )
    .unwrap();
    assert_eq!(counting.take(), 18);
    let made = tables(&out);
    let names = records(&out);
    let path = |i: usize| out.join("runs").join(&names[i]);
    let text = std::fs::read_to_string(path(0)).unwrap();
    assert!(text.starts_with("{\"checksum\":\"xxh3-64:"), "{text}");

    // The library: the changed run, and only it, is made again.
    std::fs::write(path(0), tamper(&text)).unwrap();
    let without = format!("{{{}", &text[text.find(",\"run_id\"").unwrap() + 1..]);
    serde_json::from_str::<serde_json::Value>(&without).unwrap();
    std::fs::write(path(1), &without).unwrap();
    run_study(
        &file,
        &run_options(&out, 2),
        &|s| counting.simulate(s),
        &stop,
    )
    .unwrap();
    assert_eq!(counting.take(), 2);
    assert_same(&made, &tables(&out));
    let remade = std::fs::read_to_string(path(0)).unwrap();
    assert!(bonkers::runner::store::record::RunRecord::from_json(&remade).is_ok());

    // The command line: `collect` lists them, `run` says why it redoes them.
    std::fs::write(path(0), tamper(&text)).unwrap();
    std::fs::write(path(1), &without).unwrap();
    let (code, err) = study(&["collect", s(&out)]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("2 of the 18 planned runs have no usable record"),
        "{err}"
    );
    assert!(
        err.contains("fails its checksum") && err.contains("has no checksum"),
        "{err}"
    );
    assert_same(&made, &tables(&out));
}

/// `study collect DIR MORE`: records of MORE are checked as any record (a
/// changed one is listed, not used) and a link there is not followed; a
/// `study run` into DIR then makes exactly those runs again.
#[test]
fn collect_with_more_folders_checks_their_records() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let (a, b) = (dir.path().join("a"), dir.path().join("b"));
    let stop = AtomicBool::new(false);
    for (out, index) in [(&a, 1), (&b, 2)] {
        let shard = Slice::Shard(Shard { index, count: 2 });
        run_slice(&file, &run_options(out, 2), &shard, &fake, &stop).unwrap();
    }
    let theirs = records(&b);
    let path = |i: usize| b.join("runs").join(&theirs[i]);
    let text = std::fs::read_to_string(path(0)).unwrap();
    std::fs::write(path(0), tamper(&text)).unwrap();
    let kept = dir.path().join("kept.json");
    std::fs::rename(path(1), &kept).unwrap();
    symlink(&kept, path(1)).unwrap();
    let (code, err) = study(&["collect", s(&a), s(&b)]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("2 of the 18 planned runs have no usable record"),
        "{err}"
    );
    assert!(err.contains("fails its checksum"), "{err}");
    assert!(
        err.contains("not joined") && err.contains("symbolic link"),
        "{err}"
    );

    let counting = Counting(AtomicUsize::new(0));
    run_study(&file, &run_options(&a, 2), &|s| counting.simulate(s), &stop).unwrap();
    assert_eq!(counting.take(), 2);
    let whole = dir.path().join("whole");
    run_study(&file, &run_options(&whole, 2), &fake, &stop).unwrap();
    assert_same(&tables(&whole), &tables(&a));
}
