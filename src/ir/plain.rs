//! Plain moves: blocks that only move along literal coordinates, with at
//! most a literal feed and a comment, no label and no control flow. They
//! are most of a CAM program; the streamed port chunks runs of them
//! (`crate::port::stream`) and the program walker holds them as their text
//! (`crate::interp::lazy`).

use super::{Block, Motion, MotionKind, StmtKind, Value};

/// A block that only moves: literal coordinates, no label, no flow.
pub fn is_plain(b: &Block) -> bool {
    b.label.is_none()
        && !b.stmts.is_empty()
        && b.stmts.iter().all(|s| match &s.kind {
            StmtKind::Motion(m) => plain_motion(m),
            StmtKind::Feed(v) => literal(v),
            StmtKind::Comment { .. } => true,
            _ => false,
        })
}

fn plain_motion(m: &Motion) -> bool {
    let kind = matches!(
        m.kind,
        MotionKind::Implicit | MotionKind::Rapid | MotionKind::Linear | MotionKind::Arc(_)
    );
    let coord = |c: &Option<crate::ir::Coord>| {
        c.as_ref()
            .is_none_or(|c| c.dim.is_none() && literal(&c.value))
    };
    let t = &m.target;
    let axes = [&t.x, &t.y, &t.z, &t.a, &t.b, &t.c, &t.u, &t.v, &t.w];
    let a = &m.arc;
    kind && axes.into_iter().all(coord)
        && [&a.i, &a.j, &a.k].into_iter().all(coord)
        && a.radius.as_ref().is_none_or(literal)
        && a.angle.is_none()
        && a.turns.is_none()
        && a.mid.is_none()
        && m.polar_radius.is_none()
        && m.polar_angle.is_none()
        && m.corner.is_none()
}

fn literal(v: &Value) -> bool {
    matches!(v, Value::Number(_))
}
