//! Running a program while it is read, so that memory stays flat on large
//! CAM files: blocks run one by one as the reader hands them over, until a
//! block needs the program walker (jumps, loops, calls, variables). From
//! there the whole program is read and the walker goes on from that block
//! with the same machine state (the blocks before it ran in sequence, as
//! the walker would have run them).

use super::flow::{ProgramLoader, Walker};
use super::{machine, Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, Block, Expr, Program, StmtKind};

/// The state of a streamed run between blocks.
#[derive(Debug, Default)]
pub struct StreamRun {
    stopped: bool,
    /// The index of the first block that needs the walker.
    pub handover: Option<usize>,
    index: usize,
    seen_content: bool,
    percent_start: bool,
    blocks: u64,
    diags: Vec<Diagnostic>,
}

impl StreamRun {
    /// Runs one block as it is read (nothing once the run stopped or was
    /// handed over).
    pub fn block(&mut self, it: &mut Interp<'_, '_>, b: &Block, exprs: &Arena<Expr>) {
        let index = self.index;
        self.index += 1;
        if self.stopped || self.handover.is_some() {
            return;
        }
        if b.stmts
            .iter()
            .any(|s| needs_walker(&s.kind) || calls_contour(it, &s.kind))
        {
            self.handover = Some(index);
            return;
        }
        if b.stmts.is_empty() {
            return;
        }
        self.blocks += 1;
        if self.blocks > it.opts.limits.blocks {
            let d = Diagnostic::new(Code::LimitExceeded, "more blocks run than the limit")
                .primary(b.span, "here");
            return self.stop(it, Err(Stop::Error(d)));
        }
        let first = !self.seen_content;
        self.seen_content = true;
        let skipped = b.skip.is_some() && it.opts.block_delete;
        if !skipped && b.stmts.iter().any(|s| matches!(s.kind, StmtKind::Tape)) {
            if first {
                self.percent_start = true;
            } else if self.percent_start {
                machine::finish_sequence(it);
                self.stopped = true;
                return;
            }
        }
        it.line = index as u32 + 1;
        it.hold();
        let r = it.block(b, exprs);
        let r = match it.settle_block(r, b, exprs, 0) {
            Err(stop) => it.recover(stop),
            ok => ok,
        };
        self.stop(it, r);
    }

    fn stop(&mut self, it: &mut Interp<'_, '_>, r: Result<(), Stop>) {
        match r {
            Ok(()) => self.stopped = it.ended,
            Err(Stop::End) => self.stopped = true,
            Err(Stop::Unknown(d)) => {
                self.diags.push(d);
                self.stopped = true;
            }
            Err(Stop::Error(d)) => {
                self.diags.push(d);
                machine::abort_sequence(it);
                self.stopped = true;
            }
        }
    }

    /// Ends a run cut short by a block that did not read cleanly: the
    /// run-time diagnostics so far, and rs274's abort calls.
    pub fn abandon(&mut self, it: &mut Interp<'_, '_>) -> Vec<Diagnostic> {
        if !self.stopped {
            machine::abort_sequence(it);
            self.stopped = true;
        }
        let mut diags = it.take_diags();
        diags.append(&mut self.diags);
        diags
    }

    /// Ends a run that was not handed over: its diagnostics, and the
    /// report of a program that fell off its end.
    pub fn finish(&mut self, it: &mut Interp<'_, '_>) -> Vec<Diagnostic> {
        let mut diags = it.take_diags();
        diags.append(&mut self.diags);
        if !self.stopped && self.handover.is_none() {
            machine::fell_off_end(it, &mut diags);
        }
        diags
    }

    /// Goes on with the walker over the whole program from the hand-over
    /// block; returns every diagnostic of the run.
    pub fn continue_with<'l>(
        &mut self,
        it: &mut Interp<'_, '_>,
        program: std::rc::Rc<Program>,
        lazy: Option<super::lazy::LazyBlocks<'l>>,
        loader: &'l mut dyn ProgramLoader,
    ) -> Vec<Diagnostic> {
        let at = self.handover.unwrap_or(0);
        let mut walker = Walker::new(program, loader);
        if let Some(lazy) = lazy {
            walker = walker.with_lazy(lazy);
        }
        walker.resume(at, self.percent_start, self.blocks);
        let result = walker.run(it);
        let mut diags = it.take_diags();
        diags.append(&mut self.diags);
        match result {
            Err(Stop::Error(d)) => {
                diags.push(d);
                machine::abort_sequence(it);
            }
            Err(Stop::End) => {}
            Err(Stop::Unknown(d)) => diags.push(d),
            Ok(()) => machine::fell_off_end(it, &mut diags),
        }
        diags
    }
}

/// A lathe profile cycle (G70/G71/G72): it calls its contour subroutine,
/// which only the walker can do.
fn calls_contour(it: &Interp<'_, '_>, kind: &StmtKind) -> bool {
    matches!(kind, StmtKind::Aux { letter, code, .. }
        if matches!(super::aux::machine_fn(it.spec, *letter, *code),
            Some(crate::dialect::MachineFn::LatheProfile(_))))
}

/// Statements only the program walker runs (control flow and variables).
pub fn needs_walker(kind: &StmtKind) -> bool {
    use StmtKind::*;
    match kind {
        Tape | ProgramStart { .. } | Raw { .. } | Word(_) | Command { .. } => false,
        k => super::exec::phase(k) == 0,
    }
}
