//! Coordinates that carry their own dimension (Klartext `L IX-1 IY+2`,
//! Siemens `X=IC(5)`) for a word-address target, which has G90/G91 for
//! the whole block only: a move whose coordinates are all incremental
//! (or all absolute) is written in that mode for its block, `G91 G0 X-1.
//! Y2.` and `G90` after it where the program was absolute (the mode in
//! force needs no code at all). A move that mixes the two stays as it is,
//! for the writer to name (E0601) and the moves fallback to write.

use crate::dialect::{DialectSpec, Family};
use crate::ir::{Block, Coord, DimMode, MotionKind, Program, Stmt, StmtKind, AXIS_LETTERS};
use crate::port::levels::Modal;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if to.family != Family::WordAddress || !has_dims(p) {
        return;
    }
    // The distance mode in force, followed as the other passes follow it.
    let mut modal = Modal::new(from);
    let blocks = std::mem::take(&mut p.blocks);
    p.blocks.reserve(blocks.len());
    for mut b in blocks {
        let dim = block_dim(&b);
        let distance = |s: &&Stmt| matches!(s.kind, StmtKind::Distance(_));
        b.stmts.iter().filter(distance).for_each(|s| modal.see(s));
        let absolute = modal.absolute;
        let Some(dim) = dim else {
            p.blocks.push(b);
            continue;
        };
        for s in &mut b.stmts {
            if let StmtKind::Motion(m) = &mut s.kind {
                for axis in AXIS_LETTERS {
                    if let Some(Some(c)) = m.target.slot_mut(axis) {
                        c.dim = None;
                    }
                }
            }
        }
        let in_force = if absolute {
            DimMode::Absolute
        } else {
            DimMode::Incremental
        };
        if dim == in_force {
            p.blocks.push(b);
            continue;
        }
        let span = b.span;
        b.stmts.insert(0, Stmt::new(StmtKind::Distance(dim), span));
        let back =
            crate::port::follow_block(&b, vec![Stmt::new(StmtKind::Distance(in_force), span)]);
        p.blocks.push(b);
        p.blocks.push(back);
    }
}

fn has_dims(p: &Program) -> bool {
    p.blocks.iter().any(|b| block_dim(b).is_some())
}

/// The one dimension all the coordinates of the block's move carry, when
/// each carries one and the block sets no mode and nothing else with
/// coordinates.
fn block_dim(b: &Block) -> Option<DimMode> {
    let mut moves = b.stmts.iter().filter_map(|s| match &s.kind {
        StmtKind::Motion(m) => Some(m),
        _ => None,
    });
    let m = moves.next()?;
    if moves.next().is_some()
        || !matches!(
            m.kind,
            MotionKind::Rapid | MotionKind::Linear | MotionKind::Implicit | MotionKind::Arc(_)
        )
        || m.polar_radius.is_some()
        || m.polar_angle.is_some()
    {
        return None;
    }
    let others = b.stmts.iter().any(|s| {
        matches!(
            s.kind,
            StmtKind::Distance(_)
                | StmtKind::Cycle(_)
                | StmtKind::CycleCall(_)
                | StmtKind::RefReturn { .. }
                | StmtKind::CoordShift { .. }
        )
    });
    if others {
        return None;
    }
    let coords: Vec<&Coord> = m.target.iter().map(|(_, c)| c).collect();
    let first = coords.first()?.dim?;
    coords.iter().all(|c| c.dim == Some(first)).then_some(first)
}
