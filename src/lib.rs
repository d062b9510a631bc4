//! cncc: a compiler for CNC milling part programs.
//!
//! Front ends ([`syntax`]) read a dialect's text into lines of words, the
//! shared [`lower`]ing turns them into the meta-model ([`ir`]) driven by the
//! dialect's spec ([`dialect`]); [`check`]s report [`diag`]nostics; writers
//! ([`emit`]) produce any dialect. [`driver`] runs the pipeline, [`cli`] is
//! the command line.

pub mod canon;
pub mod check;
pub mod cli;
pub mod compare;
pub mod diag;
pub mod dialect;
pub mod driver;
pub mod emit;
pub mod encoding;
pub mod fuzzing;
pub mod geom;
pub mod interp;
pub mod interpolate;
pub mod ir;
pub mod lint;
pub mod lower;
pub mod plot;
pub mod port;
pub mod post;
pub mod raise;
pub mod sim;
pub mod source;
pub mod span;
pub mod stats;
pub mod stepnc;
pub mod syntax;
pub mod toolpath;
