//! Builds programs in the IR by hand for writer and printer tests: each
//! statement gets a fresh, distinct span so diagnostics can be checked.

use crate::ir::*;
use crate::span::{FileId, Span, Spanned};

pub struct Builder {
    pub p: Program,
    pos: u32,
}

pub fn d(s: &str) -> Decimal {
    Decimal::parse(s).unwrap()
}

pub fn n(s: &str) -> Value {
    Value::Number(d(s))
}

pub fn c(s: &str) -> Coord {
    Coord {
        value: n(s),
        dim: None,
        span: Span::default(),
    }
}

pub fn axes(list: &[(char, &str)]) -> Axes {
    let mut a = Axes::default();
    for (l, v) in list {
        *a.slot_mut(*l).unwrap() = Some(c(v));
    }
    a
}

pub fn mv(kind: MotionKind, list: &[(char, &str)]) -> StmtKind {
    StmtKind::Motion(Box::new(Motion {
        target: axes(list),
        ..Motion::new(kind)
    }))
}

impl Builder {
    pub fn new(dialect: &str) -> Self {
        Builder {
            p: Program::new(FileId(0), dialect),
            pos: 0,
        }
    }

    pub fn span(&mut self) -> Span {
        let s = Span::new(FileId(0), self.pos as usize, self.pos as usize + 3);
        self.pos += 4;
        s
    }

    pub fn e(&mut self, kind: ExprKind) -> ExprId {
        let span = self.span();
        self.p.exprs.alloc(Expr { kind, span })
    }

    pub fn num(&mut self, s: &str) -> ExprId {
        self.e(ExprKind::Number(d(s)))
    }

    pub fn var(&mut self, v: Var) -> ExprId {
        self.e(ExprKind::Var(v))
    }

    pub fn bin(&mut self, op: BinaryOp, a: ExprId, b: ExprId) -> ExprId {
        self.e(ExprKind::Binary(op, a, b))
    }

    pub fn stmt(&mut self, kind: StmtKind) -> Stmt {
        let span = self.span();
        Stmt::new(kind, span)
    }

    /// Appends a block of statements; returns its index.
    pub fn line(&mut self, kinds: Vec<StmtKind>) -> usize {
        let span = self.span();
        let stmts = kinds.into_iter().map(|k| self.stmt(k)).collect();
        self.p.blocks.push(Block {
            span,
            skip: None,
            number: None,
            label: None,
            stmts,
        });
        self.p.blocks.len() - 1
    }

    /// Appends a block numbered `N{num}`.
    pub fn numbered(&mut self, num: u32, kinds: Vec<StmtKind>) -> usize {
        let i = self.line(kinds);
        let span = self.span();
        self.p.blocks[i].number = Some(Spanned::new(num, span));
        i
    }

    pub fn labelled(&mut self, label: &str, kinds: Vec<StmtKind>) -> usize {
        let i = self.line(kinds);
        let span = self.span();
        self.p.blocks[i].label = Some(Box::new(Spanned::new(label.to_string(), span)));
        i
    }

    pub fn skip(&mut self, i: usize, level: u8) {
        let span = self.span();
        self.p.blocks[i].skip = Some(Spanned::new(level, span));
    }

    /// The span of statement `s` of block `b`.
    pub fn stmt_span(&self, b: usize, s: usize) -> Span {
        self.p.blocks[b].stmts[s].span
    }
}
