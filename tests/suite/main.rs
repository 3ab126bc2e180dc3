//! Every integration test, as modules of one test binary: one link against
//! polars instead of one per file (the build and CI time this saves is in
//! the README). Shared helpers are the modules without tests.

mod accuracy_convergence;
mod accuracy_stepper;
mod accuracy_study;
mod common;
mod engine_collision_rule;
mod engine_dynamics;
mod engine_exact;
mod engine_hard_cases;
mod engine_neighbour_lists;
mod engine_save;
mod engine_thermal_walls;
mod equilibrium_study;
mod expansion_study;
mod layers;
mod mixing_study;
mod movie;
mod parquet_schema;
mod piston_2d;
mod piston_common;
mod piston_study;
mod pressure_study;
mod quickstart_end_to_end;
mod report_summary;
mod report_write;
mod scene_build;
mod scene_compress;
mod scene_errors;
mod scene_placement;
mod scene_seeds;
mod scene_stats;
mod scene_velocities;
mod study_checkpoint;
mod study_cli;
mod study_collect;
mod study_common;
mod study_descriptor;
mod study_docs;
mod study_errors;
mod study_plan;
mod study_progress;
mod study_runner;
mod study_shards;
mod study_store;
mod study_wall_heat;
