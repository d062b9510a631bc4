//! Dialects as data: specs read from `dialects/*.xml`, the built-in set,
//! aliases, and choosing a dialect for a file.

pub mod builtin;
pub mod detect;
pub mod listing;
pub mod load;
pub(crate) mod load_items;
mod load_seen;
#[cfg(test)]
mod load_tests;
mod load_text;
pub mod meaning;
pub mod post_templates;
pub mod spec;
pub mod text;
pub(crate) mod xml;

pub use builtin::{builtin, builtin_source, builtins, Registry, BUILTIN_SOURCES};
pub use detect::{detect, Detection};
pub use listing::describe_all;
pub use load::load_spec;
pub use meaning::{MachineFn, Meaning, SpindleFn};
pub use post_templates::{PostTemplateDecl, POST_TEMPLATES};
pub use spec::*;
