//! Expressions in the target's syntax, with as few brackets as keep the tree
//! the same when read back: Fanuc/LinuxCNC `#1+2`, `#[#2]`, `#<name>`,
//! `SIN[#1]`, `ATAN[a]/[b]`; Siemens `R1+2`, `SIN(R5)`, `ATAN2(a,b)`, `AC(..)`.
//! Function names come from the spec's function table.

use super::writer::{Style, Writer};
use crate::dialect::Capability;
use crate::ir::{BinaryOp, DimMode, ExprId, ExprKind, Func, UnaryOp, Var};

/// Writes expression `id` in the writer's style, or reports why it cannot.
pub fn write_expr(w: &mut Writer<'_>, id: ExprId) -> Option<String> {
    let e = &w.prog.exprs[id];
    let span = e.span;
    match &e.kind {
        ExprKind::Number(d) => Some(match w.style {
            Style::Bracket => d.normalized().to_string(),
            Style::Sinumerik => d.format(0, false),
        }),
        ExprKind::Str(s) => match w.style {
            Style::Sinumerik => Some(format!("\"{s}\"")),
            Style::Bracket => cannot(w, span, "a string value"),
        },
        ExprKind::Bool(b) => match w.style {
            Style::Sinumerik => Some(if *b { "TRUE" } else { "FALSE" }.to_string()),
            Style::Bracket => cannot(w, span, "a boolean literal"),
        },
        ExprKind::Var(v) => write_var(w, v, span),
        ExprKind::Unary(op, a) => unary(w, *op, *a, span),
        ExprKind::Binary(op, a, b) => binary(w, *op, *a, *b, span),
        ExprKind::Call(f, args) => call(w, *f, args, span),
        ExprKind::Exists(name) => {
            if !w.need(
                Capability::NamedParameters,
                span,
                "EXISTS[] on a named parameter",
            ) {
                return None;
            }
            Some(format!("EXISTS[#<{name}>]"))
        }
        ExprKind::ExistsNumbered(e) => {
            if !w.need(
                Capability::NamedParameters,
                span,
                "EXISTS[] on a numbered parameter",
            ) {
                return None;
            }
            let inner = write_expr(w, *e)?;
            Some(format!("EXISTS[#[{inner}]]"))
        }
        ExprKind::AtanSlash(a, b) => atan_slash(w, *a, *b, span),
        ExprKind::Query(name, args) => match w.style {
            Style::Sinumerik => {
                let mut a = Vec::with_capacity(args.len());
                for x in args {
                    a.push(write_expr(w, *x)?);
                }
                Some(format!("{name}({})", a.join(",")))
            }
            Style::Bracket => cannot(w, span, &format!("the control function {name}")),
        },
        ExprKind::Dimension(mode, a) => match w.style {
            Style::Sinumerik => {
                let f = if *mode == DimMode::Absolute {
                    "AC"
                } else {
                    "IC"
                };
                Some(format!("{f}({})", write_expr(w, *a)?))
            }
            Style::Bracket => cannot(w, span, "a per-value AC()/IC() dimension"),
        },
    }
}

fn cannot(w: &mut Writer<'_>, span: crate::span::Span, what: &str) -> Option<String> {
    w.cannot(
        span,
        what,
        "rewrite the expression with what the target dialect offers",
    );
    None
}

/// A variable reference as the target writes it.
pub fn write_var(w: &mut Writer<'_>, v: &Var, span: crate::span::Span) -> Option<String> {
    match (v, w.style) {
        (Var::Numbered(n), Style::Bracket) => Some(format!("#{n}")),
        (Var::Indirect(e), Style::Bracket) => Some(format!("#[{}]", write_expr(w, *e)?)),
        (Var::Named(n), Style::Bracket) => {
            if !w.need(Capability::NamedParameters, span, "a named parameter") {
                return None;
            }
            Some(format!("#<{n}>"))
        }
        (Var::R(n), Style::Sinumerik) => Some(format!("R{n}")),
        (Var::RIndirect(e), Style::Sinumerik) => Some(format!("R[{}]", write_expr(w, *e)?)),
        (Var::User(n, idx) | Var::System(n, idx), Style::Sinumerik) => {
            if idx.is_empty() {
                return Some(n.clone());
            }
            let parts = list(w, idx)?;
            Some(format!("{n}[{}]", parts.join(",")))
        }
        (Var::Numbered(_) | Var::Indirect(_) | Var::Named(_), Style::Sinumerik) => {
            cannot(w, span, "a `#` parameter")
        }
        (Var::R(_) | Var::RIndirect(_), Style::Bracket) => cannot(w, span, "an R parameter"),
        (Var::User(..), Style::Bracket) => cannot(w, span, "a DEF user variable"),
        (Var::System(..), Style::Bracket) => cannot(w, span, "a named system variable"),
        (Var::Q(..), Style::Bracket | Style::Sinumerik) => {
            cannot(w, span, "a Heidenhain Q parameter")
        }
    }
}

fn list(w: &mut Writer<'_>, ids: &[ExprId]) -> Option<Vec<String>> {
    let mut out = Vec::with_capacity(ids.len());
    let mut ok = true;
    for id in ids {
        match write_expr(w, *id) {
            Some(s) => out.push(s),
            None => ok = false,
        }
    }
    ok.then_some(out)
}

fn open_close(w: &Writer<'_>) -> (char, char) {
    match w.style {
        Style::Bracket => ('[', ']'),
        Style::Sinumerik => ('(', ')'),
    }
}

