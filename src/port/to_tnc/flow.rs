//! Variables, loops and conditionals of a word-address or Sinumerik
//! program in Klartext's forms: Q parameters ([`super::vars`]) and labels
//! with the conditional jumps `FN 9..12` ([`super::jumps`]).
//!
//! * `WHILE c` → a jump past the loop when c fails, `LBL top`, the body,
//!   and at the end a jump back to `LBL top` while c holds (one jump per
//!   pass: `FN 12: IF +Q1 LT +3 GOTO LBL 1`).
//! * `FOR v=a TO b` → `v = a` (and the bound in a `QL` when it is not a
//!   number: FOR evaluates it once), then as WHILE `v <= b` with
//!   `v = v + 1` before the test at the end.
//! * LinuxCNC `repeat [n]` → a `QL` counter, as WHILE counter > 0, counted
//!   down at the top; `do` ... `while [c]` and Siemens `REPEAT` ...
//!   `UNTIL c` → `LBL top` and a jump back at the end; `LOOP` → an
//!   unconditional one.
//! * `IF c` / `ELSE IF` / `ELSE` / `ENDIF` → jumps around the branches;
//!   Fanuc `IF [c] THEN stmt` → a jump around the statement.
//! * `BREAK`/`CONTINUE` → jumps to the loop's end or its next pass.
//! * `GOTO` to a label or sequence number ([`super::labels`]) → the same
//!   jump to a `LBL`; Siemens `CASE` → one `EQU` jump per value.
//!
//! Each jump and label is a block of its own, with the span of the
//! statement it comes from.

use super::labels::{sequence_jumps, Labels};
use super::vars::Alloc;
use crate::diag::Diagnostic;
use crate::ir::{BinaryOp, Block, Decimal, ExprId, ExprKind, Program, Stmt, StmtKind as K, Var};
use crate::span::{Span, Spanned};

/// How an open loop ends.
pub(super) enum LoopEnd {
    /// Jump back to the top (LOOP).
    Forever,
    /// After `step`, jump back while (`until`: until) the condition holds:
    /// `cond`, or the closing statement's (DO ... WHILE, REPEAT ... UNTIL).
    Test {
        cond: Option<ExprId>,
        until: bool,
        step: Option<(Var, ExprId)>,
    },
}

pub(super) enum Open {
    If {
        next: Option<String>,
        end: Option<String>,
    },
    Loop {
        top: String,
        end: Option<String>,
        /// Where CONTINUE goes when it is not the top.
        cont: Option<String>,
        at_end: LoopEnd,
    },
}

pub(super) struct Flow<'a> {
    pub p: &'a mut Program,
    pub labels: Labels,
    pub diags: &'a mut Vec<Diagnostic>,
    pub alloc: &'a mut Alloc,
    out: Vec<Block>,
    pub stack: Vec<Open>,
    /// The block being split (skip level, and its number and label until
    /// the first piece is written).
    like: Block,
}

/// Runs the variable and control-flow mapping on `p`.
pub(super) fn run(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    let mut alloc = Alloc::default();
    super::vars::run(p, &mut alloc, diags);
    let mut labels = Labels::of(p);
    sequence_jumps(p, &mut labels, diags);
    let blocks = std::mem::take(&mut p.blocks);
    let empty = Block {
        span: Span::default(),
        skip: None,
        number: None,
        label: None,
        stmts: Vec::new(),
    };
    let mut f = Flow {
        p,
        labels,
        diags,
        alloc: &mut alloc,
        out: Vec::with_capacity(blocks.len()),
        stack: Vec::new(),
        like: empty,
    };
    for mut b in blocks {
        let stmts = std::mem::take(&mut b.stmts);
        f.like = b;
        let mut cur = Vec::new();
        for s in stmts {
            f.stmt(s, &mut cur);
        }
        f.flush(&mut cur);
    }
    f.p.blocks = std::mem::take(&mut f.out);
}

