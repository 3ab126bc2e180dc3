//! Errors shown to users: where (file:line:col), what is wrong, what would be right.

use std::fmt;

/// A problem with a study descriptor or with the command line that names it.
/// Displayed as `<file>:<line>:<col>: <message>` followed by one `hint:` line each.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub struct DescriptorError {
    pub file: String,
    /// 1-based line and column, when the problem has a place in the file.
    pub position: Option<(usize, usize)>,
    /// Dotted key path the problem concerns, when known (e.g. `run.duration`).
    pub key: Option<String>,
    pub message: String,
    pub hints: Vec<String>,
}

impl DescriptorError {
    pub fn new(file: &str, message: impl Into<String>) -> Self {
        DescriptorError {
            file: file.to_string(),
            position: None,
            key: None,
            message: message.into(),
            hints: Vec::new(),
        }
    }

    pub fn at(mut self, position: Option<(usize, usize)>) -> Self {
        self.position = position;
        self
    }

    pub fn key(mut self, key: impl Into<String>) -> Self {
        self.key = Some(key.into());
        self
    }

    pub fn hint(mut self, hint: impl Into<String>) -> Self {
        self.hints.push(hint.into());
        self
    }
}

impl fmt::Display for DescriptorError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.position {
            Some((line, col)) => write!(f, "{}:{}:{}: {}", self.file, line, col, self.message)?,
            None => write!(f, "{}: {}", self.file, self.message)?,
        }
        for hint in &self.hints {
            write!(f, "\n  hint: {hint}")?;
        }
        Ok(())
    }
}

/// How a `study` command ended, mapped to the process exit code.
#[derive(Debug, thiserror::Error)]
pub enum StudyError {
    /// Bad input: descriptor, command line or plan (exit 2).
    #[error(transparent)]
    Input(#[from] DescriptorError),
    /// Ctrl-C: completed runs are kept for resuming, nothing else is written (exit 130).
    #[error("interrupted: {0} completed runs are kept; run the same command again to resume")]
    Interrupted(usize),
    /// Anything else, e.g. an output directory that cannot be written (exit 1).
    #[error("{0:#}")]
    Other(#[from] anyhow::Error),
}

impl StudyError {
    pub fn exit_code(&self) -> i32 {
        match self {
            StudyError::Input(_) => 2,
            StudyError::Interrupted(_) => 130,
            StudyError::Other(_) => 1,
        }
    }
}
