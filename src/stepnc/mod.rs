//! STEP-NC (ISO 14649 ARM, Part 21): the typed model ([`model`]) that
//! programs are raised into, Part 21 files are read into and written
//! from, and post-processors read.

pub mod model;
pub mod part21;
