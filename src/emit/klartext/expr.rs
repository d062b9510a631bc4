//! Klartext values and formulas: signed coordinates (`X+10`, `X-Q5`,
//! `IX+2`), Q parameter formulas (`Q1 = Q2 + SIN (Q3)`), FN conditions.

use super::super::number::NumKind;
use super::super::writer::Writer;
use crate::ir::{BinaryOp, Decimal, ExprId, ExprKind, Func, UnaryOp, Value, Var};
use crate::span::Span;

/// A value with its sign always written: `+10`, `-2.5`, `+Q3`, `-Q3`,
/// `+(Q1+2)` ([?] parenthesised formulas in coordinates: newer controls).
pub fn signed(w: &mut Writer<'_>, v: &Value, kind: NumKind, span: Span) -> Option<String> {
    match v {
        Value::Number(d) => signed_num(w, *d, kind, span),
        Value::Expr(e) => signed_expr(w, *e),
    }
}

fn signed_num(w: &mut Writer<'_>, d: Decimal, kind: NumKind, span: Span) -> Option<String> {
    let s = w.num(d, kind, span)?;
    Some(if s.starts_with('-') {
        s
    } else {
        format!("+{s}")
    })
}

fn signed_expr(w: &mut Writer<'_>, e: ExprId) -> Option<String> {
    let p = w.prog;
    match &p.exprs[e].kind {
        ExprKind::Number(d) => signed_num(w, *d, NumKind::Plain, p.exprs[e].span),
        ExprKind::Var(v) => Some(format!("+{}", var(w, v, p.exprs[e].span)?)),
        ExprKind::Unary(UnaryOp::Neg, inner)
            if matches!(p.exprs[*inner].kind, ExprKind::Var(_)) =>
        {
            Some(format!("-{}", formula(w, *inner)?))
        }
        ExprKind::Dimension(_, inner) => signed_expr(w, *inner),
        _ => Some(format!("+({})", formula(w, e)?)),
    }
}

/// `Q12`, `QL3`; other variables cannot be written.
pub fn var(w: &mut Writer<'_>, v: &Var, span: Span) -> Option<String> {
    match v {
        Var::Q(bank, n) => Some(format!("{}{n}", bank.prefix())),
        Var::Numbered(_)
        | Var::Indirect(_)
        | Var::Named(_)
        | Var::R(_)
        | Var::RIndirect(_)
        | Var::User(..)
        | Var::System(..) => {
            w.cannot(
                span,
                "a variable other than a Q parameter",
                "use Q parameters (Q1..Q1999) for values computed by the program",
            );
            None
        }
    }
}

/// A formula as the TNC writes it: `Q2 * 3 + SIN (Q1)`.
pub fn formula(w: &mut Writer<'_>, e: ExprId) -> Option<String> {
    let p = w.prog;
    let x = &p.exprs[e];
    match &x.kind {
        ExprKind::Number(d) => w.num(*d, NumKind::Plain, x.span),
        ExprKind::Var(v) => var(w, v, x.span),
        ExprKind::Unary(UnaryOp::Neg, a) => Some(format!("-{}", operand(w, *a, 8, false)?)),
        ExprKind::Unary(UnaryOp::Plus, a) => Some(format!("+{}", operand(w, *a, 8, false)?)),
        ExprKind::Binary(op, a, b) => {
            let sym = match op {
                BinaryOp::Add => "+",
                BinaryOp::Sub => "-",
                BinaryOp::Mul => "*",
                BinaryOp::Div => "/",
                BinaryOp::Pow => "^",
                _ => {
                    w.cannot(
                        x.span,
                        "this operator in a Q parameter formula",
                        "Klartext formulas use + - * / ^ and functions; compare with FN 9..12",
                    );
                    return None;
                }
            };
            let pr = op.precedence();
            let l = operand(w, *a, pr, false)?;
            let r = operand(w, *b, pr, true)?;
            Some(format!("{l} {sym} {r}"))
        }
        ExprKind::Call(f, args) if args.len() == 1 => {
            let name = match f {
                Func::Sin => "SIN",
                Func::Cos => "COS",
                Func::Tan => "TAN",
                Func::Asin => "ASIN",
                Func::Acos => "ACOS",
                Func::Atan => "ATAN",
                Func::Sqrt => "SQRT",
                Func::Square => "SQ",
                Func::Abs => "ABS",
                Func::Trunc => "INT",
                Func::Ln => "LN",
                Func::Exp => "EXP",
                Func::Sign => "SGN",
                Func::Log10 => "LOG",
                Func::Atan2
                | Func::Round
                | Func::Floor
                | Func::Ceil
                | Func::RoundAway
                | Func::Pow
                | Func::Bin
                | Func::Bcd
                | Func::PosShortest
                | Func::PosPlus
                | Func::PosMinus
                | Func::Min
                | Func::Max => {
                    w.cannot(
                        x.span,
                        &format!("the function {f:?} in a formula"),
                        "rewrite it with SIN COS TAN ASIN ACOS ATAN SQRT SQ ABS INT LN LOG EXP SGN",
                    );
                    return None;
                }
            };
            Some(format!("{name} ({})", formula(w, args[0])?))
        }
        _ => {
            w.cannot(
                x.span,
                "this expression in a Q parameter formula",
                "compute it with Q parameter formulas",
            );
            None
        }
    }
}

fn operand(w: &mut Writer<'_>, e: ExprId, parent: u8, right: bool) -> Option<String> {
    let s = formula(w, e)?;
    Some(match &w.prog.exprs[e].kind {
        ExprKind::Binary(op, ..)
            if op.precedence() < parent || (right && op.precedence() == parent) =>
        {
            format!("( {s} )")
        }
        ExprKind::Unary(..) if parent == 8 => format!("( {s} )"),
        _ => s,
    })
}

/// `Q = ATAN2(b, a)`: written as `FN 13: Q = +a ANG +b`.
pub fn is_angle(w: &Writer<'_>, e: ExprId) -> bool {
    matches!(&w.prog.exprs[e].kind, ExprKind::Call(Func::Atan2, args) if args.len() == 2)
}

pub fn fn13(w: &mut Writer<'_>, v: &Var, e: ExprId, span: Span) -> Option<String> {
    let ExprKind::Call(_, args) = w.prog.exprs[e].kind.clone() else {
        return None;
    };
    let q = var(w, v, span)?;
    let a = signed(w, &Value::Expr(args[1]), NumKind::Plain, span)?;
    let b = signed(w, &Value::Expr(args[0]), NumKind::Plain, span)?;
    Some(format!("FN 13: {q} = {a} ANG {b}"))
}
