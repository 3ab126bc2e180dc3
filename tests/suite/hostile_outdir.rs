//! Data loss without --force, and publishing: a name pattern is no proof
//! that bonkers made a folder or a file; records that leave the plan are
//! kept unless `--prune`, and another descriptor's are never replaced
//! silently; OUT holds the old set of outputs or the new one whole, at
//! every change publishing makes, even killed there.

use crate::study_common::{PISTON, fake, run_into, run_options, tables, write_descriptor};
use bonkers::descriptor::load::parse;
use bonkers::runner::cluster::shard::Shard;
use bonkers::runner::pipeline::{Slice, StudyOptions, collect_folder, run_slice, run_study};
use bonkers::runner::plan::plan;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

const LIMIT: Duration = Duration::from_secs(60);

/// The `study` binary with `args` and `env`: exit code and stderr.
fn study_env(args: &[&str], env: &[(&str, String)]) -> (i32, String) {
    let mut command = Command::new(env!("CARGO_BIN_EXE_study"));
    command
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::piped());
    for (k, v) in env {
        command.env(k, v);
    }
    let mut child = command.spawn().unwrap();
    let start = Instant::now();
    while child.try_wait().unwrap().is_none() {
        if start.elapsed() > LIMIT {
            let _ = child.kill();
            panic!("`study {}` hung", args.join(" "));
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    let out = child.wait_with_output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn study(args: &[&str]) -> (i32, String) {
    study_env(args, &[])
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Every entry under `dir` (links as their targets, folders as None).
fn snapshot(dir: &Path) -> BTreeMap<PathBuf, Option<Vec<u8>>> {
    let mut found = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let t = e.file_type().unwrap();
            let content = if t.is_dir() {
                stack.push(e.path());
                None
            } else if t.is_symlink() {
                Some(
                    std::fs::read_link(e.path())
                        .unwrap()
                        .into_os_string()
                        .into_encoded_bytes(),
                )
            } else {
                Some(std::fs::read(e.path()).unwrap())
            };
            found.insert(e.path(), content);
        }
    }
    found
}

fn plant(out: &Path, names: &[&str]) {
    for name in names {
        let path = out.join(name);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(&path, format!("{name} as planted")).unwrap();
    }
}

fn planted(out: &Path, name: &str) -> bool {
    std::fs::read_to_string(out.join(name)).ok() == Some(format!("{name} as planted"))
}

fn record_count(out: &Path) -> usize {
    std::fs::read_dir(out.join("runs"))
        .unwrap()
        .flatten()
        .filter(|e| {
            let n = e.file_name().to_string_lossy().into_owned();
            n.starts_with("run-") && n.ends_with(".json")
        })
        .count()
}

/// Item 4: folders holding only names bonkers makes, but no marker it
/// wrote, are foreign: `run`, a shard and `slurm` refuse them with exit 2
/// (naming the folder, --force and a new or empty folder) and leave them
/// as they were; with `--force` nothing bonkers did not write is removed:
/// a staging folder without its marker stays whole, records of other runs
/// stay (only the temporary file's name is then taken as bonkers' own).
#[test]
fn names_alone_do_not_make_a_folder_bonkers_output() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    // (what the folder holds, what survives --force)
    let cases: [(&[&str], &[&str]); 5] = [
        (
            &[".staging-2024/thesis.tex", ".staging-2024/chapters/one.tex"],
            &[".staging-2024/thesis.tex", ".staging-2024/chapters/one.tex"],
        ),
        (
            &["runs/run-123.json", "runs/run-9.ckpt", ".run-1.2-3.tmp"],
            &["runs/run-123.json", "runs/run-9.ckpt"],
        ),
        (&["runs/notes.txt"], &["runs/notes.txt"]),
        (
            &[".outputs-3/report.md", ".staging-12/.bonkers"],
            &[".outputs-3/report.md"],
        ),
        (&["slurm/notes.txt", ".study.lock"], &["slurm/notes.txt"]),
    ];
    for (i, (holds, survive)) in cases.into_iter().enumerate() {
        let out = dir.path().join(format!("out{i}"));
        std::fs::create_dir(&out).unwrap();
        plant(&out, holds);
        let before = snapshot(&out);
        let top = holds[0].split('/').next().unwrap();
        let err = run_into(&file, &out, 2, &fake).unwrap_err();
        assert_eq!(err.exit_code(), 2, "{holds:?}: {err}");
        for args in [
            vec!["run", s(&file), "--out", s(&out), "--quick"],
            vec![
                "run",
                s(&file),
                "--out",
                s(&out),
                "--quick",
                "--shard",
                "1/2",
            ],
            vec!["slurm", s(&file), "--out", s(&out), "--shards", "2"],
        ] {
            let (code, msg) = study(&args);
            assert_eq!(code, 2, "{holds:?} {args:?}: {msg}");
            assert!(msg.contains(s(&out)) && msg.contains(top), "{msg}");
            assert!(
                msg.contains("--force") && msg.contains("new or empty"),
                "{msg}"
            );
            assert_eq!(snapshot(&out), before, "{holds:?} {args:?}");
        }
        let (code, msg) = study(&["run", s(&file), "--out", s(&out), "--quick", "--force"]);
        assert_eq!(code, 0, "{holds:?}: {msg}");
        for name in survive {
            assert!(planted(&out, name), "{holds:?}: {name} removed; {msg}");
        }
        assert!(out.join("index.html").is_file());
    }
    // A folder holding only the lock files bonkers leaves is as good as empty.
    let locks = dir.path().join("locks");
    std::fs::create_dir(&locks).unwrap();
    std::fs::write(locks.join(".study.lock"), "4242\n").unwrap();
    std::fs::write(locks.join(".shard-1-of-2.lock"), "").unwrap();
    run_into(&file, &locks, 2, &fake).unwrap();
}

