//! The meta-model as stable, readable text, for `cncc ir` and snapshot
//! tests: one line per block (`N10 /1 LABEL:` then its statements, split by
//! ` | `), numbers as written, expressions with brackets by precedence.
//! Deterministic, and the same whatever dialect the program came from.

use super::expr::{BinaryOp, DimMode, ExprId, ExprKind, UnaryOp, Value, Var};
use super::program::Program;
use super::stmt::*;
use super::{Arena, Expr};
use crate::span::Span;
use std::fmt::Write;

/// What to print besides the program itself.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PrintOptions {
    /// Append `@start..end` to each block and statement.
    pub spans: bool,
    /// Print numbers by value (`10` for both `10` and `10.000`), for
    /// comparing meta-models regardless of how numbers were written.
    pub by_value: bool,
}

/// The program as text, one line per block, without spans.
pub fn print_program(p: &Program) -> String {
    print_program_with(p, PrintOptions::default())
}

pub fn print_program_with(p: &Program, opts: PrintOptions) -> String {
    let pr = Printer {
        exprs: &p.exprs,
        opts,
    };
    let mut out = String::new();
    for b in &p.blocks {
        out.push_str(&pr.block(b));
        out.push('\n');
    }
    out
}

/// One block as [`print_program`] prints it (without the line end), its
/// expressions in `exprs`: for a program printed as it is read.
pub fn print_block(b: &Block, exprs: &Arena<Expr>) -> String {
    let pr = Printer {
        exprs,
        opts: PrintOptions::default(),
    };
    pr.block(b)
}

struct Printer<'a> {
    exprs: &'a Arena<Expr>,
    opts: PrintOptions,
}

impl Printer<'_> {
    fn num(&self, d: crate::ir::Decimal) -> String {
        if self.opts.by_value {
            crate::ir::Decimal {
                point: false,
                ..d.normalized()
            }
            .to_string()
        } else {
            d.to_string()
        }
    }
}

fn at(span: Span) -> String {
    format!("@{}..{}", span.start, span.end)
}

impl Printer<'_> {
    fn block(&self, b: &Block) -> String {
        let mut head = Vec::new();
        if let Some(n) = &b.number {
            head.push(format!("N{}", n.node));
        }
        if let Some(s) = &b.skip {
            head.push(if s.node == 0 {
                "/".to_string()
            } else {
                format!("/{}", s.node)
            });
        }
        if let Some(l) = &b.label {
            head.push(format!("{}:", l.node));
        }
        if self.opts.spans {
            head.push(at(b.span));
        }
        let stmts: Vec<String> = b.stmts.iter().map(|s| self.stmt_spanned(s)).collect();
        let mut line = head.join(" ");
        if !stmts.is_empty() {
            if !line.is_empty() {
                line.push(' ');
            }
            line.push_str(&stmts.join(" | "));
        }
        if line.is_empty() {
            line.push_str("(blank)");
        }
        line
    }

    fn stmt_spanned(&self, s: &Stmt) -> String {
        let text = self.stmt(&s.kind);
        if self.opts.spans {
            format!("{text} {}", at(s.span))
        } else {
            text
        }
    }

    fn expr(&self, id: ExprId) -> String {
        let e = &self.exprs[id];
        match &e.kind {
            ExprKind::Number(d) => self.num(*d),
            ExprKind::Str(s) => format!("{s:?}"),
            ExprKind::Bool(b) => b.to_string(),
            ExprKind::Var(v) => self.var(v),
            ExprKind::Unary(op, a) => {
                let sym = match op {
                    UnaryOp::Neg => "-",
                    UnaryOp::Plus => "+",
                    UnaryOp::Not => "NOT ",
                    UnaryOp::BitNot => "BNOT ",
                };
                format!("{sym}{}", self.operand(*a, u8::MAX, false))
            }
            ExprKind::Binary(op, a, b) => {
                let p = op.precedence();
                format!(
                    "{}{}{}",
                    self.operand(*a, p, false),
                    bin_sym(*op),
                    self.operand(*b, p, true)
                )
            }
            ExprKind::Call(f, args) => {
                let a: Vec<String> = args.iter().map(|x| self.expr(*x)).collect();
                format!("{}({})", format!("{f:?}").to_lowercase(), a.join(", "))
            }
            ExprKind::Exists(n) => format!("exists(#<{n}>)"),
            ExprKind::ExistsNumbered(e) => format!("exists(#[{}])", self.expr(*e)),
            ExprKind::Query(n, args) => {
                let a: Vec<String> = args.iter().map(|x| self.expr(*x)).collect();
                format!("{n}?({})", a.join(", "))
            }
            ExprKind::AtanSlash(a, b) => format!("atan({})/({})", self.expr(*a), self.expr(*b)),
            ExprKind::Dimension(m, a) => format!("{}({})", dim(*m), self.expr(*a)),
        }
    }

    fn operand(&self, id: ExprId, parent: u8, right: bool) -> String {
        let s = self.expr(id);
        match &self.exprs[id].kind {
            ExprKind::Binary(op, ..)
                if op.precedence() < parent || (right && op.precedence() == parent) =>
            {
                format!("({s})")
            }
            _ => s,
        }
    }

    fn var(&self, v: &Var) -> String {
        match v {
            Var::Numbered(n) => format!("#{n}"),
            Var::Indirect(e) => format!("#[{}]", self.expr(*e)),
            Var::Named(n) => format!("#<{n}>"),
            Var::R(n) => format!("R{n}"),
            Var::Q(bank, n) => format!("{}{n}", bank.prefix()),
            Var::RIndirect(e) => format!("R[{}]", self.expr(*e)),
            Var::User(n, idx) | Var::System(n, idx) => {
                if idx.is_empty() {
                    n.clone()
                } else {
                    let i: Vec<String> = idx.iter().map(|x| self.expr(*x)).collect();
                    format!("{n}[{}]", i.join(", "))
                }
            }
        }
    }

    /// A value: a number as written, an expression in brackets unless simple.
    fn value(&self, v: &Value) -> String {
        match v {
            Value::Number(d) => self.num(*d),
            Value::Expr(id) => match &self.exprs[*id].kind {
                ExprKind::Number(_) | ExprKind::Var(_) => self.expr(*id),
                _ => format!("[{}]", self.expr(*id)),
            },
        }
    }

    fn kv(&self, out: &mut String, key: &str, v: &Option<Value>) {
        if let Some(v) = v {
            let _ = write!(out, " {key}={}", self.value(v));
        }
    }

    fn coord(&self, c: &Coord) -> String {
        match c.dim {
            None => self.value(&c.value),
            Some(m) => format!("{}({})", dim(m), self.value(&c.value)),
        }
    }

    fn axes(&self, a: &Axes) -> String {
        a.iter()
            .map(|(l, c)| format!(" {l}={}", self.coord(c)))
            .collect()
    }

    fn words(&self, ws: &[Word]) -> String {
        ws.iter()
            .map(|w| format!(" {}={}", w.address(), self.value(&w.value)))
            .collect()
    }

    fn cond(&self, c: ExprId) -> String {
        format!("[{}]", self.expr(c))
    }

    fn opt_expr(&self, e: Option<ExprId>) -> String {
        e.map(|e| format!(" {}", self.cond(e))).unwrap_or_default()
    }
}

