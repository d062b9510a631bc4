//! Dialects as data: specs read from `dialects/*.xml`, the built-in set,
//! aliases, and choosing a dialect for a file.

pub mod meaning;
pub mod spec;

pub use meaning::{Meaning, SpindleFn};
pub use spec::*;
