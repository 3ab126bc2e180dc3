//! A problem with a request, named by its key path so that the descriptor can
//! point at it in the file and the scene builder can say which key is at
//! fault: what is wrong, and what would be right.

use std::fmt;

/// One problem: the key it concerns, what is wrong, what would be right.
#[derive(Debug, Clone, PartialEq)]
pub struct Problem {
    pub key: String,
    pub message: String,
    pub hint: Option<String>,
}

pub type Check = Result<(), Problem>;

/// Shown where there is no file to point into (a run's error):
/// `` `key`: message; hint ``.
impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}`: {}", self.key, self.message)?;
        if let Some(hint) = &self.hint {
            write!(f, "; {hint}")?;
        }
        Ok(())
    }
}

/// The longest name of a study, case or species, in bytes: names become
/// folder, file and column names (`reports/<study>-quick/`,
/// `series_kinetic_energy_<species>_2.svg`), and file systems allow 255
/// bytes per file name.
pub const MAX_NAME_BYTES: usize = 100;

/// A name short enough to go into file names (`MAX_NAME_BYTES`).
pub fn name_fits(key: &str, name: &str) -> Check {
    if name.len() <= MAX_NAME_BYTES {
        return Ok(());
    }
    let start: String = name.chars().take(24).collect();
    bad(
        key,
        format!(
            "\"{start}…\" is {} bytes long; names go into file names, so at most {MAX_NAME_BYTES}",
            name.len()
        ),
        Some("use a shorter name (the description can say more)"),
    )
}

pub fn bad(key: impl Into<String>, message: impl Into<String>, hint: Option<&str>) -> Check {
    Err(Problem {
        key: key.into(),
        message: message.into(),
        hint: hint.map(str::to_string),
    })
}

pub fn positive(key: &str, v: f64) -> Check {
    if v.is_finite() && v > 0.0 {
        Ok(())
    } else {
        bad(
            key,
            format!("must be a positive number, got {}", compact(v)),
            None,
        )
    }
}

/// A number as a message shows it: as written for everyday magnitudes,
/// `1e300` rather than three hundred digits beyond them.
pub fn compact(x: f64) -> String {
    if x == 0.0 || (x.is_finite() && (1e-4..1e7).contains(&x.abs())) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// Radii may be 0: point particles (an ideal gas, or MacKay's point rods).
pub fn non_negative(key: &str, v: f64) -> Check {
    if v.is_finite() && v >= 0.0 {
        Ok(())
    } else {
        bad(
            key,
            format!("must be a number >= 0, got {}", compact(v)),
            None,
        )
    }
}
