//! Files that are not main programs, checked alone: a subprogram, macro or
//! Siemens PROC that returns to its caller (M99, M17, RET) instead of
//! ending the program, or a library of subroutine definitions with nothing
//! to run between them (LinuxCNC `o<name> sub` files). Their parameters,
//! and the modal state they start in, come from a caller cncc does not
//! have: they run with [`Interp::from_outside`] set, so the run stops with
//! W0590 at the first value only the caller knows, instead of reporting
//! the caller's business as the file's mistake.

use super::flow::{ProgramLoader, Walker};
use super::{Interp, Options, Sink, Stop};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Block, Program, StmtKind, StopKind};
use std::rc::Rc;

/// What kind of file that is not a main program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Fragment {
    /// The file itself is called: it runs from the top and returns.
    Called,
    /// Only subroutine definitions: the index of each one's first block.
    Library(Vec<usize>),
}

/// What the top level of a program (outside subroutine definitions) holds.
#[derive(Default)]
struct TopLevel {
    subs: Vec<usize>,
    open: usize,
    runs_something: bool,
    returns: bool,
    ends: bool,
}

/// Whether `p` is a subprogram or a subroutine library rather than a main
/// program.
pub fn detect(p: &Program) -> Option<Fragment> {
    let mut top = TopLevel::default();
    for (i, b) in p.blocks.iter().enumerate() {
        for s in &b.stmts {
            top.statement(i, &s.kind);
        }
    }
    top.fragment()
}

/// [`detect`] block by block, for a program read as a stream: when it says
/// the file is a main program, the file need not be read whole to know.
#[derive(Default)]
pub struct Detector {
    top: TopLevel,
    blocks: usize,
}

impl Detector {
    pub fn block(&mut self, b: &Block) {
        for s in &b.stmts {
            self.top.statement(self.blocks, &s.kind);
        }
        self.blocks += 1;
    }

    /// Whether [`detect`] on the whole program would find a fragment.
    pub fn is_fragment(&self) -> bool {
        self.top.ends_as_fragment()
    }
}

impl TopLevel {
    fn fragment(self) -> Option<Fragment> {
        if !self.ends_as_fragment() {
            return None;
        }
        if self.returns || self.open > 0 {
            // A Siemens PROC is a definition that is never closed: the
            // file is its body.
            return Some(Fragment::Called);
        }
        Some(Fragment::Library(self.subs))
    }

    fn ends_as_fragment(&self) -> bool {
        !self.ends
            && (self.returns || self.open > 0 || (!self.subs.is_empty() && !self.runs_something))
    }

    fn statement(&mut self, block: usize, kind: &StmtKind) {
        match kind {
            StmtKind::SubStart { .. } => {
                if self.open == 0 {
                    self.subs.push(block);
                }
                self.open += 1;
            }
            StmtKind::SubEnd { .. } => self.open = self.open.saturating_sub(1),
            _ if self.open > 0 => {}
            StmtKind::SubReturn { .. } | StmtKind::Return { .. } => self.returns = true,
            StmtKind::Stop(StopKind::End | StopKind::EndRewind) | StmtKind::ProgramEnd { .. } => {
                self.ends = true
            }
            k if is_layout(k) => {}
            _ => self.runs_something = true,
        }
    }
}

/// Statements that do not make a program of their own.
fn is_layout(k: &StmtKind) -> bool {
    matches!(
        k,
        StmtKind::Comment { .. } | StmtKind::Tape | StmtKind::ProgramStart { .. }
    )
}

/// Runs a fragment with its outside values unknown; returns the run's
/// diagnostics. A library runs each subroutine on its own.
pub fn run(
    program: Rc<Program>,
    fragment: &Fragment,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
    sink: &mut Sink<'_>,
) -> Vec<Diagnostic> {
    let starts = match fragment {
        Fragment::Called => vec![0],
        Fragment::Library(subs) => subs.iter().map(|i| i + 1).collect(),
    };
    let mut diags = Vec::new();
    for at in starts {
        let mut sink = &mut *sink;
        let mut it = Interp::new(spec, opts, &mut sink);
        it.from_outside = true;
        it.start();
        let mut walker = Walker::new(program.clone(), loader);
        walker.resume(at, false, 0);
        if *fragment == Fragment::Called {
            walker.run_as_called();
        }
        let result = walker.run(&mut it);
        diags.append(&mut it.take_diags());
        match result {
            Err(Stop::Error(d)) | Err(Stop::Unknown(d)) => diags.push(d),
            Err(Stop::End) | Ok(()) => {}
        }
        if diags.iter().any(Diagnostic::is_error) {
            break;
        }
    }
    diags
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fragment(dialect: &str, text: &str) -> Option<Fragment> {
        let spec = crate::dialect::builtin::builtin(dialect).unwrap();
        let (p, d) = crate::driver::read_program(text, crate::span::FileId(0), &spec);
        assert!(d.iter().all(|d| !d.is_error()), "{d:?}");
        // The block-by-block detector says the same.
        let mut streamed = Detector::default();
        p.blocks.iter().for_each(|b| streamed.block(b));
        let found = detect(&p);
        assert_eq!(streamed.is_fragment(), found.is_some(), "{text}");
        found
    }

    #[test]
    fn a_main_program_is_not_a_fragment() {
        assert_eq!(fragment("fanuc", "O1\nG0 X1\nM30\n"), None);
        assert_eq!(
            fragment(
                "linuxcnc",
                "o<a> sub\nG0 X#1\no<a> endsub\no<a> call [1]\nM2\n"
            ),
            None
        );
    }

    #[test]
    fn a_macro_that_returns_is_called() {
        assert_eq!(
            fragment("fanuc", "O9001\nG0 X#24\nM99\n"),
            Some(Fragment::Called)
        );
        assert_eq!(
            fragment("siemens840d", "PROC P(REAL A)\nG0 X=A\nM17\n"),
            Some(Fragment::Called)
        );
    }

    #[test]
    fn a_file_of_sub_definitions_is_a_library() {
        let text = "(lib)\no<a> sub\nG0 X#1\no<a> endsub\no<b> sub\nG0 Y#1\no<b> endsub\n";
        assert_eq!(
            fragment("linuxcnc", text),
            Some(Fragment::Library(vec![1, 4]))
        );
    }
}
