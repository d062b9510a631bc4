//! `cncc port --verify`: run the source and the ported program and compare
//! what they cut.
//!
//! Both programs run through the interpreter into toolpath events
//! ([`crate::toolpath`]) and the comparison engine ([`crate::compare`])
//! compares them: feed moves and arcs within 1 µm with their feeds,
//! drilling as holes (position and depth), tools by number (the source's
//! renumbered by the tool map).
//!
//! Rapids are checked from the first move to the last (after the last cut
//! too): every rapid that goes below the highest cutting height of the
//! source (the highest Z of any feed move) must be the same rapid, in the
//! same order, on both sides, or the verification fails. A vertical rapid
//! at a place the program has already cut down to below the rapid's lowest
//! point (a peck's retract and re-entry, the way out of a hole or pocket)
//! moves in air and is not compared (G83 and CYCLE83 re-enter at their own
//! clearances). Rapids that differ above that height are listed (W0611)
//! and do not fail it, and so are the approach rapids between a tool
//! change (or the start) and the first feed move after it: there the
//! positions rest on what neither run knows (the tool's length, the
//! machine's reference and tool-change positions), and controllers
//! approach differently. The same holds after a move in machine
//! coordinates or to a reference point ([`MACHINE_MARK`]). [?] An
//! approach rapid below the cutting height on one side only is therefore
//! not caught.

use super::verify_digest::{Digest, Tally};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::flow::ProgramLoader;
use crate::interp::Options;
use crate::ir::Program;
use crate::span::Span;
use crate::toolpath::{Event, Tracker};
use std::collections::HashSet;
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
    /// Rapids that differ above the highest cutting height (listed only).
    pub rapids: Vec<Difference>,
    /// The first rapid below the highest cutting height that is not the
    /// same on both sides (None: they match).
    pub low_rapid: Option<Difference>,
}

impl Verdict {
    /// Keeps the first cutting difference found, else takes `d`.
    fn with_cutting(mut self, d: Option<Difference>) -> Self {
        if self.cutting.is_none() {
            self.cutting = d;
        }
        self
    }

    pub fn same(&self) -> bool {
        self.cutting.is_none() && self.low_rapid.is_none()
    }
}

/// Runs `p` (a whole program) and returns its toolpath events.
pub fn events(
    p: Rc<Program>,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
) -> (Vec<Event>, Vec<Diagnostic>) {
    let mut rec = Recorder::new(machine_spans(&p, spec));
    let diags = {
        let mut sink = |call: crate::canon::Canon, span: Span| rec.call(call, span);
        crate::interp::run(p, spec, opts, loader, &mut sink)
    };
    (rec.out, diags)
}

/// Turns a run's canonical calls into the events [`compare`] reads,
/// with the marks it needs ([`MACHINE_MARK`], [`LENGTH_MARK`]).
pub(crate) struct Recorder {
    /// The statements of blocks that move in machine coordinates.
    machine: HashSet<Span>,
    tracker: Tracker,
    pub out: Vec<Event>,
}

impl Recorder {
    pub fn new(machine: HashSet<Span>) -> Self {
        Recorder {
            machine,
            tracker: Tracker::new(),
            out: Vec::new(),
        }
    }

    pub fn call(&mut self, call: crate::canon::Canon, span: Span) {
        let mut out = std::mem::take(&mut self.out);
        self.call_with(call, span, |e| out.push(e));
        self.out = out;
    }

    /// [`Recorder::call`], giving each event to `emit` instead of
    /// keeping it.
    pub fn call_with(
        &mut self,
        call: crate::canon::Canon,
        span: Span,
        mut emit: impl FnMut(Event),
    ) {
        let mark = self.machine.contains(&span);
        self.tracker.push(&call, span, |e| {
            if mark && matches!(e, Event::Move(_)) {
                emit(Event::Comment {
                    text: MACHINE_MARK.into(),
                    span,
                });
            }
            emit(e)
        });
        if matches!(call, crate::canon::Canon::UseToolLengthOffset(_)) {
            emit(Event::Comment {
                text: format!("{LENGTH_MARK}{}", self.tracker.length_offset_mm()),
                span,
            });
        }
    }
}

