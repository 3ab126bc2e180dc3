//! Estimators and error bars shared by studies, and numbers as text.

pub mod format;
pub mod replicas;
pub mod summary;
