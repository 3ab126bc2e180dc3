//! `study slurm` and the command line under hostile input. Flag values and
//! paths with newlines, `$()`, backticks, quotes, `;`, `%`, `&`, `|`, `*`,
//! blanks, a leading `-` or non-UTF-8 bytes are either refused (exit 2,
//! naming the flag, writing nothing) or carried exactly: the scripts pass
//! `bash -n`, each `#SBATCH` line is one option sbatch reads literally, and
//! run with bash (sbatch stubbed) they execute nothing injected and reach
//! exactly OUT, whose records and status they then find. Sizes given on
//! the command line (shards, run ids) cost memory of the plan, not of the
//! numbers. A fixed-seed fuzz does the same with random values; every
//! command is bounded in time and memory (`bounded.rs`).

use crate::bounded::{Finished, config, finish, limited, names};
use proptest::prelude::*;
use std::ffi::{OsStr, OsString};
use std::os::unix::ffi::{OsStrExt, OsStringExt};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// Two cheap runs (5 rods in 1D).
const TINY: &str = r#"
[study]
name = "tiny"
description = "Five rods between walls."
replicas = 2
seed = 50

[scene]
dimension = 1
box = [20.0]
boundary = ["walls"]
velocities = { kind = "maxwell", temperature = 1.0 }

[[scene.species]]
name = "gas"
count = 5

[run]
duration = 5.0
sample_every = 1.0

[observe]
scalars = ["wall_pressure"]
"#;

/// What every injected command would create, in its working folder.
const PAYLOAD: &str = "pwned";

/// Records its arguments (each NUL-ended, one file per call) and prints a
/// job id, as `sbatch --parsable` does.
const SBATCH_STUB: &str = "#!/bin/sh\n\
    n=$(ls \"$SBATCH_CALLS\" | wc -l)\n\
    printf '%s\\0' \"$@\" > \"$SBATCH_CALLS/$n\"\n\
    echo 42\n";

const LIMIT: Duration = Duration::from_secs(60);

fn os(bytes: &[u8]) -> OsString {
    OsString::from_vec(bytes.to_vec())
}

/// A folder for one case: `in/` holds the descriptor, `cwd/` is every
/// command's working folder, `bin/` the sbatch stub (its calls in
/// `bin/calls/`); OUT and anything else a case makes go beside them.
struct Place {
    dir: tempfile::TempDir,
}

impl Place {
    fn new() -> Place {
        let place = Place {
            dir: tempfile::tempdir().unwrap(),
        };
        for sub in ["in", "cwd", "bin/calls"] {
            std::fs::create_dir_all(place.root().join(sub)).unwrap();
        }
        let stub = place.root().join("bin/sbatch");
        std::fs::write(&stub, SBATCH_STUB).unwrap();
        use std::os::unix::fs::PermissionsExt;
        std::fs::set_permissions(&stub, std::fs::Permissions::from_mode(0o755)).unwrap();
        std::fs::write(place.file(), TINY).unwrap();
        place
    }

    fn root(&self) -> &Path {
        self.dir.path()
    }

    fn file(&self) -> PathBuf {
        self.root().join("in/f.toml")
    }

    /// `program args` in `cwd/`, the stub first on the PATH, bounded.
    fn command(&self, program: &OsStr, args: &[OsString]) -> Finished {
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut paths = vec![self.root().join("bin")];
        paths.extend(std::env::split_paths(&path));
        let mut command = limited(program);
        command
            .args(args)
            .current_dir(self.root().join("cwd"))
            .env("PATH", std::env::join_paths(paths).unwrap())
            .env("SBATCH_CALLS", self.root().join("bin/calls"))
            .env("SLURM_ARRAY_TASK_ID", "1")
            .env("SLURM_JOB_ID", "7")
            .env("SLURM_CPUS_PER_TASK", "1");
        let what = format!("{program:?} {args:?}");
        let done = finish(command, &what, LIMIT);
        assert!(!done.stderr.contains("panicked"), "{what}: {}", done.stderr);
        done
    }

    fn study(&self, args: &[OsString]) -> Finished {
        self.command(env!("CARGO_BIN_EXE_study").as_ref(), args)
    }

