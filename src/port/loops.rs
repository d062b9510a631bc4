//! Siemens `FOR v=a TO b` ... `ENDFOR` for a target without FOR: `v=a`,
//! a WHILE loop on `v LE b` (in the target's form, see
//! [`super::flow_ids`]) and `v=v+1` before its end. The bound `b` is
//! evaluated on every pass where FOR evaluates it once: a bound the loop
//! itself changes would run differently (W0610).

use super::follow_block;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{BinaryOp, Decimal, Expr, ExprId, ExprKind, FlowId, Program, Stmt, StmtKind, Var};
use crate::span::Span;

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::StructuredControl) {
        return;
    }
    let mut open: Vec<Var> = Vec::new();
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut cur = Vec::new();
        let mut after = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::For {
                    var,
                    from,
                    to: bound,
                } => {
                    if !matches!(p.exprs[bound].kind, ExprKind::Number(_)) {
                        diags.push(Diagnostic::new(Code::PortApproximate, "the FOR bound is evaluated on every pass of the WHILE loop it becomes")
                            .primary(span, "an expression bound").help("make sure the loop does not change it"));
                    }
                    let v = var_expr(p, &var, span);
                    let cond = binary(p, BinaryOp::Le, v, bound, span);
                    cur.push(Stmt::new(
                        StmtKind::Assign {
                            var: var.clone(),
                            value: from,
                        },
                        span,
                    ));
                    after.push(follow_block(
                        &b,
                        vec![Stmt::new(
                            StmtKind::While {
                                cond,
                                id: FlowId::Nested,
                            },
                            span,
                        )],
                    ));
                    open.push(var);
                }
                StmtKind::EndFor => {
                    let Some(var) = open.pop() else {
                        cur.push(Stmt::new(StmtKind::EndFor, span));
                        continue;
                    };
                    let v = var_expr(p, &var, span);
                    let one = p.exprs.alloc(Expr {
                        kind: ExprKind::Number(Decimal::from_int(1)),
                        span,
                    });
                    let value = binary(p, BinaryOp::Add, v, one, span);
                    cur.push(Stmt::new(StmtKind::Assign { var, value }, span));
                    after.push(follow_block(
                        &b,
                        vec![Stmt::new(StmtKind::EndWhile { id: FlowId::Nested }, span)],
                    ));
                }
                kind => cur.push(Stmt::new(kind, span)),
            }
        }
        b.stmts = cur;
        p.blocks.push(b);
        p.blocks.extend(after);
    }
}

fn var_expr(p: &mut Program, v: &Var, span: Span) -> ExprId {
    p.exprs.alloc(Expr {
        kind: ExprKind::Var(v.clone()),
        span,
    })
}

fn binary(p: &mut Program, op: BinaryOp, a: ExprId, b: ExprId, span: Span) -> ExprId {
    p.exprs.alloc(Expr {
        kind: ExprKind::Binary(op, a, b),
        span,
    })
}
