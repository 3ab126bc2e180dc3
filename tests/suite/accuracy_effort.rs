//! The studies' error models (`Study::error_model`) against seeded runs:
//! each predicts the standard error of its headline result over n replicas
//! before anything runs; n replicas with seeds other than the calibration's
//! (studies/accuracy.toml, seed 15) measure it. They must agree within four
//! standard errors of the comparison: the measured standard error's own
//! (relative, from the values' fourth moment; 1/sqrt(2(n-1)) for normal
//! values) and the model constant's (from its calibration runs). And
//! `study validate` prints the prediction.

use bonkers::descriptor::load::parse;
use bonkers::model::descriptor::Descriptor;
use bonkers::runner::plan::error_bars::two_digits;
use bonkers::runner::plan::plan;
use bonkers::stats::error_model::scatter_uncertainty_of;
use bonkers::stats::summary::Stats;
use bonkers::studies::{self, ErrorModel};
use std::process::Command;

/// The model at the descriptor, and the headline result of each replica.
fn predicted_and_measured(text: &str) -> (ErrorModel, Vec<f64>) {
    let loaded = parse("test.toml", text).expect("valid descriptor");
    let specs = plan(&loaded).expect("plan");
    let d: &Descriptor = &specs[0].descriptor;
    let (_, model) = studies::error_models(d)
        .into_iter()
        .next()
        .expect("the study has a model here");
    let result = model.result;
    let values: Vec<f64> = std::thread::scope(|scope| {
        let handles: Vec<_> = specs
            .chunks(specs.len().div_ceil(2))
            .map(|chunk| {
                scope.spawn(move || {
                    chunk
                        .iter()
                        .map(|s| bonkers::runner::execute::simulate::run(s).expect("run"))
                        .filter_map(|o| o.scalar(result))
                        .collect::<Vec<f64>>()
                })
            })
            .collect();
        handles
            .into_iter()
            .flat_map(|h| h.join().unwrap())
            .collect::<Vec<f64>>()
    })
    .into_iter()
    .filter(|v| v.is_finite())
    .collect();
    (model, values)
}

fn agrees(text: &str, replicas: usize) {
    let (model, values) = predicted_and_measured(text);
    let n = values.len();
    assert_eq!(n, replicas, "{n} of {replicas} runs measured it");
    let s = Stats::of(&values);
    let measured = s.std / s.mean.abs() / (n as f64).sqrt();
    let predicted = model.stderr(n as u32);
    // The measured error's own uncertainty from the values' fourth moment
    // (heavy tails widen it), and the model constant's.
    let u = scatter_uncertainty_of(&values).hypot(model.uncertainty);
    let z = (measured / predicted - 1.0) / u;
    eprintln!(
        "{}: standard error over {n} replicas predicted {predicted:.5}, measured {measured:.5} ({z:+.2} σ)",
        model.label
    );
    assert!(
        z.abs() < 4.0,
        "{}: predicted standard error {predicted:.4} over {n} replicas, measured {measured:.4} \
         ({z:.1} standard errors; model: {})",
        model.label,
        model.basis
    );
}

#[test]
fn pressure_model_predicts_the_error_of_z() {
    // 64 disks at eta = 0.3 for 100 time units: a quarter of the
    // calibration's N and other lengths, so the 1/sqrt(N T) form is tested.
    agrees(
        r#"
[study]
name = "z"
replicas = 24
seed = 1501
[scene]
box = [12.9441727504, 12.9441727504]
boundary = ["periodic", "periodic"]
velocities = { kind = "maxwell", temperature = 1.0, zero_momentum = true }
placement = { kind = "random" }
[[scene.species]]
name = "gas"
count = 64
radius = 0.5
[run]
duration = 100.0
equilibrate = 20.0
sample_every = 0.5
[observe]
series = ["virial_pressure"]
[analysis.pressure]
"#,
        24,
    );
}

#[test]
fn piston_model_predicts_the_error_of_the_frequency_ratio() {
    agrees(
        r#"
[study]
name = "piston"
replicas = 32
seed = 1502
[scene]
preset = "mackay-piston"
velocities = { kind = "maxwell", temperature = 1.0 }
piston = { mass = 100.0, position = 0.5, radius = 0.0, energy = 10.0, per_side = 5 }
[run]
duration = 300.0
sample_every = 0.5
[analysis.piston]
"#,
        32,
    );
}

#[test]
fn mixing_model_predicts_the_error_of_the_mixing_time() {
    agrees(
        r#"
[study]
name = "mixing"
replicas = 32
seed = 1503
[scene]
dimension = 1
box = [100.0]
boundary = ["walls"]
velocities = { kind = "equal", velocity = [0.0] }
piston = { mass = 1.0, velocity = 4.0, radius = 0.5 }
[[scene.species]]
name = "gas"
count = 9
mass = [1.0, 1.3]
radius = 0.5
[run]
duration = 4000.0
sample_every = 2.0
[analysis.mixing]
"#,
        32,
    );
}

#[test]
fn expansion_model_predicts_the_error_of_the_relaxation_time() {
    // 100 disks: four times the calibration's N, so 1/sqrt(N) is tested.
    agrees(
        r#"
[study]
name = "expansion"
replicas = 32
seed = 1504
[scene]
dimension = 2
box = [40.0, 40.0]
boundary = ["walls", "walls"]
velocities = { kind = "maxwell", temperature = 1.0 }
[[scene.species]]
name = "gas"
count = 100
radius = 0.05
region = { from = [0.0, 0.0], to = [0.5, 1.0] }
[run]
duration = 100.0
sample_every = 0.5
[analysis.expansion]
"#,
        32,
    );
}

#[test]
fn validate_prints_the_error_bars_the_models_predict() {
    let root = env!("CARGO_MANIFEST_DIR");
    for (file, study) in [
        ("studies/piston.toml", "piston"),
        ("studies/pressure.toml", "pressure"),
        ("studies/mixing.toml", "mixing"),
        ("studies/expansion.toml", "expansion"),
    ] {
        let path = format!("{root}/{file}");
        let out = Command::new(env!("CARGO_BIN_EXE_study"))
            .args(["validate", &path, "--quick"])
            .output()
            .unwrap();
        assert!(out.status.success());
        let text = String::from_utf8_lossy(&out.stdout);
        // The widest error bar of the plan, as the model gives it.
        let text_file = std::fs::read_to_string(&path).unwrap();
        let loaded = bonkers::descriptor::load::parse(&path, &text_file).unwrap();
        let loaded = bonkers::descriptor::load::quick(&loaded).unwrap();
        let specs = plan(&loaded).unwrap();
        let widest = specs
            .iter()
            .filter_map(|s| {
                let n = specs.iter().filter(|t| t.point_id == s.point_id).count();
                let model = studies::find(study)?.error_model(&s.descriptor)?;
                Some(model.stderr(n as u32))
            })
            .fold(0.0, f64::max);
        assert!(widest > 0.0, "{file}: no point has a model");
        let line = text
            .lines()
            .find(|l| l.trim_start().starts_with(&format!("{study}: ")))
            .unwrap_or_else(|| panic!("{file}: no error-bar line in\n{text}"));
        assert!(
            line.contains(&format!("{} %", two_digits(100.0 * widest))),
            "{file}: expected ±{} % in {line}",
            two_digits(100.0 * widest)
        );
    }
}