    /// The arguments of each sbatch call so far, in order.
    fn sbatch_calls(&self) -> Vec<Vec<OsString>> {
        let calls = self.root().join("bin/calls");
        (0..names(&calls).len())
            .map(|n| {
                let bytes = std::fs::read(calls.join(n.to_string())).unwrap();
                let mut args: Vec<OsString> = bytes.split(|&b| b == 0).map(os).collect();
                args.pop();
                args
            })
            .collect()
    }

    /// Nothing injected ran, and nothing was written but in OUT and `extra`
    /// (names beside `in`, `cwd` and `bin`).
    fn assert_clean(&self, extra: &[&OsStr], what: &str) {
        let found = walk(self.root())
            .into_iter()
            .filter(|p| {
                p.file_name()
                    .is_some_and(|n| n.as_bytes().starts_with(PAYLOAD.as_bytes()))
            })
            .collect::<Vec<_>>();
        assert!(found.is_empty(), "{what}: injected commands ran: {found:?}");
        assert!(
            names(&self.root().join("cwd")).is_empty(),
            "{what}: written in the working folder"
        );
        let inputs = names(&self.root().join("in"));
        assert!(
            inputs.iter().all(|n| n.ends_with(".toml")),
            "{what}: beside the descriptor: {inputs:?}"
        );
        for entry in std::fs::read_dir(self.root()).unwrap() {
            let name = entry.unwrap().file_name();
            let known = ["in", "cwd", "bin"].iter().any(|k| name == *k);
            assert!(
                known || extra.contains(&name.as_os_str()),
                "{what}: wrote {name:?}"
            );
        }
    }
}

/// Every path under `dir`, links not followed.
fn walk(dir: &Path) -> Vec<PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if entry.file_type().is_ok_and(|t| t.is_dir()) {
            found.extend(walk(&path));
        }
        found.push(path);
    }
    found
}

/// An `--output` file name pattern as sbatch expands it for array task
/// `task` (sbatch(1), "filename pattern"): `%%` is `%`, `%a` the task id;
/// no other pattern may be left in a path of ours.
fn expand(pattern: &str, task: u32) -> String {
    let mut out = String::new();
    let mut chars = pattern.chars();
    while let Some(c) = chars.next() {
        if c != '%' {
            out.push(c);
            continue;
        }
        match chars.next() {
            Some('%') => out.push('%'),
            Some('a') => out += &task.to_string(),
            other => panic!("a pattern %{other:?} in {pattern:?}"),
        }
    }
    out
}

/// Both scripts of `out`: bash reads them (`bash -n`), no control
/// character but newlines, every `#SBATCH` line among the leading comments
/// (sbatch stops at the first command) and one option without sbatch's
/// syntax in it, and `--output` naming the log in OUT exactly.
fn assert_scripts(out: &Path, what: &str) {
    for (script, log) in [
        ("shards.sbatch", "shard-1.log"),
        ("collect.sbatch", "collect.log"),
    ] {
        let path = out.join("slurm").join(script);
        let text = std::fs::read_to_string(&path).unwrap();
        let o = std::process::Command::new("bash")
            .arg("-n")
            .arg(&path)
            .output()
            .unwrap();
        assert!(
            o.status.success(),
            "{what}: bash -n {script}: {o:?}\n{text}"
        );
        assert!(
            !text.chars().any(|c| c.is_control() && c != '\n'),
            "{what}: {text:?}"
        );
        let mut commands = false;
        for line in text.lines().skip(1) {
            if !line.starts_with('#') {
                commands = true;
            } else if let Some(option) = line.strip_prefix("#SBATCH ") {
                assert!(!commands, "{what}: sbatch ignores {line:?}:\n{text}");
                let lower = option.to_ascii_lowercase();
                assert!(
                    option.starts_with("--")
                        && !option
                            .chars()
                            .any(|c| c.is_whitespace() || "\"'\\#".contains(c))
                        && !lower.contains("hetjob")
                        && !lower.contains("packjob"),
                    "{what}: not one literal option: {line:?}"
                );
            } else {
                assert!(!line.starts_with("#SBATCH"), "{what}: {line:?}");
            }
        }
        let output = text
            .lines()
            .find_map(|l| l.strip_prefix("#SBATCH --output="))
            .unwrap();
        let want = out.join("slurm").join(log);
        assert_eq!(expand(output, 1), want.to_str().unwrap(), "{what}");
    }
}

