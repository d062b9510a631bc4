//! Jump targets of one program: sequence numbers and labels seen so far,
//! and the jumps (GOTO, GOTOF/GOTOB, CASE, section REPEAT, `M99 P`,
//! `M97 P`) whose target has not been found yet.
//!
//! Sequence numbers are kept as runs (`N10`, `N20`, `N30`... is one run),
//! so a CAM program numbering every block needs next to no memory.

use crate::diag::{Code, Diagnostic};
use crate::ir::{CallKind, CallTarget, JumpDir, JumpTarget, Stmt, StmtKind, Value};
use crate::span::Span;
use std::collections::HashMap;

/// Where a jump goes. Labels are compared without regard to case, as the
/// controls (and the interpreter's flow index) find them.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum Target {
    Number(u32),
    Label(String),
}

/// A label target, keyed in upper case.
fn label(name: &str) -> Target {
    Target::Label(name.to_ascii_uppercase())
}

impl Target {
    fn show(&self) -> String {
        match self {
            Target::Number(n) => format!("N{n}"),
            Target::Label(l) => l.clone(),
        }
    }
}

/// A jump whose target was not (yet) found.
#[derive(Clone, Debug)]
struct Pending {
    target: Target,
    /// The target as the jump wrote it.
    shown: String,
    dir: JumpDir,
    span: Span,
    /// A Heidenhain `CALL LBL` (not a jump).
    call: bool,
}

/// A set of numbers stored as arithmetic runs `first, first+step, ..=last`.
#[derive(Default, Debug)]
struct NumberSet {
    runs: Vec<(u32, u32, u32)>,
}

impl NumberSet {
    fn insert(&mut self, n: u32) {
        if let Some((first, last, step)) = self.runs.last_mut() {
            if *first == *last && n > *last {
                *step = n - *last;
                *last = n;
                return;
            }
            if n > *last && n - *last == *step {
                *last = n;
                return;
            }
        }
        if !self.contains(n) {
            self.runs.push((n, n, 1));
        }
    }

    fn contains(&self, n: u32) -> bool {
        self.runs.iter().any(|&(first, last, step)| {
            (first..=last).contains(&n) && (n - first).is_multiple_of(step.max(1))
        })
    }

    fn clear(&mut self) {
        self.runs.clear();
    }
}

/// The labels of the current program and its unresolved jumps.
#[derive(Default)]
pub(super) struct Labels {
    numbers: NumberSet,
    names: HashMap<String, Span>,
    pending: Vec<Pending>,
    /// Heidenhain labels (`LBL n`): missing ones are told in its terms.
    klartext: bool,
}

impl Labels {
    pub fn new(klartext: bool) -> Self {
        Labels {
            klartext,
            ..Labels::default()
        }
    }

    fn seen(&self, t: &Target) -> bool {
        match t {
            Target::Number(n) => self.numbers.contains(*n),
            Target::Label(l) => self.names.contains_key(l),
        }
    }

    /// Forward and either-way jumps waiting for `t` are resolved.
    fn resolve(&mut self, t: &Target) {
        if !self.pending.is_empty() {
            self.pending
                .retain(|p| p.target != *t || p.dir == JumpDir::Backward);
        }
    }

    pub fn define_number(&mut self, n: u32) {
        self.resolve(&Target::Number(n));
        self.numbers.insert(n);
    }

    /// Defines a label; returns where it was first defined if it was.
    pub fn define_label(&mut self, name: &str, span: Span) -> Option<Span> {
        let key = name.to_ascii_uppercase();
        if let Some(first) = self.names.get(&key) {
            return Some(*first);
        }
        self.resolve(&Target::Label(key.clone()));
        self.names.insert(key, span);
        None
    }