/// A comment [`events`] puts before a move in machine coordinates or to
/// a reference point (`G53`, `SUPA`, `M91`, `G28`, `G74`): where it ends
/// in work coordinates rests on offsets and tool lengths the run does not
/// know, so the rapids after it, up to the next feed move, are an
/// approach (not compared). Comments are not compared.
pub const MACHINE_MARK: &str = "\u{0}cncc: machine-referenced move";

/// A comment [`events`] puts where a tool length offset (mm, along Z)
/// comes into force, for [`length_offsets`].
pub(crate) const LENGTH_MARK: &str = "\u{0}cncc: tool length offset ";

/// The statements of blocks that move in machine coordinates or to a
/// reference point.
fn machine_spans(p: &Program, spec: &DialectSpec) -> HashSet<Span> {
    let mut spans = HashSet::new();
    for b in &p.blocks {
        add_machine_spans(b, spec, &mut spans);
    }
    spans
}

/// Adds the statements of `b` when it moves in machine coordinates or to
/// a reference point.
pub(crate) fn add_machine_spans(
    b: &crate::ir::Block,
    spec: &DialectSpec,
    spans: &mut HashSet<Span>,
) {
    use crate::ir::StmtKind;
    let machine = b
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::RefReturn { .. }) || spec.in_machine_coords(&s.kind));
    if machine {
        spans.extend(b.stmts.iter().map(|s| s.span));
    }
}

/// Compares the events of the source (`a`) and the port (`b`) with the
/// comparison engine ([`crate::compare`]); the source's tool numbers are
/// renumbered by the tool map first.
pub fn compare(a: &[Event], b: &[Event], tools: &crate::port::ToolMap) -> Verdict {
    compare_within(a, b, tools, TOLERANCE_MM)
}

/// How close the port's points must be: 1 µm, or half the target's
/// smallest increment where the target cannot write finer (a Fanuc inch
/// program's 0.0001 in is 2.54 µm; a value the port rounds to it moves by
/// up to 1.27 µm).
pub fn tolerance_for(target: &crate::dialect::DialectSpec) -> f64 {
    let step = |places: u8, mm: f64| mm * 10f64.powi(-(places as i32)) / 2.0;
    let n = &target.numbers;
    TOLERANCE_MM
        .max(step(n.length_places_inch, 25.4))
        .max(step(n.length_places_mm, 1.0))
}

/// [`compare_within`] on runs the caller no longer needs: each run's
/// events are dropped as soon as they are reduced, so the proof never
/// holds both forms of both runs.
pub fn compare_owned(
    a: Vec<Event>,
    b: Vec<Event>,
    tools: &crate::port::ToolMap,
    tolerance_mm: f64,
) -> Verdict {
    let da = digest(&a, Some(tools), tolerance_mm);
    drop(a);
    let db = digest(&b, None, tolerance_mm);
    drop(b);
    verdict_of_digests(da, db, tools, tolerance_mm)
}

/// [`compare`] with the points' tolerance given (mm).
pub fn compare_within(
    a: &[Event],
    b: &[Event],
    tools: &crate::port::ToolMap,
    tolerance_mm: f64,
) -> Verdict {
    let da = digest(a, Some(tools), tolerance_mm);
    let db = digest(b, None, tolerance_mm);
    verdict_of_digests(da, db, tools, tolerance_mm)
}

/// A whole run reduced (the source's tools renumbered by the map).
fn digest(ev: &[Event], tools: Option<&crate::port::ToolMap>, tolerance_mm: f64) -> Digest {
    let mut d = Digest::new(tolerance_mm);
    for e in ev {
        d.push(e, tools);
    }
    d
}