/// Run both scripts as a node would (bash; sbatch's variables set): shard
/// 1 of 2 saves its run's record in OUT, the collect then finds it and
/// the other missing (exit 1), and its status counts them.
fn assert_scripts_run(place: &Place, out: &Path, what: &str) {
    let slurm = out.join("slurm");
    let shard = place.command(OsStr::new("bash"), &[slurm.join("shards.sbatch").into()]);
    assert_eq!(shard.code, 0, "{what}: {}", shard.stderr);
    assert!(
        shard.stdout.starts_with("shard 1/2: job 7 on "),
        "{what}: {}",
        shard.stdout
    );
    let records = names(&out.join("runs"));
    assert_eq!(records.len(), 1, "{what}: {records:?}");
    let collect = place.command(OsStr::new("bash"), &[slurm.join("collect.sbatch").into()]);
    assert_eq!(collect.code, 1, "{what}: {}", collect.stderr);
    assert!(
        collect.stdout.contains("done: 1, failed: 0, pending: 1"),
        "{what}: {}\n{}",
        collect.stdout,
        collect.stderr
    );
}

/// Where a hostile value goes.
#[derive(Debug, Clone, Copy)]
enum Flag {
    Partition,
    Mem,
    Time,
    /// The name of the --out folder.
    Out,
    /// The name of the descriptor file.
    File,
    /// The name of the folder holding the study executable.
    Exe,
}

/// `study slurm` with `value` at `flag` (and plain values elsewhere) in a
/// fresh place; returns the place, the outcome, OUT and the names a case
/// may add beside `in`, `cwd` and `bin`.
fn slurm_with(
    flag: Flag,
    value: &[u8],
    more: &[&str],
) -> (Place, Finished, PathBuf, Vec<OsString>) {
    let place = Place::new();
    let mut out = place.root().join("out");
    let mut file = place.file();
    let mut study = PathBuf::from(env!("CARGO_BIN_EXE_study"));
    let mut extra = vec![OsString::from("out")];
    let mut flags: Vec<OsString> = Vec::new();
    // `--flag=value`: a value may start with `-`.
    let joined = |flag: &str| os(&[flag.as_bytes(), b"=", value].concat());
    match flag {
        Flag::Partition => flags.push(joined("--partition")),
        Flag::Mem => flags.push(joined("--mem")),
        Flag::Time => flags.push(joined("--time")),
        Flag::Out => {
            out = place.root().join(os(value));
            extra = vec![os(value)];
        }
        Flag::File => {
            file = place.root().join("in").join(os(value));
            std::fs::write(&file, TINY).unwrap();
        }
        Flag::Exe => {
            let dir = place.root().join(os(value));
            std::fs::create_dir(&dir).unwrap();
            study = dir.join("study");
            std::fs::copy(env!("CARGO_BIN_EXE_study"), &study).unwrap();
            extra.push(os(value));
        }
    }
    let mut args: Vec<OsString> = vec![
        "slurm".into(),
        file.into(),
        "--out".into(),
        out.clone().into(),
    ];
    args.extend(["--shards".into(), "2".into()]);
    args.extend(flags);
    args.extend(more.iter().map(OsString::from));
    let done = place.command(study.as_os_str(), &args);
    (place, done, out, extra)
}

