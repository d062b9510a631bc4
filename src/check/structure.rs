//! Program structure, checked while the blocks stream past: control-flow
//! openers and closers pair up (E0302, E0303), jumps and local calls find
//! their targets (E0301), labels and subprograms are defined once (E0304),
//! `return`/`break` sit where they can (E0306), and a program that must
//! end does (E0305).
//!
//! Memory grows with the open structures, labels and unresolved jumps,
//! never with the number of blocks. Labels are scoped per program: a
//! `ProgramStart` (`O1234`) begins a new scope for sequence numbers.

mod jumps;

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Arena, Block, Expr, FlowId, Stmt, StmtKind, StopKind};
use crate::span::Span;
use jumps::Labels;
use std::collections::HashMap;

use crate::ir::FlowKind as Opener;

impl Opener {
    fn word(self) -> &'static str {
        match self {
            Opener::If => "IF",
            Opener::While => "WHILE",
            Opener::Do => "DO",
            Opener::Repeat => "REPEAT",
            Opener::For => "FOR",
            Opener::Loop => "LOOP",
            Opener::RepeatUntil => "REPEAT",
            Opener::Sub => "SUB",
        }
    }
}

/// Names a structure as written: `o100 IF`, `DO 1`, `WHILE`.
fn describe(kind: Opener, id: &FlowId) -> String {
    match id {
        FlowId::Nested => kind.word().to_string(),
        FlowId::OWord(o) => format!("o{o} {}", kind.word().to_ascii_lowercase()),
        FlowId::Do(m) if kind == Opener::While => format!("WHILE .. DO {m}"),
        FlowId::Do(m) => format!("{} {m}", kind.word()),
    }
}

/// Names a closer as written: `ENDIF`, `o100 endif`, `END 2`.
fn closer(word: &str, id: &FlowId) -> String {
    match id {
        FlowId::Nested => word.to_string(),
        FlowId::OWord(o) => format!("o{o} {}", word.to_ascii_lowercase()),
        FlowId::Do(m) => format!("END {m}"),
    }
}

#[derive(Clone, Debug)]
struct Open {
    kind: Opener,
    id: FlowId,
    span: Span,
}

/// The streaming structure checker (see the module doc).
pub struct StructureChecker {
    end_required: bool,
    /// A program number given twice is no error (the first is called).
    first_program_wins: bool,
    /// `strict-sub-styles`: an M99 inside an o-word sub is an error.
    strict_sub_styles: bool,
    /// `main-return-ends`: an M99 outside any sub ends the program as M2.
    main_return_ends: bool,
    /// o-word subs called from the main program since its last M2/M30
    /// (lower case), for `strict-sub-styles`.
    called_in_main: std::collections::HashSet<String>,
    stack: Vec<Open>,
    /// How many `Sub` openers `stack` holds (kept so that asking is O(1)
    /// however deep the nesting).
    subs_open: usize,
    diags: Vec<Diagnostic>,
    /// Sequence numbers and labels of the current program.
    labels: Labels,
    subs: HashMap<String, Span>,
    programs: HashMap<u32, Span>,
    /// Inside a Siemens `PROC` (ends with the file).
    in_proc: bool,
    saw_end: bool,
    /// The last statement of the main program (outside subroutines).
    last_main: Option<Span>,
}

impl StructureChecker {
    pub fn new(spec: &DialectSpec) -> Self {
        StructureChecker {
            end_required: spec.has(Capability::ProgramEndRequired),
            first_program_wins: spec.has(Capability::FirstProgramWins),
            strict_sub_styles: spec.has(Capability::StrictSubStyles),
            called_in_main: Default::default(),
            main_return_ends: spec.has(Capability::MainReturnEnds),
            stack: Vec::new(),
            subs_open: 0,
            diags: Vec::new(),
            labels: Labels::new(spec.family == crate::dialect::Family::Klartext),
            subs: HashMap::new(),
            programs: HashMap::new(),
            in_proc: false,
            saw_end: false,
            last_main: None,
        }
    }

