//! Comparing two programs by what they cut: the engine behind `cncc diff`,
//! the overlay marks of `cncc plot` and `cncc port --verify`.
//!
//! # API (stable)
//!
//! ```ignore
//! let opts = CompareOptions::default(); // 1 µm, feeds compared, rapids listed
//! let c: Comparison = compare(&events_a, &events_b, &opts);
//! if !c.same { let first = &c.differences[0]; /* first.what, first.a, first.b */ }
//! ```
//!
//! Both event lists ([`crate::toolpath::Event`], millimetres, work
//! coordinates) are reduced to operations ([`ops`]):
//! * straight feeds compared by end point, arcs by end point, centre,
//!   direction and turns, probes by end point;
//! * drilling as holes: a run of vertical feeds at one X Y with only
//!   vertical rapids between is one plunge compared by X Y and deepest Z,
//!   so G83 pecks and CYCLE83 pecks compare equal;
//! * tool changes by tool number;
//! * with `compare_feeds`, the feed (mm/min; per-revolution feeds times the
//!   spindle speed), spindle speed and direction, and dwells of operations
//!   that cut the same;
//! * with `compare_rapids`, the rapids before each matching operation are
//!   listed in [`Comparison::rapid_differences`]; they never make two
//!   programs different (retract levels and tool-change moves differ
//!   between controllers without changing the part).
//!
//! Comments, coolant and stops are not compared. Where the two part, the
//! comparison looks ahead for the nearest place both go on the same way
//! and reports what lies between as one [`Difference`] naming the first
//! statement on each side. It stops after
//! [`align::MAX_DIFFERENCES`] differences (`truncated`).

/// Feeds and spindle speeds are the same within this fraction of their
/// value (0.02 %): a target writing fewer decimal places rounds them
/// (W0614), and no machine's feed or speed control resolves finer.
pub const RATE_TOLERANCE: f64 = 2e-4;

pub mod align;
pub mod describe;
pub mod ops;
mod technology;
pub mod window;

#[cfg(test)]
mod tests;

pub use ops::{Op, OpBuilder, OpKind, Ops};
pub use window::OpWindow;

/// Rapid differences listed at most.
pub const MAX_LISTED: usize = align::MAX_DIFFERENCES;

use crate::span::Span;
use crate::toolpath::{Event, P3};
use std::ops::Range;

/// What a comparison looks at.
#[derive(Clone, Debug, PartialEq)]
pub struct CompareOptions {
    /// How far two points may be apart and still be the same (mm).
    pub tolerance_mm: f64,
    /// Compare feeds, spindle speeds and dwells of matching operations.
    pub compare_feeds: bool,
    /// List differing rapids (never fatal).
    pub compare_rapids: bool,
}

impl Default for CompareOptions {
    fn default() -> Self {
        CompareOptions {
            tolerance_mm: 0.001,
            compare_feeds: true,
            compare_rapids: true,
        }
    }
}

/// What kind of difference.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DiffKind {
    /// Cutting moves or holes differ, or are only on one side.
    Cuts,
    /// Tool changes differ.
    Tool,
    /// The same cut at another feed.
    Feed,
    /// The same cut at another spindle speed or direction.
    Spindle,
    /// Another dwell after the same cut.
    Dwell,
    /// Other rapids before the same cut (listed, never fatal).
    Rapids,
}

/// One place where the programs differ.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    pub kind: DiffKind,
    /// What differs, readable (`A: hole at X10 Y10 to Z-10; B: ...`).
    pub what: String,
    /// The first statement concerned in A (none: nothing on that side).
    pub a: Option<Span>,
    /// The first statement concerned in B.
    pub b: Option<Span>,
    /// The operations concerned on each side (indices into each side's
    /// [`Ops::ops`]; empty when only the other side has some).
    pub a_ops: Range<usize>,
    pub b_ops: Range<usize>,
    /// The operation group (tool changes before it) and tool on each side.
    pub group_a: usize,
    pub group_b: usize,
    pub tool_a: i64,
    pub tool_b: i64,
    /// The box around the points concerned on both sides (mm, work
    /// coordinates), for marking on a plot.
    pub region: Option<[P3; 2]>,
}

/// The result of a comparison.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// No differences (rapid differences do not count).
    pub same: bool,
    /// In program order.
    pub differences: Vec<Difference>,
    /// Rapids that differ before matching operations.
    pub rapid_differences: Vec<Difference>,
    /// The comparison stopped after [`align::MAX_DIFFERENCES`].
    pub truncated: bool,
    /// How many operations each side has.
    pub ops_a: usize,
    pub ops_b: usize,
}

/// Compares two runs (see the module doc).
pub fn compare(a: &[Event], b: &[Event], opts: &CompareOptions) -> Comparison {
    let oa = Ops::from_events(a, opts.tolerance_mm);
    let ob = Ops::from_events(b, opts.tolerance_mm);
    compare_ops(&oa, &ob, opts)
}

/// Compares two programs' operations (built with [`OpBuilder`] while
/// streaming, or [`Ops::from_events`]).
pub fn compare_ops(a: &Ops, b: &Ops, opts: &CompareOptions) -> Comparison {
    compare_windows(OpWindow::whole(a), OpWindow::whole(b), opts)
}

/// Compares two runs given as windows ([`window`]): held whole, or read
/// side by side as they run, holding a few hundred operations each.
pub fn compare_windows(a: OpWindow<'_>, b: OpWindow<'_>, opts: &CompareOptions) -> Comparison {
    align::Aligner::new(a, b, opts).run()
}