fn verdict_of_digests(
    a: Digest,
    b: Digest,
    tools: &crate::port::ToolMap,
    tolerance_mm: f64,
) -> Verdict {
    let (oa, ob) = (a.ops.finish(), b.ops.finish());
    let c = crate::compare::compare_ops(&oa, &ob, &compare_options(tolerance_mm));
    verdict(c, &a.tally, &b.tally, tools, tolerance_mm)
}

/// What the proof compares operations by.
pub(crate) fn compare_options(tolerance_mm: f64) -> crate::compare::CompareOptions {
    crate::compare::CompareOptions {
        tolerance_mm,
        ..crate::compare::CompareOptions::default()
    }
}

/// The verdict of a comparison of the operations and of the two runs'
/// tallies (low rapids; length offsets where the tools are not renumbered:
/// a tool the map renumbers is the same tool under the target's number,
/// its length in the target's table, not the run's).
pub(crate) fn verdict(
    c: crate::compare::Comparison,
    a: &Tally,
    b: &Tally,
    tools: &crate::port::ToolMap,
    tolerance_mm: f64,
) -> Verdict {
    let diff = |d: &crate::compare::Difference| Difference {
        what: d.what.clone(),
        a: d.a,
        b: d.b,
    };
    let v = Verdict {
        cutting: if c.same {
            None
        } else {
            c.differences.first().map(diff)
        },
        cutting_moves: c.ops_a,
        rapids: c.rapid_differences.iter().map(diff).collect(),
        low_rapid: a.low_rapid(b, tolerance_mm),
    };
    v.with_cutting(match tools.is_empty() {
        true => a.length_offset(b),
        false => None,
    })
}

