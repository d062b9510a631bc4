//! A condition as Klartext conditional jumps. `FN 9..12` jump when two
//! values are equal (EQU), not equal (NE), greater (GT) or less (LT); the
//! other comparisons and their negations take two jumps (`a LE b`: LT,
//! then EQU), `AND`/`OR`/`NOT` become sequences of jumps with a label to
//! skip to, and a plain value counts as true when it is not 0 (LinuxCNC
//! `o1 if [#1]`). An operand that is a formula is computed into a `QL`
//! parameter just before the jump. Bitwise operators and strings have no
//! form: E0622.

use super::flow::Flow;
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    BinaryOp, Decimal, Expr, ExprId, ExprKind, JumpDir, JumpTarget, StmtKind, UnaryOp,
};
use crate::span::Span;

/// The FN comparisons that together make `op` true (or false: `neg`).
fn fn_ops(op: BinaryOp, neg: bool) -> &'static [BinaryOp] {
    use BinaryOp::*;
    match (op, neg) {
        (Eq, false) | (Ne, true) => &[Eq],
        (Ne, false) | (Eq, true) => &[Ne],
        (Lt, false) | (Ge, true) => &[Lt],
        (Gt, false) | (Le, true) => &[Gt],
        (Le, false) | (Gt, true) => &[Lt, Eq],
        (Ge, false) | (Lt, true) => &[Gt, Eq],
        _ => &[],
    }
}

/// Whether `e` is a condition (a comparison or a logical combination of
/// them) rather than a value.
fn is_condition(exprs: &crate::ir::Arena<Expr>, e: ExprId) -> bool {
    match &exprs[e].kind {
        ExprKind::Binary(op, a, b) => {
            op.is_comparison()
                || (matches!(op, BinaryOp::And | BinaryOp::Or)
                    && is_condition(exprs, *a)
                    && is_condition(exprs, *b))
        }
        ExprKind::Unary(UnaryOp::Not, a) => is_condition(exprs, *a),
        ExprKind::Bool(_) => true,
        _ => false,
    }
}

impl Flow<'_> {
    /// Jumps to `target` when `cond` holds (`neg`: when it does not).
    pub(super) fn jump_if(&mut self, cond: ExprId, neg: bool, target: &str, span: Span) {
        let kind = self.p.exprs[cond].kind.clone();
        match kind {
            ExprKind::Binary(op, a, b) if op.is_comparison() => {
                let (a, b) = (self.operand(a, span), self.operand(b, span));
                for &o in fn_ops(op, neg) {
                    let c = self.expr(ExprKind::Binary(o, a, b), span);
                    self.goto(Some(c), target, span);
                }
            }
            ExprKind::Binary(op @ (BinaryOp::And | BinaryOp::Or), a, b)
                if is_condition(&self.p.exprs, cond) =>
            {
                // AND jumps when both hold; NOT (a OR b) when both fail.
                if (op == BinaryOp::And) != neg {
                    let skip = self.labels.fresh();
                    self.jump_if(a, !neg, &skip, span);
                    self.jump_if(b, neg, target, span);
                    self.label(skip, span);
                } else {
                    self.jump_if(a, neg, target, span);
                    self.jump_if(b, neg, target, span);
                }
            }
            ExprKind::Unary(UnaryOp::Not, a) if is_condition(&self.p.exprs, a) => {
                self.jump_if(a, !neg, target, span)
            }
            ExprKind::Bool(v) => {
                if v != neg {
                    self.goto(None, target, span);
                }
            }
            ExprKind::Number(d) => {
                if (d.to_f64() != 0.0) != neg {
                    self.goto(None, target, span);
                }
            }
            ExprKind::Var(_)
            | ExprKind::Call(..)
            | ExprKind::Unary(UnaryOp::Neg | UnaryOp::Plus, _)
            | ExprKind::Binary(
                BinaryOp::Add | BinaryOp::Sub | BinaryOp::Mul | BinaryOp::Div | BinaryOp::Pow,
                ..,
            ) => {
                let cond = self.operand(cond, span);
                let zero = self.expr(ExprKind::Number(Decimal::from_int(0)), span);
                for &o in fn_ops(BinaryOp::Ne, neg) {
                    let c = self.expr(ExprKind::Binary(o, cond, zero), span);
                    self.goto(Some(c), target, span);
                }
            }
            ExprKind::Str(_)
            | ExprKind::Exists(_)
            | ExprKind::ExistsNumbered(_)
            | ExprKind::Query(..)
            | ExprKind::AtanSlash(..)
            | ExprKind::Dimension(..)
            | ExprKind::Unary(UnaryOp::Not | UnaryOp::BitNot, _)
            | ExprKind::Binary(..) => {
                let at = self.p.exprs[cond].span;
                self.diags.push(
                    Diagnostic::new(
                        Code::PortJump,
                        "Klartext jumps (FN 9..12) cannot test this condition",
                    )
                    .primary(at, "this condition")
                    .help("write it with comparisons joined by AND, OR, NOT"),
                );
            }
        }
    }

    /// An operand an FN jump takes as it is (a number, a parameter, either
    /// negated), or a local parameter computed just before the jump: the
    /// TNC manuals show FN operands as signed numbers and parameters only,
    /// a formula in parentheses there is accepted by newer controls [?].
    fn operand(&mut self, e: ExprId, span: Span) -> ExprId {
        let simple = |k: &ExprKind| matches!(k, ExprKind::Number(_) | ExprKind::Var(_));
        let kind = &self.p.exprs[e].kind;
        let plain = simple(kind)
            || matches!(kind, ExprKind::Unary(UnaryOp::Neg | UnaryOp::Plus, x)
                if simple(&self.p.exprs[*x].kind));
        if plain {
            return e;
        }
        let q = self.alloc.scratch();
        self.assign(q.clone(), e, span);
        self.expr(ExprKind::Var(q), span)
    }

    /// `FN 9..12: IF .. GOTO LBL target`, or the unconditional form.
    pub(super) fn goto(&mut self, cond: Option<ExprId>, target: &str, span: Span) {
        let k = StmtKind::Goto {
            target: JumpTarget::Label(target.to_string()),
            dir: JumpDir::Either,
            cond,
        };
        self.emit(vec![crate::ir::Stmt::new(k, span)], span);
    }

    pub(super) fn expr(&mut self, kind: ExprKind, span: Span) -> ExprId {
        self.p.exprs.alloc(Expr { kind, span })
    }
}
