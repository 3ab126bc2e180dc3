//! The exact event-driven engine.
