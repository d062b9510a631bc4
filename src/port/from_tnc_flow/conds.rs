//! Conditions of Klartext jumps for structured targets: a run of jumps to
//! the same label (how a Klartext program, or our port to Klartext, writes
//! `a LE b` or an AND) becomes one jump on the OR of their conditions, and
//! a condition is negated operator by operator (LinuxCNC has no NOT).

use crate::ir::{BinaryOp, Expr, ExprId, ExprKind, JumpTarget, Program, StmtKind, UnaryOp};

/// The label and condition of a block that is one conditional jump.
fn lone_jump(b: &crate::ir::Block) -> Option<(String, ExprId)> {
    match b.stmts.as_slice() {
        [s] => match &s.kind {
            StmtKind::Goto {
                target: JumpTarget::Label(l),
                cond: Some(c),
                ..
            } => Some((l.to_ascii_uppercase(), *c)),
            _ => None,
        },
        _ => None,
    }
}

/// Consecutive conditional jumps to one label (no label between them) as
/// one jump on the OR of their conditions.
pub(super) fn merge_runs(p: &mut Program) {
    let blocks = std::mem::take(&mut p.blocks);
    let mut out: Vec<crate::ir::Block> = Vec::with_capacity(blocks.len());
    for b in blocks {
        let prev = out.last().and_then(lone_jump);
        if let (Some((l0, c0)), Some((l1, c1)), None) = (prev, lone_jump(&b), &b.label) {
            if l0 == l1 {
                let span = p.exprs[c0].span;
                let or = p.exprs.alloc(Expr {
                    kind: ExprKind::Binary(BinaryOp::Or, c0, c1),
                    span,
                });
                if let Some(StmtKind::Goto { cond, .. }) = out
                    .last_mut()
                    .and_then(|x| x.stmts.first_mut())
                    .map(|s| &mut s.kind)
                {
                    *cond = Some(or);
                }
                continue;
            }
        }
        out.push(b);
    }
    p.blocks = out;
}

/// `c` negated: comparisons flipped, AND and OR exchanged.
pub(super) fn negate(p: &mut Program, c: ExprId) -> ExprId {
    let span = p.exprs[c].span;
    let kind = match p.exprs[c].kind {
        ExprKind::Binary(op, a, b) => match op {
            BinaryOp::Eq => ExprKind::Binary(BinaryOp::Ne, a, b),
            BinaryOp::Ne => ExprKind::Binary(BinaryOp::Eq, a, b),
            BinaryOp::Lt => ExprKind::Binary(BinaryOp::Ge, a, b),
            BinaryOp::Ge => ExprKind::Binary(BinaryOp::Lt, a, b),
            BinaryOp::Gt => ExprKind::Binary(BinaryOp::Le, a, b),
            BinaryOp::Le => ExprKind::Binary(BinaryOp::Gt, a, b),
            BinaryOp::Or | BinaryOp::And => {
                let (na, nb) = (negate(p, a), negate(p, b));
                let flip = if op == BinaryOp::Or {
                    BinaryOp::And
                } else {
                    BinaryOp::Or
                };
                ExprKind::Binary(flip, na, nb)
            }
            _ => ExprKind::Unary(UnaryOp::Not, c),
        },
        _ => ExprKind::Unary(UnaryOp::Not, c),
    };
    p.exprs.alloc(Expr { kind, span })
}
