//! What the grammar's actions build with: the expression arena, span
//! conversion, and the [`Node`]s a line is read into before they become
//! [`crate::syntax::Item`]s.

use super::classify::Spanner;
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::{
    Arena, Arg, Axes, BinaryOp, Coord, Decimal, DimMode, Expr, ExprId, ExprKind, FrameOp, Stmt,
    StmtKind, Transform, UnaryOp, Value, Var,
};
use crate::span::Span;

/// One piece of a line as the grammar reads it (short-lived: one line).
#[derive(Clone, Debug, PartialEq)]
#[allow(clippy::large_enum_variant)]
pub enum Node {
    /// `X10`, `X=R1+5`, `X=AC(5)`, `CR=10`, `T="DRILL"`.
    Word {
        addr: String,
        addr_span: Span,
        value: Value,
        dim: Option<DimMode>,
        extended: bool,
        span: Span,
    },
    /// An address with no value: an error reported when the line is finished.
    Bare {
        addr: String,
        span: Span,
    },
    /// `L140(2)`: a numbered subprogram call with arguments.
    WordCall {
        addr: String,
        number: Decimal,
        args: Vec<Arg>,
        span: Span,
    },
    Stmt(Stmt),
}

/// The grammar's context.
pub struct Builder<'a> {
    pub exprs: &'a mut Arena<Expr>,
    pub sp: Spanner,
    pub spec: &'a DialectSpec,
    pub diags: Vec<Diagnostic>,
    /// Set when the line holds something only kept as text (an unknown
    /// function, a message built from an expression).
    pub raw_reason: Option<(String, Span)>,
}

impl Builder<'_> {
    pub fn span(&self, l: usize, r: usize) -> Span {
        self.sp.span(l, r)
    }

    pub fn expr(&mut self, kind: ExprKind, l: usize, r: usize) -> ExprId {
        let span = self.span(l, r);
        self.exprs.alloc(Expr { kind, span })
    }

    pub fn bin(&mut self, op: BinaryOp, a: ExprId, b: ExprId, l: usize, r: usize) -> ExprId {
        self.expr(ExprKind::Binary(op, a, b), l, r)
    }

    pub fn un(&mut self, op: UnaryOp, a: ExprId, l: usize, r: usize) -> ExprId {
        self.expr(ExprKind::Unary(op, a), l, r)
    }

    /// `-e`; a negated number literal stays a number (`-5`).
    pub fn neg(&mut self, e: ExprId, l: usize, r: usize) -> ExprId {
        if let ExprKind::Number(d) = self.exprs[e].kind {
            let span = self.span(l, r);
            self.exprs[e] = Expr {
                kind: ExprKind::Number(d.neg()),
                span,
            };
            return e;
        }
        self.un(UnaryOp::Neg, e, l, r)
    }

    pub fn var(&mut self, v: Var, l: usize, r: usize) -> ExprId {
        self.expr(ExprKind::Var(v), l, r)
    }

    pub fn stmt(&self, kind: StmtKind, l: usize, r: usize) -> Node {
        Node::Stmt(Stmt::new(kind, self.span(l, r)))
    }

    /// An expression as a word value: a plain number stays a number.
    pub fn value(&self, e: ExprId) -> Value {
        match &self.exprs[e].kind {
            ExprKind::Number(d) => Value::Number(*d),
            _ => Value::Expr(e),
        }
    }

    pub fn word(
        &self,
        addr: (usize, String, usize),
        value: Value,
        dim: Option<DimMode>,
        extended: bool,
        r: usize,
    ) -> Node {
        let addr_span = self.span(addr.0, addr.2);
        Node::Word {
            addr: addr.1,
            addr_span,
            value,
            dim,
            extended,
            span: self.span(addr.0, r),
        }
    }

    pub fn arg(&self, value: Option<ExprId>, l: usize, r: usize) -> Arg {
        Arg {
            value,
            span: self.span(l, r),
        }
    }

    /// `G[8]=..`, `AX[_Z]=..`: an address with a computed extension. The
    /// line is kept as text (W0005); the node itself is never finished.
    pub fn indirect(&mut self, addr: String, l: usize, r: usize) -> Node {
        self.keep_raw(
            format!("`{addr}[..]=`: an address with an extension in brackets (axis, spindle or G group), known only when the program runs"),
            l,
            r,
        );
        Node::Bare {
            addr,
            span: self.span(l, r),
        }
    }

    /// Marks the line to be kept as text.
    pub fn keep_raw(&mut self, why: String, l: usize, r: usize) {
        let span = self.span(l, r);
        self.keep_raw_at(why, span);
    }

    pub fn keep_raw_at(&mut self, why: String, span: Span) {
        if self.raw_reason.is_none() {
            self.raw_reason = Some((why, span));
        }
    }
}

