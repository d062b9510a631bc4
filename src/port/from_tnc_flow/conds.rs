//! Conditions of Klartext jumps for structured targets: a run of jumps to
//! the same label (how a Klartext program, or our port to Klartext, writes
//! `a LE b` or an AND) becomes one jump on the OR of their conditions, a
//! jump over a jump (an OR) one jump on an AND, and a condition is negated
//! operator by operator (LinuxCNC has no NOT).

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

/// The label and condition (None: always) of a block that is one jump.
fn any_jump(b: &crate::ir::Block) -> Option<(String, Option<ExprId>)> {
    match b.stmts.as_slice() {
        [s] => match &s.kind {
            StmtKind::Goto {
                target: JumpTarget::Label(l),
                cond,
                ..
            } => Some((l.to_ascii_uppercase(), *cond)),
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

/// `FN ..: IF a GOTO LBL s`, `FN ..: IF c GOTO LBL n`, `LBL s` (how an OR
/// is written with jumps) as one jump on `NOT a AND c` to `n` (`NOT a`
/// when the second jump always jumps), when no other jump goes to `s`.
/// Returns whether it merged any.
pub(super) fn merge_skips(p: &mut Program) -> bool {
    let mut count: std::collections::HashMap<String, usize> = Default::default();
    for s in p.blocks.iter().flat_map(|b| b.stmts.iter()) {
        if let StmtKind::Goto {
            target: JumpTarget::Label(l),
            ..
        } = &s.kind
        {
            *count.entry(l.to_ascii_uppercase()).or_default() += 1;
        }
    }
    let mut drop = vec![false; p.blocks.len()];
    let mut i = 0;
    while i + 2 < p.blocks.len() {
        let (first, second) = (lone_jump(&p.blocks[i]), any_jump(&p.blocks[i + 1]));
        let skip_to = p.blocks[i + 2]
            .label
            .as_ref()
            .map(|l| l.node.to_ascii_uppercase());
        if let (Some((l1, c1)), Some((l2, c2)), None, Some(s)) =
            (first, second, &p.blocks[i + 1].label, skip_to)
        {
            if l1 == s && l1 != l2 && count.get(&l1) == Some(&1) && !drop[i] {
                let not_a = negate(p, c1);
                let and = match c2 {
                    Some(c2) => p.exprs.alloc(Expr {
                        kind: ExprKind::Binary(BinaryOp::And, not_a, c2),
                        span: p.exprs[c2].span,
                    }),
                    None => not_a,
                };
                if let Some(StmtKind::Goto { cond, .. }) =
                    p.blocks[i + 1].stmts.first_mut().map(|s| &mut s.kind)
                {
                    *cond = Some(and);
                }
                drop[i] = true;
                i += 2;
                continue;
            }
        }
        i += 1;
    }
    let merged = drop.contains(&true);
    let mut k = 0;
    p.blocks.retain(|_| {
        k += 1;
        !drop[k - 1]
    });
    merged
}

/// Blocks that are only a label no jump goes to and nothing calls.
pub(super) fn drop_unused_labels(p: &mut Program, called: &std::collections::HashSet<String>) {
    let mut used: std::collections::HashSet<String> = called.clone();
    for s in p.blocks.iter().flat_map(|b| b.stmts.iter()) {
        if let StmtKind::Goto {
            target: JumpTarget::Label(l),
            ..
        } = &s.kind
        {
            used.insert(l.to_ascii_uppercase());
        }
    }
    p.blocks.retain(|b| {
        !(b.stmts.is_empty()
            && b.number.is_none()
            && b.label
                .as_ref()
                .is_some_and(|l| !used.contains(&l.node.to_ascii_uppercase())))
    });
}
