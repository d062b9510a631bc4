//! Subprograms for the verification run of a ported program: a call in
//! the port (`L1000`) loads the subprogram file the source calls
//! (`O1000.nc` beside it), read in the source dialect, ports it with the
//! same options and reads the result back with the target's front end.
//! So `--verify` proves the called subprograms' port as well, without
//! needing target files on disk.
//!
//! The ported subprogram keeps the source file's id: its spans point into
//! the source text (diagnostics of the port itself are kept in `diags`).

use super::{port_program, PortOptions};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::driver::{read_program, FsLoader};
use crate::interp::flow::ProgramLoader;
use crate::ir::{CallTarget, Program};
use std::rc::Rc;

pub struct PortingLoader<'a> {
    pub source: FsLoader<'a>,
    pub from: &'a DialectSpec,
    pub to: &'a DialectSpec,
    pub opts: &'a PortOptions,
    /// Why a called subprogram could not be ported.
    pub diags: Vec<Diagnostic>,
}

impl ProgramLoader for PortingLoader<'_> {
    fn load(&mut self, target: &CallTarget) -> Option<Rc<Program>> {
        let src = self.source.load(target)?;
        self.diags.append(&mut self.source.diags);
        let (ported, mut d) = port_program(&src, self.from, self.to, self.opts);
        let failed = d.iter().any(Diagnostic::is_error);
        self.diags.append(&mut d);
        if failed {
            return None;
        }
        let text = match crate::emit::write_program(&ported, self.to) {
            Ok(t) => t,
            Err(mut errs) => {
                self.diags.append(&mut errs);
                return None;
            }
        };
        // A subprogram file need not end the program (E0305 is for mains);
        // any other error means the port does not read back.
        let (p, d) = read_program(&text, src.file, self.to);
        let mut errs: Vec<Diagnostic> = d
            .into_iter()
            .filter(|d| d.is_error() && d.code != crate::diag::Code::NoProgramEnd)
            .collect();
        let failed = !errs.is_empty();
        self.diags.append(&mut errs);
        (!failed).then(|| Rc::new(p))
    }
}