/// A hostile value at `flag`: refused (exit 2, nothing written, no
/// control character echoed; its stderr returned) or carried exactly (the
/// scripts as `assert_scripts` and `assert_scripts_run` want them; None).
fn refused_or_carried(flag: Flag, value: &[u8]) -> Option<String> {
    let what = format!("{flag:?} {:?}", os(value));
    let (place, done, out, extra) = slurm_with(flag, value, &[]);
    let extra: Vec<&OsStr> = extra.iter().map(OsString::as_os_str).collect();
    assert!(
        [0, 2].contains(&done.code),
        "{what}: exit {}: {}",
        done.code,
        done.stderr
    );
    if done.code == 2 {
        assert!(!out.exists(), "{what}: refused, yet OUT was made");
        // The folder of the executable is the case's own.
        let made = if matches!(flag, Flag::Exe) {
            &extra[1..]
        } else {
            &[]
        };
        place.assert_clean(made, &what);
        // clap's own usage errors aside, a refusal shows values escaped.
        if !done.stderr.contains("Usage:") {
            assert!(
                !done.stderr.chars().any(|c| c.is_control() && c != '\n'),
                "{what}: echoed raw: {:?}",
                done.stderr
            );
        }
        return Some(done.stderr);
    }
    assert_scripts(&out, &what);
    assert_scripts_run(&place, &out, &what);
    place.assert_clean(&extra, &what);
    None
}

/// Every hostile value of the table: refused (Some(what stderr says)) or
/// carried (None), scripts run, nothing injected executed.
#[test]
fn study_slurm_refuses_or_carries_every_hostile_value() {
    let cases: &[(Flag, &[u8], Option<&str>)] = &[
        (Flag::Partition, b"debug", None),
        (Flag::Partition, b"a_b-c.d,e", None),
        (
            Flag::Partition,
            b"debug\ntouch pwned",
            Some("--partition: \"debug\\ntouch pwned\" has a control character (U+000A at byte 5)"),
        ),
        (
            Flag::Partition,
            b"debug\rx",
            Some("control character (U+000D"),
        ),
        (
            Flag::Partition,
            b"debug\x1b[31m",
            Some("control character (U+001B"),
        ),
        (
            Flag::Partition,
            b"debug\x7f",
            Some("control character (U+007F"),
        ),
        (
            Flag::Partition,
            b"debug touch",
            Some("has ' ', which has no place in an `#SBATCH` line"),
        ),
        (
            Flag::Partition,
            b"$(touch pwned)",
            Some("--partition takes ASCII letters, digits and `_` `-` `.` `,` only"),
        ),
        (Flag::Partition, b"`touch pwned`", Some("--partition")),
        (Flag::Partition, b"a;touch pwned", Some("--partition")),
        (Flag::Partition, b"a'b", Some("--partition")),
        (Flag::Partition, b"a\"b", Some("--partition")),
        (Flag::Partition, b"a#b", Some("--partition")),
        (Flag::Partition, b"a%j", Some("--partition")),
        (Flag::Partition, b"hetjob", Some("splits a Slurm job")),
        (Flag::Partition, b"", Some("--partition: \"\" is empty")),
        (Flag::Partition, b"-x", None),
        (Flag::Mem, b"4G", None),
        (
            Flag::Mem,
            b"4G\ntouch pwned",
            Some("--mem: \"4G\\ntouch pwned\" has a control character"),
        ),
        (
            Flag::Mem,
            b"4G&",
            Some("--mem takes ASCII letters and digits only, e.g. --mem 4G"),
        ),
        (Flag::Mem, b"4G|x", Some("--mem")),
        (Flag::Mem, b"*", Some("--mem")),
        (Flag::Time, b"1-00:00:10", None),
        (Flag::Time, b"10", None),
        (
            Flag::Time,
            b"10\ntouch pwned",
            Some("--time: \"10\\ntouch pwned\" has a control character"),
        ),
        (
            Flag::Time,
            b"inf",
            Some("--time: \"inf\" is not a Slurm time limit"),
        ),
        (Flag::Time, b"1e3", Some("is not a Slurm time limit")),
        (Flag::Out, b"out$(touch${IFS}pwned)", None),
        (Flag::Out, b"out`touch${IFS}pwned`", None),
        (Flag::Out, b"out;touch${IFS}pwned&|*?[x]~!{a,b}", None),
        (Flag::Out, b"out%a%j%%", None),
        (Flag::Out, b"-out", None),
        (Flag::Out, "out-é".as_bytes(), None),
        (Flag::Out, b"out\ntouch pwned", Some("--out: \"")),
        (
            Flag::Out,
            b"out\rx",
            Some("has a control character (U+000D"),
        ),
        (
            Flag::Out,
            b"out\tx",
            Some("has a control character (U+0009"),
        ),
        (
            Flag::Out,
            b"out\x1b[31m",
            Some("has a control character (U+001B"),
        ),
        (
            Flag::Out,
            "out\u{85}".as_bytes(),
            Some("has a control character (U+0085"),
        ),
        (Flag::Out, b"out\xff", Some("is not UTF-8 text")),
        (
            Flag::Out,
            b"out $(touch pwned)",
            Some("has ' ', which sbatch reads in `#SBATCH --output=`"),
        ),
        (
            Flag::Out,
            b"out'x",
            Some("choose a folder whose path has no blanks, quotes, `\\` or `#`"),
        ),
        (Flag::Out, b"out\"x", Some("--out")),
        (Flag::Out, b"out\\x", Some("--out")),
        (Flag::Out, b"out#x", Some("--out")),
        (
            Flag::Out,
            b"out-HetJob",
            Some("has `hetjob`, which splits a Slurm job"),
        ),
        (
            Flag::File,
            b"f $(touch pwned) `touch pwned`;'\"%a&|*.toml",
            None,
        ),
        (Flag::File, b"-f.toml", None),
        (Flag::File, b"f\ntouch pwned\n.toml", Some("FILE: \"")),
        (Flag::File, b"f\xff.toml", Some("FILE: \"")),
        (
            Flag::Exe,
            b"bin $(touch pwned) `touch pwned`;'\"%a&|*",
            None,
        ),
        (
            Flag::Exe,
            b"bin\ntouch pwned",
            Some("the study executable: \""),
        ),
        (Flag::Exe, b"bin\xff", Some("is not UTF-8 text")),
    ];
    for &(flag, value, refused) in cases {
        let what = format!("{flag:?} {:?}", os(value));
        match (refused, refused_or_carried(flag, value)) {
            (None, None) => {}
            (Some(says), Some(stderr)) => assert!(stderr.contains(says), "{what}: {stderr}"),
            (want, got) => panic!("{what}: wanted {want:?}, got {got:?}"),
        }
    }
}

