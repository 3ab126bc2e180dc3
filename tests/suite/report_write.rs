//! The report on synthetic studies: every file written, self-contained HTML,
//! well-formed SVG, and no panics on NaN, failures or degenerate data.
//! Set BONKERS_KEEP_REPORT=<dir> to keep the full demo report for viewing.

use bonkers::model::chart::{ChartSpec, Layer, Paint};
use bonkers::model::descriptor::Descriptor;
use bonkers::model::report::{Figure, ReportSection};
use bonkers::model::run_output::{Histogram, RunOutput, Series};
use bonkers::model::run_spec::RunSpec;
use bonkers::report::{ReportMeta, write};
use bonkers::stats::ensemble::Runs;
use bonkers::stats::summary::summarize;
use std::path::Path;

const SWEPT: &str = "[study]\nname = \"piston <demo> & co\"\ndescription = \"Synthetic piston study.\"\n\
replicas = 3\nseed = 1\n[scene]\ndimension = 1\n[sweep.parameters]\n\
\"scene.piston.mass\" = [1.0, 10.0, 100.0, 1000.0]\n\"scene.species.0.count\" = [4, 8]\n\
[run]\nduration = 50.0\nsample_every = 1.0\n";

const PLAIN: &str = "[study]\nname = \"t\"\nreplicas = 3\nseed = 1\n[scene]\ndimension = 1\n[run]\nduration = 1.0\n";

fn descriptor(text: &str) -> Descriptor {
    toml::from_str(text).expect("test descriptor parses")
}

