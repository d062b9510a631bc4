//! What the Klartext grammar builds ([`Node`]) and the context its actions
//! use ([`Ctx`]: the expression arena, spans, the block's tokens and
//! comments); [`Ctx::items`] turns a node into the line's items.

use super::lexer::Spanned3;
use super::token::{Kw, Tok};
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    Arena, BinaryOp, Decimal, Expr, ExprId, ExprKind, Func, Stmt, StmtKind, ToolRef, UnaryOp,
    Value, Var,
};
use crate::span::{FileId, Span};
use crate::syntax::{Address, Item, WordSyntax};

/// A word as the grammar reads it: `X+10`, `RL`, `DR-`, `FQ5`.
#[derive(Clone, Debug)]
pub struct WordNode {
    pub name: String,
    pub sign: Option<char>,
    pub value: Option<Operand>,
    pub l: usize,
    pub r: usize,
}

impl WordNode {
    pub fn new(
        name: String,
        sign: Option<char>,
        value: Option<Operand>,
        l: usize,
        r: usize,
    ) -> Self {
        WordNode {
            name,
            sign,
            value,
            l,
            r,
        }
    }
}

/// A value after an address or in an FN function.
#[derive(Clone, Debug)]
pub enum Operand {
    Num(Decimal, usize, usize),
    Expr(ExprId),
}

pub type Signed = (Option<char>, Operand);

/// A block as the grammar read it; `usize` fields are the file offset
/// where the token-by-token part starts.
#[derive(Clone, Debug)]
pub enum Node {
    Begin(usize),
    End(usize),
    BlkForm(Decimal, Vec<WordNode>),
    ToolDef(Option<ToolRef>, Vec<WordNode>),
    ToolCall(Option<ToolRef>, Vec<WordNode>),
    Path(Kw, Vec<WordNode>),
    Chamfer(Signed, Vec<WordNode>),
    Approach(bool, Vec<WordNode>),
    Label(String, usize, usize),
    CallLabel(usize),
    CallPgm(usize),
    FnAssign(
        Decimal,
        (Var, usize, usize),
        (Option<Signed>, Option<String>, Signed),
    ),
    FnIf(Decimal, Signed, String, Signed, String, usize, usize),
    FnOther(Decimal, usize),
    Formula((Var, usize, usize), ExprId),
    CyclDef(usize),
    CyclCall(Vec<WordNode>),
    PatternDef(usize),
    /// `TCH PROBE n ...` from the tokens at the index.
    TchProbe(usize),
    Stop(Vec<WordNode>),
    Words(Vec<WordNode>),
}

/// A `;` comment of one physical line: its text and byte range.
#[derive(Clone, Debug)]
pub struct LineComment {
    pub text: String,
    pub start: usize,
    pub end: usize,
}

pub struct Ctx<'a> {
    pub spec: &'a crate::dialect::DialectSpec,
    pub file: FileId,
    pub exprs: &'a mut Arena<Expr>,
    /// The block's tokens (for the parts read token by token).
    pub toks: &'a [Spanned3],
    /// The block's code text and the file offset where it starts.
    pub text: &'a str,
    pub base: usize,
    pub comments: &'a [LineComment],
    pub diags: Vec<Diagnostic>,
    /// `LBL n` of this block.
    pub label: Option<(String, Span)>,
    /// Comments used as cycle parameter labels (not repeated as comments).
    pub used_comments: Vec<usize>,
}