/// `--submit` hands sbatch the scripts' exact paths, and the commands
/// `study slurm` prints, run by bash, do the same: nothing injected runs.
#[test]
fn submitted_and_printed_sbatch_commands_carry_exact_paths() {
    let name: &[u8] = b"out$(touch${IFS}pwned)`touch${IFS}pwned`;&|*%a";
    let (place, done, out, extra) = slurm_with(Flag::Out, name, &["--submit"]);
    assert_eq!(done.code, 0, "{}", done.stderr);
    assert!(
        done.stdout.contains("submitted: array job 42"),
        "{}",
        done.stdout
    );
    let (shards, collect) = (
        out.join("slurm/shards.sbatch"),
        out.join("slurm/collect.sbatch"),
    );
    let submitted: Vec<Vec<OsString>> = vec![
        vec!["--parsable".into(), shards.clone().into()],
        vec![
            "--parsable".into(),
            "--dependency=afterany:42".into(),
            collect.clone().into(),
        ],
    ];
    assert_eq!(place.sbatch_calls(), submitted);
    let printed: Vec<&str> = done
        .stdout
        .lines()
        .skip_while(|l| *l != "submit with:")
        .skip(1)
        .take(2)
        .map(str::trim)
        .collect();
    assert_eq!(printed.len(), 2, "{}", done.stdout);
    let ran = place.command(
        OsStr::new("bash"),
        &["-c".into(), printed.join("\n").into()],
    );
    assert_eq!(ran.code, 0, "{}", ran.stderr);
    let calls = place.sbatch_calls();
    assert_eq!(calls[2], vec![OsString::from("--parsable"), shards.into()]);
    assert_eq!(
        calls[3],
        vec![OsString::from("--dependency=afterany:42"), collect.into()]
    );
    let extra: Vec<&OsStr> = extra.iter().map(OsString::as_os_str).collect();
    place.assert_clean(&extra, "submit");
}

