//! `cncc port --verify`: run the source and the ported program and compare
//! what they cut.
//!
//! Both programs run through the interpreter into toolpath events
//! ([`crate::toolpath`]) and the comparison engine ([`crate::compare`])
//! compares them: feed moves and arcs within 1 µm with their feeds,
//! drilling as holes (position and depth), tools by number (the source's
//! renumbered by the tool map). Rapids that differ are listed; they do not
//! fail the verification.

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::flow::ProgramLoader;
use crate::interp::Options;
use crate::ir::Program;
use crate::span::Span;
use crate::toolpath::{Event, Tracker};
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

/// Compares the events of the source (`a`) and the port (`b`) with the
/// comparison engine ([`crate::compare`]); the source's tool numbers are
/// renumbered by the tool map first.
pub fn compare(a: &[Event], b: &[Event], tools: &crate::port::ToolMap) -> Verdict {
    let a: Vec<Event> = a.iter().cloned().map(|e| renumber(e, tools)).collect();
    let c = crate::compare::compare(&a, b, &crate::compare::CompareOptions::default());
    let diff = |d: &crate::compare::Difference| Difference {
        what: d.what.clone(),
        a: d.a,
        b: d.b,
    };
    Verdict {
        cutting: if c.same {
            None
        } else {
            c.differences.first().map(diff)
        },
        cutting_moves: c.ops_a,
        rapids: c.rapid_differences.iter().map(diff).collect(),
    }
}

fn renumber(e: Event, tools: &crate::port::ToolMap) -> Event {
    match e {
        Event::Move(mut m) => {
            m.tool = tools.map(m.tool);
            Event::Move(m)
        }
        Event::ToolChange { tool, span } => Event::ToolChange {
            tool: tools.map(tool),
            span,
        },
        other => other,
    }
}
