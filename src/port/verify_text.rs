//! `port --verify` over program texts read as streams: each side is
//! scanned once (its read diagnostics, the blocks that move in machine
//! coordinates, whether it is a subprogram rather than a main program)
//! and then run while it is read ([`crate::interp::file`]), so the proof
//! holds the events of the two runs, not the two programs. A program
//! with control flow is read whole from its first such block, as `canon`
//! reads it.

use super::verify::{add_machine_spans, Recorder};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::flow::ProgramLoader;
use crate::interp::fragment::Detector;
use crate::interp::Options;
use crate::span::{FileId, Span};
use crate::toolpath::Event;
use std::collections::HashSet;
use std::sync::Arc;

/// What one reading of a program's text tells the proof.
#[derive(Clone)]
pub struct Scan {
    /// The reader's diagnostics.
    pub diags: Vec<Diagnostic>,
    /// The statements of blocks that move in machine coordinates.
    pub machine: HashSet<Span>,
    /// A subprogram or macro ported alone (see [`crate::interp::fragment`]).
    pub fragment: bool,
    /// Some block needs the program walker (control flow, a call): the
    /// run reads the program whole from there, and may load others.
    pub walker: bool,
}

impl Scan {
    pub fn has_errors(&self) -> bool {
        self.diags.iter().any(Diagnostic::is_error)
    }
}

/// Reads `text` (registered as `id`) block by block, keeping no block.
pub fn scan(text: &str, id: FileId, spec: &DialectSpec) -> Scan {
    let mut seen = Scanning::default();
    let read = crate::driver::check_stream_flagged(text.as_bytes(), id, spec, |b, _, _| {
        seen.block(b, spec)
    });
    // Reading from memory cannot fail.
    seen.finish(read.map(|r| r.diagnostics).unwrap_or_default())
}

/// A [`Scan`] being made from the blocks of one reading, by whoever reads
/// them (the streamed port reads its source once for both).
#[derive(Default)]
pub struct Scanning {
    machine: HashSet<Span>,
    detector: Detector,
    walker: bool,
}

impl Scanning {
    /// The next block read.
    pub fn block(&mut self, b: &crate::ir::Block, spec: &DialectSpec) {
        add_machine_spans(b, spec, &mut self.machine);
        self.detector.block(b);
        self.walker |= b
            .stmts
            .iter()
            .any(|s| crate::interp::stream::needs_walker(&s.kind));
    }

    /// The scan, with the reader's diagnostics.
    pub fn finish(self, diags: Vec<Diagnostic>) -> Scan {
        Scan {
            diags,
            machine: self.machine,
            fragment: self.detector.is_fragment(),
            walker: self.walker,
        }
    }
}

/// Runs `text` while it is read and returns its toolpath events, as
/// [`super::verify::events`] does for a program held whole.
pub fn events(
    text: &str,
    id: FileId,
    scan: Scan,
    spec: &Arc<DialectSpec>,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
) -> (Vec<Event>, Vec<Diagnostic>) {
    let mut rec = Recorder::new(scan.machine);
    let diags = {
        let mut sink = |call: crate::canon::Canon, span: Span| rec.call(call, span);
        crate::interp::file::run_text_loading(text, id, spec, opts, loader, &mut sink)
    };
    (rec.out, diags)
}