/// Item 4, in a study's own folder: staging and set folders are removed
/// only if they hold bonkers' marker, nobody holds it locked (a live
/// process), and then only the names a set holds; anything else stays and
/// is said.
#[test]
fn in_its_own_folder_bonkers_removes_only_what_it_wrote() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick", "--quiet"]);
    assert_eq!(code, 0, "{err}");
    plant(
        &out,
        &[
            // A user's folder of a bonkers-like name: no marker.
            ".staging-77/thesis.tex",
            ".staging-77/sub/notes.txt",
            ".outputs-99/report.md",
            // bonkers' leftover, with a user's file put into it.
            ".staging-78/.bonkers",
            ".staging-78/runs.parquet",
            ".staging-78/thesis.tex",
            // A live process's staging (its marker is locked below).
            ".staging-79/.bonkers",
            ".staging-79/runs.parquet",
            // A plain leftover of a killed run.
            ".staging-80/.bonkers",
            ".staging-80/summary.parquet",
            ".outputs-98/.bonkers",
            ".outputs-98/index.html",
        ],
    );
    let live = std::fs::File::options()
        .read(true)
        .write(true)
        .open(out.join(".staging-79/.bonkers"))
        .unwrap();
    live.lock().unwrap();
    let (code, err) = study(&["run", s(&file), "--out", s(&out), "--quick"]);
    assert_eq!(code, 0, "{err}");
    for kept in [
        ".staging-77/thesis.tex",
        ".staging-77/sub/notes.txt",
        ".outputs-99/report.md",
        ".staging-78/thesis.tex",
        ".staging-78/.bonkers",
        ".staging-79/.bonkers",
        ".staging-79/runs.parquet",
    ] {
        assert!(planted(&out, kept), "{kept} removed");
    }
    assert!(!out.join(".staging-78/runs.parquet").exists());
    assert!(!out.join(".staging-80").exists());
    assert!(!out.join(".outputs-98").exists());
    assert!(
        err.contains(".staging-77") && err.contains("no .bonkers"),
        "{err}"
    );
    assert!(
        err.contains(".staging-78") && err.contains("thesis.tex"),
        "{err}"
    );
    drop(live);
}

/// The descriptor with `replicas` replicas per point (the plan's runs).
fn runs_of(text: &str) -> usize {
    plan(&parse("s.toml", text).unwrap()).unwrap().len()
}

/// runs.parquet's run ids, sorted.
fn run_ids(out: &Path) -> Vec<u64> {
    let df = bonkers::runner::store::read_parquet(&out.join("runs.parquet")).unwrap();
    let mut ids: Vec<u64> = df
        .column("run_id")
        .unwrap()
        .u64()
        .unwrap()
        .into_no_null_iter()
        .collect();
    ids.sort();
    ids
}

