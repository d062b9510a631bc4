//! Heidenhain label subprograms for a target of another family:
//! `LBL n` ... `LBL 0` after the program's end, called with `CALL LBL n`,
//! and the program-section repeat around a call (`LBL m`, `CALL LBL n`,
//! `CALL LBL m REP k`: the call made k + 1 times).
//!
//! * A target with o-words is served first (LinuxCNC has both).
//! * A target with local subprogram calls (Haas): the subprogram stays
//!   after `M30` as the blocks from `N n` to `M99`, called with `M97 P n`
//!   (`L k+1` for a section around the call), all in one program.
//! * A target with numbered programs (Fanuc): the subprogram is a
//!   program of its own in the same file, `O n` ... `M99` after the main
//!   program's `M30` (a Fanuc tape holding several programs, as the control
//!   loads it into memory); `CALL LBL n` is `M98 P n`, and a section that
//!   holds only that call `M98 P n L k+1`. Another section repeat has no
//!   Fanuc form here (E0617).
//! * A target with o-words (LinuxCNC): `o n sub` ... `o n endsub` where the
//!   label was (LinuxCNC finds a subroutine defined after `M2`, checked
//!   with rs274), `CALL LBL n` is `o n call`, and any section repeat is
//!   `o m repeat [k+1]` ... `o m endrepeat` around the section.
//! * Siemens (which keeps subprograms in files of their own, not written
//!   by the port): the subprograms are inlined at their calls ([`super::inline`]).
//! * Others: E0617.
//!
//! Labels must be numbers for these targets; named labels are E0617.
//! Runs after [`crate::port::frame`] (which drops the Klartext block
//! numbers, so the Haas `N n` stays).

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Family};
use crate::ir::{Block, CallArgs, CallKind, CallTarget, FlowId, Program, Stmt, StmtKind, StopKind};
use crate::span::Span;

/// The target's form of a subprogram.
#[derive(Clone, Copy, PartialEq)]
enum Form {
    Numbered,
    /// Haas `M97 P n`: the subprogram at sequence number `N n` in this program.
    Local,
    OWord,
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if from.family != Family::Klartext || to.family == Family::Klartext {
        return;
    }
    if !uses_labels(p) {
        return;
    }
    let form = if to.has(Capability::OWords) {
        Form::OWord
    } else if to.has(Capability::LocalSubprogramCall) {
        Form::Local
    } else if to.has(Capability::NumberedPrograms) {
        Form::Numbered
    } else if to.family == Family::Sinumerik {
        return super::inline::run(p, diags);
    } else {
        let span = first_call(p);
        diags.push(refusal(
            span,
            format!("{} has no subprogram form the port writes", to.name),
        ));
        return;
    };
    super::sections::repeats(p, form == Form::OWord, diags);
    bodies(p, form, diags);
    calls(p, form, diags);
}

/// Before [`crate::port::frame`] turns `BEGIN PGM 3009` into a comment:
/// a main program that will share its file with numbered subprograms
/// (Fanuc) keeps its number.
pub fn number_main(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let numbered = !to.has(Capability::OWords)
        && !to.has(Capability::LocalSubprogramCall)
        && to.has(Capability::NumberedPrograms);
    if from.family == Family::Klartext
        && to.family != Family::Klartext
        && numbered
        && uses_labels(p)
    {
        main_number(p);
    }
}

fn uses_labels(p: &Program) -> bool {
    p.blocks.iter().flat_map(|b| &b.stmts).any(|s| {
        matches!(
            s.kind,
            StmtKind::Call {
                kind: CallKind::Label,
                ..
            } | StmtKind::SectionRepeat { .. }
        )
    })
}

pub(super) fn refusal(span: Span, msg: String) -> Diagnostic {
    Diagnostic::new(Code::PortSubprogram, msg)
        .primary(span, "here")
        .help("expand the subprogram in the source, or port to a target with local subprograms")
}

