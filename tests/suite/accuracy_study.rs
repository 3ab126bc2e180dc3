//! The accuracy study end to end on a small plan (fixed steps and the exact
//! reference on one scene), and the descriptor checks of `[run] integrator`.

use bonkers::descriptor::check::check;
use bonkers::descriptor::load::parse;
use bonkers::model::run_output::RunOutput;
use bonkers::model::run_spec::RunSpec;
use bonkers::runner::plan::plan;
use bonkers::stats::ensemble::Runs;
use bonkers::studies::{self, Study};

fn ensemble(text: &str) -> Vec<(RunSpec, RunOutput)> {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    plan(&loaded)
        .expect("plan")
        .into_iter()
        .map(|r| {
            let out = bonkers::runner::execute::simulate::run(&r).expect("run");
            (r, out)
        })
        .collect()
}

const SMALL: &str = r#"
[study]
name = "accuracy-test"
replicas = 2
seed = 3

[scene]
preset = "disks-dense"

[sweep.parameters]
"run.dt" = [0.003, 0.1]
"run.integrator" = ["fixed-step", "fixed-step-naive"]

[run]
integrator = "fixed-step"
duration = 10.0
sample_every = 0.5

[observe]
scalars = ["wall_pressure"]

[analysis.accuracy]

[[case]]
name = "exact"
replicas = 4
[case.set]
"run.integrator" = "exact"
"#;

#[test]
fn a_small_study_compares_both_integrators() {
    let runs = ensemble(SMALL);
    assert_eq!(runs.len(), 2 * 2 * 2 + 4);
    for (spec, out) in &runs {
        assert!(out.scalar("wall_pressure").unwrap() > 0.0);
        // Dense disks: βP = Z ρ well above the ideal gas's ρ = 0.51 (the
        // exact engine's: the naive fixed step's stuck pairs push it far up).
        let beta_p = out.scalar("beta_pressure").unwrap();
        assert!(beta_p > 0.0);
        if spec.descriptor.run.integrator.is_exact() {
            assert!(beta_p > 1.2 && beta_p < 2.2, "βP {beta_p}");
        }
        assert!(out.scalar("collision_rate").unwrap() > 0.0);
        let drift = out.scalar("energy_drift").unwrap();
        assert!(drift < 1e-12, "energy drift {drift}");
        let stepped = !spec.descriptor.run.integrator.is_exact();
        assert_eq!(out.scalar("overlap_depth_max").is_some(), stepped);
        // Without a piston the piston's series is not kept.
        assert!(out.series("piston_position").is_none());
    }
    let section = studies::accuracy::Accuracy
        .section(&runs[0].0.descriptor, &Runs::from(runs.clone()))
        .unwrap();
    assert_eq!(
        section.figures.len(),
        1,
        "the error-cost chart:\n{}",
        section.markdown
    );
    let md = &section.markdown;
    for want in [
        "Sticking, disks-dense",
        "Energy:",
        "| exact |",
        "| fixed-step | 0.1 |",
    ] {
        assert!(md.contains(want), "section lacks {want:?}:\n{md}");
    }
}

fn problem(run: &str) -> String {
    let text = format!(
        "[study]\nname = \"x\"\n[scene]\npreset = \"disks-dilute\"\n[run]\nduration = 1.0\n{run}\n"
    );
    let err = refused(&text);
    format!(
        "{} {:?} {:?} {}",
        err.message,
        err.key,
        err.position,
        err.hints.join(" ")
    )
}

/// Loading checks the descriptor; what it lets through `check` must refuse.
fn refused(text: &str) -> bonkers::descriptor::errors::DescriptorError {
    match parse("bad.toml", text) {
        Err(e) => e,
        Ok(loaded) => check(&loaded).expect_err("refused"),
    }
}

#[test]
fn integrator_keys_are_checked_with_what_would_be_right() {
    let e = problem("integrator = \"fixed-step\"");
    assert!(
        e.contains("run.integrator") && e.contains("dt = 0.01"),
        "{e}"
    );
    let e = problem("dt = 0.1");
    assert!(e.contains("run.dt") && e.contains("fixed-step"), "{e}");
    let e = problem("integrator = \"fixed-step\"\ndt = -1.0");
    assert!(e.contains("run.dt") && e.contains("positive"), "{e}");
    let e = problem("integrator = \"leapfrog\"\ndt = 0.1");
    assert!(e.contains("fixed-step") && e.contains("Some((7"), "{e}");
    // Point rods never overlap: a fixed step cannot see them collide.
    let text = "[study]\nname = \"x\"\n[scene]\npreset = \"mackay-ten\"\n[run]\nduration = 1.0\nintegrator = \"fixed-step\"\ndt = 0.01\n";
    let err = refused(text);
    assert!(err.message.contains("radius 0"), "{}", err.message);
}
