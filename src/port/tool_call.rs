//! `T.. M6` for a Klartext target: one `TOOL CALL n Z S..` block.
//!
//! The word-address and Siemens forms spread the tool call over blocks:
//! the plane (`G17`) in the safety block before it, `T2 M6`, and the
//! spindle speed a few blocks later with `M3`. Klartext gives the tool
//! axis and the speed in the `TOOL CALL` itself, so this pass moves into
//! the tool-change block
//! * the plane of a block before it that holds only modal settings (no
//!   move), when no move comes between them;
//! * the first spindle speed after it, when no feed move (or spindle
//!   start in another block) comes before: the spindle is stopped by the
//!   tool change, so setting its speed earlier changes nothing.
//!
//! What cannot be moved stays where it was (`TOOL CALL Z`, `TOOL CALL S..`).

use crate::dialect::{DialectSpec, Family};
use crate::ir::{MotionKind, Program, Stmt, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if to.family != Family::Klartext || from.family == Family::Klartext {
        return;
    }
    let n = p.blocks.len();
    for i in 0..n {
        let changes = p.blocks[i]
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ToolChange));
        if !changes {
            continue;
        }
        if !has(p, i, |s| matches!(s.kind, StmtKind::Plane(_))) {
            // Back to the nearest plane, through blocks without moves.
            for j in (0..i).rev() {
                if has(p, j, is_move) {
                    break;
                }
                if let Some(k) = p.blocks[j]
                    .stmts
                    .iter()
                    .position(|s| matches!(s.kind, StmtKind::Plane(_)))
                {
                    let s = p.blocks[j].stmts.remove(k);
                    p.blocks[i].stmts.push(s);
                    break;
                }
            }
        }
        if !has(p, i, |s| matches!(s.kind, StmtKind::SpindleSpeed(_))) {
            for j in i + 1..n {
                if has(p, j, |s| matches!(s.kind, StmtKind::ToolChange)) {
                    break;
                }
                if let Some(k) = p.blocks[j]
                    .stmts
                    .iter()
                    .position(|s| matches!(s.kind, StmtKind::SpindleSpeed(_)))
                {
                    let s = p.blocks[j].stmts.remove(k);
                    p.blocks[i].stmts.push(s);
                    break;
                }
                if has(p, j, is_feed_move) || has(p, j, |s| matches!(s.kind, StmtKind::Spindle(_)))
                {
                    break;
                }
            }
        }
    }
    p.blocks
        .retain(|b| !b.stmts.is_empty() || b.number.is_some() || b.label.is_some());
}

fn has(p: &Program, i: usize, f: fn(&Stmt) -> bool) -> bool {
    p.blocks[i].stmts.iter().any(f)
}

fn is_move(s: &Stmt) -> bool {
    matches!(
        s.kind,
        StmtKind::Motion(_) | StmtKind::Cycle(_) | StmtKind::CycleCall(_)
    )
}

fn is_feed_move(s: &Stmt) -> bool {
    match &s.kind {
        StmtKind::Motion(m) => m.kind != MotionKind::Rapid,
        StmtKind::Cycle(_) | StmtKind::CycleCall(_) => true,
        _ => false,
    }
}
