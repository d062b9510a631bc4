//! Label numbers for the Klartext forms of loops and jumps.
//!
//! * `GOTO 10` (a jump to sequence number N10) becomes a jump to `LBL 10`
//!   on that block, when the number is free as a label and in 1..999
//!   (else the next free number); a computed target (`GOTO #1`) or a number no block (or more
//!   than one block) carries is E0622.
//! * The labels the loop forms need are numbered from 1 up, skipping the
//!   numbers the program already uses (its `LBL`s, `CALL LBL`s and the
//!   labels given to sequence numbers). Older controls take `LBL 1..999`
//!   [?]; a program that needs more is rare enough not to be handled.

use crate::diag::{Code, Diagnostic};
use crate::ir::{CallKind, CallTarget, JumpTarget, Program, Stmt, StmtKind, Value};
use crate::span::Spanned;
use std::collections::HashSet;

#[derive(Default)]
pub(super) struct Labels {
    used: HashSet<String>,
    next: u32,
}

impl Labels {
    /// The labels `p` already uses.
    pub fn of(p: &Program) -> Labels {
        let mut used = HashSet::new();
        for b in &p.blocks {
            if let Some(l) = &b.label {
                used.insert(l.node.to_ascii_uppercase());
            }
            for s in &b.stmts {
                match &s.kind {
                    StmtKind::Call {
                        kind: CallKind::Label,
                        target,
                        ..
                    } => match target {
                        CallTarget::Number(n) => {
                            used.insert(n.to_string());
                        }
                        CallTarget::Name(n) => {
                            used.insert(n.to_ascii_uppercase());
                        }
                        CallTarget::Computed(_) => {}
                    },
                    StmtKind::SectionRepeat { start, end, .. } => {
                        used.insert(start.to_ascii_uppercase());
                        used.extend(end.iter().map(|e| e.to_ascii_uppercase()));
                    }
                    _ => {}
                }
            }
        }
        Labels { used, next: 0 }
    }

    /// A label number not used yet.
    pub fn fresh(&mut self) -> String {
        loop {
            self.next += 1;
            let l = self.next.to_string();
            if self.used.insert(l.clone()) {
                return l;
            }
        }
    }

    /// `n` itself when free and a label number every control takes
    /// (1..999; `LBL 0` ends a subprogram), else a fresh number.
    fn claim(&mut self, n: i64) -> String {
        let l = n.to_string();
        if (1..=999).contains(&n) && self.used.insert(l.clone()) {
            l
        } else {
            self.fresh()
        }
    }
}

fn sequence_jump(s: &mut Stmt) -> Option<&mut JumpTarget> {
    match &mut s.kind {
        StmtKind::Goto { target, .. } => Some(target),
        StmtKind::IfThen { then, .. } => sequence_jump(then),
        _ => None,
    }
}

/// Jumps to sequence numbers become jumps to labels on their blocks.
pub(super) fn sequence_jumps(p: &mut Program, labels: &mut Labels, diags: &mut Vec<Diagnostic>) {
    let mut wanted = Vec::new();
    for (bi, b) in p.blocks.iter_mut().enumerate() {
        for (si, s) in b.stmts.iter_mut().enumerate() {
            let span = s.span;
            let Some(JumpTarget::Sequence(v)) = sequence_jump(s) else {
                continue;
            };
            match v {
                Value::Number(d) if d.as_int().is_some() => {
                    wanted.push((bi, si, d.as_int().unwrap_or(0)))
                }
                _ => diags.push(
                    Diagnostic::new(Code::PortJump, "Klartext cannot jump to a computed target")
                        .primary(span, "this jump")
                        .help("jump to a fixed sequence number"),
                ),
            }
        }
    }
    let mut numbered: std::collections::HashMap<i64, Vec<usize>> = Default::default();
    for (i, b) in p.blocks.iter().enumerate() {
        if let Some(x) = &b.number {
            numbered.entry(x.node as i64).or_default().push(i);
        }
    }
    for (bi, si, n) in wanted {
        let hits = numbered.get(&n).cloned().unwrap_or_default();
        let span = p.blocks[bi].stmts[si].span;
        let [ti] = hits[..] else {
            let why = if hits.is_empty() {
                format!("no block is numbered N{n}")
            } else {
                format!("more than one block is numbered N{n}")
            };
            diags.push(
                Diagnostic::new(
                    Code::PortJump,
                    format!("cannot give this jump a label: {why}"),
                )
                .primary(span, "this jump")
                .help("number the target block once"),
            );
            continue;
        };
        let target = &mut p.blocks[ti];
        let bspan = target.span;
        let name = match &target.label {
            Some(l) => l.node.clone(),
            None => {
                let l = labels.claim(n);
                target.label = Some(Box::new(Spanned {
                    node: l.clone(),
                    span: bspan,
                }));
                l
            }
        };
        if let Some(t) = sequence_jump(&mut p.blocks[bi].stmts[si]) {
            *t = JumpTarget::Label(name);
        }
    }
}
