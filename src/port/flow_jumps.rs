//! Structured conditionals (Siemens `IF`/`ELSE`/`ENDIF`, LinuxCNC `o100
//! if`/`elseif`/`else`/`endif`) for a target whose only conditional is a
//! jump (Macro B `IF [c] GOTO n`; capability `macro-b` without
//! `structured-control` or `o-words`: Fanuc, Haas):
//!
//! ```text
//! IF c          IF [NOT c] GOTO else      (the negation written exactly)
//!   a             a
//! ELSE          GOTO end
//!   b           else: b
//! ENDIF         end:
//! ```
//!
//! `ELSEIF c2` closes the branch before it the same way and opens its own
//! jump. Loops that test at their end have no Macro B form either (its
//! `WHILE` tests first), so they become a backward jump:
//!
//! ```text
//! o10 do            top:
//!   a                 a
//! o10 while [c]     IF [c] GOTO top
//! REPEAT .. UNTIL c   (the same, on NOT c)
//! LOOP .. ENDLOOP     (the same, unconditional)
//! ```
//!
//! A `break` of such a loop jumps past its end, a `continue` to its test.
//! The labels get sequence numbers in the target's form
//! ([`super::forms`]). The negation is exact: a comparison becomes its
//! opposite (`EQ` ↔ `NE`, `GT` ↔ `LE`, `LT` ↔ `GE`), `AND`/`OR` swap by De
//! Morgan's laws, `NOT x` is `x`, and any other value `v` is `v EQ 0`
//! (the control takes a nonzero value as true).

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{
    BinaryOp, Block, Decimal, Expr, ExprId, ExprKind, FlowId, JumpDir, JumpTarget, Program, Stmt,
    StmtKind, UnaryOp,
};
use crate::span::{Span, Spanned};

/// One open conditional: where a false condition jumps, and where the
/// end of a taken branch jumps.
struct Open {
    next: Option<String>,
    end: String,
    end_used: bool,
}

/// One open loop: for a loop that becomes jumps, its labels.
struct OpenLoop {
    id: Option<FlowId>,
    jumps: Option<LoopLabels>,
}

struct LoopLabels {
    top: String,
    test: String,
    end: String,
    test_used: bool,
    end_used: bool,
}

struct Lowering {
    out: Vec<Block>,
    open: Vec<Open>,
    loops: Vec<OpenLoop>,
    count: u32,
}

pub fn run(p: &mut Program, to: &DialectSpec) {
    if to.has(Capability::StructuredControl)
        || !to.has(Capability::MacroB)
        || to.has(Capability::OWords)
        || !p
            .blocks
            .iter()
            .flat_map(|b| &b.stmts)
            .any(|s| is_if(&s.kind) || is_end_tested(&s.kind))
    {
        return;
    }
    let mut low = Lowering {
        out: Vec::with_capacity(p.blocks.len()),
        open: Vec::new(),
        loops: Vec::new(),
        count: 0,
    };
    for b in std::mem::take(&mut p.blocks) {
        low.block(p, b);
    }
    p.blocks = low.out;
}

fn is_if(k: &StmtKind) -> bool {
    matches!(
        k,
        StmtKind::If { .. }
            | StmtKind::ElseIf { .. }
            | StmtKind::Else { .. }
            | StmtKind::EndIf { .. }
    )
}

/// The openers of loops that test at their end (or never).
fn is_end_tested(k: &StmtKind) -> bool {
    matches!(
        k,
        StmtKind::Do { .. } | StmtKind::RepeatUntil | StmtKind::Loop
    )
}

/// The statements this pass rewrites or must see (loop nesting).
fn is_flow(k: &StmtKind) -> bool {
    use StmtKind as K;
    is_if(k)
        || matches!(
            k,
            K::Do { .. }
                | K::DoWhile { .. }
                | K::RepeatUntil
                | K::Until { .. }
                | K::Loop
                | K::EndLoop
                | K::While { .. }
                | K::EndWhile { .. }
                | K::Repeat { .. }
                | K::EndRepeat { .. }
                | K::For { .. }
                | K::EndFor
                | K::Break { .. }
                | K::Continue { .. }
        )
}

