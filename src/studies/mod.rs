//! Studies as plug-ins. A study is one folder that implements `Study`: its
//! options, what it needs observed, what it adds to each run, the theory for
//! its results and its report section. Registering one is a line in
//! `registry!`; a descriptor asks for it as `[analysis.<name>]`.

pub mod curves;
pub mod options;
pub mod parts;

use crate::model::descriptor::Descriptor;
use crate::model::need::Need;
use crate::model::problem::Check;
use crate::model::report::ReportSection;
use crate::model::run_output::RunOutput;
use crate::model::scene::SceneSpec;
use crate::observe::Context;
use crate::scene::Built;
use crate::stats::ensemble::Runs;
pub use crate::stats::error_model::ErrorModel;
pub use options::StudyOption;

/// Each study's folder and its plug-in, declared together so that a new
/// study is one line here.
macro_rules! registry {
    ($($folder:ident::$study:ident),* $(,)?) => {
        $(pub mod $folder;)*
        /// Every study bonkers knows, in the order `study list` shows them.
        pub const REGISTRY: &[&dyn Study] = &[$(&$folder::$study),*];
    };
}

registry![
    piston::Piston,
    pressure::Pressure,
    expansion::Expansion,
    heat::Heat,
    mixing::Mixing,
    equilibrium::Equilibrium,
    accuracy::Accuracy,
];

/// A finished run as a study sees it: its descriptor, the scene as built
/// (in its dimension) and what the run measured.
pub struct Finished<'a> {
    pub descriptor: &'a Descriptor,
    pub start: Start<'a>,
    pub context: &'a Context<'a>,
}

/// The scene a run started from, in its dimension.
#[derive(Clone, Copy)]
pub enum Start<'a> {
    Rods(&'a Built<1>),
    Disks(&'a Built<2>),
    Spheres(&'a Built<3>),
}

impl<'a> Start<'a> {
    /// The scene of a run in dimension `D` (1, 2 or 3: the engine has no other).
    pub fn of<const D: usize>(built: &'a Built<D>) -> Start<'a> {
        let any: &dyn std::any::Any = built;
        match (any.downcast_ref(), any.downcast_ref(), any.downcast_ref()) {
            (Some(b), _, _) => Start::Rods(b),
            (_, Some(b), _) => Start::Disks(b),
            (_, _, Some(b)) => Start::Spheres(b),
            _ => unreachable!("scenes have 1, 2 or 3 dimensions"),
        }
    }
}

pub trait Study: Sync {
    /// The name a descriptor uses: `[analysis.<name>]`.
    fn name(&self) -> &'static str;
    /// One line for `study list` and docs/descriptor.md.
    fn about(&self) -> &'static str;
    fn options(&self) -> &'static [StudyOption] {
        &[]
    }
    /// What the scene and run must give it (checked before anything runs).
    fn needs(&self) -> &'static [Need] {
        &[]
    }
    /// What `needs` cannot say: the scene (resolved) and `[observe]` that
    /// its runs would fail without, refused at `key` before anything runs.
    fn check(&self, _d: &Descriptor, _scene: &SceneSpec, _key: &str) -> Check {
        Ok(())
    }
    /// Series observables every run records for it, beside those the
    /// descriptor asks for.
    fn series(&self) -> &'static [&'static str] {
        &[]
    }
    /// Every scalar result it can add to a run; its section presents them.
    fn results(&self) -> &'static [&'static str];
    /// Exactly the results a run of `d` gets from it (sweep values
    /// applied): all of `results` unless the descriptor decides, e.g. the
    /// heat study's relaxation or conduction runs. A value the run cannot
    /// measure is written as NaN, not left out.
    fn writes(&self, _d: &Descriptor) -> Vec<&'static str> {
        self.results().to_vec()
    }
    /// Add this study's results to a finished run's output.
    fn per_run(&self, run: &Finished, out: &mut RunOutput) -> Result<(), String>;
    /// Theory for one of its results at a run's descriptor (sweep values
    /// applied), or None where none applies.
    fn theory(&self, _d: &Descriptor, _result: &str) -> Option<f64> {
        None
    }
    /// Results whose theory is a contrast: set beside the measurement to
    /// show where it stops holding (a limit, a law the gas does not obey),
    /// not one the runs must agree with. The report does not flag them.
    fn contrast(&self, _d: &Descriptor, _result: &str) -> bool {
        false
    }
    /// The error model of its headline result at a descriptor (sweep
    /// values applied), where it has one (`stats::error_model`).
    fn error_model(&self, _d: &Descriptor) -> Option<ErrorModel> {
        None
    }
    /// Its part of the report, from the successful runs of the plan: their
    /// scalars and histograms, each point's series means (`runs.mean`), and
    /// the series themselves only for the first `stats::ensemble::KEPT`
    /// replicas of each point.
    fn section(&self, d: &Descriptor, runs: &Runs) -> anyhow::Result<ReportSection>;
}

