//! Scenes: the physical setup a run starts from.

pub mod spec;