fn group(w: &Writer<'_>, s: String) -> String {
    let (o, c) = open_close(w);
    format!("{o}{s}{c}")
}

fn is_binary(w: &Writer<'_>, id: ExprId) -> bool {
    matches!(w.prog.exprs[id].kind, ExprKind::Binary(..))
}

fn unary(w: &mut Writer<'_>, op: UnaryOp, a: ExprId, span: crate::span::Span) -> Option<String> {
    let prefix = match (op, w.style) {
        (UnaryOp::Neg, _) => "-",
        (UnaryOp::Plus, _) => "+",
        (UnaryOp::Not, Style::Sinumerik) => "NOT ",
        (UnaryOp::BitNot, Style::Sinumerik) => "B_NOT ",
        (UnaryOp::Not, Style::Bracket) => return cannot(w, span, "a logical NOT"),
        (UnaryOp::BitNot, Style::Bracket) => return cannot(w, span, "a bitwise NOT"),
    };
    let inner = write_expr(w, a)?;
    let inner = if is_binary(w, a) {
        group(w, inner)
    } else {
        inner
    };
    Some(format!("{prefix}{inner}"))
}

/// The operator's text in the target, or `None` when it has none.
fn op_text(w: &Writer<'_>, op: BinaryOp) -> Option<&'static str> {
    use BinaryOp::*;
    let bracket = w.style == Style::Bracket;
    Some(match op {
        Add => "+",
        Sub => "-",
        Mul => "*",
        Div => "/",
        Pow if bracket && w.spec.has(Capability::PowerOperator) => "**",
        Pow => return None,
        Mod => " MOD ",
        IntDiv if !bracket => " DIV ",
        IntDiv => return None,
        Eq if bracket => " EQ ",
        Ne if bracket => " NE ",
        Gt if bracket => " GT ",
        Ge if bracket => " GE ",
        Lt if bracket => " LT ",
        Le if bracket => " LE ",
        Eq => "==",
        Ne => "<>",
        Gt => ">",
        Ge => ">=",
        Lt => "<",
        Le => "<=",
        And => " AND ",
        Or => " OR ",
        Xor => " XOR ",
        BitAnd | BitOr | BitXor | Concat if bracket => return None,
        BitAnd => " B_AND ",
        BitOr => " B_OR ",
        BitXor => " B_XOR ",
        Concat => "<<",
    })
}

/// Binding strength in the target's grammar; higher binds tighter.
fn prec(style: Style, op: BinaryOp) -> u8 {
    use BinaryOp::*;
    match style {
        Style::Bracket => match op {
            Or | Xor | And | BitOr | BitXor | BitAnd => 1,
            Concat => 2,
            Eq | Ne | Gt | Ge | Lt | Le => 3,
            Add | Sub => 5,
            Mul | Div | Mod | IntDiv => 6,
            Pow => 7,
        },
        // Siemens: comparisons bind weakest, then <<, OR, XOR, AND, B_OR...
        Style::Sinumerik => match op {
            Eq | Ne | Gt | Ge | Lt | Le => 1,
            Concat => 2,
            Or => 3,
            Xor => 4,
            And => 5,
            BitOr => 6,
            BitXor => 7,
            BitAnd => 8,
            Add | Sub => 9,
            Mul | Div | Mod | IntDiv | Pow => 10,
        },
    }
}

fn is_logical(op: BinaryOp) -> bool {
    matches!(op, BinaryOp::And | BinaryOp::Or | BinaryOp::Xor)
}

fn operand(w: &mut Writer<'_>, parent: BinaryOp, child: ExprId, right: bool) -> Option<String> {
    let text = write_expr(w, child)?;
    let ExprKind::Binary(cop, ..) = w.prog.exprs[child].kind else {
        return Some(text);
    };
    let (p, c) = (prec(w.style, parent), prec(w.style, cop));
    // Fanuc binds AND like `*` and OR like `+`: operands of logical
    // operators are always bracketed so every reader sees the same tree.
    let always = w.style == Style::Bracket && is_logical(parent);
    let need = always || c < p || (right && c == p);
    Some(if need { group(w, text) } else { text })
}

fn binary(
    w: &mut Writer<'_>,
    op: BinaryOp,
    a: ExprId,
    b: ExprId,
    span: crate::span::Span,
) -> Option<String> {
    let Some(t) = op_text(w, op) else {
        return cannot(w, span, &format!("the operator {op:?}"));
    };
    let l = operand(w, op, a, false);
    let r = operand(w, op, b, true);
    Some(format!("{}{t}{}", l?, r?))
}

fn call(w: &mut Writer<'_>, f: Func, args: &[ExprId], span: crate::span::Span) -> Option<String> {
    let Some(name) = w.spec.function_name(f).map(str::to_string) else {
        return cannot(w, span, &format!("the function {f:?}"));
    };
    let parts = list(w, args)?;
    Some(format!("{name}{}", group(w, parts.join(","))))
}

fn atan_slash(w: &mut Writer<'_>, a: ExprId, b: ExprId, span: crate::span::Span) -> Option<String> {
    match w.style {
        Style::Sinumerik => call(w, Func::Atan2, &[a, b], span),
        Style::Bracket => {
            let name = w
                .spec
                .function_name(Func::Atan2)
                .or_else(|| w.spec.function_name(Func::Atan));
            let Some(name) = name.map(str::to_string) else {
                return cannot(w, span, "the function Atan");
            };
            let (x, y) = (write_expr(w, a), write_expr(w, b));
            Some(format!("{name}[{}]/[{}]", x?, y?))
        }
    }
}
