//! Loop and conditional forms in the target's own syntax. A structure's
//! [`FlowId`] says its form: Fanuc `DO m` (WHILE only, m = 1..3 by
//! nesting), Siemens nesting (`WHILE`/`ENDWHILE`, `IF`/`ENDIF`), LinuxCNC
//! o-words (`o100 while`). A form the target has is kept; otherwise the
//! structure takes the first the target offers of: nesting, o-words
//! (numbered from o1000 up), Macro B DO ids (loops only). Openers and
//! closers are matched with a stack, as the structure check has already
//! made sure they pair up. What has no form is E0614.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{FlowId, Program, StmtKind};
use crate::span::Span;

struct Ids<'a> {
    to: &'a DialectSpec,
    /// The open structures: their new id and whether they are loops.
    stack: Vec<(FlowId, bool)>,
    next_oword: u32,
    diags: &'a mut Vec<Diagnostic>,
}

#[derive(Clone, Copy, PartialEq)]
enum Role {
    /// Opens a structure (`true`: a loop).
    Open(bool),
    /// ELSE/ELSEIF: of the innermost structure.
    Middle,
    /// BREAK/CONTINUE: of the innermost loop.
    LoopExit,
    Close,
}

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let mut ids = Ids {
        to,
        stack: Vec::new(),
        next_oword: 1000,
        diags,
    };
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let span = s.span;
            let (id, role, is_while) = match &mut s.kind {
                StmtKind::While { id, .. } => (id, Role::Open(true), true),
                StmtKind::EndWhile { id } => (id, Role::Close, true),
                StmtKind::If { id, .. } => (id, Role::Open(false), false),
                StmtKind::Do { id } | StmtKind::Repeat { id, .. } => (id, Role::Open(true), false),
                StmtKind::ElseIf { id, .. } | StmtKind::Else { id } => (id, Role::Middle, false),
                StmtKind::Break { id } | StmtKind::Continue { id } => (id, Role::LoopExit, false),
                StmtKind::EndIf { id }
                | StmtKind::DoWhile { id, .. }
                | StmtKind::EndRepeat { id } => (id, Role::Close, false),
                _ => continue,
            };
            ids.fix(id, role, is_while, span);
        }
    }
}

fn cap_of(id: &FlowId) -> Capability {
    match id {
        FlowId::Nested => Capability::StructuredControl,
        FlowId::OWord(_) => Capability::OWords,
        FlowId::Do(_) => Capability::MacroB,
    }
}

impl Ids<'_> {
    fn fix(&mut self, id: &mut FlowId, role: Role, is_while: bool, span: Span) {
        match role {
            Role::Open(is_loop) => {
                let new = self.choose(id, is_while, span);
                self.stack.push((new.clone(), is_loop));
                *id = new;
            }
            Role::Middle => {
                if let Some((top, _)) = self.stack.last() {
                    *id = top.clone();
                }
            }
            Role::LoopExit => {
                if let Some((top, _)) = self.stack.iter().rev().find(|(_, l)| *l) {
                    *id = top.clone();
                }
            }
            Role::Close => {
                if let Some((top, _)) = self.stack.pop() {
                    *id = top;
                }
            }
        }
    }

    fn choose(&mut self, id: &FlowId, is_while: bool, span: Span) -> FlowId {
        if self.to.has(cap_of(id)) && !matches!(id, FlowId::Do(_)) {
            return id.clone();
        }
        if self.to.has(Capability::StructuredControl) {
            return FlowId::Nested;
        }
        if self.to.has(Capability::OWords) {
            self.next_oword += 1;
            return FlowId::OWord(self.next_oword.to_string());
        }
        let depth = self
            .stack
            .iter()
            .filter(|(i, _)| matches!(i, FlowId::Do(_)))
            .count() as u8;
        if is_while && self.to.has(Capability::MacroB) && depth < 3 {
            return FlowId::Do(depth + 1);
        }
        if !is_while || !self.to.has(Capability::MacroB) {
            return id.clone(); // the writer names what it cannot write
        }
        self.diags.push(
            Diagnostic::new(
                Code::PortControlFlow,
                format!("{} nests at most three DO loops", self.to.name),
            )
            .primary(span, "a fourth nested loop")
            .help("move the inner loop into a subprogram"),
        );
        id.clone()
    }
}
