//! What a descriptor may name under `[analysis.<name>]`: each analysis, the
//! options it reads (name, range, default) and what the scene and run must
//! give it. Validation checks descriptors against this list before anything
//! runs; `study list` and docs/descriptor.md show it.
//!
//! The analyses themselves live in `crate::analysis`; this list must name
//! exactly the options they read (a test checks the names against
//! `crate::analysis::KNOWN`).

/// What an analysis or an observable needs from the scene and the run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Need {
    /// A piston in the scene.
    Piston,
    /// `[run] sample_every`: the quantity is read off samples.
    Sampling,
    /// At least one axis with walls (not periodic).
    Walls,
    /// At least one thermal wall.
    ThermalWalls,
}

/// One option of an analysis: a number in (`above`, `at_most`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AnalysisOption {
    pub name: &'static str,
    pub above: f64,
    pub at_most: f64,
    pub default: f64,
    pub about: &'static str,
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Analysis {
    pub name: &'static str,
    pub about: &'static str,
    pub options: &'static [AnalysisOption],
    pub needs: &'static [Need],
}

pub const ANALYSES: &[Analysis] = &[Analysis {
    name: "piston",
    about: "piston oscillation frequency against adiabatic and isothermal theory, relaxation time, late energy share against equipartition",
    options: &[
        AnalysisOption {
            name: "window_periods",
            above: 0.0,
            at_most: f64::INFINITY,
            default: 4.0,
            about: "full periods of the piston's motion, from the start, over which the frequency is measured",
        },
        AnalysisOption {
            name: "band",
            above: 0.0,
            at_most: 0.5,
            default: 0.1,
            about: "hysteresis band for turning points, as a fraction of the piston position's range",
        },
        AnalysisOption {
            name: "late_fraction",
            above: 0.0,
            at_most: 1.0,
            default: 0.5,
            about: "final fraction of the run over which the piston's energy share is averaged",
        },
    ],
    needs: &[Need::Piston, Need::Sampling],
}];

pub fn find(name: &str) -> Option<&'static Analysis> {
    ANALYSES.iter().find(|a| a.name == name)
}

pub fn names() -> Vec<String> {
    ANALYSES.iter().map(|a| a.name.to_string()).collect()
}

impl AnalysisOption {
    /// "a number > 0 and <= 1", "a number > 0".
    pub fn range_text(&self) -> String {
        if self.at_most.is_finite() {
            format!("a number > {} and <= {}", self.above, self.at_most)
        } else {
            format!("a number > {}", self.above)
        }
    }

    pub fn admits(&self, x: f64) -> bool {
        x > self.above && x <= self.at_most && !x.is_nan()
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn every_analysis_bonkers_runs_is_described() {
        let mut described = super::names();
        described.sort();
        let mut known: Vec<String> = crate::analysis::KNOWN
            .iter()
            .map(|s| s.to_string())
            .collect();
        known.sort();
        assert_eq!(described, known);
    }
}
