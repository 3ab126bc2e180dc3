//! The exact event-driven engine for hard rods (1D), disks (2D) and spheres (3D).
//!
//! Read `simulation.rs` first: it is the event loop. Everything else is one
//! idea per file: the collision rule, the box, the queue, the neighbour lists,
//! the observer hooks, the checks a system passes before it runs, and the
//! `Dynamics` trait a run loop drives any integrator through.

pub mod bodies;
pub mod boundary;
pub mod build;
pub mod collide;
mod contacts;
pub mod dynamics;
pub mod halt;
pub mod neighbours;
mod next;
pub mod observer;
pub mod particle;
mod prefetch;
pub mod queue;
mod save;
pub mod simulation;
pub mod stepper;
pub mod thermal;
pub mod vector;

pub use bodies::{Bodies, Body};
pub use boundary::{Axis, SimBox, Wall};
pub use build::BuildError;
pub use dynamics::Dynamics;
pub use halt::Halt;
pub use neighbours::{Chain, Image, NeighbourList, Neighbourhood, PLANE, Persist};
pub use observer::{Observer, PairCollision, Snapshot, WallHit};
pub use particle::{Particle, Shape};
pub use prefetch::Lines;
pub use save::{FORMAT_VERSION, SaveError};
pub use simulation::{Counts, Simulation, Stop, degrees_of_freedom};
pub use stepper::Stepper;

/// The engine for each dimension: a chain of neighbours in 1D, neighbour
/// lists above; `WithPlane` for 2D/3D systems with a piston wall.
pub type Rods<O> = Simulation<1, Chain, O>;
pub type Disks<O> = Simulation<2, NeighbourList<2>, O>;
pub type Spheres<O> = Simulation<3, NeighbourList<3>, O>;
pub type WithPlane<const D: usize, O> = Simulation<D, NeighbourList<D, true>, O>;
