//! Cycles, labels, calls and Q parameters to items: `CYCL DEF` (numbered
//! cycles with their `Qnnn=value ;LABEL` lines, and old-style sub-numbered
//! lines), `CYCL CALL [POS|PAT]`, `PATTERN DEF`, `LBL`, `CALL LBL [REP]`,
//! `CALL PGM`, `FN 0..13` and formulas.
//!
//! FN 0..8 and 13 become assignments (FN 8 `a LEN b` = √(a²+b²), FN 13
//! `a ANG b` = the angle of (a, b)); FN 9..12 conditional jumps to a label;
//! the other FN functions (14 ERROR, 18 SYSREAD, ...) are kept as text
//! with a W0005 warning.

use super::build::{Ctx, Operand, Signed, WordNode};
use super::lexer::Spanned3;
use super::token::Tok;
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    BinaryOp, CallArgs, CallKind, CallTarget, CycleDef, CycleLine, CycleRunKind, Decimal, ExprKind,
    Func, JumpDir, JumpTarget, PatternItem, QParam, StmtKind, Value, Var,
};
use crate::syntax::Item;

/// `CYCL DEF ...` from the tokens at `from`.
pub fn cycl_def(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let Some((nl, Tok::Num(num), nr)) = toks.first().cloned() else {
        ctx.error(
            Code::KlartextBadCycle,
            l,
            r,
            "CYCL DEF without a cycle number",
            "write `CYCL DEF 200 DRILLING` or `CYCL DEF 7.0 DATUM SHIFT`",
        );
        return Vec::new();
    };
    let text = ctx.slice(nl, nr).to_string();
    if let Some((c, sub)) = text.split_once('.') {
        let (Ok(cycle), Ok(sub)) = (c.parse::<u32>(), sub.parse::<u32>()) else {
            ctx.error(
                Code::KlartextBadCycle,
                nl,
                nr,
                format!("`{text}` is not a cycle number"),
                "old-style cycles are numbered n.m (7.0, 7.1)",
            );
            return Vec::new();
        };
        return match ctx.cycle_words(&toks[1..]) {
            Some(words) => {
                let k = StmtKind::CycleLine(Box::new(CycleLine { cycle, sub, words }));
                vec![ctx.stmt(k, l, r)]
            }
            None => vec![kept(ctx, l, r)],
        };
    }
    let number = num.as_int().unwrap_or(0).clamp(0, 99_999) as u32;
    // The name runs up to the first parameter (`TAPPING W/ CHIP BRKG`).
    let mut i = 1;
    while i < toks.len() && !matches!(toks[i].1, Tok::Q(..)) {
        i += 1;
    }
    let name_end = toks.get(i).map(|t| t.0).unwrap_or(ctx.end());
    let name: Vec<String> = ctx
        .slice(nr, name_end)
        .split_whitespace()
        .map(String::from)
        .collect();
    let mut params = Vec::new();
    while i < toks.len() {
        let Some(p) = q_param(ctx, &toks, &mut i) else {
            let (a, _, b) = toks[i].clone();
            ctx.error(
                Code::KlartextBadCycle,
                a,
                b,
                "expected a cycle parameter `Qnnn=value`",
                "write one `Qnnn=value` per parameter",
            );
            break;
        };
        params.push(p);
    }
    missing_params(ctx, number, &params, l, r);
    let def = CycleDef {
        number,
        name: name.join(" "),
        params,
    };
    vec![ctx.stmt(StmtKind::CycleDef(Box::new(def)), l, r)]
}

/// E0320: the parameters the spec lists for the cycle that are not given.
fn missing_params(ctx: &mut Ctx<'_>, number: u32, params: &[QParam], l: usize, r: usize) {
    let Some(sig) = ctx.spec.cycle(&number.to_string()) else {
        ctx.diags.push(
            Diagnostic::new(Code::CannotExpandCycle, format!("cycle {number} is not in the dialect's cycle table"))
                .primary(ctx.span(l, r), "kept with its parameters, not checked")
                .help("its Q parameters are kept as written; it cannot be run or mapped to another control"),
        );
        return;
    };
    let missing: Vec<String> = sig
        .params
        .iter()
        .filter(|p| !params.iter().any(|q| format!("Q{}", q.q) == p.name))
        .map(|p| format!("{} ({})", p.name, p.doc))
        .collect();
    if !missing.is_empty() {
        let d = Diagnostic::new(
            Code::KlartextCycleMissingParameter,
            format!(
                "CYCL DEF {number} lacks {}",
                if missing.len() == 1 {
                    "a parameter"
                } else {
                    "parameters"
                }
            ),
        )
        .primary(ctx.span(l, r), format!("missing: {}", missing.join(", ")))
        .help(format!(
            "cycle {number} takes {}; add one `Qnnn=value` line for each",
            sig.params
                .iter()
                .map(|p| p.name.as_str())
                .collect::<Vec<_>>()
                .join(" ")
        ));
        ctx.diags.push(d);
    }
}

