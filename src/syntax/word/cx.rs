//! The parse context the grammar's actions build with: the line, the
//! dialect, the expression arena, and where items and diagnostics go.
//! Actions stay one line in the grammar; the work is done here.

use super::lexer::Tok;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::num::NumberError;
use crate::ir::{
    Arena, BinaryOp, Decimal, Expr, ExprId, ExprKind, Stmt, StmtKind, UnaryOp, Value, Var,
};
use crate::span::{FileId, Span};
use crate::syntax::{Item, WordSyntax};
use lalrpop_util::ErrorRecovery;
use std::cell::RefCell;

/// An expression while it is being parsed: a literal stays unallocated
/// until something combines it, so `X-1.5` never touches the arena.
#[derive(Clone, Copy, Debug)]
pub struct PExpr {
    pub v: PV,
    pub span: Span,
    /// Ends in arithmetic outside brackets (`#1/2`, not `[#1/2]`).
    pub arith: bool,
}

#[derive(Clone, Copy, Debug)]
pub enum PV {
    Lit(Decimal),
    Id(ExprId),
}

/// A recovered syntax error, as LALRPOP hands it over.
pub type Recovered = ErrorRecovery<usize, Tok, ()>;

pub struct Cx<'a> {
    pub text: &'a str,
    pub file: FileId,
    pub offset: u32,
    pub spec: &'a DialectSpec,
    pub exprs: RefCell<&'a mut Arena<Expr>>,
    pub diags: RefCell<&'a mut Vec<Diagnostic>>,
    pub items: RefCell<Vec<Item>>,
    pub errors: RefCell<Vec<Recovered>>,
    /// O-words of `do` loops still open (a `while` with one closes it).
    pub open_do: RefCell<&'a mut Vec<String>>,
    pub unknown_seen: std::cell::Cell<bool>,
}

impl<'a> Cx<'a> {
    pub fn span(&self, l: usize, r: usize) -> Span {
        Span::new(
            self.file,
            l + self.offset as usize,
            r + self.offset as usize,
        )
    }

