//! The resolved event stream reduced to the operations a comparison looks
//! at: cutting moves, drilled plunges and tool changes, each with the
//! technology it ran with and the rapids that led to it.
//!
//! A run of vertical feed moves at one X Y, with only vertical rapids
//! between them, is one [`OpKind::Plunge`] (a hole), known by its X Y and
//! deepest Z: G83 pecks, CYCLE83 pecks and a single G81 plunge to the same
//! depth are the same hole. Dwells are added to the operation before them;
//! comments, stops and coolant are not compared.

use crate::span::Span;
use crate::toolpath::{ArcGeom, Event, FeedMode, Move, MoveKind, P3};
use std::ops::Range;

/// What one operation does.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum OpKind {
    /// A straight feed move, compared by its end point.
    Line { to: P3 },
    /// A circular or helical move: end point, centre (in-plane
    /// coordinates), plane (the in-plane and normal axes, as in
    /// [`ArcGeom::axes`]), and rotation (sign: direction, magnitude: turns).
    Arc {
        to: P3,
        centre: [f64; 2],
        axes: [u8; 3],
        rotation: i32,
    },
    /// Vertical feeds at one X Y: `at` is X, Y and the deepest Z reached;
    /// `top` the highest Z the feeds started from.
    Plunge { at: P3, top: f64 },
    /// A probing move, by its end point.
    Probe { to: P3 },
    /// A tool change to this tool.
    Tool(i64),
}

/// One operation with its technology and where it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct Op {
    pub kind: OpKind,
    /// The statement of its first move (of the tool change).
    pub span: Span,
    /// Feed rate in mm/min (per-revolution feeds times the spindle speed).
    pub feed: f64,
    pub feed_mode: FeedMode,
    /// Spindle speed in rpm, signed (negative: counter-clockwise).
    pub spindle: f64,
    /// The tool in the spindle.
    pub tool: i64,
    /// Seconds of dwell after it.
    pub dwell: f32,
    /// The rapids since the operation before, as indices into
    /// [`Ops::rapids`] (kept only when the builder is asked to).
    pub rapids: Range<u32>,
    /// How many tool changes came before it (its operation group).
    pub group: u32,
}

/// The operations of one program, with the rapids between them.
#[derive(Clone, Debug, Default)]
pub struct Ops {
    pub ops: Vec<Op>,
    /// Rapid end points with their statements, in order.
    pub rapids: Vec<(P3, Span)>,
}

impl Ops {
    /// The operations of a whole event list.
    pub fn from_events(events: &[Event], tolerance_mm: f64) -> Ops {
        let mut b = OpBuilder::new(tolerance_mm);
        for e in events {
            b.push(e);
        }
        b.finish()
    }
}

fn arc_op(to: P3, g: &ArcGeom) -> OpKind {
    let [u, v, w] = g.axes;
    OpKind::Arc {
        to,
        centre: [g.centre[u], g.centre[v]],
        axes: [u as u8, v as u8, w as u8],
        rotation: g.rotation.clamp(i32::MIN as i64, i32::MAX as i64) as i32,
    }
}

/// Builds [`Ops`] from events one at a time (for streamed runs).
#[derive(Clone, Debug)]
pub struct OpBuilder {
    out: Ops,
    tol: f64,
    /// Is the last operation a plunge that may still grow?
    open_plunge: bool,
    rapids_start: usize,
    keep_rapids: bool,
    group: u32,
    /// The index of `out.rapids[0]` among all the run's rapids (batches
    /// taken with [`OpBuilder::take_ready`] are gone).
    rapid_base: usize,
}

impl OpBuilder {
    /// A builder that keeps the rapids between operations.
    pub fn new(tolerance_mm: f64) -> OpBuilder {
        OpBuilder {
            out: Ops::default(),
            tol: tolerance_mm.max(1e-9),
            open_plunge: false,
            rapids_start: 0,
            keep_rapids: true,
            group: 0,
            rapid_base: 0,
        }
    }

    /// A builder that keeps no rapids (less memory; for comparisons
    /// without `compare_rapids`).
    pub fn without_rapids(tolerance_mm: f64) -> OpBuilder {
        OpBuilder {
            keep_rapids: false,
            ..OpBuilder::new(tolerance_mm)
        }
    }

    fn same_xy(&self, a: P3, b: P3) -> bool {
        (a[0] - b[0]).abs() <= self.tol && (a[1] - b[1]).abs() <= self.tol
    }

