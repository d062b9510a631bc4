//! `port --verify` with the two programs run side by side: the source
//! and the port each run on a thread of its own, reduced as they go
//! ([`super::verify_digest`]), their operations handed over in batches
//! to the comparison ([`crate::compare::compare_windows`]), which holds
//! a few hundred of each. The proof's memory is then that of two runs
//! (each as `canon` streams it), not of their events.
//!
//! Not for a subprogram ported alone. A program with control flow runs
//! here too (the walker holds its plain moves as text), as long as it
//! loads no other file: a run that asks for one is said in the
//! [`Outcome`], and the caller proves the port with the files loaded.

use super::verify::{self, Recorder, Verdict};
use super::verify_digest::{Digest, Tally};
use super::verify_text::Scan;
use crate::compare::window::{hand_over, QUEUED};
use crate::compare::{OpWindow, Ops};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::flow::{NoLoader, ProgramLoader};
use crate::interp::Options;
use crate::span::{FileId, Span};
use std::sync::mpsc::{sync_channel, SyncSender};
use std::sync::Arc;

/// One program to run.
#[derive(Clone)]
pub struct Side<'t> {
    pub text: &'t str,
    pub id: FileId,
    pub scan: Scan,
    pub spec: &'t Arc<DialectSpec>,
    pub opts: &'t Options,
}

impl Side<'_> {
    /// Can it run side by side (see the module doc)?
    pub fn streams(&self) -> bool {
        !self.scan.fragment
    }
}

/// What comparing side by side gives: the verdict, and each run's
/// diagnostics (the verdict means nothing where a run stopped).
pub struct Outcome {
    pub verdict: Verdict,
    pub source: Vec<Diagnostic>,
    pub port: Vec<Diagnostic>,
    /// A run asked for another program (not loaded here): the verdict
    /// means nothing.
    pub called_out: bool,
}

/// Loads nothing, and remembers being asked.
#[derive(Default)]
struct Refusing {
    asked: bool,
}

impl ProgramLoader for Refusing {
    fn load(&mut self, _: &crate::ir::CallTarget) -> Option<std::rc::Rc<crate::ir::Program>> {
        self.asked = true;
        None
    }
}

/// Runs both programs side by side and compares them; the source's
/// tools are renumbered by `tools`.
pub fn compare(
    source: Side<'_>,
    port: Side<'_>,
    tools: &super::ToolMap,
    tolerance_mm: f64,
) -> Outcome {
    std::thread::scope(|s| {
        let (ta, ra) = sync_channel::<Ops>(QUEUED);
        let (tb, rb) = sync_channel::<Ops>(QUEUED);
        let ha = s.spawn(move || run(source, Some(tools), tolerance_mm, ta));
        let hb = s.spawn(move || run(port, None, tolerance_mm, tb));
        let wa = OpWindow::pulled(Box::new(move || ra.recv().ok()));
        let wb = OpWindow::pulled(Box::new(move || rb.recv().ok()));
        let opts = verify::compare_options(tolerance_mm);
        let c = crate::compare::compare_windows(wa, wb, &opts);
        let joined = |h: std::thread::ScopedJoinHandle<'_, Ran>| {
            h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))
        };
        let (a, da, asked_a) = joined(ha);
        let (b, db, asked_b) = joined(hb);
        Outcome {
            verdict: verify::verdict(c, &a, &b, tools, tolerance_mm),
            source: da,
            port: db,
            called_out: asked_a || asked_b,
        }
    })
}

/// What one side's run gives: its tally, its diagnostics, and whether
/// it asked for another program.
type Ran = (Tally, Vec<Diagnostic>, bool);

/// Runs one side, sending its operations as they are made.
fn run(
    side: Side<'_>,
    tools: Option<&super::ToolMap>,
    tolerance_mm: f64,
    to: SyncSender<Ops>,
) -> Ran {
    let Side {
        text,
        id,
        scan,
        spec,
        opts,
    } = side;
    let mut rec = Recorder::new(scan.machine);
    let mut digest = Digest::new(tolerance_mm);
    // The comparison stops listening only when it has all it needs.
    let mut listening = true;
    let mut loader = Refusing::default();
    let diags = {
        let mut sink = |call: crate::canon::Canon, span: Span| {
            rec.call_with(call, span, |e| digest.push(&e, tools));
            listening = hand_over(&mut digest.ops, &to, listening);
        };
        crate::interp::file::run_text_loading(text, id, spec, opts, &mut loader, &mut sink)
    };
    let Digest { ops, tally } = digest;
    if listening {
        // A comparison that has stopped listening needs no more.
        let _ = to.send(ops.finish());
    }
    (tally, diags, loader.asked)
}

/// The tools a program's run changes to, each with its statement, in
/// order: the proof gives them to a target that reads its tool table
/// before the source has run (a run of its own, which holds nothing).
pub fn tool_changes(
    text: &str,
    id: FileId,
    spec: &Arc<DialectSpec>,
    opts: &Options,
) -> Vec<(i64, Span)> {
    let mut tracker = crate::toolpath::Tracker::new();
    let mut out = Vec::new();
    let mut sink = |call: crate::canon::Canon, span: Span| {
        tracker.push(&call, span, |e| {
            if let crate::toolpath::Event::ToolChange { tool, span } = e {
                out.push((tool, span));
            }
        });
    };
    crate::interp::file::run_text_loading(text, id, spec, opts, &mut NoLoader, &mut sink);
    out
}