    /// Records the jumps a statement makes.
    pub fn jumps(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Goto { target, dir, .. } => self.jump_target(target, *dir, s.span),
            StmtKind::IfThen { then, .. } => self.jumps(then),
            StmtKind::Case { arms, default, .. } => {
                for arm in arms {
                    self.jump(label(&arm.target), &arm.target, arm.dir, s.span);
                }
                if let Some((l, dir)) = default {
                    self.jump(label(l), l, *dir, s.span);
                }
            }
            StmtKind::SectionRepeat {
                start, end, single, ..
            } => {
                let dir = if *single {
                    JumpDir::Either
                } else {
                    JumpDir::Backward
                };
                self.jump(label(start), start, dir, s.span);
                if let Some(end) = end {
                    self.jump(label(end), end, dir, s.span);
                }
            }
            StmtKind::Call {
                kind: CallKind::Local,
                target: CallTarget::Number(n),
                ..
            } => self.jump(
                Target::Number(*n),
                &format!("N{n}"),
                JumpDir::Either,
                s.span,
            ),
            StmtKind::Call {
                kind: CallKind::Label,
                target,
                ..
            } => {
                let name = match target {
                    CallTarget::Number(n) => n.to_string(),
                    CallTarget::Name(n) => n.clone(),
                    CallTarget::Computed(_) => return,
                };
                self.pending_call(label(&name), name, s.span);
            }
            StmtKind::SubReturn { to: Some(v) } => {
                self.jump_target(&JumpTarget::Sequence(v.clone()), JumpDir::Either, s.span)
            }
            _ => {}
        }
    }

    fn jump_target(&mut self, target: &JumpTarget, dir: JumpDir, span: Span) {
        let t = match target {
            JumpTarget::Label(l) => return self.jump(label(l), l, dir, span),
            JumpTarget::Sequence(Value::Number(d)) => {
                match d.as_int().and_then(|n| u32::try_from(n).ok()) {
                    Some(n) => Target::Number(n),
                    None => return,
                }
            }
            JumpTarget::Sequence(Value::Expr(_)) => return,
        };
        let shown = t.show();
        self.jump(t, &shown, dir, span);
    }

    fn jump(&mut self, target: Target, shown: &str, dir: JumpDir, span: Span) {
        let known = self.seen(&target);
        match dir {
            JumpDir::EitherNoAlarm => {}
            JumpDir::Either | JumpDir::Backward if known => {}
            _ => self.pending.push(Pending {
                target,
                shown: shown.to_string(),
                dir,
                span,
                call: false,
            }),
        }
    }

    /// `CALL LBL`: the label may come anywhere in the program.
    fn pending_call(&mut self, target: Target, shown: String, span: Span) {
        if !self.seen(&target) {
            self.pending.push(Pending {
                target,
                shown,
                dir: JumpDir::Either,
                span,
                call: true,
            });
        }
    }

    /// Reports the jumps of the program just ended and forgets its labels.
    pub fn close_scope(&mut self, diags: &mut Vec<Diagnostic>) {
        for p in std::mem::take(&mut self.pending) {
            let seen = self.seen(&p.target);
            diags.push(if self.klartext {
                missing_label(&p, seen)
            } else {
                missing_target(&p, seen)
            });
        }
        self.numbers.clear();
        self.names.clear();
    }
}

fn missing_target(p: &Pending, exists: bool) -> Diagnostic {
    let name = p.shown.clone();
    let (msg, help) = match (p.dir, exists) {
        (JumpDir::Forward, true) => (
            format!("`{name}` is not found after this jump"),
            "the label is before the jump: a forward jump (GOTOF) cannot reach it; use GOTOB or GOTO".to_string(),
        ),
        (JumpDir::Backward, true) => (
            format!("`{name}` is not found before this jump"),
            "the label is after the jump: a backward search (GOTOB, REPEAT) cannot reach it; use GOTOF or GOTO"
                .to_string(),
        ),
        _ => (format!("`{name}` does not exist in this program"), format!("add `{name}` or correct the target")),
    };
    Diagnostic::new(Code::JumpTargetMissing, msg)
        .primary(p.span, "jumps to a missing target")
        .help(help)
}

/// E0321 in Heidenhain's terms: `CALL LBL 5` / `GOTO LBL 5` / `REP` to a
/// label the program lacks (or, for a section repeat, has only after it).
fn missing_label(p: &Pending, exists: bool) -> Diagnostic {
    let name = p.shown.clone();
    let lbl = if name.bytes().all(|b| b.is_ascii_digit()) {
        format!("LBL {name}")
    } else {
        format!("LBL \"{name}\"")
    };
    let (msg, help) = match (p.call, p.dir, exists) {
        (false, JumpDir::Backward, true) => (
            format!("`CALL {lbl} REP` repeats from a label that comes after it"),
            format!("a program-section repeat runs from `{lbl}` down to the CALL: put `{lbl}` before it"),
        ),
        (true, ..) => (
            format!("`CALL {lbl}` calls a label this program does not have"),
            format!("add the subprogram `{lbl}` ... `LBL 0` (after M30) or correct the label"),
        ),
        _ => (
            format!("`{lbl}` does not exist in this program"),
            format!("add `{lbl}` or correct the label the jump goes to"),
        ),
    };
    Diagnostic::new(Code::KlartextLabelMissing, msg)
        .primary(p.span, "no such label")
        .help(help)
}

#[cfg(test)]
mod tests {
    use super::NumberSet;

    #[test]
    fn number_runs() {
        let mut s = NumberSet::default();
        for n in (10..=100_000).step_by(10) {
            s.insert(n);
        }
        s.insert(5);
        s.insert(7);
        assert_eq!(s.runs.len(), 2, "{:?}", s.runs);
        assert!(s.contains(99_990) && s.contains(5) && s.contains(7));
        assert!(!s.contains(15) && !s.contains(6) && !s.contains(100_010));
    }
}
