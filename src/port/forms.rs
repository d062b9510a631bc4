//! Statement forms that differ between targets but mean the same:
//!
//! * numbered variables: `#n` (word address) ↔ `Rn` (Siemens), same number,
//!   when the target declares that number in its variable ranges (E0613
//!   otherwise). `#[e]` ↔ `R[e]`. Named and declared variables are not
//!   mapped (the writer reports them).
//! * loop and conditional ids (see [`super::flow_ids`]).
//! * labels, for a target without them: the labelled block gets a sequence
//!   number (its own, or a new one above all others) and jumps go to it.
//! * tool length: `G43 H` → `D1`, `G49` → `D0` for a target whose tools
//!   carry their length in the cutting edge; `D0` → `G49`, `Dn` → `G43 H`
//!   with the tool's number for the other way (W0610 when H or D is not
//!   the one the target derives).
//! * the tool map on T, H and D numbers.

use super::PortOptions;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Family, Meaning};
use crate::ir::{Decimal, ExprKind, JumpDir, JumpTarget, Program, StmtKind, Value, Var};
use crate::span::Spanned;
use std::collections::HashMap;

pub fn run(
    p: &mut Program,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &PortOptions,
    diags: &mut Vec<Diagnostic>,
) {
    cycle_dwells(p, from, to);
    program_name(p, to);
    archive_frame(p, to);
    variables(p, to, diags);
    super::flow_ids::run(p, to, diags);
    labels(p, to);
    super::tools::run(p, to, opts, diags);
}

/// A Siemens program name is an identifier: a title that is not one (a
/// Fanuc `O1234 (TITLE)`) stays as a comment and the number names it.
fn program_name(p: &mut Program, to: &DialectSpec) {
    if to.family != Family::Sinumerik {
        return numbered_program(p, to);
    }
    for b in &mut p.blocks {
        let mut titles = Vec::new();
        for s in &mut b.stmts {
            if let StmtKind::ProgramStart {
                number: Some(_),
                name,
            } = &mut s.kind
            {
                let ident = name
                    .as_ref()
                    .is_some_and(|n| n.chars().all(|c| c.is_ascii_alphanumeric() || c == '_'));
                if !ident {
                    if let Some(t) = name.take() {
                        titles.push(crate::ir::Stmt::new(
                            StmtKind::Comment {
                                text: t,
                                style: crate::ir::CommentStyle::Semicolon,
                            },
                            s.span,
                        ));
                    }
                }
            }
        }
        b.stmts.extend(titles);
    }
}

/// Siemens programs are framed by their archive header `%_N_NAME_MPF`
/// alone: the bare `%` tape marks of a word-address tape around it are
/// not Siemens text, so they go once the program has its header (they
/// carry nothing but the frame).
fn archive_frame(p: &mut Program, to: &DialectSpec) {
    if to.family != Family::Sinumerik {
        return;
    }
    let named = p.blocks.iter().flat_map(|b| &b.stmts).any(|s| {
        matches!(&s.kind, StmtKind::ProgramStart { name: Some(n), .. } if !n.is_empty())
            || matches!(
                &s.kind,
                StmtKind::ProgramStart {
                    number: Some(_),
                    ..
                }
            )
    });
    if !named {
        return;
    }
    let tape_only = |b: &crate::ir::Block| {
        !b.stmts.is_empty() && b.stmts.iter().all(|s| matches!(s.kind, StmtKind::Tape))
    };
    p.blocks
        .retain(|b| !tape_only(b) || b.number.is_some() || b.label.is_some());
    for b in &mut p.blocks {
        b.stmts.retain(|s| !matches!(s.kind, StmtKind::Tape));
    }
}

/// For a target of numbered programs: Siemens `%_N_O2000_MPF` (read as
/// the name `O2000_MPF`) is program 2000; a bare `%` start is the tape mark.
fn numbered_program(p: &mut Program, to: &DialectSpec) {
    if !to.has(Capability::NumberedPrograms) {
        return;
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let StmtKind::ProgramStart { number: None, name } = &s.kind else {
                continue;
            };
            let Some(name) = name.as_ref().filter(|n| !n.is_empty()) else {
                s.kind = StmtKind::Tape;
                continue;
            };
            let upper = name.to_ascii_uppercase();
            let base = upper.trim_end_matches("_MPF").trim_end_matches("_SPF");
            let digits = base.strip_prefix('O').unwrap_or(base);
            if let Ok(n) = digits.parse::<u32>() {
                s.kind = StmtKind::ProgramStart {
                    number: Some(n),
                    name: None,
                };
            }
        }
    }
}

fn sequence_jumps_to_labels(p: &mut Program) {
    let mut jumps = Vec::new();
    for (bi, b) in p.blocks.iter().enumerate() {
        for (si, s) in b.stmts.iter().enumerate() {
            if let StmtKind::Goto {
                target: JumpTarget::Sequence(Value::Number(d)),
                ..
            } = &s.kind
            {
                if let Some(n) = d.as_int() {
                    jumps.push((bi, si, n));
                }
            }
        }
    }
    for (bi, si, n) in jumps {
        let Some(ti) = p
            .blocks
            .iter()
            .position(|b| b.number.as_ref().is_some_and(|x| x.node as i64 == n))
        else {
            continue;
        };
        let target = &mut p.blocks[ti];
        let span = target.span;
        let label = target
            .label
            .get_or_insert_with(|| {
                Box::new(Spanned {
                    node: format!("SEQ{n}"),
                    span,
                })
            })
            .node
            .clone();
        if let StmtKind::Goto { target, dir, .. } = &mut p.blocks[bi].stmts[si].kind {
            *target = JumpTarget::Label(label);
            *dir = if ti <= bi {
                JumpDir::Backward
            } else {
                JumpDir::Forward
            };
        }
    }
}