/// Item 5: fewer replicas keep the records that leave the plan (said on
/// stderr, out of the tables); going back reuses them; `--prune` deletes
/// them; `--fresh` redoes the plan's runs and keeps the others.
#[test]
fn records_that_leave_the_plan_are_kept_unless_pruned() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let run = |extra: &[&str]| {
        let mut args = vec!["run", s(&file), "--out", s(&out), "--quick"];
        args.extend(extra);
        let (code, err) = study(&args);
        assert_eq!(code, 0, "{extra:?}: {err}");
        err
    };
    run(&["--replicas", "4"]);
    assert_eq!(record_count(&out), 16);
    let err = run(&["--replicas", "1"]);
    assert!(
        err.contains("kept 12 records that are not in this plan (runs/run-")
            && err.contains("and 9 more); --prune deletes them"),
        "{err}"
    );
    assert_eq!(record_count(&out), 16);
    assert_eq!(run_ids(&out), [0, 1, 2, 3]);
    let err = run(&["--replicas", "4"]);
    assert!(err.contains("16 runs (0 run now, 16 resumed"), "{err}");
    let err = run(&["--replicas", "1", "--fresh"]);
    assert!(err.contains("4 runs (4 run now, 0 resumed"), "{err}");
    assert_eq!(record_count(&out), 16);
    let err = run(&["--replicas", "1", "--prune"]);
    assert!(
        err.contains("removed 12 saved runs that are not in this plan"),
        "{err}"
    );
    assert_eq!(record_count(&out), 4);
    assert_eq!(run_ids(&out), [0, 1, 2, 3]);
}

/// Item 5: a plan whose runs would replace another descriptor's successful
/// records (`--quick` into the full study's folder, an edited descriptor,
/// a shard of one, `study slurm` of one) is refused with exit 2 and writes
/// nothing, `.study.json` included; the finished study still collects to
/// the same tables. `--prune` lets it replace them.
#[test]
fn another_descriptor_never_replaces_records_silently() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let stop = AtomicBool::new(false);
    run_into(&file, &out, 2, &fake).unwrap();
    let made = tables(&out);
    let before = snapshot(&out.join("runs"));
    let origin = std::fs::read(out.join(".study.json")).unwrap();

    let quick = StudyOptions {
        quick: true,
        ..run_options(&out, 2)
    };
    let edited = dir.path().join("edited.toml");
    std::fs::write(
        &edited,
        PISTON.replace("duration = 100.0", "duration = 50.0"),
    )
    .unwrap();
    let shard = Slice::Shard(Shard { index: 1, count: 2 });
    type Attempt<'a> = Box<dyn Fn() -> Result<(), bonkers::descriptor::errors::StudyError> + 'a>;
    let attempts: [(&str, Attempt); 4] = [
        (
            "--quick",
            Box::new(|| run_study(&file, &quick, &fake, &stop).map(|_| ())),
        ),
        (
            "edited",
            Box::new(|| run_study(&edited, &run_options(&out, 2), &fake, &stop).map(|_| ())),
        ),
        (
            "shard of edited",
            Box::new(|| {
                run_slice(&edited, &run_options(&out, 2), &shard, &fake, &stop).map(|_| ())
            }),
        ),
        (
            "slurm of edited",
            Box::new(|| {
                let (code, err) = study(&["slurm", s(&edited), "--out", s(&out), "--shards", "2"]);
                match code {
                    2 => Err(anyhow::anyhow!(err).into()),
                    _ => Ok(()),
                }
            }),
        ),
    ];
    for (what, attempt) in attempts {
        let err = attempt().unwrap_err();
        let msg = err.to_string();
        assert!(
            err.exit_code() == 2 || what.starts_with("slurm"),
            "{what}: {msg}"
        );
        assert!(msg.contains(s(&out)), "{what}: {msg}");
        assert!(
            msg.contains("would replace them") && msg.contains("--prune"),
            "{what}: {msg}"
        );
        assert_eq!(snapshot(&out.join("runs")), before, "{what}");
        assert_eq!(
            std::fs::read(out.join(".study.json")).unwrap(),
            origin,
            "{what}"
        );
        assert!(!out.join("slurm").exists(), "{what}");
    }
    collect_folder(&out, &[], vec!["study".into()]).unwrap();
    crate::study_common::assert_same(&made, &tables(&out));

    // --prune: the quick plan replaces what it shares and deletes the rest.
    let pruned = StudyOptions {
        prune: true,
        ..quick
    };
    let outcome = run_study(&file, &pruned, &fake, &stop).unwrap();
    let quick_runs = outcome.planned;
    assert_eq!(outcome.ran, quick_runs);
    assert_eq!(record_count(&out), quick_runs);
    assert_eq!(run_ids(&out), (0..quick_runs as u64).collect::<Vec<_>>());
    assert!(quick_runs < runs_of(PISTON));
}

