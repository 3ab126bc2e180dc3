//! Sharded studies: `study run --shard K/N` parts sharing one folder, then
//! `study collect DIR`, give the tables of one `study run` (real simulator,
//! bit for bit but timings); missing runs are listed with the command that
//! redoes exactly them; `study status` counts; locks keep parts apart from
//! whole runs; `study slurm` writes the job array.

use crate::study_common::{PISTON, assert_same, fake, run_options, write_descriptor};
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::cluster::shard::Shard;
use bonkers::runner::execute::run::run_file;
use bonkers::runner::pipeline::{Slice, run_slice};
use bonkers::runner::store::lock::OutLock;
use bonkers::runner::store::read_parquet;
use polars::prelude::DataFrame;
use std::collections::HashMap;
use std::path::Path;
use std::process::{Command, Output};
use std::sync::Mutex;
use std::sync::atomic::AtomicBool;

/// The tables `dir` has (the real piston runs record no histograms),
/// without the timing columns.
fn tables(dir: &Path) -> Vec<(String, DataFrame)> {
    let mut found = Vec::new();
    for name in ["runs", "series", "histograms", "summary"] {
        let path = dir.join(format!("{name}.parquet"));
        if !path.exists() {
            continue;
        }
        let mut df = read_parquet(&path).unwrap();
        for col in ["wall_seconds", "cpu_seconds", "prepare_seconds"] {
            if df.column(col).is_ok() {
                df = df.drop(col).unwrap();
            }
        }
        found.push((name.to_string(), df));
    }
    assert!(found.len() >= 3, "{}: {found:?}", dir.display());
    found
}

