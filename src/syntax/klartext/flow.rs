//! Labels, calls and Q parameters to items: `LBL`, `CALL LBL [REP]`,
//! `CALL PGM`, `FN 0..13` and formulas.
//!
//! FN 0..8 and 13 become assignments (FN 8 `a LEN b` = √(a²+b²), FN 13
//! `a ANG b` = the angle of (a, b)); FN 9..12 conditional jumps to a label;
//! FN 14..20 are read in [`super::functions`]; other FN functions (table
//! access 26..28 ...) are kept as text with a W0005 warning.

use super::build::{Ctx, Signed};
use super::lexer::Spanned3;
use super::token::Tok;
use crate::diag::Code;
use crate::ir::{
    BinaryOp, CallArgs, CallKind, CallTarget, Decimal, ExprKind, Func, JumpDir, JumpTarget,
    StmtKind, Value, Var,
};
use crate::syntax::Item;

/// `LBL 1`, `LBL "name"`; `LBL 0` ends a subprogram.
pub fn label(ctx: &mut Ctx<'_>, id: String, il: usize, ir: usize, l: usize, r: usize) -> Vec<Item> {
    if id == "0" {
        return vec![ctx.stmt(StmtKind::SubReturn { to: None }, l, r)];
    }
    ctx.label = Some((id, ctx.span(il, ir)));
    Vec::new()
}

/// `CALL LBL 1`, `CALL LBL "name" REP 3/3`.
pub fn call_label(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let id = match toks.first().map(|t| &t.1) {
        Some(Tok::Num(d)) => d.format(0, false),
        Some(Tok::Str(s)) => s.clone(),
        Some(Tok::Name(n)) => n.clone(),
        _ => {
            ctx.error(
                Code::SyntaxError,
                l,
                r,
                "CALL LBL needs a label number or name",
                "write `CALL LBL 1` or `CALL LBL \"NAME\"`",
            );
            return Vec::new();
        }
    };
    let rep = match &toks[1..] {
        [] => None,
        [(_, Tok::Name(n), _), (a, Tok::Num(d), b), rest @ ..]
            if n == "REP" && matches!(rest, [] | [(_, Tok::Slash, _), (_, Tok::Num(_), _)]) =>
        {
            Some((*d, *a, *b))
        }
        _ => {
            let (a, b) = (toks[1].0, toks[toks.len() - 1].2);
            ctx.error(
                Code::SyntaxError,
                a,
                b,
                "expected `REP n` after the label",
                "write `CALL LBL 1 REP 3`",
            );
            None
        }
    };
    let kind = match rep {
        Some((d, a, b)) => {
            let count = ctx.number(d, a, b);
            StmtKind::SectionRepeat {
                start: id,
                end: None,
                count: Some(count),
                single: false,
            }
        }
        None => {
            let target = match id.parse::<u32>() {
                Ok(n) if matches!(toks.first().map(|t| &t.1), Some(Tok::Num(_))) => {
                    CallTarget::Number(n)
                }
                _ => CallTarget::Name(id),
            };
            StmtKind::Call {
                kind: CallKind::Label,
                target,
                args: CallArgs::None,
                repeat: None,
            }
        }
    };
    vec![ctx.stmt(kind, l, r)]
}

/// `CALL PGM TNC:\Plan.h`: the rest of the block names the program.
pub fn call_pgm(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let name = ctx.slice(from, ctx.end()).trim().to_string();
    if name.is_empty() {
        ctx.error(
            Code::SyntaxError,
            l,
            r,
            "CALL PGM needs a program name",
            "write `CALL PGM NAME` or `CALL PGM TNC:\\DIR\\NAME.H`",
        );
        return Vec::new();
    }
    let k = StmtKind::Call {
        kind: CallKind::Named,
        target: CallTarget::Name(name),
        args: CallArgs::None,
        repeat: None,
    };
    vec![ctx.stmt(k, l, r)]
}

fn fn_number(ctx: &mut Ctx<'_>, n: Decimal, l: usize, r: usize) -> Option<u32> {
    let v = n.as_int().filter(|v| (0..=99).contains(v));
    if v.is_none() {
        ctx.error(
            Code::SyntaxError,
            l,
            r,
            "FN needs a function number",
            "FN 0..FN 13: arithmetic, FN 9..12: jumps",
        );
    }
    v.map(|v| v as u32)
}

