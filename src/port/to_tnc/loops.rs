//! Opening and closing the loops and conditionals of [`super::flow`]: the
//! labels at their top and end, the jumps back, BREAK/CONTINUE targets.

use super::flow::{Flow, LoopEnd, Open};
use crate::ir::{BinaryOp, Decimal, ExprId, ExprKind, Var};
use crate::span::Span;

impl Flow<'_> {
    pub(super) fn open_loop(&mut self, top: String, end: Option<String>, at_end: LoopEnd) {
        self.stack.push(Open::Loop {
            top,
            end,
            cont: None,
            at_end,
        });
    }

    /// `LBL top` and a loop that tests at its end (or never).
    pub(super) fn top_loop(&mut self, at_end: LoopEnd, span: Span) {
        let top = self.labels.fresh();
        self.label(top.clone(), span);
        self.open_loop(top, None, at_end);
    }

    /// The end of the innermost loop: `cond` for a loop that tests there.
    pub(super) fn close_loop(&mut self, cond: Option<ExprId>, span: Span) {
        let Some(Open::Loop {
            top,
            end,
            cont,
            at_end,
        }) = self.stack.pop()
        else {
            return;
        };
        if let Some(c) = cont {
            self.label(c, span);
        }
        match at_end {
            LoopEnd::Forever => self.goto(None, &top, span),
            LoopEnd::Test {
                cond: own,
                until,
                step,
            } => {
                if let Some((v, e)) = step {
                    self.assign(v, e, span);
                }
                if let Some(c) = own.or(cond) {
                    self.jump_if(c, until, &top, span);
                }
            }
        }
        if let Some(e) = end {
            self.label(e, span);
        }
    }

    /// Where BREAK (`next`: CONTINUE) of the innermost loop jumps.
    pub(super) fn loop_label(&mut self, next: bool) -> Option<String> {
        let labels = &mut self.labels;
        self.stack.iter_mut().rev().find_map(|o| match o {
            Open::If { .. } => None,
            Open::Loop {
                top,
                end,
                cont,
                at_end,
            } => Some(match (next, at_end) {
                (true, LoopEnd::Forever) => top.clone(),
                (true, _) => cont.get_or_insert_with(|| labels.fresh()).clone(),
                (false, _) => end.get_or_insert_with(|| labels.fresh()).clone(),
            }),
        })
    }

    /// A loop entered only when `cond` holds, tested again at its end
    /// (after `step`).
    pub(super) fn guarded_loop(&mut self, cond: ExprId, step: Option<(Var, ExprId)>, span: Span) {
        let (top, end) = (self.labels.fresh(), self.labels.fresh());
        self.jump_if(cond, true, &end, span);
        self.label(top.clone(), span);
        let at_end = LoopEnd::Test {
            cond: Some(cond),
            until: false,
            step,
        };
        self.open_loop(top, Some(end), at_end);
    }

    /// `FOR v=a TO b`: `v = a`, the bound kept when it is computed, and a
    /// WHILE `v <= b` with `v = v + 1` at its end.
    pub(super) fn for_loop(&mut self, var: Var, from: ExprId, to: ExprId, span: Span) {
        self.assign(var.clone(), from, span);
        let bound = if matches!(self.p.exprs[to].kind, ExprKind::Number(_)) {
            to
        } else {
            let b = self.alloc.scratch();
            self.assign(b.clone(), to, span);
            self.expr(ExprKind::Var(b), span)
        };
        let v = self.expr(ExprKind::Var(var.clone()), span);
        let test = self.expr(ExprKind::Binary(BinaryOp::Le, v, bound), span);
        let one = self.expr(ExprKind::Number(Decimal::from_int(1)), span);
        let step = self.expr(ExprKind::Binary(BinaryOp::Add, v, one), span);
        self.guarded_loop(test, Some((var, step)), span);
    }

    /// The end of an IF branch: a jump to the structure's end and the label
    /// of the next branch. False when no IF is open.
    pub(super) fn branch_end(&mut self, span: Span) -> bool {
        let Some(Open::If { next, end }) = self.stack.last_mut() else {
            return false;
        };
        let next = next.take();
        let end = end.get_or_insert_with(|| self.labels.fresh()).clone();
        self.goto(None, &end, span);
        if let Some(n) = next {
            self.label(n, span);
        }
        true
    }

    pub(super) fn set_next(&mut self, label: Option<String>) {
        if let Some(Open::If { next, .. }) = self.stack.last_mut() {
            *next = label;
        }
    }
}