fn p_unit(spec: &DialectSpec) -> Option<crate::ir::DwellUnit> {
    spec.code_for(Meaning::Dwell).and_then(|c| {
        c.dwell_units
            .iter()
            .find(|(l, _)| *l == 'P')
            .map(|(_, u)| *u)
    })
}

/// A canned cycle's dwell P in the target's unit (Fanuc milliseconds,
/// LinuxCNC seconds): numbers are converted exactly (a conversion that is
/// not exact is left for the writer to report).
fn cycle_dwells(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    use crate::ir::DwellUnit::{Milliseconds, Seconds};
    let shift = match (p_unit(from), p_unit(to)) {
        (Some(Milliseconds), Some(Seconds)) => -3,
        (Some(Seconds), Some(Milliseconds)) => 3,
        _ => return,
    };
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            if let StmtKind::Cycle(c) = &mut s.kind {
                if let Some(Value::Number(d)) = &c.p {
                    if let Some(n) = crate::emit::number::shift_decimal(*d, shift) {
                        c.p = Some(Value::Number(n));
                    }
                }
            }
        }
    }
}

/// The target's form of a numbered variable, or None.
fn map_var(v: &Var, to: &DialectSpec) -> Result<Option<Var>, String> {
    let sin = to.family == Family::Sinumerik;
    Ok(match (v, sin) {
        (Var::Numbered(n), true) => match to.var_range('R', *n) {
            Some(_) => Some(Var::R(*n)),
            None => return Err(format!("#{n} (the target has no R{n})")),
        },
        (Var::Indirect(e), true) => Some(Var::RIndirect(*e)),
        (Var::R(n), false) => match to.var_range('#', *n) {
            Some(r) if r.writable => Some(Var::Numbered(*n)),
            _ => return Err(format!("R{n} (the target has no writable #{n})")),
        },
        (Var::RIndirect(e), false) => Some(Var::Indirect(*e)),
        _ => None,
    })
}

fn variables(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let mut fail = |span, what: String| {
        diags.push(
            Diagnostic::new(Code::PortVariable, format!("{} cannot hold {what}", to.name))
                .primary(span, "this variable")
                .help("use a variable number the target has (Fanuc #100-#199, #500-#999; Siemens R0-R99 by default)"),
        );
    };
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        let e = &p.exprs[id];
        let ExprKind::Var(v) = &e.kind else { continue };
        match map_var(v, to) {
            Ok(Some(nv)) => p.exprs[id].kind = ExprKind::Var(nv),
            Ok(None) => {}
            Err(what) => fail(e.span, what),
        }
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let var = match &mut s.kind {
                StmtKind::Assign { var, .. } | StmtKind::For { var, .. } => var,
                _ => continue,
            };
            match map_var(var, to) {
                Ok(Some(nv)) => *var = nv,
                Ok(None) => {}
                Err(what) => fail(s.span, what),
            }
        }
    }
}

/// Jumps to sequence numbers become jumps to labels for a target with
/// labels (`GOTO 10` → `GOTOB SEQ10` with `SEQ10:` on block N10, the
/// direction from where the block is); labels become sequence numbers for
/// a target without them.
fn labels(p: &mut Program, to: &DialectSpec) {
    // Klartext jumps and calls go to its own `LBL`s.
    if to.family == Family::Klartext {
        return;
    }
    if to.has(Capability::StructuredControl) {
        return sequence_jumps_to_labels(p);
    }
    if to.family == Family::Klartext {
        return; // jumps go to `LBL`s (see `to_tnc::flow`)
    }
    if p.blocks.iter().all(|b| b.label.is_none()) {
        return;
    }
    let top = p
        .blocks
        .iter()
        .filter_map(|b| b.number.as_ref().map(|n| n.node))
        .max()
        .unwrap_or(0);
    let mut next = (top / 1000 + 1) * 1000;
    let mut numbers = HashMap::new();
    for b in &mut p.blocks {
        let Some(l) = b.label.take() else { continue };
        // The label's name stays as a comment on its block, unless the
        // port made it.
        if !l.node.starts_with(super::MADE_LABEL) {
            let note = StmtKind::Comment {
                text: format!("{}:", l.node),
                style: crate::ir::CommentStyle::Paren,
            };
            b.stmts.push(crate::ir::Stmt::new(note, l.span));
        }
        let n = match &b.number {
            Some(n) => n.node,
            None => {
                next += 10;
                b.number = Some(Spanned {
                    node: next,
                    span: l.span,
                });
                next
            }
        };
        numbers.insert(l.node.to_ascii_uppercase(), n);
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            if let StmtKind::Goto { target, dir, .. } = &mut s.kind {
                if let JumpTarget::Label(l) = target {
                    if let Some(n) = numbers.get(&l.to_ascii_uppercase()) {
                        *target = JumpTarget::Sequence(Value::Number(Decimal::from_int(*n as i64)));
                        *dir = JumpDir::Either;
                    }
                }
            }
        }
    }
}
