//! A main program that ends without M2/M30, for a target that requires an
//! end (capability `program-end-required`: LinuxCNC stops with "file
//! ended with no percent sign or program end"). Heidenhain's `END PGM`
//! ends the program by itself, and a Siemens main program may end at the
//! end of its file; neither resets the modes as M2 does. The target's
//! form for "the text ends here" without M2's actions is the tape mark:
//! the program goes between `%` lines. A subprogram (one that returns)
//! is left as it is.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Block, Program, Stmt, StmtKind, StopKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if !to.has(Capability::ProgramEndRequired) || p.blocks.is_empty() {
        return;
    }
    let stmts = || p.blocks.iter().flat_map(|b| &b.stmts);
    let ends = stmts().any(|s| {
        matches!(
            s.kind,
            StmtKind::Stop(StopKind::End | StopKind::EndRewind)
                | StmtKind::Tape
                | StmtKind::SubReturn { .. }
                | StmtKind::SubStart { .. }
                | StmtKind::Return { .. }
        )
    });
    if ends {
        return;
    }
    let first = p.blocks[0].span;
    let last = p.blocks[p.blocks.len() - 1].span;
    p.blocks.insert(0, tape(first));
    p.blocks.push(tape(last));
}

fn tape(span: crate::span::Span) -> Block {
    Block {
        span,
        skip: None,
        number: None,
        label: None,
        stmts: vec![Stmt::new(StmtKind::Tape, span)],
    }
}