fn dim(m: DimMode) -> &'static str {
    match m {
        DimMode::Absolute => "AC",
        DimMode::Incremental => "IC",
    }
}

fn bin_sym(op: BinaryOp) -> &'static str {
    use BinaryOp::*;
    match op {
        Add => "+",
        Sub => "-",
        Mul => "*",
        Div => "/",
        Pow => "**",
        Mod => " MOD ",
        IntDiv => " DIV ",
        Eq => " EQ ",
        Ne => " NE ",
        Gt => " GT ",
        Ge => " GE ",
        Lt => " LT ",
        Le => " LE ",
        And => " AND ",
        Or => " OR ",
        Xor => " XOR ",
        BitAnd => " BAND ",
        BitOr => " BOR ",
        BitXor => " BXOR ",
        Concat => " << ",
    }
}

fn flow_id(id: &FlowId) -> String {
    match id {
        FlowId::Nested => String::new(),
        FlowId::OWord(n) => format!(" (o{n})"),
        FlowId::Do(m) => format!(" (do{m})"),
    }
}

/// Kebab-case names of the IR's small enums.
fn kebab(debug: String) -> String {
    let mut out = String::new();
    for (i, ch) in debug.chars().enumerate() {
        if ch.is_ascii_uppercase() {
            if i > 0 {
                out.push('-');
            }
            out.push(ch.to_ascii_lowercase());
        } else {
            out.push(ch);
        }
    }
    out
}

fn name<T: std::fmt::Debug>(v: T) -> String {
    kebab(format!("{v:?}"))
}

mod stmts;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::emit::tests::{builder::*, programs};

    #[test]
    fn fanuc_program_as_text() {
        insta::assert_snapshot!(print_program(&programs::fanuc().p));
    }

    #[test]
    fn linuxcnc_program_as_text() {
        insta::assert_snapshot!(print_program(&programs::linuxcnc().p));
    }

    #[test]
    fn siemens_program_as_text() {
        insta::assert_snapshot!(print_program(&programs::siemens().p));
    }

    #[test]
    fn spans_on_request() {
        let mut b = Builder::new("fanuc");
        b.numbered(
            10,
            vec![
                mv(MotionKind::Linear, &[('X', "10"), ('Y', "2.5")]),
                StmtKind::Feed(n("100")),
            ],
        );
        b.line(vec![]);
        let plain = print_program(&b.p);
        assert_eq!(plain, "N10 motion linear X=10 Y=2.5 | feed 100\n(blank)\n");
        let spanned = print_program_with(
            &b.p,
            PrintOptions {
                spans: true,
                ..Default::default()
            },
        );
        assert_eq!(
            spanned,
            "N10 @0..3 motion linear X=10 Y=2.5 @4..7 | feed 100 @8..11\n@16..19\n"
        );
    }

    #[test]
    fn expressions_bracket_by_precedence() {
        use BinaryOp::*;
        let mut b = Builder::new("fanuc");
        let (a, c1, c2) = (b.var(Var::Numbered(1)), b.num("2"), b.num("3"));
        let sum = b.bin(Add, c1, c2);
        let prod = b.bin(Mul, a, sum);
        let sub = b.bin(Sub, prod, a);
        b.line(vec![StmtKind::Assign {
            var: Var::Named("x".into()),
            value: sub,
        }]);
        assert_eq!(print_program(&b.p), "assign #<x> = #1*(2+3)-#1\n");
    }
}