/// Cheap deterministic noise in [-1, 1].
fn noise(k: u64) -> f64 {
    let x = k
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    ((x >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
}

fn swept_runs() -> Vec<(RunSpec, RunOutput)> {
    let base = descriptor(SWEPT);
    let mut runs = Vec::new();
    let mut point = 0;
    for mass in [1.0, 10.0, 100.0, 1000.0] {
        for count in [4_i64, 8] {
            for replica in 0..3_u32 {
                let id = point * 3 + u64::from(replica);
                let freq = (count as f64 / mass).sqrt() * (1.0 + 0.05 * noise(id));
                let len = 50 - replica as usize; // unequal lengths: truncated
                let t: Vec<f64> = (0..len).map(|i| i as f64).collect();
                let x = t
                    .iter()
                    .map(|t| 0.5 + 0.2 * (freq * t).sin() + 0.02 * noise(id + *t as u64))
                    .collect();
                let counts = (0..10)
                    .map(|b| {
                        100.0 * (-((b as f64 - 4.5) / 2.0).powi(2)).exp() + 5.0 * noise(id + b)
                    })
                    .collect();
                let spec = RunSpec {
                    run_id: id,
                    point_id: point,
                    replica,
                    seed: 1000 + id,
                    params: vec![
                        ("scene.piston.mass".into(), toml::Value::Float(mass)),
                        ("scene.species.0.count".into(), toml::Value::Integer(count)),
                    ]
                    .into(),
                    case: None,
                    descriptor: base.clone().into(),
                };
                let out = RunOutput {
                    scalars: vec![
                        ("frequency".into(), freq),
                        ("biased".into(), 1.0 + 0.01 * noise(id + 7)),
                        (
                            "sometimes".into(),
                            if replica == 1 { f64::NAN } else { mass },
                        ),
                    ],
                    series: vec![Series {
                        observable: "piston_x".into(),
                        t,
                        value: x,
                    }],
                    histograms: vec![Histogram {
                        observable: "vx".into(),
                        lo: (0..10).map(|b| -2.5 + 0.5 * b as f64).collect(),
                        hi: (0..10).map(|b| -2.0 + 0.5 * b as f64).collect(),
                        count: counts,
                    }],
                    events: 5000,
                    collisions: 4000 + id * 10,
                    wall_seconds: 0.01 * (1.0 + mass.log10()),
                    cpu_seconds: 0.05,
                    prepare_seconds: 0.0,
                };
                runs.push((spec, out));
            }
            point += 1;
        }
    }
    runs
}

/// Theory from the run's parameters (the synthetic descriptor is not
/// substituted, so the test looks the point up by its result).
fn theory(name: &str, params: &[(String, f64)]) -> Option<f64> {
    let get = |k: &str| params.iter().find(|(p, _)| p == k).map(|(_, v)| *v);
    match name {
        "frequency" => Some((get("scene.species.0.count")? / get("scene.piston.mass")?).sqrt()),
        "biased" => Some(2.0),
        "sometimes" => get("scene.piston.mass"),
        _ => None,
    }
}

fn meta(failed: Vec<(u64, String)>) -> ReportMeta {
    ReportMeta {
        command: "study run studies/piston.toml".into(),
        threads: 2,
        started: "2026-01-01T00:00:00Z".into(),
        finished: "2026-01-01T00:00:03Z".into(),
        version: "0.1.0".into(),
        total_wall_seconds: 1.5,
        runs_wall_seconds: 0.6,
        resumed_runs: 0,
        planned_runs: 24,
        failed_runs: failed,
    }
}

fn summary_with_theory(runs: &[(RunSpec, RunOutput)]) -> Vec<bonkers::model::summary::SummaryRow> {
    let mut rows = summarize(runs, &|_: &Descriptor, _: &str| None);
    for r in &mut rows {
        r.theory = theory(&r.result, &r.params);
        r.z = r
            .theory
            .filter(|_| r.n >= 2 && r.stderr > 0.0)
            .map(|t| (r.mean - t) / r.stderr);
    }
    rows
}

/// Tags balance: every opened element is closed in order.
pub(crate) fn balanced(svg: &str) -> Result<(), String> {
    let mut stack: Vec<String> = Vec::new();
    let mut rest = svg;
    while let Some(start) = rest.find('<') {
        let end = rest[start..].find('>').ok_or("unterminated tag")? + start;
        let tag = &rest[start + 1..end];
        rest = &rest[end + 1..];
        if tag.starts_with('?') || tag.starts_with('!') || tag.ends_with('/') {
            continue;
        }
        let name: String = tag
            .trim_start_matches('/')
            .chars()
            .take_while(|c| c.is_alphanumeric())
            .collect();
        if tag.starts_with('/') {
            if stack.pop().as_deref() != Some(name.as_str()) {
                return Err(format!("unexpected </{name}>"));
            }
        } else {
            stack.push(name);
        }
    }
    if stack.is_empty() {
        Ok(())
    } else {
        Err(format!("unclosed {stack:?}"))
    }
}

fn svg_files(dir: &Path) -> Vec<std::path::PathBuf> {
    let mut v: Vec<_> = std::fs::read_dir(dir)
        .expect("out dir readable")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    v.sort();
    v
}

fn check_svgs(dir: &Path) {
    for f in svg_files(dir) {
        let svg = std::fs::read_to_string(&f).expect("svg readable");
        assert!(
            svg.trim_start().starts_with("<svg"),
            "{f:?} starts with <svg"
        );
        assert!(svg.trim_end().ends_with("</svg>"), "{f:?} ends with </svg>");
        balanced(&svg).unwrap_or_else(|e| panic!("{f:?}: {e}"));
    }
}

#[test]
fn full_report_writes_every_file() {
    let keep = std::env::var_os("BONKERS_KEEP_REPORT");
    let tmp = tempfile::tempdir().expect("temp dir");
    let dir = keep.as_ref().map_or(tmp.path(), Path::new);
    std::fs::create_dir_all(dir).expect("out dir");
    let runs = swept_runs();
    let summary = summary_with_theory(&runs);
    // A study's section hands its figure over as chart data: the report renders it.
    let chart = ChartSpec {
        title: "piston path".into(),
        layers: vec![Layer::Line {
            points: vec![(0.0, 1.0), (1.0, 2.0)],
            paint: Paint::solid((0, 0, 0)),
            width: 1,
            dashed: false,
            label: None,
        }],
        ..Default::default()
    };
    let sections = vec![ReportSection {
        title: "Space-time diagram".into(),
        markdown: "The piston **oscillates**; see `runs.parquet` and <this>.\n\n| a | b |\n|---|---|\n| 1 | 2 |\n\n![an extra figure](extra.svg)".into(),
        figures: vec![Figure {
            file: "extra.svg".into(),
            chart,
        }],
        presents: Vec::new(),
    }];
    let d = descriptor(SWEPT);
    write(
        dir,
        &d,
        &Runs::from(runs.clone()),
        &summary,
        &sections,
        &meta(vec![]),
    )
    .expect("report written");

    for f in [
        "report.md",
        "index.html",
        "scalar_frequency.svg",
        "scalar_biased.svg",
        "series_piston_x.svg",
        "hist_vx.svg",
        "extra.svg",
    ] {
        assert!(dir.join(f).is_file(), "{f} written");
    }
    assert!(
        std::fs::read_dir(dir).expect("dir").all(|e| !e
            .expect("entry")
            .path()
            .to_string_lossy()
            .ends_with(".tmp"))
    );
    check_svgs(dir);

    let md = std::fs::read_to_string(dir.join("report.md")).expect("md");
    assert!(md.contains("![") && md.contains("(scalar_frequency.svg)"));
    assert!(md.contains("8 points × 3 replicas = 24 runs"));
    assert!(md.contains("⚠"), "the biased result is flagged");
    assert!(md.contains("2 of 3"), "NaN results are visible in n");
    assert!(md.contains("## Space-time diagram"));
    assert!(md.contains("runs.parquet") && md.contains("summary.parquet"));
    // Cost: CPU seconds of the runs (24 x 0.05 s) against the time spent
    // running them (0.6 s), not against their own sum.
    assert!(md.contains("| CPU s |"), "{md}");
    assert!(
        md.contains(
            "The runs took 1.2 CPU seconds in 0.6 s of wall time on 2 threads (parallel speed-up 2)"
        ),
        "{md}"
    );

    let html = std::fs::read_to_string(dir.join("index.html")).expect("html");
    assert!(!html.contains("http"), "no external references");
    assert!(html.contains("<svg"));
    assert_eq!(
        html.matches("<svg").count(),
        6,
        "5 plots + the section's figure inlined"
    );
    assert_eq!(html.matches("<svg").count(), html.matches("</svg>").count());
    assert!(
        html.contains("piston &lt;demo&gt; &amp; co"),
        "title escaped"
    );
    assert!(html.contains("&lt;this&gt;"), "section text escaped");
    assert!(!html.contains("<script") && !html.contains("<link"));
    let frequency = std::fs::read_to_string(dir.join("scalar_frequency.svg")).expect("svg");
    assert!(
        frequency.contains("<text") && frequency.contains("theory"),
        "labels render without ttf"
    );
}

#[test]
fn nan_results_and_failed_runs_do_not_panic() {
    let dir = tempfile::tempdir().expect("temp dir");
    let d = descriptor(PLAIN);
    let mut runs = swept_runs();
    runs.truncate(3);
    for (_, out) in &mut runs {
        out.scalars = vec![("frequency".into(), f64::NAN)];
        out.wall_seconds = f64::NAN;
        out.series[0].value.iter_mut().for_each(|v| *v = f64::NAN);
    }
    let summary = summarize(&runs, &|_: &Descriptor, _: &str| Some(1.0));
    let failed = vec![(99, "overlap at start:\nparticle 3 | particle 4".to_string())];
    write(
        dir.path(),
        &d,
        &Runs::from(runs.clone()),
        &summary,
        &[],
        &meta(failed),
    )
    .expect("report written");
    let md = std::fs::read_to_string(dir.path().join("report.md")).expect("md");
    assert!(
        md.contains("## Failed runs")
            && md.contains("run 99: overlap at start: particle 3 \\| particle 4")
    );
    assert!(md.contains("0 of 3"));
    let series = std::fs::read_to_string(dir.path().join("series_piston_x.svg")).expect("svg");
    assert!(series.contains("no finite data to plot"));
    check_svgs(dir.path());
}

#[test]
fn degenerate_data_gives_placeholders_not_panics() {
    let d = descriptor(PLAIN);
    let spec = |replica: u32| RunSpec {
        run_id: u64::from(replica),
        point_id: 0,
        replica,
        seed: 5,
        params: vec![].into(),
        case: None,
        descriptor: d.clone().into(),
    };
    let empty_series = Series {
        observable: "empty".into(),
        t: vec![],
        value: vec![],
    };
    let one_sample = Series {
        observable: "one".into(),
        t: vec![0.0],
        value: vec![1.0],
    };
    let empty_hist = Histogram {
        observable: "h".into(),
        lo: vec![],
        hi: vec![],
        count: vec![],
    };
    let out = RunOutput {
        scalars: vec![
            ("flat".into(), 2.0),
            ("gone".into(), f64::NAN),
            ("inf".into(), f64::INFINITY),
        ],
        series: vec![empty_series, one_sample],
        histograms: vec![empty_hist],
        ..RunOutput::default()
    };
    let cases: Vec<Vec<(RunSpec, RunOutput)>> = vec![
        vec![],
        vec![(spec(0), out.clone())],
        (0..3).map(|r| (spec(r), out.clone())).collect(),
    ];
    for runs in cases {
        let dir = tempfile::tempdir().expect("temp dir");
        let theory = |_: &Descriptor, name: &str| (name == "flat").then_some(2.0);
        let summary = summarize(&runs, &theory);
        write(
            dir.path(),
            &d,
            &Runs::from(runs.clone()),
            &summary,
            &[],
            &meta(vec![]),
        )
        .expect("report written");
        assert!(dir.path().join("index.html").is_file());
        check_svgs(dir.path());
        if !runs.is_empty() {
            let gone = std::fs::read_to_string(dir.path().join("scalar_gone.svg")).expect("svg");
            assert!(gone.contains("no finite data to plot"));
            let flat = std::fs::read_to_string(dir.path().join("scalar_flat.svg")).expect("svg");
            assert!(
                flat.contains("<circle"),
                "a single or zero-spread point is still drawn"
            );
        }
    }
}
