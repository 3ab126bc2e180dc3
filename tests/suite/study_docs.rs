//! docs/descriptor.md tells the truth: its annotated example validates with
//! every name it uses and runs end to end (its `--quick` version), its table
//! of observables is the observable catalogue, and it lists every analysis
//! option bonkers knows and, per analysis, every result and need.

use crate::study_common::run_options;
use bonkers::descriptor::load::{parse, quick};
use bonkers::descriptor::sweep::count;
use bonkers::observe::{CATALOGUE, Entry, catalogue};
use bonkers::runner::pipeline::{StudyOptions, run_study};
use bonkers::runner::store::read_parquet;
use bonkers::studies::REGISTRY;
use std::sync::atomic::AtomicBool;

fn doc() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/descriptor.md")).unwrap()
}

fn example() -> String {
    doc()
        .split("```toml\n")
        .nth(1)
        .unwrap()
        .split("```")
        .next()
        .unwrap()
        .to_string()
}

#[test]
fn the_documented_example_is_valid() {
    let loaded = parse("docs/descriptor.md", &example()).unwrap();
    // 6 sweep points x 8 replicas and one case x 4.
    assert_eq!(count(&loaded), (6 + 1, 48 + 4));
    let q = quick(&loaded).unwrap();
    assert_eq!(count(&q), (4 + 1, 8 + 4));
    // Every name is one bonkers knows (parse checks them; these make sure
    // the example exercises each kind of name).
    let d = &loaded.descriptor;
    assert!(!d.observe.series.is_empty() && !d.observe.scalars.is_empty());
    assert!(!d.observe.histograms.is_empty());
    assert!(d.analysis["piston"].contains_key("window_periods"));
    assert_eq!(d.case.len(), 1);
}

/// The example's --quick version on the real engine: every run succeeds and
/// every table and the report are there, with the observed quantities.
#[test]
fn the_documented_example_runs() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("example.toml");
    std::fs::write(&file, example()).unwrap();
    let out = dir.path().join("out");
    let options = StudyOptions {
        quick: true,
        command_line: vec!["study".into()],
        ..run_options(&out, 2)
    };
    let outcome = run_study(
        &file,
        &options,
        &bonkers::runner::execute::simulate::run,
        &AtomicBool::new(false),
    )
    .unwrap();
    assert_eq!((outcome.planned, outcome.failed), (8 + 4, 0));
    let runs = read_parquet(&out.join("runs.parquet")).unwrap();
    for column in [
        "wall_pressure",
        "temperature",
        "frequency_ratio",
        "cpu_seconds",
    ] {
        assert!(runs.column(column).is_ok(), "runs.parquet lacks {column}");
    }
    let series = read_parquet(&out.join("series.parquet")).unwrap();
    let observables = series.column("observable").unwrap().str().unwrap();
    for name in ["kinetic_energy", "piston_position", "kinetic_energy.light"] {
        assert!(
            (0..observables.len()).any(|k| observables.get(k) == Some(name)),
            "no {name} series"
        );
    }
    assert!(
        read_parquet(&out.join("histograms.parquet"))
            .unwrap()
            .height()
            > 0
    );
    assert!(read_parquet(&out.join("summary.parquet")).unwrap().height() > 0);
    assert!(out.join("index.html").is_file() && out.join("manifest.json").is_file());
}

#[test]
fn every_analysis_option_is_documented() {
    let doc = doc();
    for a in REGISTRY {
        for o in a.options() {
            let row = format!("| `{}` | `{}` |", a.name(), o.name);
            assert!(doc.contains(&row), "docs/descriptor.md lacks the row {row}");
        }
    }
}

/// The text of the subsection `#### `<name>``, up to the next heading.
fn subsection<'a>(doc: &'a str, name: &str) -> Option<&'a str> {
    let heading = format!("#### `{name}`\n");
    let rest = &doc[doc.find(&heading)? + heading.len()..];
    Some(&rest[..rest.find("\n#").map_or(rest.len(), |end| end + 1)])
}

/// Every analysis has its subsection, which names (in backticks) every
/// result it can write, says each of its needs as the observables table
/// does (`catalogue::need_text`), and links its physics page.
#[test]
fn every_analysis_result_is_documented() {
    let doc = doc();
    for a in REGISTRY {
        let name = a.name();
        let text = subsection(&doc, name)
            .unwrap_or_else(|| panic!("docs/descriptor.md lacks the heading #### `{name}`"));
        let missing: Vec<&str> = (a.results().iter().copied())
            .filter(|r| !text.contains(&format!("`{r}`")))
            .collect();
        assert!(
            missing.is_empty(),
            "docs/descriptor.md, #### `{name}`, does not document the results {}",
            missing.join(", ")
        );
        for need in a.needs() {
            let need = catalogue::need_text(*need);
            assert!(
                text.contains(&need),
                "docs/descriptor.md, #### `{name}`, does not say it needs {need}"
            );
        }
        let link = format!("]({name}.md)");
        assert!(
            text.contains(&link),
            "docs/descriptor.md, #### `{name}`, does not link {name}.md"
        );
    }
}

const OBSERVABLES_HEADER: &str = "| kind | name | gives | writes | unit | needs |";

/// The cells of each row of the observables table, unescaped and trimmed.
fn observable_rows(doc: &str) -> Vec<Vec<String>> {
    let mut lines = doc.lines().skip_while(|l| *l != OBSERVABLES_HEADER);
    assert!(
        lines.next().is_some(),
        "docs/descriptor.md lacks the observables table {OBSERVABLES_HEADER}"
    );
    lines
        .skip(1) // |---|...
        .take_while(|l| l.starts_with('|'))
        .map(|l| {
            // Split at the `|` that are not escaped as `\|`.
            let cells = l.trim().trim_matches('|').replace("\\|", "\u{1}");
            cells
                .split('|')
                .map(|c| c.trim().replace('\u{1}', "|"))
                .collect()
        })
        .collect()
}

/// A catalogue entry as its row of the table says it.
fn documented(e: &Entry) -> Vec<String> {
    let needs: Vec<String> = e.needs.iter().map(|n| catalogue::need_text(*n)).collect();
    vec![
        format!("`{}`", e.kind.key()),
        format!("`{}`", e.name),
        e.doc.to_string(),
        format!("`{}`", e.writes),
        e.unit.to_string(),
        needs.join(", "),
    ]
}

/// The observables table of docs/descriptor.md and the catalogue are the
/// same list: every entry has its row (kind, name, doc, names written, unit,
/// needs), and every row is an entry.
#[test]
fn the_observables_table_is_the_catalogue() {
    let rows = observable_rows(&doc());
    for e in CATALOGUE {
        let row = documented(e);
        let same_name = rows.iter().find(|r| r[..2] == row[..2]);
        assert_eq!(
            same_name,
            Some(&row),
            "docs/descriptor.md: the row of {} `{}` should read\n| {} |",
            e.kind.key(),
            e.name,
            row.join(" | ")
        );
    }
    for row in &rows {
        assert!(
            CATALOGUE.iter().any(|e| documented(e)[..2] == row[..2]),
            "docs/descriptor.md documents {} {}, which the catalogue lacks",
            row[0],
            row[1]
        );
    }
    assert_eq!(rows.len(), CATALOGUE.len(), "a row is there twice");
}