/// Shard counts and run ids as large as the flags take cost memory of the
/// plan (two runs here), under `bounded.rs`'s 2 GB: a shard beyond the
/// runs runs nothing, more --shards than runs and ids outside the plan are
/// refused (exit 2) naming the plan's size, and a script claiming 2^32 - 1
/// array tasks is read by `study status` at once.
#[test]
fn sizes_on_the_command_line_cost_memory_of_the_plan() {
    let place = Place::new();
    let file = place.file();
    let out = place.root().join("out");
    let run = |more: &[&str]| {
        let mut args: Vec<OsString> = vec!["run".into(), file.clone().into()];
        args.extend(["--out".into(), out.clone().into(), "--quiet".into()]);
        args.extend(more.iter().map(OsString::from));
        place.study(&args)
    };
    let max = u64::MAX.to_string();
    let cases: &[(&[&str], i32, &str)] = &[
        (&["--shard", "4294967295/4294967295"], 0, ""),
        (&["--shard", "1/4294967295"], 0, ""),
        (
            &["--runs", "0-18446744073709551615"],
            2,
            "--runs: run 2 is not in the plan, whose runs are 0 to 1",
        ),
        (
            &["--runs", &max],
            2,
            "run 18446744073709551615 is not in the plan",
        ),
        (
            &["--runs", "1,5-9,0"],
            2,
            "run 5 is not in the plan, whose runs are 0 to 1",
        ),
        (&["--runs", "1,0-1,1-1"], 0, ""),
        (&["--runs", "18446744073709551616"], 2, "is not a run id"),
        (
            &["--checkpoint-every", "1e300"],
            2,
            "is not a number of seconds from 0 to 1e9",
        ),
    ];
    for &(more, code, says) in cases {
        let done = run(more);
        assert_eq!(done.code, code, "{more:?}: {}", done.stderr);
        assert!(done.stderr.contains(says), "{more:?}: {}", done.stderr);
    }
    assert_eq!(names(&out.join("runs")).len(), 2, "every run recorded once");

    let slurm = |shards: &str| {
        let args: Vec<OsString> = [
            "slurm".into(),
            file.clone().into(),
            "--out".into(),
            out.clone().into(),
        ]
        .into_iter()
        .chain(["--shards".into(), shards.into()])
        .collect();
        place.study(&args)
    };
    let done = place.study(&[
        "slurm".into(),
        file.clone().into(),
        "--shards".into(),
        "1".into(),
        "--cpus".into(),
        "4097".into(),
    ]);
    assert_eq!(done.code, 2, "{}", done.stderr);
    for shards in ["4294967295", "3"] {
        let done = slurm(shards);
        assert_eq!(done.code, 2, "{}", done.stderr);
        assert!(
            done.stderr.contains(&format!(
                "--shards: {shards} is more shards than the plan has runs (2)"
            )),
            "{}",
            done.stderr
        );
    }
    assert_eq!(slurm("2").code, 0);
    let script = out.join("slurm/shards.sbatch");
    let text = std::fs::read_to_string(&script).unwrap();
    std::fs::write(
        &script,
        text.replace("--array=1-2\n", "--array=1-4294967295\n"),
    )
    .unwrap();
    let record = &names(&out.join("runs"))[0];
    std::fs::remove_file(out.join("runs").join(record)).unwrap();
    let done = place.study(&["status".into(), out.clone().into()]);
    assert_eq!(done.code, 0, "{}", done.stderr);
    for want in [
        "done: 1, failed: 0, pending: 1",
        "shards (of 4294967295) with runs left: ",
    ] {
        assert!(done.stdout.contains(want), "{want}: {}", done.stdout);
    }
    place.assert_clean(&[OsStr::new("out")], "sizes");
}

/// Pieces of hostile values: shell and sbatch syntax, and plain text so
/// that some values are valid...
const PRINTABLE: &[&[u8]] = &[
    b"a",
    b"4G",
    b"debug",
    b"10",
    b":",
    b",",
    b"-",
    b"--",
    b".",
    b"_",
    b"1",
    "é".as_bytes(),
    b" ",
    b"$(touch pwned)",
    b"$(touch${IFS}pwned)",
    b"`touch${IFS}pwned`",
    b"'",
    b"\"",
    b";",
    b"%",
    b"%a",
    b"%%",
    b"&",
    b"|",
    b"*",
    b"?",
    b"\\",
    b"#",
    b"!",
    b"~",
    b"{a,b}",
    b"hetjob",
    b"${IFS}",
    b"$HOME",
];