/// `()` is read as one empty slot; it means no arguments.
/// Array sizes as read (a number, or a name the machine defines) split into
/// the numbers and the named ones by index; `first` is the index of the
/// first one (1 when a STRING length comes before them).
pub fn split_dims(d: Vec<(u32, Option<String>)>, first: usize) -> (Vec<u32>, Vec<(usize, String)>) {
    let names = d
        .iter()
        .enumerate()
        .filter_map(|(i, (_, n))| n.clone().map(|n| (i + first, n)))
        .collect();
    (d.into_iter().map(|(v, _)| v).collect(), names)
}

pub fn args(list: Vec<Arg>) -> Vec<Arg> {
    if list.len() == 1 && list[0].value.is_none() {
        Vec::new()
    } else {
        list
    }
}

/// A programmable frame statement from its keyword and words.
pub fn frame(
    ctx: &mut Builder<'_>,
    f: (FrameOp, bool),
    words: Vec<Node>,
    l: usize,
    r: usize,
) -> Node {
    let mut axes = Axes::default();
    let mut rpl = None;
    for w in words {
        let Node::Word {
            addr,
            value,
            dim,
            span,
            ..
        } = w
        else {
            continue;
        };
        let mut cs = addr.chars();
        let slot = match (cs.next(), cs.next()) {
            (Some(c), None) => axes.slot_mut(c),
            _ => None,
        };
        match slot {
            Some(slot) => *slot = Some(Coord { value, dim, span }),
            None if addr == "RPL" => rpl = Some(value),
            None => ctx.keep_raw_at(format!("`{addr}` in a frame statement"), span),
        }
    }
    ctx.stmt(
        StmtKind::Transform(Box::new(Transform::Frame {
            op: f.0,
            additive: f.1,
            axes,
            rpl,
        })),
        l,
        r,
    )
}

/// A call of a function from the spec's table, its argument count checked.
pub fn call(ctx: &mut Builder<'_>, name: String, args: Vec<ExprId>, l: usize, r: usize) -> ExprId {
    let Some(def) = ctx.spec.function(&name) else {
        ctx.keep_raw(
            format!("the function `{name}` is not in this dialect's function table"),
            l,
            r,
        );
        return ctx.expr(ExprKind::Str(name), l, r);
    };
    let (func, arity) = (def.func, def.arity);
    if args.len() != arity {
        let d = Diagnostic::new(
            Code::SyntaxError,
            format!("`{name}` takes {arity} argument(s), not {}", args.len()),
        )
        .primary(ctx.span(l, r), "wrong number of arguments")
        .help(format!("call it as `{name}(` with {arity} argument(s) `)`"));
        ctx.diags.push(d);
    }
    ctx.expr(ExprKind::Call(func, args), l, r)
}

/// `NAME(args)` in an expression, NAME not in the spec's function table: a
/// control function kept by name ([`ExprKind::Query`]); its value is not
/// known at check time. An argument left empty keeps the line as text.
pub fn query(ctx: &mut Builder<'_>, name: String, args: Vec<Arg>, l: usize, r: usize) -> ExprId {
    let mut vals = Vec::with_capacity(args.len());
    for a in args {
        match a.value {
            Some(v) => vals.push(v),
            None => {
                ctx.keep_raw(
                    format!("the control function `{name}` with an empty argument"),
                    l,
                    r,
                );
                return ctx.expr(ExprKind::Str(name), l, r);
            }
        }
    }
    ctx.expr(ExprKind::Query(name, vals), l, r)
}