    pub fn push(&mut self, e: &Event) {
        match e {
            Event::Move(m) => self.motion(m),
            Event::ToolChange { tool, span } => {
                self.open_plunge = false;
                self.group += 1;
                let op = Op {
                    kind: OpKind::Tool(*tool),
                    span: *span,
                    feed: 0.0,
                    feed_mode: FeedMode::PerMinute,
                    spindle: 0.0,
                    tool: *tool,
                    dwell: 0.0,
                    rapids: self.take_rapids(),
                    group: self.group,
                };
                self.out.ops.push(op);
            }
            Event::Dwell { seconds, .. } => {
                if let Some(last) = self.out.ops.last_mut() {
                    last.dwell += *seconds as f32;
                }
            }
            Event::Stop { .. } | Event::Comment { .. } => {}
        }
    }

    /// The operations not yet taken (all of them where none were), with
    /// their rapids.
    pub fn finish(self) -> Ops {
        self.out
    }

    /// How many operations [`OpBuilder::take_ready`] would give.
    pub fn ready(&self) -> usize {
        self.out.ops.len().saturating_sub(1)
    }

    /// Takes the operations that can no longer change (all but the last,
    /// which a plunge may still deepen or a dwell follow) and the rapids
    /// that lead to them, for a comparison that streams
    /// ([`super::window::OpWindow::pulled`]). Indices (an op's `rapids`)
    /// stay those of the whole run.
    pub fn take_ready(&mut self) -> Ops {
        let n = self.ready();
        let ops: Vec<Op> = self.out.ops.drain(..n).collect();
        let kept = self
            .out
            .ops
            .first()
            .map(|o| o.rapids.start as usize)
            .unwrap_or(self.rapids_start)
            .min(self.rapids_start);
        let nr = kept - self.rapid_base;
        let rapids = self.out.rapids.drain(..nr).collect();
        self.rapid_base += nr;
        Ops { ops, rapids }
    }

    fn take_rapids(&mut self) -> Range<u32> {
        let end = self.rapid_base + self.out.rapids.len();
        let r = self.rapids_start as u32..end as u32;
        self.rapids_start = end;
        r
    }

    fn motion(&mut self, m: &Move) {
        let vertical = self.same_xy(m.from, m.to);
        let kind = match m.kind {
            MoveKind::Rapid => {
                // A rapid to where the tool already is goes nowhere.
                let still = vertical && (m.from[2] - m.to[2]).abs() <= self.tol;
                if !still && !(self.open_plunge && vertical) {
                    self.open_plunge = false;
                    // Indices stay within u32: past that, rapids are not kept.
                    if self.keep_rapids
                        && self.rapid_base + self.out.rapids.len() < u32::MAX as usize
                    {
                        self.out.rapids.push((m.to, m.span));
                    }
                }
                return;
            }
            MoveKind::Line if vertical => {
                if (m.from[2] - m.to[2]).abs() <= self.tol {
                    return; // a move of no length cuts nothing
                }
                if self.grow_plunge(m) {
                    return;
                }
                self.open_plunge = true;
                let at = [m.to[0], m.to[1], m.to[2].min(m.from[2])];
                OpKind::Plunge {
                    at,
                    top: m.from[2].max(m.to[2]),
                }
            }
            MoveKind::Line => OpKind::Line { to: m.to },
            MoveKind::Arc(geom) => arc_op(m.to, &geom),
            MoveKind::Probe => OpKind::Probe { to: m.to },
        };
        if !matches!(kind, OpKind::Plunge { .. }) {
            self.open_plunge = false;
        }
        let feed = match m.feed_mode {
            FeedMode::PerMinute => m.feed,
            FeedMode::PerRev => m.feed * m.spindle.abs(),
        };
        let op = Op {
            kind,
            span: m.span,
            feed,
            feed_mode: m.feed_mode,
            spindle: m.spindle,
            tool: m.tool,
            dwell: 0.0,
            rapids: self.take_rapids(),
            group: self.group,
        };
        self.out.ops.push(op);
    }

    /// Adds a vertical feed to the open plunge at its X Y, if there is one.
    fn grow_plunge(&mut self, m: &Move) -> bool {
        if !self.open_plunge {
            return false;
        }
        let tol = self.tol;
        let Some(last) = self.out.ops.last_mut() else {
            return false;
        };
        let OpKind::Plunge { at, top } = &mut last.kind else {
            return false;
        };
        if (at[0] - m.to[0]).abs() > tol || (at[1] - m.to[1]).abs() > tol {
            return false;
        }
        at[2] = at[2].min(m.to[2]);
        *top = top.max(m.from[2]).max(m.to[2]);
        true
    }
}