    /// The line text of a file span.
    pub fn slice(&self, s: Span) -> &'a str {
        let o = self.offset as usize;
        self.text
            .get(s.start as usize - o..s.end as usize - o)
            .unwrap_or("")
    }

    pub fn has(&self, cap: Capability) -> bool {
        self.spec.has(cap)
    }

    pub fn diag(&self, d: Diagnostic) {
        self.diags.borrow_mut().push(d);
    }

    pub fn push_stmt(&self, kind: StmtKind, span: Span) {
        self.items
            .borrow_mut()
            .push(Item::Stmt(Stmt::new(kind, span)));
    }

    pub fn recover(&self, e: Recovered) {
        self.errors.borrow_mut().push(e);
    }

    /// Reports a construct the dialect lacks; true when it is allowed.
    pub fn require(&self, cap: Capability, span: Span, what: &str) -> bool {
        if self.has(cap) {
            return true;
        }
        self.diag(
            Diagnostic::new(
                Code::NotInDialect,
                format!("{what} are not part of this dialect"),
            )
            .primary(span, format!("needs the `{}` capability", cap.name()))
            .help("choose the dialect the program was written for with `--dialect`"),
        );
        false
    }

    /// Numbered and indirect `#` parameters: Macro B or LinuxCNC.
    pub fn require_params(&self, span: Span) {
        let ok = self.has(Capability::MacroB)
            || self.has(Capability::OWords)
            || self.has(Capability::NamedParameters);
        if !ok {
            self.require(Capability::MacroB, span, "`#` parameters");
        }
    }

    // ---- expressions

    pub fn alloc(&self, kind: ExprKind, span: Span) -> ExprId {
        self.exprs.borrow_mut().alloc(Expr { kind, span })
    }

    pub fn id(&self, p: PExpr) -> ExprId {
        match p.v {
            PV::Id(id) => id,
            PV::Lit(d) => self.alloc(ExprKind::Number(d), p.span),
        }
    }

    fn node(&self, kind: ExprKind, span: Span, arith: bool) -> PExpr {
        PExpr {
            v: PV::Id(self.alloc(kind, span)),
            span,
            arith,
        }
    }

    /// Reads a number token exactly; a bad one is reported and read as 0.
    pub fn decimal(&self, l: usize, r: usize) -> Decimal {
        let span = self.span(l, r);
        match Decimal::parse(&self.text[l..r]) {
            Ok(d) => d,
            Err(e) => {
                self.diag(number_error(e, span));
                Decimal::ZERO
            }
        }
    }

    pub fn number(&self, l: usize, r: usize) -> PExpr {
        PExpr {
            v: PV::Lit(self.decimal(l, r)),
            span: self.span(l, r),
            arith: false,
        }
    }

    /// A whole number that fits `max`, or a reported error.
    pub fn whole(&self, l: usize, r: usize, max: u32, what: &str) -> Option<u32> {
        let d = self.decimal(l, r);
        let v = d
            .as_int()
            .filter(|v| (0..=max as i64).contains(v))
            .filter(|_| !d.point || d.scale == 0);
        if v.is_none() && !self.text[l..r].is_empty() {
            self.diag(
                Diagnostic::new(
                    Code::InvalidValue,
                    format!("{what} must be a whole number from 0 to {max}"),
                )
                .primary(self.span(l, r), "not a valid number here")
                .help(format!("write {what} as a whole number")),
            );
        }
        v.map(|v| v as u32)
    }

    pub fn bin(&self, op: BinaryOp, a: PExpr, b: PExpr) -> PExpr {
        let span = a.span.to(b.span);
        let (x, y) = (self.id(a), self.id(b));
        self.node(ExprKind::Binary(op, x, y), span, true)
    }

    pub fn pow(&self, a: PExpr, b: PExpr, ol: usize, or: usize) -> PExpr {
        self.require(Capability::PowerOperator, self.span(ol, or), "`**` powers");
        self.bin(BinaryOp::Pow, a, b)
    }

    pub fn neg(&self, l: usize, e: PExpr) -> PExpr {
        let span = Span {
            start: self.span(l, l).start,
            ..e.span
        };
        match e.v {
            PV::Lit(d) if !e.arith => PExpr {
                v: PV::Lit(d.neg()),
                span,
                arith: false,
            },
            PV::Lit(_) | PV::Id(_) => {
                let id = self.id(e);
                self.node(ExprKind::Unary(UnaryOp::Neg, id), span, e.arith)
            }
        }
    }

    pub fn plus(&self, l: usize, e: PExpr) -> PExpr {
        PExpr {
            span: Span {
                start: self.span(l, l).start,
                ..e.span
            },
            ..e
        }
    }

    /// `[e]`: the expression's span grows to take in the brackets.
    pub fn bracket(&self, e: PExpr, l: usize, r: usize) -> PExpr {
        let span = self.span(l, r);
        if let PV::Id(id) = e.v {
            self.exprs.borrow_mut()[id].span = span;
        }
        PExpr {
            arith: false,
            span,
            ..e
        }
    }

    pub fn var_expr(&self, v: (Var, Span)) -> PExpr {
        self.node(ExprKind::Var(v.0), v.1, false)
    }

    pub fn var_num(&self, nl: usize, nr: usize, l: usize) -> (Var, Span) {
        let span = self.span(l, nr);
        self.require_params(span);
        let n = self
            .whole(nl, nr, u32::MAX, "a parameter number")
            .unwrap_or(0);
        (Var::Numbered(n), span)
    }

    pub fn var_named(&self, nl: usize, nr: usize, l: usize) -> (Var, Span) {
        let span = self.span(l, nr);
        self.require(Capability::NamedParameters, span, "`#<name>` parameters");
        (Var::Named(self.name_inside(nl, nr)), span)
    }

    pub fn var_indirect(&self, e: PExpr, l: usize, r: usize) -> (Var, Span) {
        let span = self.span(l, r);
        self.require_params(span);
        (Var::Indirect(self.id(e)), span)
    }

    pub fn var_of_var(&self, v: (Var, Span), l: usize, r: usize) -> (Var, Span) {
        let span = self.span(l, r);
        let inner = self.var_expr(v);
        (Var::Indirect(self.id(inner)), span)
    }

    /// The text between `<` and `>`, as written.
    pub fn name_inside(&self, l: usize, r: usize) -> String {
        self.text
            .get(l + 1..r.saturating_sub(1))
            .unwrap_or("")
            .to_string()
    }

    pub fn call(&self, nl: usize, nr: usize, args: Vec<PExpr>, l: usize, r: usize) -> PExpr {
        let span = self.span(l, r);
        let name = &self.text[nl..nr];
        let Some(f) = self.spec.function(name) else {
            self.diag(
                Diagnostic::new(Code::UnknownKeyword, format!("`{name}` is not a function of this dialect"))
                    .primary(self.span(nl, nr), "unknown function")
                    .help("check the spelling; functions are SIN COS TAN ASIN ACOS ATAN SQRT ABS ROUND FIX FUP LN EXP and the like"),
            );
            return PExpr {
                arith: false,
                span,
                ..args[0]
            };
        };
        if f.arity != args.len() {
            self.diag(
                Diagnostic::new(
                    Code::SyntaxError,
                    format!(
                        "`{name}` takes {} argument(s), {} given",
                        f.arity,
                        args.len()
                    ),
                )
                .primary(span, "wrong number of arguments")
                .help(format!("give `{name}` {} argument(s)", f.arity)),
            );
        }
        let ids = args.iter().map(|a| self.id(*a)).collect();
        self.node(ExprKind::Call(f.func, ids), span, false)
    }

    pub fn atan_slash(&self, a: PExpr, b: PExpr, l: usize, r: usize) -> PExpr {
        let (x, y) = (self.id(a), self.id(b));
        self.node(ExprKind::AtanSlash(x, y), self.span(l, r), false)
    }

    pub fn atan2(&self, a: PExpr, b: PExpr, l: usize, r: usize) -> PExpr {
        let ids = vec![self.id(a), self.id(b)];
        self.node(
            ExprKind::Call(crate::ir::Func::Atan2, ids),
            self.span(l, r),
            false,
        )
    }

    pub fn exists(&self, v: (Var, Span), l: usize, r: usize) -> PExpr {
        let span = self.span(l, r);
        self.require(Capability::NamedParameters, span, "`EXISTS[#<name>]` tests");
        let kind = match v.0 {
            Var::Named(name) => ExprKind::Exists(name),
            Var::Numbered(n) => {
                let num = self.node(
                    ExprKind::Number(crate::ir::Decimal::from_int(n as i64)),
                    v.1,
                    false,
                );
                ExprKind::ExistsNumbered(self.id(num))
            }
            Var::Indirect(e) => ExprKind::ExistsNumbered(e),
            other => {
                let e = self.node(ExprKind::Var(other), v.1, false);
                ExprKind::ExistsNumbered(self.id(e))
            }
        };
        self.node(kind, span, false)
    }

    // ---- words and simple statements

    pub fn value(&self, p: PExpr) -> Value {
        match p.v {
            PV::Lit(d) => Value::Number(d),
            PV::Id(id) => Value::Expr(id),
        }
    }

    pub fn word(&self, letter: u8, l: usize, v: PExpr, r: usize) {
        if matches!(letter, b'@' | b'^') {
            self.require(
                Capability::PolarWords,
                self.span(l, l + 1),
                "polar words `@` and `^`",
            );
        }
        self.push_word(char::from(letter).to_string(), l, l + 1, v, r);
    }

    /// Fanuc `,C` chamfer and `,R` corner rounding words.
    pub fn comma_word(&self, letter: u8, l: usize, v: PExpr, r: usize) {
        self.require(
            Capability::CommaCornerWords,
            self.span(l, l + 2),
            "`,C` / `,R` corner words",
        );
        self.push_word(
            format!(",{}", char::from(letter)),
            l,
            self.letter_end(l),
            v,
            r,
        );
    }

    /// The end of `,R` (spaces may stand between comma and letter).
    fn letter_end(&self, l: usize) -> usize {
        let b = self.text.as_bytes();
        (l + 1..b.len())
            .find(|&i| b[i].is_ascii_alphabetic())
            .map_or(l + 1, |i| i + 1)
    }

    fn push_word(&self, address: String, l: usize, ar: usize, v: PExpr, r: usize) {
        if v.arith && !self.has(crate::dialect::Capability::UnbracketedExpressions) {
            self.unbracketed(&address, v.span);
        }
        let w = WordSyntax {
            address: address.into(),
            value: self.value(v),
            dim: None,
            extended: false,
            span: self.span(l, r),
            address_span: self.span(l, ar),
        };
        self.items.borrow_mut().push(Item::Word(w));
    }

    fn unbracketed(&self, address: &str, span: Span) {
        let text = self.slice(span);
        self.diag(
            Diagnostic::new(
                Code::UnbracketedExpression,
                "arithmetic in a word value needs brackets in this dialect",
            )
            .primary(span, "unbracketed expression")
            .help(format!("write {address}[{text}]")),
        );
    }

    pub fn tape(&self, l: usize, r: usize) {
        self.push_stmt(StmtKind::Tape, self.span(l, r));
    }

    pub fn assign(&self, v: (Var, Span), e: PExpr) -> Stmt {
        let span = v.1.to(e.span);
        Stmt::new(
            StmtKind::Assign {
                var: v.0,
                value: self.id(e),
            },
            span,
        )
    }

    pub fn push(&self, s: Stmt) {
        self.items.borrow_mut().push(Item::Stmt(s));
    }

    pub fn unknown_keyword(&self, l: usize, r: usize) {
        // Report the first unknown name of a line only: text such as
        // `[put the XY pairs here]` would otherwise give one per word.
        if self.unknown_seen.replace(true) {
            return;
        }
        let name = &self.text[l..r];
        if name.as_bytes()[0].eq_ignore_ascii_case(&b'O') && self.has(Capability::NumberedPrograms)
        {
            return self.diag(
                Diagnostic::new(
                    Code::UnknownKeyword,
                    format!("`{name}` is not a program number"),
                )
                .primary(self.span(l, r), "programs are numbered in this dialect")
                .help(format!(
                    "write a number and keep the name as a comment: `O1234 ({})`",
                    &name[1..]
                )),
            );
        }
        self.diag(
            Diagnostic::new(Code::UnknownKeyword, format!("`{name}` is not a keyword of this dialect"))
                .primary(self.span(l, r), "unknown keyword")
                .help("an address is a single letter followed by its value, as in `G1` or `X10.`; put other text in a comment"),
        );
    }
}

/// The diagnostic for a number `Decimal::parse` refused.
pub fn number_error(e: NumberError, span: Span) -> Diagnostic {
    match e {
        NumberError::Malformed => Diagnostic::new(Code::MalformedNumber, "malformed number")
            .primary(span, "not a number")
            .help("a number has digits and at most one decimal point, as in `1.25` or `.5`"),
        NumberError::TooLong => Diagnostic::new(Code::NumberTooLong, "number has too many digits")
            .primary(span, "more than 18 significant digits")
            .help("shorten the number"),
    }
}