    /// Feeds the next block.
    pub fn block(&mut self, _index: usize, block: &Block, _exprs: &Arena<Expr>) {
        if block
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ProgramStart { .. }))
        {
            self.labels.close_scope(&mut self.diags);
        }
        if let Some(n) = &block.number {
            self.labels.define_number(n.node);
        }
        if let Some(l) = &block.label {
            let first = self.labels.define_label(&l.node, l.span);
            self.duplicate(first, l.span, &format!("label `{}`", l.node));
        }
        for s in &block.stmts {
            self.stmt(s);
        }
    }

    /// Reports what is still open or unresolved, and a missing program end.
    pub fn finish(mut self) -> Vec<Diagnostic> {
        self.labels.close_scope(&mut self.diags);
        self.subs_open = 0;
        for open in std::mem::take(&mut self.stack) {
            let name = describe(open.kind, &open.id);
            self.diags.push(
                Diagnostic::new(Code::UnbalancedBlock, format!("`{name}` is never closed"))
                    .primary(open.span, "opened here")
                    .help(format!("add the statement that closes this `{name}`")),
            );
        }
        self.check_end();
        self.diags
    }

    fn check_end(&mut self) {
        let Some(last) = self.last_main else { return };
        if self.end_required && !self.saw_end {
            self.diags.push(
                Diagnostic::new(
                    Code::NoProgramEnd,
                    "the program ends without M2, M30 or a closing `%`",
                )
                .primary(last, "the program's last statement")
                .help("end the program with `M2` or `M30`"),
            );
        }
    }

    fn in_sub(&self) -> bool {
        self.in_proc || self.subs_open > 0
    }

    fn stmt(&mut self, s: &Stmt) {
        self.track_content(s);
        self.flow(s);
        self.labels.jumps(s);
    }

    /// Notes program ends and the main program's statements.
    fn track_content(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Stop(StopKind::End | StopKind::EndRewind) => {
                self.saw_end = true;
                self.called_in_main.clear();
            }
            StmtKind::SubReturn { .. } if self.main_return_ends && !self.in_sub() => {
                self.saw_end = true;
                self.called_in_main.clear();
            }
            StmtKind::Call {
                kind: crate::ir::CallKind::OWord,
                target,
                ..
            } if !self.in_sub() => {
                let name = match target {
                    crate::ir::CallTarget::Number(n) => n.to_string(),
                    crate::ir::CallTarget::Name(n) => n.to_ascii_lowercase(),
                    crate::ir::CallTarget::Computed(_) => String::new(),
                };
                self.called_in_main.insert(name);
                self.last_main = Some(s.span);
            }
            StmtKind::Tape if self.last_main.is_some() => self.saw_end = true,
            StmtKind::Tape | StmtKind::Comment { .. } | StmtKind::ProgramStart { .. } => {}
            StmtKind::SubStart { .. } | StmtKind::SubEnd { .. } => {}
            _ if self.in_sub() => {}
            _ => self.last_main = Some(s.span),
        }
    }

    /// Openers, middles and closers.
    fn flow(&mut self, s: &Stmt) {
        use Opener as O;
        let sp = s.span;
        match &s.kind {
            StmtKind::If { id, .. } => self.open(O::If, id, sp),
            StmtKind::ElseIf { id, .. } | StmtKind::Else { id } => self.middle(O::If, id, sp),
            StmtKind::EndIf { id } => self.close(&[O::If], id, sp, "ENDIF"),
            StmtKind::While {
                id: id @ FlowId::OWord(_),
                ..
            } if self.top_is(O::Do, id) => self.close(&[O::Do], id, sp, "WHILE"),
            StmtKind::While { id, .. } => self.open(O::While, id, sp),
            StmtKind::EndWhile { id } => self.close(&[O::While, O::Do], id, sp, "ENDWHILE"),
            StmtKind::Do { id } => self.open(O::Do, id, sp),
            StmtKind::DoWhile { id, .. } => self.close(&[O::Do], id, sp, "WHILE"),
            StmtKind::Repeat { id, .. } => self.open(O::Repeat, id, sp),
            StmtKind::EndRepeat { id } => self.close(&[O::Repeat], id, sp, "ENDREPEAT"),
            StmtKind::For { .. } => self.open(O::For, &FlowId::Nested, sp),
            StmtKind::EndFor => self.close(&[O::For], &FlowId::Nested, sp, "ENDFOR"),
            StmtKind::Loop => self.open(O::Loop, &FlowId::Nested, sp),
            StmtKind::EndLoop => self.close(&[O::Loop], &FlowId::Nested, sp, "ENDLOOP"),
            StmtKind::RepeatUntil => self.open(O::RepeatUntil, &FlowId::Nested, sp),
            StmtKind::Until { .. } => self.close(&[O::RepeatUntil], &FlowId::Nested, sp, "UNTIL"),
            StmtKind::SubStart { name, id, .. } => self.sub_start(name, id, sp),
            StmtKind::SubEnd { id, .. } => self.close(&[O::Sub], id, sp, "ENDSUB"),
            StmtKind::Return { .. } => self.misplaced_return(sp),
            StmtKind::SubReturn { .. } => self.return_in_oword_sub(sp),
            StmtKind::Break { id } => self.misplaced_break(id, sp, "break"),
            StmtKind::Continue { id } => self.misplaced_break(id, sp, "continue"),
            StmtKind::ProgramStart {
                number: Some(n), ..
            } => {
                let first = self.programs.get(n).copied();
                if !self.first_program_wins {
                    self.duplicate(first, sp, &format!("program O{n}"));
                }
                self.programs.entry(*n).or_insert(sp);
            }
            _ => {}
        }
    }

    fn top_is(&self, kind: Opener, id: &FlowId) -> bool {
        self.stack
            .last()
            .map(|o| o.kind == kind && o.id == *id)
            .unwrap_or(false)
    }

    fn open(&mut self, kind: Opener, id: &FlowId, span: Span) {
        if kind == Opener::Sub {
            self.subs_open += 1;
        }
        self.stack.push(Open {
            kind,
            id: id.clone(),
            span,
        });
    }

    /// `ELSE`/`ELSEIF`: the innermost open structure must be its `IF`.
    fn middle(&mut self, kind: Opener, id: &FlowId, span: Span) {
        if self.top_is(kind, id) {
            return;
        }
        self.mismatch_or_unopened(span, &closer("ELSE", id), kind);
    }

    /// A closer: pops its opener, or reports what it finds instead.
    fn close(&mut self, accepts: &[Opener], id: &FlowId, span: Span, word: &str) {
        let word = &closer(word, id);
        let fits = |o: &Open| accepts.contains(&o.kind) && o.id == *id;
        let Some(top) = self.stack.last() else {
            return self.unopened(span, word, accepts[0]);
        };
        if fits(top) {
            self.pop();
            return;
        }
        let top = top.clone();
        self.diags.push(self.mismatch(span, word, &top));
        if let Some(i) = self.stack.iter().rposition(fits) {
            while self.stack.len() > i {
                self.pop();
            }
        } else if accepts.contains(&top.kind) {
            self.pop();
        }
    }

    fn pop(&mut self) -> Option<Open> {
        let o = self.stack.pop()?;
        if o.kind == Opener::Sub {
            self.subs_open -= 1;
        }
        Some(o)
    }

    fn mismatch(&self, span: Span, word: &str, top: &Open) -> Diagnostic {
        let name = describe(top.kind, &top.id);
        Diagnostic::new(
            Code::MismatchedEnd,
            format!("`{word}` does not close the innermost open `{name}`"),
        )
        .primary(span, "closes something else")
        .secondary(top.span, format!("`{name}` opened here is still open"))
        .help(format!(
            "close `{name}` first, or correct the number or name of this end"
        ))
    }

    fn mismatch_or_unopened(&mut self, span: Span, word: &str, kind: Opener) {
        match self.stack.last().cloned() {
            Some(top) if self.stack.iter().any(|o| o.kind == kind) => {
                self.diags.push(self.mismatch(span, word, &top))
            }
            _ => self.unopened(span, word, kind),
        }
    }

    fn unopened(&mut self, span: Span, word: &str, kind: Opener) {
        self.diags.push(
            Diagnostic::new(
                Code::UnbalancedBlock,
                format!("`{word}` without an open `{}`", kind.word()),
            )
            .primary(span, "nothing to close here")
            .help(format!(
                "add the `{}` this belongs to, or remove it",
                kind.word()
            )),
        );
    }

    fn sub_start(&mut self, name: &str, id: &FlowId, span: Span) {
        // An o-word sub inside another: rs274's "Nested subroutine
        // definition", at the inner `sub`.
        let nested =
            matches!(id, FlowId::OWord(_)) && self.stack.iter().any(|o| o.kind == Opener::Sub);
        if nested {
            self.misplaced(
                span,
                "Nested subroutine definition".into(),
                "end the outer sub before defining this one",
            );
        }
        // rs274 runs on from a call into the definition of the sub it
        // called (no M2/M30 between): "sub found in illegal location"
        // [?: a call under a condition not taken is counted too].
        let reached = matches!(id, FlowId::OWord(_))
            && self.strict_sub_styles
            && !nested
            && self.called_in_main.contains(&name.to_ascii_lowercase());
        if reached {
            self.misplaced(
                span,
                format!("sub: o|{name}| found in illegal location"),
                "end the main program with M2 or M30 before the subroutines it calls",
            );
        }
        let first = self.subs.get(name).copied();
        self.duplicate(first, span, &format!("subroutine `{name}`"));
        self.subs.entry(name.to_string()).or_insert(span);
        match id {
            FlowId::Nested => self.in_proc = true,
            _ => self.open(Opener::Sub, id, span),
        }
    }

    fn duplicate(&mut self, first: Option<Span>, span: Span, what: &str) {
        let Some(first) = first else { return };
        self.diags.push(
            Diagnostic::new(Code::DuplicateLabel, format!("{what} is defined twice"))
                .primary(span, "defined again here")
                .secondary(first, "first defined here")
                .help("rename one of them"),
        );
    }

    fn misplaced(&mut self, span: Span, msg: String, help: &str) {
        self.diags.push(
            Diagnostic::new(Code::ControlOutsideSub, msg)
                .primary(span, "not allowed here")
                .help(help),
        );
    }

    /// Where subroutine styles do not mix (LinuxCNC): an M99 inside an
    /// `O1 sub` is rs274's error at the M99; the sub counts as closed.
    fn return_in_oword_sub(&mut self, span: Span) {
        let in_oword_sub = self
            .stack
            .last()
            .is_some_and(|o| o.kind == Opener::Sub && matches!(o.id, FlowId::OWord(_)));
        if !self.strict_sub_styles || !in_oword_sub {
            return;
        }
        self.misplaced(
            span,
            "'O.... endsub' or 'O.... return' must follow 'O.... sub' subroutine definition".into(),
            "end an `O1 sub` with `O1 endsub`; M99 ends an `O1` program called by M98",
        );
        self.pop();
    }

    fn misplaced_return(&mut self, span: Span) {
        if !self.in_sub() {
            self.misplaced(
                span,
                "`return` outside a subroutine".into(),
                "a return belongs inside a subroutine body",
            );
        }
    }

    fn misplaced_break(&mut self, id: &FlowId, span: Span, word: &str) {
        let ok = self
            .stack
            .iter()
            .any(|o| o.kind.is_loop() && (*id == FlowId::Nested || o.id == *id));
        if !ok {
            let msg = format!("`{word}` outside a loop it could leave");
            self.misplaced(
                span,
                msg,
                "put it inside the loop it belongs to, with that loop's number",
            );
        }
    }
}

#[cfg(test)]
mod tests;
