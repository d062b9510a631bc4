//! The meta-model: one dialect-neutral representation of a part program.
//!
//! Blocks are kept in order, flat, as the controller reads them: jumps
//! (`GOTO`, `GOTOB`, `M99 P`) can enter and leave any structure, so control
//! flow is a sequence of opener/closer statements whose pairing is checked
//! by [`crate::check::structure`]. Expressions live in an arena and are
//! referred to by handle; every node carries its source span.

pub mod arena;
pub mod depth;
pub mod expr;
pub mod num;
pub mod plain;
pub mod print;
pub mod program;
pub mod stmt;
pub mod tnc;

pub use arena::{Arena, Handle};
pub use expr::*;
pub use num::Decimal;
pub use program::Program;
pub use stmt::*;
pub use tnc::*;