fn study(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_study"))
        .args(args)
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

fn specs() -> Vec<RunSpec> {
    bonkers::runner::plan::plan(&bonkers::descriptor::load::parse("s.toml", PISTON).unwrap())
        .unwrap()
}

/// Three shard processes at once into one folder, then `study collect DIR`:
/// the tables of one whole `study run`, with the real simulator.
#[test]
fn three_shards_then_collect_equal_one_run() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let whole = dir.path().join("whole");
    let o = study(&["run", s(&file), "--out", s(&whole), "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));

    let out = dir.path().join("sharded");
    let children: Vec<_> = (1..=3)
        .map(|k| {
            Command::new(env!("CARGO_BIN_EXE_study"))
                .args(["run", s(&file), "--out", s(&out), "--threads", "1"])
                .args(["--shard", &format!("{k}/3")])
                .output()
        })
        .collect();
    let mut picked = 0;
    for child in children {
        let o = child.unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        let text = stderr(&o);
        let n: usize = text
            .split(" runs (")
            .next()
            .and_then(|t| t.rsplit(' ').next())
            .and_then(|n| n.parse().ok())
            .unwrap_or_else(|| panic!("{text}"));
        picked += n;
    }
    assert_eq!(picked, 18, "every run in exactly one shard");
    assert!(!out.join("runs.parquet").exists(), "shards make no tables");

    let o = study(&["collect", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("collected 18 runs"), "{}", stderr(&o));
    assert!(stderr(&o).contains("CPU-hours"), "{}", stderr(&o));
    assert_same(&tables(&whole), &tables(&out));
}

/// Shards saved into folders of their own (one per node, no shared file
/// system), then `study collect DIR MORE...`: the tables of one whole run.
/// A folder of another plan is refused, naming it.
#[test]
fn shards_in_separate_folders_are_joined_by_collect() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let whole = dir.path().join("whole");
    let o = study(&["run", s(&file), "--out", s(&whole), "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let parts: Vec<_> = (1..=3)
        .map(|k| dir.path().join(format!("node-{k}")))
        .collect();
    for (k, part) in parts.iter().enumerate() {
        let shard = format!("{}/3", k + 1);
        let o = study(&[
            "run",
            s(&file),
            "--out",
            s(part),
            "--shard",
            &shard,
            "--quiet",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    // One folder alone lacks the others' runs.
    let o = study(&["collect", s(&parts[0])]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));

    let other = dir.path().join("other");
    std::fs::create_dir_all(dir.path().join("edited")).unwrap();
    let edited = write_descriptor(
        &dir.path().join("edited"),
        &PISTON.replacen("seed = ", "seed = 1", 1),
    );
    let o = study(&[
        "run",
        s(&edited),
        "--out",
        s(&other),
        "--shard",
        "1/3",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = study(&["collect", s(&parts[0]), s(&other)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("holds runs of another plan"),
        "{}",
        stderr(&o)
    );

    let o = study(&["collect", s(&parts[0]), s(&parts[1]), s(&parts[2])]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("collected 18 runs"), "{}", stderr(&o));
    assert_same(&tables(&whole), &tables(&parts[0]));
}

/// Whatever N, each run is computed by exactly one of the N shards.
#[test]
fn every_run_is_in_exactly_one_shard_whatever_n() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    for n in [1, 2, 3, 5, 18, 25] {
        let out = dir.path().join(format!("n{n}"));
        let calls = Mutex::new(HashMap::<u64, usize>::new());
        let counting = |spec: &RunSpec| {
            *calls.lock().unwrap().entry(spec.run_id).or_default() += 1;
            fake(spec)
        };
        for index in 1..=n {
            let shard = Slice::Shard(Shard { index, count: n });
            run_slice(
                &file,
                &run_options(&out, 2),
                &shard,
                &counting,
                &AtomicBool::new(false),
            )
            .unwrap();
        }
        let calls = calls.into_inner().unwrap();
        assert_eq!(calls.len(), 18, "N = {n}");
        assert!(calls.values().all(|&c| c == 1), "N = {n}: {calls:?}");
    }
}

/// Records gone: collect lists them with the command that runs exactly
/// them; that command, then collect, completes the study. Status counts.
#[test]
fn missing_runs_are_redone_by_the_command_collect_names() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let whole = dir.path().join("whole");
    assert!(
        study(&["run", s(&file), "--out", s(&whole), "--quiet"])
            .status
            .success()
    );
    let out = dir.path().join("parts");
    for k in 1..=2 {
        let o = study(&[
            "run",
            s(&file),
            "--out",
            s(&out),
            "--shard",
            &format!("{k}/2"),
            "--quiet",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
    }
    let specs = specs();
    for id in [3, 11, 12] {
        std::fs::remove_file(run_file(&out, specs[id].seed)).unwrap();
    }

    let o = study(&["status", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    assert!(text.contains("18 planned runs"), "{text}");
    assert!(text.contains("done: 15, failed: 0, pending: 3"), "{text}");
    assert!(text.contains("CPU time spent"), "{text}");
    assert!(text.contains("left: ~"), "{text}");

    let o = study(&["collect", s(&out)]);
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    let command = format!(
        "or exactly them, records only (e.g. while shards still run): `study run {} --out {} --runs 3,11-12`, then `study collect {}`",
        s(&file),
        s(&out),
        s(&out)
    );
    assert!(stderr(&o).contains(&command), "{}", stderr(&o));
    assert!(!out.join("runs.parquet").exists());

    let o = study(&["run", s(&file), "--out", s(&out), "--runs", "3,11-12"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("3 runs (3 run now, 0 resumed, 0 failed)"),
        "{}",
        stderr(&o)
    );
    let o = study(&["collect", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_same(&tables(&whole), &tables(&out));
    let o = study(&["status", s(&out)]);
    assert!(
        stdout(&o).contains("done: 18, failed: 0, pending: 0"),
        "{}",
        stdout(&o)
    );
}

/// Parts share a folder; the same shard twice, or a whole run beside a part,
/// fails at once and says why.
#[test]
fn locks_keep_parts_and_whole_runs_apart() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap();
    let held = OutLock::shared(&out, Some("2-of-3")).unwrap();

    let o = study(&[
        "run",
        s(&file),
        "--out",
        s(&out),
        "--shard",
        "2/3",
        "--quiet",
    ]);
    assert_eq!(o.status.code(), Some(1));
    let pid = std::process::id();
    assert!(
        stderr(&o).contains(&format!("shard 2/3 is already running (process {pid})")),
        "{}",
        stderr(&o)
    );
    let o = study(&[
        "run",
        s(&file),
        "--out",
        s(&out),
        "--shard",
        "1/3",
        "--quiet",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = study(&["status", s(&out)]);
    assert!(
        stdout(&o).contains(&format!("running now: shard 2/3 (process {pid})")),
        "{}",
        stdout(&o)
    );
    for args in [
        vec!["run", s(&file), "--out", s(&out), "--quiet"],
        vec!["collect", s(&out)],
    ] {
        let o = study(&args);
        assert_eq!(o.status.code(), Some(1));
        assert!(stderr(&o).contains("another `study run`"), "{}", stderr(&o));
    }
    drop(held);
    let o = study(&["run", s(&file), "--out", s(&out), "--quiet"]);
    assert!(o.status.success(), "{}", stderr(&o));
}

/// Bad shards and run ids are bad input (exit 2), named.
#[test]
fn bad_parts_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    for (flag, value, says) in [
        ("--shard", "4/3", "write K/N with 1 <= K <= N"),
        ("--runs", "5-2", "`5-2` is not a run id"),
    ] {
        let o = study(&["run", s(&file), "--out", s(&out), flag, value]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains(says), "{}", stderr(&o));
    }
    let o = study(&["run", s(&file), "--out", s(&out), "--runs", "18"]);
    assert!(
        stderr(&o).contains("run 18 is not in the plan"),
        "{}",
        stderr(&o)
    );
    let o = study(&["status", s(dir.path())]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("has no .study.json"), "{}", stderr(&o));
}

/// `study slurm` writes the array and collect scripts, prints the cost and
/// the sbatch commands; `study status` then names the tasks to submit.
#[test]
fn study_slurm_writes_the_job_array() {
    let dir = tempfile::tempdir().unwrap();
    let file = write_descriptor(dir.path(), PISTON);
    let out = dir.path().join("out");
    let o = study(&[
        "slurm",
        s(&file),
        "--out",
        s(&out),
        "--shards",
        "3",
        "--cpus",
        "2",
        "--time",
        "0:10:00",
        "--partition",
        "debug",
        "--mem",
        "1G",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = stdout(&o);
    for want in [
        "an array of 3 shards",
        "estimated cost: ~",
        "shard 3: ~",
        "jobid=$(sbatch --parsable",
        "--dependency=afterany:${jobid%%;*}",
    ] {
        assert!(text.contains(want), "{want}: {text}");
    }
    let array = std::fs::read_to_string(out.join("slurm/shards.sbatch")).unwrap();
    for want in [
        "#SBATCH --array=1-3\n",
        "#SBATCH --cpus-per-task=2\n",
        "#SBATCH --time=0:10:00\n",
        "#SBATCH --partition=debug\n",
        "#SBATCH --mem=1G\n",
        "#SBATCH --requeue\n",
        "--shard \"${SLURM_ARRAY_TASK_ID}/3\" --threads \"${SLURM_CPUS_PER_TASK:-1}\"",
    ] {
        assert!(array.contains(want), "{want}: {array}");
    }
    let collect = std::fs::read_to_string(out.join("slurm/collect.sbatch")).unwrap();
    assert!(
        collect.contains(&format!("collect {}", s(&out))),
        "{collect}"
    );

    let o = study(&["status", s(&out)]);
    let text = stdout(&o);
    assert!(text.contains("pending: 18"), "{text}");
    assert!(
        text.contains(&format!(
            "sbatch --array=1,2,3 {}",
            out.join("slurm/shards.sbatch").display()
        )),
        "{text}"
    );
    assert!(
        study(&[
            "slurm",
            s(&file),
            "--out",
            s(&out),
            "--shards",
            "3",
            "--time",
            "soon"
        ])
        .status
        .code()
            == Some(2)
    );
}