/// `study collect DIR DIR` (or DIR and a link to it) names the mistake,
/// with exit 2, instead of blaming its own process for holding the lock.
#[test]
fn collect_of_a_folder_given_twice_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    run_into(&file, &out, 2, &fake).unwrap();
    let link = dir.path().join("link");
    std::os::unix::fs::symlink(&out, &link).unwrap();
    for again in [&out, &link] {
        let (code, err) = study(&["collect", s(&out), s(again)]);
        assert_eq!(code, 2, "{err}");
        assert!(err.contains("cannot be joined into itself"), "{err}");
        assert!(!err.contains("process"), "{err}");
    }
}

/// The published outputs of OUT as a reader finds them: each top-level
/// name of a published kind that opens as a file, with its bytes.
fn published(out: &Path) -> BTreeMap<String, Vec<u8>> {
    std::fs::read_dir(out)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| bonkers::runner::store::publish::published_kind(n))
        .filter(|n| out.join(n).is_file())
        .map(|n| {
            let bytes = std::fs::read(out.join(&n)).unwrap();
            (n, bytes)
        })
        .collect()
}

/// The names `manifest.json` lists, sorted (none without one).
fn listed(set: &BTreeMap<String, Vec<u8>>) -> Vec<String> {
    let Some(bytes) = set.get("manifest.json") else {
        return Vec::new();
    };
    let manifest: serde_json::Value = serde_json::from_slice(bytes).unwrap();
    let mut names: Vec<String> = serde_json::from_value(manifest["outputs"].clone()).unwrap();
    names.sort();
    names
}

/// Which study a set is: the description its report and manifest carry.
fn description_of(set: &BTreeMap<String, Vec<u8>>) -> String {
    let manifest: serde_json::Value = serde_json::from_slice(&set["manifest.json"]).unwrap();
    manifest["descriptor"]["study"]["description"]
        .as_str()
        .unwrap()
        .to_string()
}

/// OUT is a whole set: the manifest lists exactly the files a reader finds,
/// and it is `old` byte for byte, or a set of the study described `new`
/// with the names of `new_names` whose deterministic files equal `new`'s.
fn assert_whole(
    out: &Path,
    old: &BTreeMap<String, Vec<u8>>,
    new: &BTreeMap<String, Vec<u8>>,
    at: &str,
) -> bool {
    let found = published(out);
    let names: Vec<String> = found.keys().cloned().collect();
    assert_eq!(
        listed(&found),
        names,
        "{at}: the manifest lists what is there"
    );
    if found == *old {
        return false;
    }
    assert_eq!(
        names,
        new.keys().cloned().collect::<Vec<_>>(),
        "{at}: neither the old set nor the new one"
    );
    assert_eq!(description_of(&found), description_of(new), "{at}");
    for (name, bytes) in &found {
        let timed = [
            "manifest.json",
            "report.md",
            "index.html",
            "runs.parquet",
            "summary.parquet",
        ];
        if !timed.contains(&name.as_str()) {
            assert_eq!(bytes, &new[name], "{at}: {name} is not the new set's");
        }
        if name == "report.md" || name == "index.html" {
            let text = String::from_utf8_lossy(bytes);
            assert!(text.contains(&description_of(new)), "{at}: {name}");
        }
    }
    true
}

/// Copy a folder, links as links.
fn copy_tree(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap().flatten() {
        let (src, dst) = (e.path(), to.join(e.file_name()));
        let t = e.file_type().unwrap();
        if t.is_symlink() {
            std::os::unix::fs::symlink(std::fs::read_link(&src).unwrap(), &dst).unwrap();
        } else if t.is_dir() {
            copy_tree(&src, &dst);
        } else {
            std::fs::copy(&src, &dst).unwrap();
        }
    }
}