impl Lowering {
    /// The block's statements, with each conditional keyword replaced by
    /// its jumps and labels; the statements around it keep their block.
    fn block(&mut self, p: &mut Program, mut b: Block) {
        if !b.stmts.iter().any(|s| is_flow(&s.kind)) {
            self.out.push(b);
            return;
        }
        let stmts = std::mem::take(&mut b.stmts);
        let mut current = b;
        for s in stmts {
            if !is_flow(&s.kind) || !self.rewrites(&s.kind) {
                self.track(&s.kind);
                current.stmts.push(s);
                continue;
            }
            let like = current.clone();
            self.flush(&mut current);
            self.keyword(p, &like, s);
        }
        self.flush(&mut current);
    }

    /// Ends the block being filled (kept if it has a statement, number or
    /// label); the next statements go into a plain block like it.
    fn flush(&mut self, current: &mut Block) {
        let next = super::follow_block(current, Vec::new());
        let done = std::mem::replace(current, next);
        if !done.stmts.is_empty() || done.number.is_some() || done.label.is_some() {
            self.out.push(done);
        }
    }

    fn keyword(&mut self, p: &mut Program, like: &Block, s: Stmt) {
        let span = s.span;
        let brk = matches!(s.kind, StmtKind::Break { .. });
        match s.kind {
            StmtKind::If { cond, .. } => {
                let next = self.new_label("E");
                let end = self.new_label("X");
                self.jump(p, like, &next, Some(cond), span);
                self.open.push(Open {
                    next: Some(next),
                    end,
                    end_used: false,
                });
            }
            StmtKind::ElseIf { cond, .. } => {
                self.close_branch(like, span);
                let next = self.new_label("E");
                self.jump(p, like, &next, Some(cond), span);
                if let Some(top) = self.open.last_mut() {
                    top.next = Some(next);
                }
            }
            StmtKind::Else { .. } => self.close_branch(like, span),
            StmtKind::EndIf { .. } => {
                let Some(top) = self.open.pop() else { return };
                if let Some(next) = top.next {
                    self.label(like, next, span);
                }
                if top.end_used {
                    self.label(like, top.end, span);
                }
            }
            StmtKind::Do { id } => self.open_loop(like, Some(id), span),
            StmtKind::RepeatUntil | StmtKind::Loop => self.open_loop(like, None, span),
            StmtKind::DoWhile { cond, .. } => self.close_loop(p, like, Some(cond), false, span),
            StmtKind::Until { cond } => self.close_loop(p, like, Some(cond), true, span),
            StmtKind::EndLoop => self.close_loop(p, like, None, false, span),
            StmtKind::Break { id } | StmtKind::Continue { id } => {
                let Some(l) = self.loop_of(&id).and_then(|l| l.jumps.as_mut()) else {
                    return;
                };
                let to = if brk {
                    l.end_used = true;
                    l.end.clone()
                } else {
                    l.test_used = true;
                    l.test.clone()
                };
                self.jump(p, like, &to, None, span);
            }
            _ => {}
        }
    }

    /// Whether the statement becomes jumps (the others are only tracked).
    fn rewrites(&mut self, k: &StmtKind) -> bool {
        match k {
            StmtKind::Break { id } | StmtKind::Continue { id } => {
                self.loop_of(id).is_some_and(|l| l.jumps.is_some())
            }
            k => is_if(k) || is_end_tested(k) || self.closes_lowered(k),
        }
    }

    fn closes_lowered(&self, k: &StmtKind) -> bool {
        matches!(
            k,
            StmtKind::DoWhile { .. } | StmtKind::Until { .. } | StmtKind::EndLoop
        ) && self.loops.last().is_some_and(|l| l.jumps.is_some())
    }

    /// Loops kept as they are still count for `break` and `continue`.
    fn track(&mut self, k: &StmtKind) {
        match k {
            StmtKind::While { id, .. } | StmtKind::Repeat { id, .. } => self.loops.push(OpenLoop {
                id: Some(id.clone()),
                jumps: None,
            }),
            StmtKind::For { .. } => self.loops.push(OpenLoop {
                id: None,
                jumps: None,
            }),
            StmtKind::EndWhile { .. } | StmtKind::EndRepeat { .. } | StmtKind::EndFor => {
                self.loops.pop();
            }
            _ => {}
        }
    }

    /// The loop a `break`/`continue` leaves: by its o-word, else the
    /// innermost.
    fn loop_of(&mut self, id: &FlowId) -> Option<&mut OpenLoop> {
        match id {
            FlowId::OWord(_) => self
                .loops
                .iter_mut()
                .rev()
                .find(|l| l.id.as_ref() == Some(id)),
            FlowId::Nested | FlowId::Do(_) => self.loops.last_mut(),
        }
    }