/// ...and control characters and bytes that are not UTF-8.
const CONTROL: &[&[u8]] = &[
    b"\n",
    b"\r",
    b"\t",
    b"\x1b[31m",
    b"\x7f",
    b"\xc2\x85",
    b"\xff",
    b"\xe2\x80\xa8",
];

/// A flag (0 to 4) and a value: half of them printable, half with control
/// characters or other bytes among the pieces.
fn hostile() -> impl Strategy<Value = (u8, Vec<u8>)> {
    let printable = proptest::sample::select(PRINTABLE);
    let any = proptest::sample::select([PRINTABLE, CONTROL].concat());
    let pieces = prop_oneof![
        proptest::collection::vec(printable, 1..5),
        proptest::collection::vec(any, 1..5),
    ];
    (0u8..5, pieces).prop_map(|(flag, pieces)| (flag, pieces.concat()))
}

proptest! {
    #![proptest_config(config(32))]

    /// Random hostile values at every text flag of `study slurm`: refused
    /// or carried, as `refused_or_carried` checks.
    #[test]
    fn hostile_slurm_values_are_refused_or_carried((flag, value) in hostile()) {
        let (flag, value) = match flag {
            0 => (Flag::Partition, value),
            1 => (Flag::Mem, value),
            2 => (Flag::Time, value),
            // One name in the place, never a path that leaves it.
            3 => (Flag::Out, [b"o".as_slice(), &value].concat()),
            _ => (Flag::File, [b"f".as_slice(), &value, b".toml"].concat()),
        };
        let _ = refused_or_carried(flag, &value);
    }
}

/// Numbers as a hostile tester writes them.
const NUMBERS: &[&str] = &[
    "0",
    "1",
    "2",
    "-1",
    "4294967295",
    "4294967296",
    "18446744073709551615",
    "18446744073709551616",
    "1e9",
    "1e300",
    "NaN",
    "inf",
    "",
    " 1",
    "1/0",
    "0/0",
    "4294967295/4294967295",
    "1/4294967295",
    "2/1",
    "0-18446744073709551615",
    "3,1-2,18446744073709551615",
    "1-0",
    "0.5",
    "0x10",
    "1\n2",
];

const RUN_FLAGS: &[&str] = &[
    "--shard",
    "--runs",
    "--threads",
    "--replicas",
    "--checkpoint-every",
];
const SLURM_FLAGS: &[&str] = &["--shards", "--cpus", "--replicas", "--checkpoint-every"];

proptest! {
    #![proptest_config(config(24))]

    /// Hostile numbers at the numeric flags of `study run` and `study
    /// slurm`: exit 0, 1 or 2 (never a panic or a signal), within the time
    /// and memory bounds, nothing written outside OUT.
    #[test]
    fn hostile_numbers_end_with_a_code_in_bounds(
        slurm in any::<bool>(),
        flag in any::<proptest::sample::Index>(),
        number in proptest::sample::select(NUMBERS),
    ) {
        let place = Place::new();
        let out = place.root().join("out");
        let (command, flags) = if slurm { ("slurm", SLURM_FLAGS) } else { ("run", RUN_FLAGS) };
        let flag = flags[flag.index(flags.len())];
        let mut args: Vec<OsString> = vec![command.into(), place.file().into(), "--out".into(), out.into()];
        if slurm && flag != "--shards" {
            args.extend(["--shards".into(), "1".into()]);
        }
        if !slurm {
            args.push("--quiet".into());
        }
        args.extend([flag.into(), number.into()]);
        let done = place.study(&args);
        prop_assert!([0, 1, 2].contains(&done.code), "{args:?}: exit {}: {}", done.code, done.stderr);
        place.assert_clean(&[OsStr::new("out")], &format!("{args:?}"));
    }
}
