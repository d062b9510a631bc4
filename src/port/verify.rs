//! `cncc port --verify`: run the source and the ported program and compare
//! what they cut.
//!
//! Both programs run through the interpreter into toolpath events
//! ([`crate::toolpath`]), so a cycle is compared as the moves it makes
//! (which are the hole it cuts: position, depth). The cutting moves (feed
//! lines and arcs) must pair up one to one: same kind, end points within
//! 1 µm, arcs with the same centre (1 µm) and turn, the same feed rate
//! (1e-6 relative). Moves shorter than 1 µm are left out on both sides
//! (a cycle may make a zero-length lift-off). Rapids are compared by end
//! point and listed when they differ; they do not fail the verification.

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::flow::ProgramLoader;
use crate::interp::Options;
use crate::ir::Program;
use crate::span::Span;
use crate::toolpath::{dist, Event, Move, MoveKind, Tracker};
use std::rc::Rc;

/// Positions and centres must agree within this (mm).
pub const TOLERANCE_MM: f64 = 0.001;

/// One difference, with the statement on each side where there is one.
#[derive(Clone, Debug, PartialEq)]
pub struct Difference {
    pub what: String,
    pub a: Option<Span>,
    pub b: Option<Span>,
}

#[derive(Clone, Debug, Default)]
pub struct Verdict {
    /// The first cutting difference (None: the cutting moves match).
    pub cutting: Option<Difference>,
    pub cutting_moves: usize,
    pub rapids: Vec<Difference>,
}

impl Verdict {
    pub fn same(&self) -> bool {
        self.cutting.is_none()
    }
}

/// Runs `p` (a whole program) and returns its toolpath events.
pub fn events(
    p: Rc<Program>,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
) -> (Vec<Event>, Vec<Diagnostic>) {
    let mut tracker = Tracker::new();
    let mut out = Vec::new();
    let mut sink = |call: crate::canon::Canon, span: Span| {
        tracker.push(&call, span, |e| out.push(e));
    };
    let diags = crate::interp::run(p, spec, opts, loader, &mut sink);
    (out, diags)
}

fn moves(events: &[Event], cutting: bool) -> Vec<&Move> {
    events
        .iter()
        .filter_map(|e| match e {
            Event::Move(m) if m.is_feed() == cutting && dist(m.from, m.to) >= TOLERANCE_MM => {
                Some(m)
            }
            _ => None,
        })
        .collect()
}

fn fmt(p: [f64; 3]) -> String {
    format!("({:.4}, {:.4}, {:.4})", p[0], p[1], p[2])
}

/// Why two cutting moves differ, if they do.
fn differs(a: &Move, b: &Move) -> Option<String> {
    let kind = |m: &Move| match m.kind {
        MoveKind::Arc(g) if g.ccw() => "counter-clockwise arc",
        MoveKind::Arc(_) => "clockwise arc",
        MoveKind::Line => "feed line",
        MoveKind::Probe => "probe move",
        MoveKind::Rapid => "rapid",
    };
    if kind(a) != kind(b) {
        return Some(format!("a {} against a {}", kind(a), kind(b)));
    }
    if dist(a.from, b.from) > TOLERANCE_MM || dist(a.to, b.to) > TOLERANCE_MM {
        return Some(format!(
            "{} {} → {} against {} → {}",
            kind(a),
            fmt(a.from),
            fmt(a.to),
            fmt(b.from),
            fmt(b.to)
        ));
    }
    if let (MoveKind::Arc(ga), MoveKind::Arc(gb)) = (a.kind, b.kind) {
        if dist(ga.centre, gb.centre) > TOLERANCE_MM || ga.rotation != gb.rotation {
            return Some(format!(
                "arc centre {} against {}",
                fmt(ga.centre),
                fmt(gb.centre)
            ));
        }
    }
    let scale = a.feed.abs().max(b.feed.abs()).max(1.0);
    if (a.feed - b.feed).abs() > 1e-6 * scale || a.feed_mode != b.feed_mode {
        return Some(format!("feed {} against {}", a.feed, b.feed));
    }
    None
}

/// Compares the events of the source (`a`) and the port (`b`).
pub fn compare(a: &[Event], b: &[Event]) -> Verdict {
    let (ca, cb) = (moves(a, true), moves(b, true));
    let mut v = Verdict {
        cutting_moves: ca.len(),
        ..Verdict::default()
    };
    for (i, (ma, mb)) in ca.iter().zip(&cb).enumerate() {
        if let Some(why) = differs(ma, mb) {
            v.cutting = Some(Difference {
                what: format!("cutting move {}: {why}", i + 1),
                a: Some(ma.span),
                b: Some(mb.span),
            });
            break;
        }
    }
    if v.cutting.is_none() && ca.len() != cb.len() {
        let n = ca.len().min(cb.len());
        v.cutting = Some(Difference {
            what: format!("{} cutting moves against {}", ca.len(), cb.len()),
            a: ca.get(n).map(|m| m.span),
            b: cb.get(n).map(|m| m.span),
        });
    }
    let (ra, rb) = (moves(a, false), moves(b, false));
    let ends_a: Vec<_> = ra.iter().map(|m| m.to).collect();
    for mb in &rb {
        if !ends_a.iter().any(|p| dist(*p, mb.to) <= TOLERANCE_MM) {
            v.rapids.push(Difference {
                what: format!("a rapid to {} that the source does not make", fmt(mb.to)),
                a: None,
                b: Some(mb.span),
            });
        }
    }
    let ends_b: Vec<_> = rb.iter().map(|m| m.to).collect();
    for ma in &ra {
        if !ends_b.iter().any(|p| dist(*p, ma.to) <= TOLERANCE_MM) {
            v.rapids.push(Difference {
                what: format!("a rapid to {} that the port does not make", fmt(ma.to)),
                a: Some(ma.span),
                b: None,
            });
        }
    }
    v
}