/// `FN 1: Q1 = +Q2 + +5` and the other arithmetic FN functions.
pub fn fn_assign(
    ctx: &mut Ctx<'_>,
    n: Decimal,
    var: Var,
    rhs: &(Option<Signed>, Option<String>, Signed),
    l: usize,
    r: usize,
) -> Vec<Item> {
    let Some(n) = fn_number(ctx, n, l, r) else {
        return Vec::new();
    };
    let b = ctx.value(&rhs.2);
    let b = ctx.expr_of(&b, l, r);
    let a = rhs.0.as_ref().map(|a| {
        let v = ctx.value(a);
        ctx.expr_of(&v, l, r)
    });
    let op = rhs.1.as_deref();
    let bin = |ctx: &mut Ctx<'_>, o, a, b| ctx.binary(o, a, b, l, r);
    let value = match (n, a, op) {
        (0, None, None) => b,
        (1, Some(a), Some("+")) => bin(ctx, BinaryOp::Add, a, b),
        (2, Some(a), Some("-")) => bin(ctx, BinaryOp::Sub, a, b),
        (3, Some(a), Some("*")) => bin(ctx, BinaryOp::Mul, a, b),
        (4, Some(a), Some("/" | "DIV")) => bin(ctx, BinaryOp::Div, a, b),
        (5, None, Some("SQRT")) => call(ctx, Func::Sqrt, vec![b], l, r),
        (6, None, Some("SIN")) => call(ctx, Func::Sin, vec![b], l, r),
        (7, None, Some("COS")) => call(ctx, Func::Cos, vec![b], l, r),
        (8, Some(a), Some("LEN")) => {
            let aa = call(ctx, Func::Square, vec![a], l, r);
            let bb = call(ctx, Func::Square, vec![b], l, r);
            let s = bin(ctx, BinaryOp::Add, aa, bb);
            call(ctx, Func::Sqrt, vec![s], l, r)
        }
        (13, Some(a), Some("ANG")) => call(ctx, Func::Atan2, vec![b, a], l, r),
        _ => {
            ctx.error(Code::SyntaxError, l, r, format!("this is not the form of FN {n}"), "FN 0: Q = a; FN 1..4: Q = a + - * DIV b; FN 5..7: Q = SQRT/SIN/COS a; FN 8: a LEN b; FN 13: a ANG b");
            return Vec::new();
        }
    };
    vec![ctx.stmt(StmtKind::Assign { var, value }, l, r)]
}

fn call(
    ctx: &mut Ctx<'_>,
    f: Func,
    args: Vec<crate::ir::ExprId>,
    l: usize,
    r: usize,
) -> crate::ir::ExprId {
    let span = ctx.span(l, r);
    ctx.exprs.alloc(crate::ir::Expr {
        kind: ExprKind::Call(f, args),
        span,
    })
}

/// `FN 9: IF +Q1 EQU +0 GOTO LBL 5` (10 NE, 11 GT, 12 LT).
#[allow(clippy::too_many_arguments)]
pub fn fn_if(
    ctx: &mut Ctx<'_>,
    n: Decimal,
    a: &Signed,
    op: &str,
    b: &Signed,
    id: String,
    l: usize,
    r: usize,
) -> Vec<Item> {
    let Some(n) = fn_number(ctx, n, l, r) else {
        return Vec::new();
    };
    let cmp = match (n, op) {
        (9, "EQU" | "EQ") => BinaryOp::Eq,
        (10, "NE") => BinaryOp::Ne,
        (11, "GT") => BinaryOp::Gt,
        (12, "LT") => BinaryOp::Lt,
        _ => {
            ctx.error(
                Code::SyntaxError,
                l,
                r,
                format!("FN {n} does not compare with `{op}`"),
                "FN 9: EQU, FN 10: NE, FN 11: GT, FN 12: LT",
            );
            return Vec::new();
        }
    };
    let (va, vb) = (ctx.value(a), ctx.value(b));
    let (ea, eb) = (ctx.expr_of(&va, l, r), ctx.expr_of(&vb, l, r));
    let cond = ctx.binary(cmp, ea, eb, l, r);
    let k = StmtKind::Goto {
        target: JumpTarget::Label(id),
        dir: JumpDir::Either,
        cond: Some(cond),
    };
    vec![ctx.stmt(k, l, r)]
}

/// `Q1 = Q2 * 3`.
pub fn formula(
    ctx: &mut Ctx<'_>,
    var: Var,
    value: crate::ir::ExprId,
    l: usize,
    r: usize,
) -> Vec<Item> {
    let _ = Value::Number(Decimal::from_int(0));
    vec![ctx.stmt(StmtKind::Assign { var, value }, l, r)]
}