    fn open_loop(&mut self, like: &Block, id: Option<FlowId>, span: Span) {
        let top = self.new_label("T");
        self.label(like, top.clone(), span);
        let labels = LoopLabels {
            top,
            test: self.new_label("C"),
            end: self.new_label("B"),
            test_used: false,
            end_used: false,
        };
        self.loops.push(OpenLoop {
            id,
            jumps: Some(labels),
        });
    }

    /// The test at the loop's end: back to the top while `cond` holds
    /// (until it holds, for `UNTIL`; always, for `ENDLOOP`).
    fn close_loop(
        &mut self,
        p: &mut Program,
        like: &Block,
        cond: Option<ExprId>,
        until: bool,
        span: Span,
    ) {
        let Some(OpenLoop { jumps: Some(l), .. }) = self.loops.pop() else {
            return;
        };
        if l.test_used {
            self.label(like, l.test, span);
        }
        let cond = match cond {
            Some(c) if until => Some(negate(p, c)),
            c => c,
        };
        let goto = StmtKind::Goto {
            target: JumpTarget::Label(l.top),
            dir: JumpDir::Backward,
            cond,
        };
        self.out
            .push(super::follow_block(like, vec![Stmt::new(goto, span)]));
        if l.end_used {
            self.label(like, l.end, span);
        }
    }

    /// The branch that ran jumps to the end; the false condition's jump
    /// lands after it.
    fn close_branch(&mut self, like: &Block, span: Span) {
        let Some(top) = self.open.last_mut() else {
            return;
        };
        top.end_used = true;
        let end = top.end.clone();
        let next = top.next.take();
        let goto = StmtKind::Goto {
            target: JumpTarget::Label(end),
            dir: JumpDir::Forward,
            cond: None,
        };
        self.out
            .push(super::follow_block(like, vec![Stmt::new(goto, span)]));
        if let Some(next) = next {
            self.label(like, next, span);
        }
    }

    /// `IF [NOT cond] GOTO to` (or an unconditional jump).
    fn jump(&mut self, p: &mut Program, like: &Block, to: &str, cond: Option<ExprId>, span: Span) {
        let goto = StmtKind::Goto {
            target: JumpTarget::Label(to.to_string()),
            dir: JumpDir::Forward,
            cond: cond.map(|c| negate(p, c)),
        };
        self.out
            .push(super::follow_block(like, vec![Stmt::new(goto, span)]));
    }

    fn label(&mut self, like: &Block, name: String, span: Span) {
        let mut b = super::follow_block(like, Vec::new());
        b.label = Some(Box::new(Spanned { node: name, span }));
        self.out.push(b);
    }

    fn new_label(&mut self, what: &str) -> String {
        self.count += 1;
        format!("{}IF{}{what}", super::MADE_LABEL, self.count)
    }
}

/// `NOT e`, written without a NOT.
fn negate(p: &mut Program, e: ExprId) -> ExprId {
    let span = p.exprs[e].span;
    let kind = match p.exprs[e].kind.clone() {
        ExprKind::Binary(op, a, b) => match opposite(op) {
            Some(inv) => ExprKind::Binary(inv, a, b),
            None => match op {
                BinaryOp::And => ExprKind::Binary(BinaryOp::Or, negate(p, a), negate(p, b)),
                BinaryOp::Or => ExprKind::Binary(BinaryOp::And, negate(p, a), negate(p, b)),
                _ => is_zero(p, e, span),
            },
        },
        ExprKind::Unary(UnaryOp::Not, x) => return x,
        _ => is_zero(p, e, span),
    };
    p.exprs.alloc(Expr { kind, span })
}

fn is_zero(p: &mut Program, e: ExprId, span: Span) -> ExprKind {
    let zero = super::number_expr(p, Decimal::from_int(0), span);
    ExprKind::Binary(BinaryOp::Eq, e, zero)
}

fn opposite(op: BinaryOp) -> Option<BinaryOp> {
    use BinaryOp::*;
    Some(match op {
        Eq => Ne,
        Ne => Eq,
        Gt => Le,
        Le => Gt,
        Lt => Ge,
        Ge => Lt,
        _ => return None,
    })
}
