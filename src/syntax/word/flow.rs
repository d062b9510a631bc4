//! Control-flow statements: Fanuc Macro B (`IF`, `GOTO`, `WHILE`/`DO`/`END`)
//! and LinuxCNC o-words (`o100 sub`, `o<name> call`, `if`, `while`, ...).

use super::cx::{Cx, PExpr};
use crate::dialect::Capability;
use crate::ir::{CallArgs, CallKind, CallTarget, FlowId, JumpDir, JumpTarget, Stmt, StmtKind, Var};
use crate::span::Span;

/// What follows the o-word: the statement keyword and its operands.
#[derive(Debug)]
pub enum OTail {
    Sub,
    EndSub(Option<PExpr>),
    Call(Vec<PExpr>),
    Return(Option<PExpr>),
    If(PExpr),
    ElseIf(PExpr),
    Else,
    EndIf,
    While(PExpr),
    EndWhile,
    Do,
    Repeat(PExpr),
    EndRepeat,
    Break,
    Continue,
}

/// An o-word's name: `100` or `<name>`, with its byte range.
#[derive(Clone, Copy, Debug)]
pub struct OName {
    pub l: usize,
    pub r: usize,
    pub named: bool,
}

impl<'a> Cx<'a> {
    fn macro_b(&self, span: Span) -> bool {
        self.require(Capability::MacroB, span, "Macro B statements")
    }

    fn goto_stmt(&self, t: PExpr, cond: Option<PExpr>) -> StmtKind {
        let cond = cond.map(|c| self.id(c));
        StmtKind::Goto {
            target: JumpTarget::Sequence(self.value(t)),
            dir: JumpDir::Either,
            cond,
        }
    }

    pub fn goto(&self, t: PExpr, l: usize, r: usize) {
        let span = self.span(l, r);
        if self.macro_b(span) {
            self.push_stmt(self.goto_stmt(t, None), span);
        }
    }

    pub fn if_goto(&self, c: PExpr, t: PExpr, l: usize, r: usize) {
        let span = self.span(l, r);
        if self.macro_b(span) {
            self.push_stmt(self.goto_stmt(t, Some(c)), span);
        }
    }

    pub fn if_then(&self, c: PExpr, v: (Var, Span), e: PExpr, l: usize, r: usize) {
        let span = self.span(l, r);
        if self.macro_b(span) {
            let then = Box::new(self.assign(v, e));
            self.push_stmt(
                StmtKind::IfThen {
                    cond: self.id(c),
                    then,
                },
                span,
            );
        }
    }

    /// The `m` of `DO m` / `END m`.
    fn do_id(&self, nl: usize, nr: usize) -> FlowId {
        FlowId::Do(self.whole(nl, nr, 255, "a DO/END loop number").unwrap_or(0) as u8)
    }

    pub fn while_do(&self, c: PExpr, nl: usize, nr: usize, l: usize) {
        let span = self.span(l, nr);
        if self.macro_b(span) {
            let id = self.do_id(nl, nr);
            self.push_stmt(
                StmtKind::While {
                    cond: self.id(c),
                    id,
                },
                span,
            );
        }
    }

    pub fn end_do(&self, nl: usize, nr: usize, l: usize) {
        let span = self.span(l, nr);
        if self.macro_b(span) {
            let id = self.do_id(nl, nr);
            self.push_stmt(StmtKind::EndWhile { id }, span);
        }
    }

    // ---- o-words

    /// `O1234`: a Fanuc program number.
    pub fn program_number(&self, nl: usize, nr: usize, l: usize) {
        let span = self.span(l, nr);
        if self.require(Capability::NumberedPrograms, span, "`O` program numbers") {
            let number = self.whole(nl, nr, u32::MAX, "a program number");
            self.push_stmt(StmtKind::ProgramStart { number, name: None }, span);
        }
    }

    /// `O<MyProgram>` alone on a line: a main program's title (LinuxCNC,
    /// rs274 2.9 runs what follows; its 13-named-program test).
    pub fn program_name(&self, nl: usize, nr: usize, l: usize) {
        let span = self.span(l, nr);
        if self.require(Capability::NumberedPrograms, span, "`O` program names")
            && self.require(Capability::OWords, span, "`O<name>` program names")
        {
            let name = Some(self.name_inside(nl, nr));
            self.push_stmt(StmtKind::ProgramStart { number: None, name }, span);
        }
    }

