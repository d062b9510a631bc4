//! Siemens `CASE (e) OF 1 GOTOF A 2 GOTOF B DEFAULT GOTOF C` for a target
//! without structured control (capability `structured-control`) and with
//! Macro B jumps but no o-words (Fanuc, Haas): a chain
//! of conditional jumps, `IF e == 1 GOTOF A`, `IF e == 2 GOTOF B`, then
//! `GOTOF C` (exact: the first arm that matches wins in both, and the
//! selector has no side effects). The jumps to labels then take the
//! target's form ([`super::forms`]: sequence numbers for Fanuc, ...).
//! Klartext targets get theirs earlier ([`super::to_tnc`]).

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{BinaryOp, Expr, ExprKind, JumpTarget, Program, Stmt, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    // Jumps need Macro B's `IF [..] GOTO n`; rs274ngc (o-words) has no
    // GOTO, and its forward jumps would have to become o-word ifs.
    if to.has(Capability::StructuredControl)
        || !to.has(Capability::MacroB)
        || to.has(Capability::OWords)
    {
        return;
    }
    let blocks = std::mem::take(&mut p.blocks);
    let mut done = Vec::with_capacity(blocks.len());
    for mut b in blocks {
        if !b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::Case { .. }))
        {
            done.push(b);
            continue;
        }
        let stmts = std::mem::take(&mut b.stmts);
        // The jumps after the first go in blocks of their own (one
        // conditional jump per block: Fanuc `IF [..] GOTO n`).
        let mut out = Vec::with_capacity(stmts.len());
        for s in stmts {
            let StmtKind::Case {
                selector,
                arms,
                default,
            } = s.kind
            else {
                out.push(s);
                continue;
            };
            for arm in arms {
                let sel = super::funcs::copy_expr(p, to, selector);
                let cond = p.exprs.alloc(Expr {
                    kind: ExprKind::Binary(BinaryOp::Eq, sel, arm.value),
                    span: s.span,
                });
                out.push(Stmt::new(
                    StmtKind::Goto {
                        target: JumpTarget::Label(arm.target),
                        dir: arm.dir,
                        cond: Some(cond),
                    },
                    s.span,
                ));
            }
            if let Some((label, dir)) = default {
                out.push(Stmt::new(
                    StmtKind::Goto {
                        target: JumpTarget::Label(label),
                        dir,
                        cond: None,
                    },
                    s.span,
                ));
            }
        }
        let mut jumps = out.into_iter();
        let mut first: Vec<Stmt> = Vec::new();
        let mut rest: Vec<Stmt> = Vec::new();
        for s in jumps.by_ref() {
            let jump = matches!(s.kind, StmtKind::Goto { .. });
            if jump
                && first
                    .iter()
                    .any(|f| matches!(f.kind, StmtKind::Goto { .. }))
            {
                rest.push(s);
            } else {
                first.push(s);
            }
        }
        let follow: Vec<_> = rest
            .into_iter()
            .map(|s| crate::port::follow_block(&b, vec![s]))
            .collect();
        b.stmts = first;
        done.push(b);
        done.extend(follow);
    }
    p.blocks = done;
}