impl Flow<'_> {
    /// Writes the statements gathered so far as a block (the source
    /// block's number and label go with the first piece).
    fn flush(&mut self, cur: &mut Vec<Stmt>) {
        let label = self.like.label.take();
        if cur.is_empty() && label.is_none() {
            return;
        }
        self.out.push(Block {
            span: self.like.span,
            skip: self.like.skip.clone(),
            number: self.like.number.take(),
            label,
            stmts: std::mem::take(cur),
        });
    }

    /// A block of `stmts` made for the statement at `span`.
    pub(super) fn emit(&mut self, stmts: Vec<Stmt>, span: Span) {
        self.out.push(Block {
            span,
            skip: self.like.skip.clone(),
            number: None,
            label: None,
            stmts,
        });
    }

    pub(super) fn label(&mut self, name: String, span: Span) {
        self.out.push(Block {
            span,
            skip: None,
            number: None,
            label: Some(Box::new(Spanned { node: name, span })),
            stmts: Vec::new(),
        });
    }

    pub(super) fn assign(&mut self, var: Var, value: ExprId, span: Span) {
        self.emit(vec![Stmt::new(K::Assign { var, value }, span)], span);
    }

    fn stmt(&mut self, s: Stmt, cur: &mut Vec<Stmt>) {
        let span = s.span;
        if is_flow(&s.kind) {
            self.flush(cur);
        }
        match s.kind {
            K::Goto {
                target: crate::ir::JumpTarget::Label(l),
                cond,
                ..
            } => match cond {
                Some(c) => self.jump_if(c, false, &l, span),
                None => self.goto(None, &l, span),
            },
            K::IfThen { cond, then } => {
                let skip = self.labels.fresh();
                self.jump_if(cond, true, &skip, span);
                let mut inner = Vec::new();
                self.stmt(*then, &mut inner);
                if !inner.is_empty() {
                    self.emit(inner, span);
                }
                self.label(skip, span);
            }
            K::If { cond, .. } => {
                let next = self.labels.fresh();
                self.jump_if(cond, true, &next, span);
                self.stack.push(Open::If {
                    next: Some(next),
                    end: None,
                });
            }
            K::ElseIf { cond, .. } => {
                if self.branch_end(span) {
                    let next = self.labels.fresh();
                    self.jump_if(cond, true, &next, span);
                    self.set_next(Some(next));
                }
            }
            K::Else { .. } => {
                self.branch_end(span);
                self.set_next(None);
            }
            K::EndIf { .. } => {
                if let Some(Open::If { next, end }) = self.stack.pop() {
                    for l in next.into_iter().chain(end) {
                        self.label(l, span);
                    }
                }
            }
            K::While { cond, .. } => self.guarded_loop(cond, None, span),
            K::For { var, from, to } => self.for_loop(var, from, to, span),
            K::Repeat { count, .. } => {
                // A counter tested before the loop and at its end, counted
                // down at its top.
                let n = self.alloc.scratch();
                self.assign(n.clone(), count, span);
                let v = self.expr(ExprKind::Var(n.clone()), span);
                let zero = self.expr(ExprKind::Number(Decimal::from_int(0)), span);
                let test = self.expr(ExprKind::Binary(BinaryOp::Gt, v, zero), span);
                self.guarded_loop(test, None, span);
                let one = self.expr(ExprKind::Number(Decimal::from_int(1)), span);
                let down = self.expr(ExprKind::Binary(BinaryOp::Sub, v, one), span);
                self.assign(n, down, span);
            }
            K::Loop => self.top_loop(LoopEnd::Forever, span),
            K::Do { .. } => self.top_loop(test_at_end(false), span),
            K::RepeatUntil => self.top_loop(test_at_end(true), span),
            K::EndWhile { .. } | K::EndRepeat { .. } | K::EndFor | K::EndLoop => {
                self.close_loop(None, span)
            }
            K::DoWhile { cond, .. } | K::Until { cond } => self.close_loop(Some(cond), span),
            K::Break { .. } => {
                if let Some(l) = self.loop_label(false) {
                    self.goto(None, &l, span);
                }
            }
            K::Continue { .. } => {
                if let Some(l) = self.loop_label(true) {
                    self.goto(None, &l, span);
                }
            }
            K::Case {
                selector,
                arms,
                default,
            } => {
                for arm in arms {
                    let c = self.expr(ExprKind::Binary(BinaryOp::Eq, selector, arm.value), span);
                    self.jump_if(c, false, &arm.target, span);
                }
                if let Some((l, _)) = default {
                    self.goto(None, &l, span);
                }
            }
            kind => cur.push(Stmt::new(kind, span)),
        }
    }
}

/// A loop tested by its closing statement.
fn test_at_end(until: bool) -> LoopEnd {
    LoopEnd::Test {
        cond: None,
        until,
        step: None,
    }
}

/// The statements this pass turns into labels and jumps.
fn is_flow(k: &K) -> bool {
    matches!(
        k,
        K::Goto {
            target: crate::ir::JumpTarget::Label(_),
            ..
        } | K::IfThen { .. }
            | K::If { .. }
            | K::ElseIf { .. }
            | K::Else { .. }
            | K::EndIf { .. }
            | K::While { .. }
            | K::EndWhile { .. }
            | K::For { .. }
            | K::EndFor
            | K::Repeat { .. }
            | K::EndRepeat { .. }
            | K::Loop
            | K::EndLoop
            | K::Do { .. }
            | K::DoWhile { .. }
            | K::RepeatUntil
            | K::Until { .. }
            | K::Break { .. }
            | K::Continue { .. }
            | K::Case { .. }
    )
}
