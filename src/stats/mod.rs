//! Estimators and error bars shared by studies, and numbers as text.

pub mod ensemble;
pub mod format;
pub mod replicas;
pub mod summary;
