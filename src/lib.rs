//! bonkers: ensemble studies of hard-particle gases on an exact event-driven engine.

pub mod analysis;
pub mod engine;
pub mod observe;
pub mod report;
pub mod scene;
pub mod simulate;
pub mod study;
pub mod theory;
