//! A study's options (`[analysis.<name>]` keys): each a number in a range
//! with a default. The descriptor checks read the ranges; studies read the
//! values through `value`, so a default lives in one place.

use crate::model::descriptor::Descriptor;

/// One option of a study: a number in (`above`, `at_most`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyOption {
    pub name: &'static str,
    pub above: f64,
    pub at_most: f64,
    pub default: f64,
    pub about: &'static str,
}

impl StudyOption {
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

/// The value of option `key` of study `study` in `d`: as given, else its
/// default (NaN for a key the study does not declare).
pub fn value(d: &Descriptor, study: &str, options: &[StudyOption], key: &str) -> f64 {
    let given = d.analysis.get(study).and_then(|t| t.get(key));
    given
        .and_then(|v| v.as_float().or(v.as_integer().map(|i| i as f64)))
        .or_else(|| Some(options.iter().find(|o| o.name == key)?.default))
        .unwrap_or(f64::NAN)
}
