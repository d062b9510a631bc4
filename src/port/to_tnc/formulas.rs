//! Functions in Klartext formulas. The TNC formula has SIN COS TAN ASIN
//! ACOS ATAN SQRT SQ ABS INT LN EXP and `^`; the angle of two values is
//! `FN 13: Q = +x ANG +y`, an assignment of its own.
//!
//! * `POW(a, b)` → `a ^ b`; `ATAN[y]/[x]` as a whole assignment → FN 13.
//! * ROUND, FIX/FUP (floor, ceiling), MIN, MAX, BIN, BCD and a two-value
//!   arc tangent inside a larger formula have no counterpart: E0623, with
//!   the function and where it is.

use crate::diag::{Code, Diagnostic};
use crate::ir::{BinaryOp, ExprKind, Func, Program, StmtKind};
use std::collections::HashSet;

pub(super) fn run(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    let whole: HashSet<_> = p
        .blocks
        .iter()
        .flat_map(|b| b.stmts.iter())
        .filter_map(|s| match &s.kind {
            StmtKind::Assign { value, .. } => Some(*value),
            _ => None,
        })
        .collect();
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        let e = &p.exprs[id];
        let missing = match &e.kind {
            ExprKind::Call(Func::Pow, args) if args.len() == 2 => {
                let (a, b) = (args[0], args[1]);
                p.exprs[id].kind = ExprKind::Binary(BinaryOp::Pow, a, b);
                continue;
            }
            ExprKind::AtanSlash(y, x) if whole.contains(&id) => {
                let args = vec![*y, *x];
                p.exprs[id].kind = ExprKind::Call(Func::Atan2, args);
                continue;
            }
            ExprKind::Call(Func::Atan2, _) | ExprKind::AtanSlash(..) if !whole.contains(&id) => {
                "the arc tangent of two values inside a formula"
            }
            ExprKind::Call(f, _) => match f {
                Func::Round => "ROUND",
                Func::Floor => "rounding down (FIX)",
                Func::Ceil => "rounding up (FUP)",
                Func::RoundAway => "rounding away from zero (FUP)",
                Func::Min => "MIN",
                Func::Max => "MAX",
                Func::Bin => "BIN",
                Func::Bcd => "BCD",
                Func::PosShortest | Func::PosPlus | Func::PosMinus => {
                    "a rotary position with a direction (DC, ACP, ACN)"
                }
                Func::Pow => "POW with other than two arguments",
                Func::Sin
                | Func::Cos
                | Func::Tan
                | Func::Asin
                | Func::Acos
                | Func::Atan
                | Func::Atan2
                | Func::Sqrt
                | Func::Abs
                | Func::Trunc
                | Func::Ln
                | Func::Exp
                | Func::Sign
                | Func::Log10
                | Func::Square => continue,
            },
            _ => continue,
        };
        diags.push(
            Diagnostic::new(
                Code::PortTncFormula,
                format!("Klartext formulas have no counterpart for {missing}"),
            )
            .primary(e.span, "here")
            .help("rewrite it with + - * / ^ SIN COS TAN ASIN ACOS ATAN SQRT SQ ABS INT LN EXP, or compute an angle of two values into a parameter of its own"),
        );
    }
}
