//! The header of a ported subprogram for a Siemens target. A program
//! that returns to its caller (Fanuc `O1000` ... `M99`) and never ends the
//! program is a subprogram: Siemens keeps it in a `.SPF` file, and the
//! main program's `L1000` calls the file `L1000.SPF`; so the header is
//! `%_N_L1000_SPF`, not `%_N_O1000_MPF`. (A subprogram with parameters
//! would start with `PROC name(..)`; numbered programs take none.)
//! Runs after [`super::forms`], which keeps a title as a comment.

use crate::dialect::{DialectSpec, Family};
use crate::ir::{Program, StmtKind, StopKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if to.family != Family::Sinumerik || from.family == Family::Sinumerik {
        return;
    }
    let stmts = || p.blocks.iter().flat_map(|b| &b.stmts);
    let returns = stmts().any(|s| matches!(s.kind, StmtKind::SubReturn { .. }));
    let ends =
        stmts().any(|s| matches!(s.kind, StmtKind::Stop(StopKind::End | StopKind::EndRewind)));
    if !returns || ends {
        return;
    }
    for s in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        if let StmtKind::ProgramStart {
            number: Some(n),
            name,
        } = &mut s.kind
        {
            *name = Some(format!("L{n}_SPF"));
            return;
        }
    }
}
