//! Estimators and error bars shared by studies, and numbers as text.

pub mod blocking;
pub mod decay;
pub mod diffusion;
pub mod ensemble;
pub mod error_model;
pub mod fill;
pub mod format;
pub mod goodness;
pub mod groups;
pub mod late;
pub mod line;
pub mod line_fit;
pub mod mser;
pub mod named;
pub mod oscillation;
pub mod passage;
pub mod point_runs;
pub mod power_law;
pub mod quadratic;
pub mod replicas;
pub mod summary;
pub mod table;