pub(crate) fn renumber(e: Event, tools: &crate::port::ToolMap) -> Event {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interp::flow::NoLoader;

    fn run(text: &str, dialect: &str) -> Vec<Event> {
        let spec = crate::dialect::builtin::builtin(dialect).unwrap();
        let (p, d) = crate::driver::read_program(text, crate::span::FileId::default(), &spec);
        assert!(!d.iter().any(Diagnostic::is_error), "{d:?}");
        let (ev, d) = events(Rc::new(p), &spec, &Options::default(), &mut NoLoader);
        assert!(!d.iter().any(Diagnostic::is_error), "{d:?}");
        ev
    }

    fn verdict(a: &str, b: &str) -> Verdict {
        compare(
            &run(a, "fanuc"),
            &run(b, "fanuc"),
            &crate::port::ToolMap::default(),
        )
    }

    const PART: &str = "G21 G90 G54 G17\nG0 X0 Y0 Z5.\nG1 Z-5. F100.\nG1 X50.\nG1 Y50.\n";

    /// `G43 H2` while T1 is in the spindle cuts at T2's length: the same
    /// program coordinates, another depth in the part.
    #[test]
    fn a_length_offset_of_another_tool_fails() {
        let cut = "G0 X0 Y0\nG1 Z-5. F100.\nG1 X50.\nG0 Z5.\nM30\n";
        let src = format!("G21 G90 G17\nT1 M6\nG43 H1 Z5.\n{cut}");
        let bad = format!("G21 G90 G17\nT1 M6\nG43 H2 Z5.\n{cut}");
        let v = verdict(&src, &bad);
        let d = v.cutting.as_ref().expect("the length offset differs");
        assert!(d.what.contains("tool length offset: T1"), "{}", d.what);
        assert!(verdict(&src, &src).same());
        // No offset at all on one side is a convention, not compared.
        let none = format!("G21 G90 G17\nT1 M6\nG0 Z5.\n{cut}");
        assert!(verdict(&src, &none).cutting.is_none());
    }

    /// The port rapids across the part at Z-5 after the last cut: the
    /// cuts are the same, the verification must still fail.
    #[test]
    fn a_rapid_through_the_part_after_the_last_cut_fails() {
        let src = format!("{PART}G0 Z5.\nG0 X0 Y0\nM30\n");
        let bad = format!("{PART}G0 X0 Y0\nG0 Z5.\nM30\n");
        let v = verdict(&src, &bad);
        assert!(v.cutting.is_none(), "{v:?}");
        let d = v.low_rapid.as_ref().expect("the low rapid is found");
        assert!(
            d.what.contains("below the highest cutting height"),
            "{}",
            d.what
        );
        assert!(!v.same());
        assert!(verdict(&src, &src).same());
    }

    /// A different rapid before a hole, below the top of the cuts (the
    /// port goes to the hole at Z-2 instead of Z2): a failure, not a note.
    #[test]
    fn a_rapid_before_a_hole_below_the_cuts_fails() {
        let src = format!("{PART}G0 Z5.\nG0 X20. Y20.\nG0 Z2.\nG1 Z-8.\nG0 Z5.\nM30\n");
        let bad = format!("{PART}G0 Z-2.\nG0 X20. Y20.\nG0 Z2.\nG1 Z-8.\nG0 Z5.\nM30\n");
        let v = verdict(&src, &bad);
        assert!(v.cutting.is_none(), "{v:?}");
        assert!(v.low_rapid.is_some(), "{v:?}");
    }

    /// A hole at another place is a cutting difference.
    #[test]
    fn a_hole_at_another_place_fails() {
        let src = "G21 G90 G54 G17\nG0 X10. Y10. Z5.\nG81 Z-5. R2. F100.\nX20.\nG80\nM30\n";
        let bad = "G21 G90 G54 G17\nG0 X10. Y10. Z5.\nG81 Z-5. R2. F100.\nX20.001\nG80\nM30\n";
        let v = verdict(src, bad);
        assert!(!v.same(), "{v:?}");
    }

    /// Peck retracts and re-entries inside the hole already drilled, and
    /// rapids above the cuts, do not fail (G83 with another peck clearance).
    #[test]
    fn rapids_in_air_and_above_the_cuts_pass() {
        let src = "G21 G90 G54 G17\nG0 X10. Y10. Z25.\nG83 Z-10. R2. Q3. F100.\nG80\nG0 Z25.\nX0 Y0\nM30\n";
        let other = "G21 G90 G54 G17\nG0 X10. Y10. Z30.\nG0 Z2.\nG1 Z-3. F100.\nG0 Z2.\nG0 Z-2.5\nG1 Z-6.\nG0 Z2.\nG0 Z-5.5\nG1 Z-9.\nG0 Z2.\nG0 Z-8.5\nG1 Z-10.\nG0 Z2.\nG0 Z30.\nX0 Y0\nM30\n";
        let v = verdict(src, other);
        assert!(v.low_rapid.is_none(), "{v:?}");
    }

    /// A low rapid the port rounded to the target's increment (0.0001 in:
    /// 1.27 µm at most) is the same rapid within the target's tolerance;
    /// one 0.01 mm away is not.
    #[test]
    fn a_low_rapid_rounded_to_the_targets_increment_is_the_same() {
        let src = format!("{PART}G0 Z2.\nG0 X20.0004 Y20.\nG1 Z-8.\nG0 Z5.\nM30\n");
        let near = format!("{PART}G0 Z2.\nG0 X20.0016 Y20.\nG1 Z-8.\nG0 Z5.\nM30\n");
        let far = format!("{PART}G0 Z2.\nG0 X20.01 Y20.\nG1 Z-8.\nG0 Z5.\nM30\n");
        let tools = crate::port::ToolMap::default();
        let within =
            |a: &str, b: &str| compare_within(&run(a, "fanuc"), &run(b, "fanuc"), &tools, 0.00127);
        assert!(within(&src, &near).low_rapid.is_none());
        assert!(within(&src, &far).low_rapid.is_some());
        assert!(verdict(&src, &near).low_rapid.is_some(), "1 µm by default");
    }
}
