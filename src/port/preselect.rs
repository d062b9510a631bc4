//! The next tool named in a change block (`T1 T2 M6`, capability
//! `second-tool-preselects`): where the target has no such form, it
//! becomes a selection in a block of its own right after the change
//! (`T1 M6` then `T2`), which selects the same tool at the same point.

use super::follow_block;
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if to.has(Capability::SecondToolPreselects) {
        return;
    }
    let blocks = std::mem::take(&mut p.blocks);
    p.blocks.reserve(blocks.len());
    for mut b in blocks {
        let Some(at) = b
            .stmts
            .iter()
            .position(|s| matches!(s.kind, StmtKind::ToolPreselect(_)))
        else {
            p.blocks.push(b);
            continue;
        };
        let mut next = b.stmts.remove(at);
        if let StmtKind::ToolPreselect(t) = next.kind {
            next.kind = StmtKind::ToolSelect(t);
        }
        let after = follow_block(&b, vec![next]);
        p.blocks.push(b);
        p.blocks.push(after);
    }
}