/// OUT as an older bonkers left it: the outputs as plain files.
fn flatten(out: &Path) {
    for (name, bytes) in published(out) {
        std::fs::remove_file(out.join(&name)).unwrap();
        std::fs::write(out.join(&name), bytes).unwrap();
    }
    let set = std::fs::read_link(out.join(".outputs")).unwrap();
    std::fs::remove_file(out.join(".outputs")).unwrap();
    std::fs::remove_dir_all(out.join(set)).unwrap();
}

/// Nothing of publishing is left over: one set, no staging folder, no
/// temporary file, no dangling link.
fn assert_tidy(out: &Path, at: &str) {
    let mut sets = 0;
    for e in std::fs::read_dir(out).unwrap().flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        assert!(!name.starts_with(".staging-"), "{at}: {name} left");
        assert!(!name.ends_with(".tmp"), "{at}: {name} left");
        sets += usize::from(name.starts_with(".outputs-"));
        if e.file_type().unwrap().is_symlink() {
            assert!(e.path().exists(), "{at}: {name} dangles");
        }
    }
    assert_eq!(sets, 1, "{at}");
}

/// Item 6: a kill before each change publishing makes (the test hook exits
/// the process there, as a kill would) leaves OUT the old set whole or the
/// new set whole, and a rerun completes it and leaves nothing over; also
/// from an OUT of an older bonkers with plain files, and from each set to
/// the other (one has series a plot of it, the other histograms).
#[test]
fn a_kill_at_each_step_of_publishing_leaves_one_whole_set() {
    let dir = tempfile::tempdir().unwrap();
    let a_text = PISTON.replace(
        "Piston frequency against piston mass",
        "Study A of the kill test",
    );
    let b_text = a_text
        .replace("Study A of the kill test", "Study B of the kill test")
        .replace(
            "series = [\"piston_position\"]",
            "histograms = [\"scaled_velocity_x\"]",
        );
    let a = dir.path().join("a.toml");
    let b = dir.path().join("b.toml");
    std::fs::write(&a, &a_text).unwrap();
    std::fs::write(&b, &b_text).unwrap();
    let run = |file: &Path, out: &Path, exit_at: Option<usize>| {
        let env: Vec<(&str, String)> = exit_at
            .map(|k| ("BONKERS_PUBLISH_EXIT_AT", k.to_string()))
            .into_iter()
            .collect();
        let args = [
            "run",
            s(file),
            "--out",
            s(out),
            "--quick",
            "--quiet",
            "--prune",
        ];
        study_env(&args, &env)
    };
    // The two sets, each published into a fresh folder.
    let mut template = BTreeMap::new();
    let mut sets = BTreeMap::new();
    for (name, file) in [("a", &a), ("b", &b)] {
        let out = dir.path().join(format!("template-{name}"));
        let (code, err) = run(file, &out, None);
        assert_eq!(code, 0, "{err}");
        sets.insert(name, published(&out));
        template.insert(name, out);
    }
    assert!(sets["a"].contains_key("series.parquet") && !sets["b"].contains_key("series.parquet"));
    assert!(sets["b"].contains_key("histograms.parquet"));
    for (from, to, legacy) in [("a", "b", false), ("b", "a", false), ("a", "b", true)] {
        let file = if to == "a" { &a } else { &b };
        let mut k = 0;
        let mut switched = false;
        loop {
            let at = format!(
                "{from} -> {to}{}, killed before change {k}",
                if legacy { " (plain files)" } else { "" }
            );
            let out = dir.path().join(format!("out-{from}-{to}-{legacy}-{k}"));
            copy_tree(&template[from], &out);
            if legacy {
                flatten(&out);
            }
            let (code, err) = run(file, &out, Some(k));
            if code == 0 {
                assert!(switched, "{at}: never switched: {err}");
                assert!(k >= 6, "{at}: only {k} changes");
                assert_whole(&out, &sets[from], &sets[to], &at);
                assert_tidy(&out, &at);
                break;
            }
            assert_eq!(code, 137, "{at}: {err}");
            let new = assert_whole(&out, &sets[from], &sets[to], &at);
            assert!(new || !switched, "{at}: back to the old set");
            switched |= new;
            let (code, err) = run(file, &out, None);
            assert_eq!(code, 0, "{at}: the rerun: {err}");
            assert!(
                assert_whole(&out, &sets[from], &sets[to], &at),
                "{at}: rerun"
            );
            assert_tidy(&out, &at);
            std::fs::remove_dir_all(&out).unwrap();
            k += 1;
        }
    }
}
