//! The interpreter: runs the meta-model as a controller would and emits
//! canonical machining calls ([`crate::canon`]), with every modal state
//! explicit.

pub mod cycle_io;
pub mod host;
pub mod comp;
