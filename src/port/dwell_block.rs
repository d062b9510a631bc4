//! A dwell that shares its block (`G04 P.001 G0 X1 Y1 S1000 M3`,
//! LinuxCNC's idiom against blending): LinuxCNC runs the block's speed,
//! spindle and coolant, then the dwell, then the move, then a stop. On
//! Fanuc and Haas a dwell block's `X` is the dwell time, and the 840D
//! wants `G4` alone in its block (an `S` there is a dwell in
//! revolutions), so the block becomes up to three, run in the same
//! order: the rest of the block (with its number and comments), the
//! dwell alone, then the move and any stop or end. Modes set in the block
//! (G90/G91, G43) now act before the dwell rather than after it, which no
//! cut can tell. A target where a dwell shares a block (capability
//! `dwell-with-move`: LinuxCNC) keeps the block.

use super::follow_block;
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Block, Program, Stmt, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if to.has(Capability::DwellWithMove) {
        return;
    }
    let blocks = std::mem::take(&mut p.blocks);
    p.blocks.reserve(blocks.len());
    for b in blocks {
        split(b, &mut p.blocks);
    }
}

/// Where a statement of a dwell's block goes: 0 before the dwell, 1 the
/// dwell, 2 after it.
fn part(kind: &StmtKind) -> usize {
    match kind {
        StmtKind::Dwell { .. } => 1,
        StmtKind::Motion(_) | StmtKind::Stop(_) | StmtKind::ProgramEnd { .. } => 2,
        _ => 0,
    }
}

fn split(mut b: Block, out: &mut Vec<Block>) {
    let dwell = b.stmts.iter().any(|s| part(&s.kind) == 1);
    let shared = b
        .stmts
        .iter()
        .any(|s| part(&s.kind) != 1 && !matches!(s.kind, StmtKind::Comment { .. }));
    if !dwell || !shared {
        out.push(b);
        return;
    }
    let mut parts: [Vec<Stmt>; 3] = Default::default();
    for s in std::mem::take(&mut b.stmts) {
        parts[part(&s.kind)].push(s);
    }
    let [before, dwell, after] = parts;
    b.stmts = before;
    let (mid, last) = (follow_block(&b, dwell), follow_block(&b, after));
    out.push(b);
    out.push(mid);
    if !last.stmts.is_empty() {
        out.push(last);
    }
}