impl Ctx<'_> {
    pub fn span(&self, l: usize, r: usize) -> Span {
        Span::new(self.file, l, r)
    }

    fn alloc(&mut self, kind: ExprKind, l: usize, r: usize) -> ExprId {
        let span = self.span(l, r);
        self.exprs.alloc(Expr { kind, span })
    }

    pub fn var(&mut self, v: Var, l: usize, r: usize) -> ExprId {
        self.alloc(ExprKind::Var(v), l, r)
    }

    pub fn number(&mut self, d: Decimal, l: usize, r: usize) -> ExprId {
        self.alloc(ExprKind::Number(d), l, r)
    }

    pub fn binary(&mut self, op: BinaryOp, a: ExprId, b: ExprId, l: usize, r: usize) -> ExprId {
        self.alloc(ExprKind::Binary(op, a, b), l, r)
    }

    pub fn unary(&mut self, op: UnaryOp, a: ExprId, l: usize, r: usize) -> ExprId {
        self.alloc(ExprKind::Unary(op, a), l, r)
    }

    /// `SIN Q1`, `INT ( .. )`, `PI`: a function the TNC formula knows.
    pub fn func(&mut self, name: &str, arg: Option<ExprId>, l: usize, r: usize) -> ExprId {
        let f = match name {
            "SIN" => Some(Func::Sin),
            "COS" => Some(Func::Cos),
            "TAN" => Some(Func::Tan),
            "ASIN" => Some(Func::Asin),
            "ACOS" => Some(Func::Acos),
            "ATAN" => Some(Func::Atan),
            "SQRT" => Some(Func::Sqrt),
            "SQ" => Some(Func::Square),
            "ABS" => Some(Func::Abs),
            "INT" => Some(Func::Trunc),
            "LN" => Some(Func::Ln),
            "EXP" => Some(Func::Exp),
            "LOG" => Some(Func::Log10),
            "SGN" => Some(Func::Sign),
            _ => None,
        };
        match (f, arg) {
            (Some(f), Some(a)) => self.alloc(ExprKind::Call(f, vec![a]), l, r),
            // NEG x = -x.
            (None, Some(a)) if name == "NEG" => self.unary(UnaryOp::Neg, a, l, r),
            // FRAC x = x - INT x.
            (None, Some(a)) if name == "FRAC" => {
                let int = self.alloc(ExprKind::Call(Func::Trunc, vec![a]), l, r);
                self.binary(BinaryOp::Sub, a, int, l, r)
            }
            (None, None) if name == "PI" => self.number(
                Decimal::parse("3.14159265358979").unwrap_or(Decimal::from_int(3)),
                l,
                r,
            ),
            _ => {
                let what = if arg.is_some() {
                    format!("`{name}` is not a Klartext formula function")
                } else {
                    format!("`{name}` has no value in a formula")
                };
                self.error(Code::SyntaxError, l, r, what, "use SIN COS TAN ASIN ACOS ATAN SQRT SQ ABS INT FRAC NEG SGN LN LOG EXP, PI, Q parameters and numbers");
                self.number(Decimal::from_int(0), l, r)
            }
        }
    }

    pub fn error(&mut self, code: Code, l: usize, r: usize, msg: impl Into<String>, help: &str) {
        let d = Diagnostic::new(code, msg.into())
            .primary(self.span(l, r), "here")
            .help(help.to_string());
        self.diags.push(d);
    }

    /// A signed operand as a value: `-5` a negative number, `-Q1` an expression.
    pub fn value(&mut self, s: &Signed) -> Value {
        match (&s.0, &s.1) {
            (Some('-'), Operand::Num(d, ..)) => Value::Number(d.neg()),
            (_, Operand::Num(d, ..)) => Value::Number(*d),
            (Some('-'), Operand::Expr(e)) => {
                let sp = self.exprs[*e].span;
                let (l, r) = (sp.range().start, sp.range().end);
                Value::Expr(self.unary(UnaryOp::Neg, *e, l.saturating_sub(1), r))
            }
            (_, Operand::Expr(e)) => Value::Expr(*e),
        }
    }

    /// The value of a word, if it has one.
    pub fn word_value(&mut self, w: &WordNode) -> Option<Value> {
        let op = w.value.clone()?;
        Some(self.value(&(w.sign, op)))
    }

    /// A value as an expression (numbers get a node).
    pub fn expr_of(&mut self, v: &Value, l: usize, r: usize) -> ExprId {
        match v {
            Value::Number(d) => self.number(*d, l, r),
            Value::Expr(e) => *e,
        }
    }

    pub fn stmt(&self, kind: StmtKind, l: usize, r: usize) -> Item {
        Item::Stmt(Stmt::new(kind, self.span(l, r)))
    }

    /// An `M` word for the shared lowering (the spec's code table).
    pub fn m_word(&self, w: &WordNode, v: Value) -> Item {
        let span = self.span(w.l, w.r);
        Item::Word(WordSyntax {
            address: Address::new("M"),
            value: v,
            dim: None,
            extended: false,
            span,
            address_span: self.span(w.l, w.l + 1),
        })
    }

    /// The source text between two file offsets.
    pub fn slice(&self, l: usize, r: usize) -> &str {
        let s = l.saturating_sub(self.base).min(self.text.len());
        let e = r.saturating_sub(self.base).min(self.text.len()).max(s);
        self.text.get(s..e).unwrap_or("")
    }

    /// The tokens from file offset `l` on.
    pub fn toks_from(&self, l: usize) -> &[Spanned3] {
        let i = self
            .toks
            .iter()
            .position(|t| t.0 >= l)
            .unwrap_or(self.toks.len());
        &self.toks[i..]
    }

    /// The end of the block's code.
    pub fn end(&self) -> usize {
        self.base + self.text.len()
    }

    /// Tokens as a sequence of cycle words: `DIST25.000`, `X+0`, `DATUM`,
    /// `5`, `#5`, `HSC-MODE:0`, `V.IDO5`; `None` when something else is
    /// there.
    pub fn cycle_words(&mut self, toks: &[Spanned3]) -> Option<Vec<crate::ir::CycleWord>> {
        let mut out = Vec::new();
        let mut i = 0;
        while i < toks.len() {
            let (l, t, mut r) = toks[i].clone();
            let mut name = String::new();
            match t {
                Tok::Name(n) => {
                    name = n;
                    i += 1;
                    glue_name(toks, &mut i, &mut name, &mut r);
                }
                Tok::Kw(k) => {
                    name = format!("{k:?}").to_ascii_uppercase();
                    i += 1;
                }
                Tok::Hash => {
                    name = "#".into();
                    i += 1;
                }
                _ => {}
            }
            let mut sign = None;
            if let Some((_, Tok::Plus | Tok::Minus, _)) = toks.get(i) {
                if matches!(toks.get(i + 1), Some((_, Tok::Num(_) | Tok::Q(..), _))) {
                    sign = Some(if toks[i].1 == Tok::Minus { '-' } else { '+' });
                    i += 1;
                }
            }
            let value = match toks.get(i) {
                Some((a, Tok::Num(d), b)) => {
                    i += 1;
                    r = *b;
                    Some(self.value(&(sign, Operand::Num(*d, *a, *b))))
                }
                Some((a, Tok::Q(bank, n), b)) => {
                    i += 1;
                    r = *b;
                    let e = self.var(Var::Q(*bank, *n), *a, *b);
                    Some(self.value(&(sign, Operand::Expr(e))))
                }
                _ => None,
            };
            if name.is_empty() && value.is_none() {
                return None;
            }
            out.push(crate::ir::CycleWord {
                name,
                value,
                span: self.span(l, r),
            });
        }
        Some(out)
    }
}

/// A cycle word's name goes on over `-`, `.` and `:` written against it
/// and the letters after them (`HSC-MODE:` of `HSC-MODE:0`, `V.IDO` of
/// the Hungarian `V.IDO5`); `r` becomes its end.
fn glue_name(toks: &[Spanned3], i: &mut usize, name: &mut String, r: &mut usize) {
    while let Some((a, t, b)) = toks.get(*i) {
        if *a != *r {
            return;
        }
        let piece = match t {
            Tok::Minus if matches!(toks.get(*i + 1), Some((c, Tok::Name(_), _)) if *c == *b) => "-",
            Tok::Dot if matches!(toks.get(*i + 1), Some((c, Tok::Name(_), _)) if *c == *b) => ".",
            Tok::Colon => ":",
            Tok::Name(n) if name.ends_with(['-', '.']) => n.as_str(),
            _ => return,
        };
        name.push_str(piece);
        *r = *b;
        *i += 1;
    }
}
