//! Program-level checks: structure (pairing, jump targets).

pub mod structure;

pub use structure::StructureChecker;