/// `Q200=+2 ;SET-UP CLEARANCE`, `Q206=Q2`.
fn q_param(ctx: &mut Ctx<'_>, toks: &[Spanned3], i: &mut usize) -> Option<QParam> {
    let (l, Tok::Q(crate::ir::QBank::Q, q), _) = toks.get(*i).cloned()? else {
        return None;
    };
    if toks.get(*i + 1).map(|t| &t.1) != Some(&Tok::Eq) {
        return None;
    }
    let mut j = *i + 2;
    let sign = match toks.get(j).map(|t| &t.1) {
        Some(Tok::Plus) => Some('+'),
        Some(Tok::Minus) => Some('-'),
        _ => None,
    };
    if sign.is_some() {
        j += 1;
    }
    let (a, t, b) = toks.get(j).cloned()?;
    let op = match t {
        Tok::Num(d) => Operand::Num(d, a, b),
        Tok::Q(bank, n) => Operand::Expr(ctx.var(Var::Q(bank, n), a, b)),
        _ => return None,
    };
    *i = j + 1;
    let value = ctx.value(&(sign, op));
    let next = toks.get(*i).map(|t| t.0).unwrap_or(usize::MAX);
    let label = ctx
        .comments
        .iter()
        .position(|c| c.start >= b && c.start < next)
        .map(|k| {
            ctx.used_comments.push(k);
            ctx.comments[k].text.clone()
        });
    Some(QParam {
        q,
        value,
        label,
        span: ctx.span(l, b),
    })
}

/// A block kept as text, with a W0005 warning.
fn kept(ctx: &mut Ctx<'_>, l: usize, r: usize) -> Item {
    let text = ctx.slice(l, r).trim().to_string();
    ctx.diags.push(
        Diagnostic::new(Code::KeptAsText, format!("`{text}` is kept as text"))
            .primary(ctx.span(l, r), "not understood, only kept")
            .help("it is written back unchanged to Heidenhain and cannot be run or translated"),
    );
    ctx.stmt(
        StmtKind::Raw {
            dialect: "heidenhain".into(),
            text,
        },
        l,
        r,
    )
}

/// `CYCL CALL`, `CYCL CALL POS X.. Y.. Z..`, `CYCL CALL PAT`, with F and M.
pub fn cycl_call(ctx: &mut Ctx<'_>, words: &[WordNode], l: usize, r: usize) -> Vec<Item> {
    let mut out = Vec::new();
    let mut how = CycleRunKind::Call;
    let mut axes = crate::ir::Axes::default();
    let mut pos = false;
    for w in words {
        let v = ctx.word_value(w);
        match (w.name.as_str(), v) {
            ("POS", None) => pos = true,
            ("PAT", None) => how = CycleRunKind::Pattern,
            ("F", Some(v)) => out.push(ctx.stmt(StmtKind::Feed(v), w.l, w.r)),
            ("M", Some(v)) => out.extend(super::path::m_function(ctx, w, v)),
            (n, Some(v)) if pos && n.len() == 1 && "XYZABCUVW".contains(n) => {
                let c = crate::ir::Coord {
                    value: v,
                    dim: None,
                    span: ctx.span(w.l, w.r),
                };
                if let Some(s) = axes.slot_mut(n.chars().next().unwrap_or('X')) {
                    *s = Some(c);
                }
            }
            (n, _) => ctx.error(
                Code::KlartextWordNotAllowed,
                w.l,
                w.r,
                format!("CYCL CALL does not take `{n}` here"),
                "CYCL CALL takes POS with axes, PAT, F and M",
            ),
        }
    }
    if pos {
        how = CycleRunKind::Pos(Box::new(axes));
    }
    out.insert(0, ctx.stmt(StmtKind::CycleRun(how), l, r));
    out
}

/// `PATTERN DEF ~ POS1 (X+25 Y+33.5 Z+0) ~ ...`.
pub fn pattern_def(ctx: &mut Ctx<'_>, from: usize, l: usize, r: usize) -> Vec<Item> {
    let toks: Vec<Spanned3> = ctx.toks_from(from).to_vec();
    let mut items = Vec::new();
    let mut i = 0;
    while i < toks.len() {
        let (a, Tok::Name(n), _) = toks[i].clone() else {
            return vec![kept(ctx, l, r)];
        };
        let mut name = n;
        i += 1;
        if let Some((_, Tok::Num(d), _)) = toks.get(i) {
            name.push_str(&d.format(0, false));
            i += 1;
        }
        if toks.get(i).map(|t| &t.1) != Some(&Tok::LParen) {
            return vec![kept(ctx, l, r)];
        }
        let Some(close) = toks[i..]
            .iter()
            .position(|t| t.1 == Tok::RParen)
            .map(|k| k + i)
        else {
            return vec![kept(ctx, l, r)];
        };
        let Some(words) = ctx.cycle_words(&toks[i + 1..close]) else {
            return vec![kept(ctx, l, r)];
        };
        let b = toks[close].2;
        items.push(PatternItem {
            name,
            words,
            span: ctx.span(a, b),
        });
        i = close + 1;
    }
    vec![ctx.stmt(StmtKind::PatternDef(items), l, r)]
}

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

/// FN 14 and later (ERROR, PRINT, SYSREAD, ...): kept as text.
pub fn fn_other(ctx: &mut Ctx<'_>, l: usize, r: usize) -> Vec<Item> {
    vec![kept(ctx, l, r)]
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