    /// The o-word as a flow id key: `100` (leading zeros dropped) or `<name>`
    /// (lower case: LinuxCNC names ignore case).
    fn oword_key(&self, n: OName) -> String {
        if n.named {
            format!("<{}>", self.name_inside(n.l, n.r).to_ascii_lowercase())
        } else {
            self.whole(n.l, n.r, u32::MAX, "an o-word number")
                .unwrap_or(0)
                .to_string()
        }
    }

    pub fn oword(&self, n: OName, t: OTail, l: usize, r: usize) {
        let span = self.span(l, r);
        if !self.require(Capability::OWords, span, "o-word statements") {
            return;
        }
        let key = self.oword_key(n);
        let kind = self.oword_kind(n, key, t);
        self.push_stmt(kind, span);
    }

    fn opt(&self, e: Option<PExpr>) -> Option<crate::ir::ExprId> {
        e.map(|e| self.id(e))
    }

    fn oword_kind(&self, n: OName, key: String, t: OTail) -> StmtKind {
        let id = FlowId::OWord(key.clone());
        match t {
            OTail::Sub => StmtKind::SubStart {
                name: key.trim_matches(['<', '>']).to_string(),
                params: Vec::new(),
                id,
            },
            OTail::EndSub(v) => StmtKind::SubEnd {
                id,
                value: self.opt(v),
            },
            OTail::Call(args) => self.ocall(n, &key, args),
            OTail::Return(v) => StmtKind::Return {
                id,
                value: self.opt(v),
            },
            OTail::If(c) => StmtKind::If {
                cond: self.id(c),
                id,
            },
            OTail::ElseIf(c) => StmtKind::ElseIf {
                cond: self.id(c),
                id,
            },
            OTail::Else => StmtKind::Else { id },
            OTail::EndIf => StmtKind::EndIf { id },
            OTail::While(c) => self.owhile(key, c),
            OTail::EndWhile => StmtKind::EndWhile { id },
            OTail::Do => {
                self.open_do.borrow_mut().push(key);
                StmtKind::Do { id }
            }
            OTail::Repeat(c) => StmtKind::Repeat {
                count: self.id(c),
                id,
            },
            OTail::EndRepeat => StmtKind::EndRepeat { id },
            OTail::Break => StmtKind::Break { id },
            OTail::Continue => StmtKind::Continue { id },
        }
    }

    /// `oN while [c]` closes an open `oN do`, else opens a while loop.
    fn owhile(&self, key: String, c: PExpr) -> StmtKind {
        let cond = self.id(c);
        let mut open = self.open_do.borrow_mut();
        match open.iter().rposition(|k| *k == key) {
            Some(i) => {
                open.remove(i);
                StmtKind::DoWhile {
                    cond,
                    id: FlowId::OWord(key),
                }
            }
            None => StmtKind::While {
                cond,
                id: FlowId::OWord(key),
            },
        }
    }

    pub fn ocall_computed(&self, e: PExpr, args: Vec<PExpr>, l: usize, r: usize) {
        let span = self.span(l, r);
        if !self.require(Capability::OWords, span, "o-word statements") {
            return;
        }
        let args = CallArgs::Positional(args.into_iter().map(|a| Some(self.id(a))).collect());
        let kind = StmtKind::Call {
            kind: CallKind::OWord,
            target: CallTarget::Computed(self.id(e)),
            args,
            repeat: None,
        };
        self.push_stmt(kind, span);
    }

    fn ocall(&self, n: OName, key: &str, args: Vec<PExpr>) -> StmtKind {
        let target = if n.named {
            CallTarget::Name(self.name_inside(n.l, n.r))
        } else {
            CallTarget::Number(key.parse().unwrap_or(0))
        };
        let args = CallArgs::Positional(args.into_iter().map(|a| Some(self.id(a))).collect());
        StmtKind::Call {
            kind: CallKind::OWord,
            target,
            args,
            repeat: None,
        }
    }

    pub fn assign_item(&self, v: (Var, Span), e: PExpr) {
        let s: Stmt = self.assign(v, e);
        self.push(s);
    }
}