pub fn find(name: &str) -> Option<&'static dyn Study> {
    REGISTRY.iter().copied().find(|s| s.name() == name)
}

pub fn names() -> Vec<String> {
    REGISTRY.iter().map(|s| s.name().to_string()).collect()
}

/// The studies a descriptor asks for, in its order (unknown names were
/// refused by the descriptor checks).
pub fn named(d: &Descriptor) -> impl Iterator<Item = &'static dyn Study> + '_ {
    d.analysis.keys().filter_map(|name| find(name))
}

/// Series the named studies need, beside those the descriptor asks for.
pub fn series(d: &Descriptor) -> Vec<&'static str> {
    let mut all: Vec<&'static str> = Vec::new();
    for name in named(d).flat_map(|s| s.series().iter().copied()) {
        if !all.contains(&name) {
            all.push(name);
        }
    }
    all
}

/// Each named study's results for a finished run; a study that writes a
/// result it does not declare (a typo a section would read back as NaN), or
/// one twice, fails the run. That it writes all it declares for the run
/// (`Study::writes`) is checked over every bundled study by the tests.
pub fn per_run(run: &Finished, out: &mut RunOutput) -> Result<(), String> {
    named(run.descriptor).try_for_each(|s| {
        let before = out.scalars.len();
        s.per_run(run, out)?;
        as_declared(s, &out.scalars[before..])
    })
}

/// Every name written is one of `study.results()`, each once.
fn as_declared(study: &dyn Study, written: &[(String, f64)]) -> Result<(), String> {
    for (i, (name, _)) in written.iter().enumerate() {
        if !study.results().contains(&name.as_str()) {
            return Err(format!(
                "the {} analysis wrote `{name}`, which it does not declare in `results`",
                study.name()
            ));
        }
        if written[..i].iter().any(|(n, _)| n == name) {
            return Err(format!(
                "the {} analysis wrote `{name}` twice",
                study.name()
            ));
        }
    }
    Ok(())
}

/// Theory for a result, from the named study that gives it.
pub fn theory(d: &Descriptor, result: &str) -> Option<f64> {
    named(d)
        .filter(|s| s.results().contains(&result))
        .find_map(|s| s.theory(d, result))
}

/// Whether the named study that gives `result` sets its theory as a contrast.
pub fn contrast(d: &Descriptor, result: &str) -> bool {
    named(d).any(|s| s.results().contains(&result) && s.contrast(d, result))
}

/// The error models of the named studies at a descriptor, by study name.
pub fn error_models(d: &Descriptor) -> Vec<(&'static str, ErrorModel)> {
    named(d)
        .filter_map(|s| Some((s.name(), s.error_model(d)?)))
        .collect()
}

/// The named studies' report sections, in descriptor order.
pub fn sections(d: &Descriptor, runs: &Runs) -> anyhow::Result<Vec<ReportSection>> {
    named(d).map(|s| s.section(d, runs)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A study declaring `a` and `b`; only its name and results are used.
    struct Declares;
    impl Study for Declares {
        fn name(&self) -> &'static str {
            "fixture"
        }
        fn about(&self) -> &'static str {
            ""
        }
        fn results(&self) -> &'static [&'static str] {
            &["a", "b"]
        }
        fn per_run(&self, _: &Finished, _: &mut RunOutput) -> Result<(), String> {
            Ok(())
        }
        fn section(&self, _: &Descriptor, _: &Runs) -> anyhow::Result<ReportSection> {
            anyhow::bail!("not drawn")
        }
    }

    fn written(names: &[&str]) -> Vec<(String, f64)> {
        names.iter().map(|n| (n.to_string(), 1.0)).collect()
    }

    #[test]
    fn a_study_writes_only_what_it_declares_once() {
        assert!(as_declared(&Declares, &written(&["b", "a"])).is_ok());
        let typo = as_declared(&Declares, &written(&["a", "bb"])).unwrap_err();
        assert!(typo.contains("`bb`, which it does not declare"), "{typo}");
        let twice = as_declared(&Declares, &written(&["a", "a"])).unwrap_err();
        assert!(twice.contains("`a` twice"), "{twice}");
    }
}
