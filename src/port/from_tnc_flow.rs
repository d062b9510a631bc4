//! Q parameters and `FN 9..12` jumps of a Klartext program in the forms of
//! a word-address or Sinumerik target:
//!
//! * Q parameters → numbered, R or named variables ([`vars`]).
//! * `FN 9: IF +0 EQU +0 GOTO LBL n` (a condition of two numbers) → an
//!   unconditional jump, or nothing when it never holds.
//! * A target with labels (Siemens) keeps them: a label that is a number
//!   is not a Siemens name, so `LBL 5` → `LBL5:`; each jump gets its
//!   direction from where its label is (`GOTOB`/`GOTOF`).
//! * A target with jumps to sequence numbers (Fanuc, Haas): the labels
//!   become sequence numbers in [`super::forms`].
//! * A target with o-words (LinuxCNC, whose `IF .. GOTO` the interpreter
//!   of LinuxCNC does not take): the jumps become loops and
//!   conditionals ([`owords`]).

mod conds;
mod owords;
mod shape;
mod vars;

use crate::diag::Diagnostic;
use crate::dialect::{Capability, DialectSpec, Family};
use crate::ir::{BinaryOp, ExprKind, JumpDir, JumpTarget, Program, StmtKind};
use std::collections::HashMap;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if from.family != Family::Klartext || to.family == Family::Klartext {
        return;
    }
    vars::run(p, to, diags);
    constant_jumps(p);
    if to.has(Capability::StructuredControl) {
        named_labels(p);
    } else if to.has(Capability::OWords) {
        owords::run(p, diags);
    }
}

/// The value of a comparison of two numbers.
fn constant(p: &Program, e: crate::ir::ExprId) -> Option<bool> {
    let ExprKind::Binary(op, a, b) = p.exprs[e].kind else {
        return None;
    };
    let (ExprKind::Number(x), ExprKind::Number(y)) = (&p.exprs[a].kind, &p.exprs[b].kind) else {
        return None;
    };
    let (x, y) = (x.to_f64(), y.to_f64());
    Some(match op {
        BinaryOp::Eq => x == y,
        BinaryOp::Ne => x != y,
        BinaryOp::Gt => x > y,
        BinaryOp::Lt => x < y,
        BinaryOp::Ge => x >= y,
        BinaryOp::Le => x <= y,
        _ => return None,
    })
}

fn constant_jumps(p: &mut Program) {
    let mut blocks = std::mem::take(&mut p.blocks);
    for b in &mut blocks {
        b.stmts.retain_mut(|s| {
            let StmtKind::Goto { cond, .. } = &mut s.kind else {
                return true;
            };
            match cond.and_then(|c| constant(p, c)) {
                Some(true) => {
                    *cond = None;
                    true
                }
                Some(false) => false,
                None => true,
            }
        });
    }
    blocks.retain(|b| !b.stmts.is_empty() || b.label.is_some() || b.number.is_some());
    p.blocks = blocks;
}

/// A label a Siemens program can carry (`5` → `LBL5`).
fn siemens_name(l: &str) -> String {
    if l.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_') {
        l.to_string()
    } else {
        format!("LBL{l}")
    }
}

/// The labels jumps go to as Siemens names (the labels of `CALL LBL`
/// subprograms are left to that mapping), jumps with their direction.
fn named_labels(p: &mut Program) {
    let jumped: std::collections::HashSet<String> = p
        .blocks
        .iter()
        .flat_map(|b| b.stmts.iter())
        .filter_map(|s| match &s.kind {
            StmtKind::Goto {
                target: JumpTarget::Label(l),
                ..
            } => Some(l.to_ascii_uppercase()),
            _ => None,
        })
        .collect();
    let mut at: HashMap<String, usize> = HashMap::new();
    for (i, b) in p.blocks.iter_mut().enumerate() {
        if let Some(l) = &mut b.label {
            if jumped.contains(&l.node.to_ascii_uppercase()) {
                l.node = siemens_name(&l.node);
                at.insert(l.node.to_ascii_uppercase(), i);
            }
        }
    }
    for (i, b) in p.blocks.iter_mut().enumerate() {
        for s in &mut b.stmts {
            if let StmtKind::Goto {
                target: JumpTarget::Label(l),
                dir,
                ..
            } = &mut s.kind
            {
                *l = siemens_name(l);
                if let Some(&t) = at.get(&l.to_ascii_uppercase()) {
                    *dir = if t <= i {
                        JumpDir::Backward
                    } else {
                        JumpDir::Forward
                    };
                }
            }
        }
    }
}
