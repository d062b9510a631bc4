//! The canonical stream resolved into absolute moves: the level that plots,
//! machining-time statistics, program comparison (`diff`, `port --verify`)
//! and STEP-NC raising read.
//!
//! A [`Tracker`] follows the calls of one run (units, offsets, tool, feed,
//! spindle, coolant) and turns each motion call into a [`Move`] whose end
//! points are in millimetres in work coordinates: the program position
//! plus the active G92 offset, rotated by the XY rotation, plus the active
//! G5x origin (so a program that shifts its origin and one that writes the
//! shifted numbers give the same moves). Tool length offsets do not
//! change positions: canonical positions are already the tool tip's.
//! Every move keeps the span of the statement it came from.

mod arc;
mod nurbs;
pub mod stock;
mod track;

pub use arc::ArcGeom;
pub use stock::Stock;
pub use track::Tracker;

use crate::span::Span;

/// A point in millimetres, work coordinates.
pub type P3 = [f64; 3];

/// How the feed rate of a move is meant.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FeedMode {
    /// Millimetres per minute.
    PerMinute,
    /// Millimetres per spindle revolution.
    PerRev,
}

/// What kind of path a move follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MoveKind {
    /// A rapid (G0): a straight line at the machine's rapid rate.
    Rapid,
    /// A straight feed move (G1, and the straight moves of cycles).
    Line,
    /// A circular or helical feed move.
    Arc(ArcGeom),
    /// A probing move (G38.x).
    Probe,
}

/// Coolant as the machine has it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CoolantState {
    pub flood: bool,
    pub mist: bool,
}

/// One resolved move.
#[derive(Clone, Debug, PartialEq)]
pub struct Move {
    pub kind: MoveKind,
    pub from: P3,
    pub to: P3,
    /// The feed rate in force (mm/min or mm/rev by `feed_mode`; in
    /// inverse-time mode the canon already gives each move its rate per
    /// minute); meaningless for rapids.
    pub feed: f64,
    pub feed_mode: FeedMode,
    /// The tool in the spindle (0: none).
    pub tool: i64,
    /// Spindle speed in rpm, signed: positive clockwise (M3), negative
    /// counter-clockwise (M4), 0 stopped.
    pub spindle: f64,
    pub coolant: CoolantState,
    /// The statement the move came from (a cycle's moves point at it).
    pub span: Span,
}

impl Move {
    /// The path length in millimetres (helix length for arcs).
    pub fn length(&self) -> f64 {
        match &self.kind {
            MoveKind::Arc(a) => a.length(self.from, self.to),
            MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => dist(self.from, self.to),
        }
    }

    /// Is it a cutting move (feed, arc or probe)?
    pub fn is_feed(&self) -> bool {
        !matches!(self.kind, MoveKind::Rapid)
    }
}

/// What happens in a run, in order, at the level toolpaths care about.
#[derive(Clone, Debug, PartialEq)]
pub enum Event {
    Move(Move),
    /// A tool change: the tool now in the spindle.
    ToolChange {
        tool: i64,
        span: Span,
    },
    /// A dwell, in seconds.
    Dwell {
        seconds: f64,
        span: Span,
    },
    /// Program stop, optional stop or program end.
    Stop {
        end: bool,
        span: Span,
    },
    /// A comment or operator message, as written.
    Comment {
        text: String,
        span: Span,
    },
}

/// Euclidean distance.
pub fn dist(a: P3, b: P3) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Runs a program file and gathers its events (see [`Tracker`]) with the
/// run's diagnostics. For programs too large to hold, drive a [`Tracker`]
/// from [`crate::interp::file::run_file`]'s sink instead.
pub fn events_of_file(
    path: &std::path::Path,
    id: crate::span::FileId,
    spec: &std::sync::Arc<crate::dialect::DialectSpec>,
    opts: &crate::interp::Options,
    files: &mut crate::source::SourceMap,
) -> std::io::Result<(Vec<Event>, Vec<crate::diag::Diagnostic>)> {
    let mut tracker = Tracker::new();
    let mut events = Vec::new();
    let mut sink = |call: crate::canon::Canon, span: Span| {
        tracker.push(&call, span, |e| events.push(e));
    };
    let diags = crate::interp::file::run_file(path, id, spec, opts, files, &mut sink)?;
    Ok((events, diags))
}
