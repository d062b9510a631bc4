//! `G41 D1` / `G42 D1` for a target whose compensation takes the radius of
//! the tool in the spindle and names no register (capability
//! `comp-without-register`: Klartext `RL`/`RR`):
//! the register goes where it is the tool's own (`D` equal to the number
//! of the tool in the spindle, the usual convention; a tool selected after
//! the change only made ready), so the same radius is used. Any other
//! register stays, and the writer refuses it.
//!
//! Klartext sets compensation on a positioning block: a `G40` (`G41`,
//! `G42`) alone in a block goes onto the next move (`L X.. Y.. R0`)
//! instead of an empty `L R0`.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, StmtKind, ToolRef, Value};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if !to.has(Capability::CompWithoutRegister) {
        return;
    }
    off_onto_next_move(p);
    let changes = p
        .blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .any(|s| matches!(s.kind, StmtKind::ToolChange));
    // The tool last selected, and the one the last change loaded.
    let mut selected: Option<f64> = None;
    let mut spindle: Option<f64> = None;
    for b in &mut p.blocks {
        for s in &b.stmts {
            if let StmtKind::ToolSelect(t) = &s.kind {
                selected = match t {
                    ToolRef::Number(Value::Number(n)) => Some(n.to_f64()),
                    _ => None,
                };
            }
        }
        if b.stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ToolChange))
        {
            spindle = selected;
        }
        // A program that changes tools: the tool in the spindle (a `T14`
        // after `T4 M6` only makes the next one ready); one that never
        // does: the tool last selected.
        let tool = if changes { spindle } else { selected };
        for s in &mut b.stmts {
            if let StmtKind::RadiusComp {
                register,
                diameter: false,
                ..
            } = &mut s.kind
            {
                let own = match register {
                    Some(Value::Number(d)) => Some(d.to_f64()) == tool,
                    Some(Value::Expr(_)) => false,
                    None => true,
                };
                if own {
                    *register = None;
                }
            }
        }
    }
}

/// A block with `G40` (or `G41`/`G42`) and no move gives it to the next
/// block with a move (and no compensation of its own), before any other
/// compensation: `L X+2 Y+3 RL`, not an empty `L RL` (which a port back
/// to LinuxCNC would write as a bare `G1 G41`, a zero-length entry).
fn off_onto_next_move(p: &mut Program) {
    let n = p.blocks.len();
    for i in 0..n {
        let comp = |k: &StmtKind| matches!(k, StmtKind::RadiusComp { .. });
        let moves = |k: &StmtKind| matches!(k, StmtKind::Motion(_));
        let b = &p.blocks[i];
        let Some(at) = b.stmts.iter().position(|s| comp(&s.kind)) else {
            continue;
        };
        if b.stmts.iter().any(|s| moves(&s.kind)) {
            continue;
        }
        let target = (i + 1..n).find(|&j| {
            p.blocks[j]
                .stmts
                .iter()
                .any(|s| comp(&s.kind) || moves(&s.kind))
        });
        if let Some(j) = target {
            if !p.blocks[j].stmts.iter().any(|s| comp(&s.kind)) {
                let s = p.blocks[i].stmts.remove(at);
                p.blocks[j].stmts.push(s);
            }
        }
    }
    p.blocks
        .retain(|b| !b.stmts.is_empty() || b.number.is_some() || b.label.is_some());
}