fn first_call(p: &Program) -> Span {
    p.blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .find(|s| {
            matches!(
                s.kind,
                StmtKind::Call { .. } | StmtKind::SectionRepeat { .. }
            )
        })
        .map(|s| s.span)
        .unwrap_or_default()
}

fn label_number(b: &Block) -> Option<u32> {
    b.label.as_ref().and_then(|l| l.node.parse().ok())
}

/// The main program of a file that holds several gets its number: `BEGIN
/// PGM 3009` is `O3009` (a name that is not a number stays a comment).
fn main_number(p: &mut Program) {
    let Some(bi) = p.blocks.iter().position(|b| {
        b.stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ProgramStart { .. }))
    }) else {
        return;
    };
    let b = &mut p.blocks[bi];
    let si = b
        .stmts
        .iter()
        .position(|s| matches!(s.kind, StmtKind::ProgramStart { .. }))
        .expect("found above");
    if let StmtKind::ProgramStart { number, name } = &mut b.stmts[si].kind {
        let Some(n) = name.as_ref().and_then(|n| n.parse::<u32>().ok()) else {
            return;
        };
        *number = Some(n);
        *name = None;
    }
    // `O3009` alone in its block, the rest (`G21`) after it.
    let start = b.stmts.remove(si);
    let rest = std::mem::replace(&mut b.stmts, vec![start]);
    if !rest.is_empty() {
        let next = crate::port::follow_block(b, rest);
        p.blocks.insert(bi + 1, next);
    }
}

/// `LBL n` after the program's end ... `LBL 0`: the subprogram's body.
fn bodies(p: &mut Program, form: Form, diags: &mut Vec<Diagnostic>) {
    let mut ended = false;
    let mut open: Option<String> = None;
    for b in &mut p.blocks {
        if ended && open.is_none() && b.label.is_some() {
            let Some(n) = label_number(b) else {
                let l = b.label.as_ref().expect("checked");
                diags.push(refusal(l.span, format!("the named label `{}`", l.node)));
                continue;
            };
            let l = b.label.take().expect("checked");
            let start = match form {
                Form::Numbered => Some(StmtKind::ProgramStart {
                    number: Some(n),
                    name: None,
                }),
                Form::Local => {
                    b.number = Some(crate::span::Spanned {
                        node: n,
                        span: l.span,
                    });
                    None
                }
                Form::OWord => Some(StmtKind::SubStart {
                    name: n.to_string(),
                    params: Vec::new(),
                    id: FlowId::OWord(n.to_string()),
                }),
            };
            if let Some(start) = start {
                b.stmts.insert(0, Stmt::new(start, l.span));
            }
            open = Some(n.to_string());
        }
        for s in &mut b.stmts {
            match &s.kind {
                StmtKind::Stop(StopKind::End | StopKind::EndRewind) => ended = true,
                StmtKind::SubReturn { to: None } if form == Form::OWord => {
                    if let Some(n) = open.take() {
                        s.kind = StmtKind::SubEnd {
                            id: FlowId::OWord(n),
                            value: None,
                        };
                    }
                }
                StmtKind::SubReturn { to: None } => open = None,
                _ => {}
            }
        }
    }
}

/// `CALL LBL n` → `M98 P n` / `o n call`.
fn calls(p: &mut Program, form: Form, diags: &mut Vec<Diagnostic>) {
    for s in p.blocks.iter_mut().flat_map(|b| &mut b.stmts) {
        let StmtKind::Call {
            kind: kind @ CallKind::Label,
            target,
            args: CallArgs::None,
            ..
        } = &mut s.kind
        else {
            continue;
        };
        if !matches!(target, CallTarget::Number(_)) {
            diags.push(refusal(s.span, "a call of a named label".into()));
            continue;
        }
        *kind = match form {
            Form::Numbered => CallKind::Subprogram,
            Form::Local => CallKind::Local,
            Form::OWord => CallKind::OWord,
        };
    }
}
