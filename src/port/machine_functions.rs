//! The source machine's own functions (`aux` M codes) on a target that does
//! not know them. A code is a number on one control: the same number on
//! another control is another function, or none, so a code the target's
//! spec does not list is not written as a live code where that would do
//! harm:
//!
//! * a machine-datum code (`run="machine-datum"`, Heidenhain M92) puts
//!   the block in machine coordinates: the target's machine-coordinate
//!   form (G53, SUPA) carries that [?: M92's datum is the builder's, not
//!   machine zero; the run treats it as M91 too]; W0610;
//! * a code the source knows as a function that changes nothing the run
//!   computes (`run="pass"`, Heidenhain M126 shortest rotary path) and the
//!   target does not list becomes a comment naming it; W0610;
//! * a code neither spec knows (a builder's) stays a code where the target
//!   takes unknown M codes (reading it back warns, E0204), and becomes a
//!   comment where the target refuses them (capability `strict-m-codes`:
//!   LinuxCNC runs M100..M199 as user programs: a target's user-program
//!   code of the same number, `run="user-program"`, counts as not
//!   listed); W0610;
//! * any other code the source knows (one that changes what the run
//!   computes, or a kinematics function such as M128) stays as written:
//!   the target's reading of it decides, and dropping it could change
//!   what the machine does.
//!
//! A G code the source keeps as its own function (`aux`: LinuxCNC's G5.1
//! quadratic spline, a builder's G code) goes by number only to a target
//! whose code of that number is its own function too; elsewhere the same
//! number is another function (Fanuc G5.1 is AI contour control) or
//! none, so the port refuses it (E0601) and the fallback writes the moves
//! the run made for it.

use crate::diag::{Code, Diagnostic};
use crate::dialect::spec::AuxRun;
use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{CommentStyle, Program, Stmt, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let mut said: Vec<(char, crate::ir::Decimal)> = Vec::new();
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::Aux { letter, code, .. } = &s.kind else {
            continue;
        };
        let (letter, code) = (*letter, *code);
        if let Some(d) = by_meaning(s, from, to) {
            if !said.contains(&(letter, code)) {
                said.push((letter, code));
                diags.push(d);
            }
            continue;
        }
        if let Some(d) = foreign_g_code(s, from, to) {
            diags.push(d);
            continue;
        }
        if let Some(k) = replacement(s, from, to) {
            // Once per code: the first place stands for the others.
            if !said.contains(&(letter, code)) {
                said.push((letter, code));
                diags.push(note(s.span, letter, code, &k, from));
            }
            s.kind = k;
        }
    }
}

/// A source G code of its own function whose number means something else
/// on the target (or nothing).
fn foreign_g_code(s: &Stmt, from: &DialectSpec, to: &DialectSpec) -> Option<Diagnostic> {
    let StmtKind::Aux { letter, code, .. } = &s.kind else {
        return None;
    };
    let source = from.code('G', *code);
    let meaning = source.map_or(Meaning::Aux, |c| c.meaning);
    if *letter != 'G'
        || to.code('G', *code).is_some_and(|c| c.meaning == meaning)
        || source.is_some_and(|c| c.run == AuxRun::Pass)
    {
        return None;
    }
    let g = format!("G{}", code.normalized());
    let what = from
        .code('G', *code)
        .map_or(String::new(), |c| format!(" ({})", c.doc));
    let there = match to.code('G', *code) {
        Some(c) => format!("its {g} is another function ({})", c.doc),
        None => format!("it has no {g}"),
    };
    Some(
        Diagnostic::new(
            Code::CannotExpress,
            format!(
                "{} cannot express {g}{what} of {}: {there}",
                to.name, from.name
            ),
        )
        .primary(s.span, "a function of the source control")
        .help("write what it does with the target's own codes"),
    )
}

/// A kept code whose meaning the source spec names (a machine function,
/// a high-speed mode): written as the target's code of that meaning, or,
/// where the target has none, as a comment (W0610) rather than as the
/// same number, which there means something else (Fanuc `G5 P2` is
/// LinuxCNC's cubic spline), for functions that change nothing a run
/// computes; the others are left to the cycle rules and `--verify`.
fn by_meaning(s: &mut Stmt, from: &DialectSpec, to: &DialectSpec) -> Option<Diagnostic> {
    let StmtKind::Aux {
        letter,
        code,
        words,
    } = &mut s.kind
    else {
        return None;
    };
    let def = from.code(*letter, *code)?;
    let meaning = def.meaning;
    match meaning {
        Meaning::Machine(f) if !switch_only(f) => return None,
        Meaning::Machine(_) | Meaning::PathSmoothing => {}
        _ => return None,
    }
    let same = to
        .code(*letter, *code)
        .is_some_and(|c| c.meaning == meaning);
    if same {
        return None;
    }
    let name = format!("{letter}{}", code.format(0, false));
    if let (Meaning::Machine(_), Some(t)) = (meaning, to.code_for(meaning)) {
        let (l, c) = (t.letter, t.code);
        *letter = l;
        *code = c;
        return Some(
            Diagnostic::new(
                Code::PortApproximate,
                format!(
                    "{name} ({}) is written as the target's {l}{}",
                    meaning.name(),
                    c.format(0, false)
                ),
            )
            .primary(s.span, "the target's code for the same function"),
        );
    }
    let listed: Vec<String> = words.iter().map(word_text).collect();
    let doc = def.doc.clone();
    s.kind = StmtKind::Comment {
        text: format!("{name}{} {doc}", listed.concat())
            .trim_end()
            .to_string(),
        style: CommentStyle::Paren,
    };
    Some(
        Diagnostic::new(
            Code::PortApproximate,
            format!(
                "{name} ({}) has no code in {}: written as a comment",
                meaning.name(),
                to.name
            ),
        )
        .primary(s.span, "not carried as a code")
        .help("where the target machine has the same function, write its code there by hand"),
    )
}

/// A function that changes nothing a run computes (overrides, I/O): a
/// comment in its place cuts the same. Others (tool number, modal state,
/// lathe diameter, motions) are left as written, for `--verify` to judge.
fn switch_only(f: crate::dialect::MachineFn) -> bool {
    use crate::dialect::MachineFn as F;
    matches!(
        f,
        F::Overrides(_)
            | F::FeedOverride
            | F::SpeedOverride
            | F::AdaptiveFeed
            | F::FeedHold
            | F::DigitalOut { .. }
            | F::AnalogOut { .. }
            | F::WaitInput
    )
}

/// ` P2`: a word as read (a computed value as `?`).
fn word_text(w: &crate::ir::Word) -> String {
    match &w.value {
        crate::ir::Value::Number(d) => format!(" {}{}", w.letter, d),
        _ => format!(" {}?", w.letter),
    }
}

/// What an Aux code of the source becomes on the target, if not itself.
fn replacement(s: &Stmt, from: &DialectSpec, to: &DialectSpec) -> Option<StmtKind> {
    let StmtKind::Aux {
        letter,
        code,
        words,
    } = &s.kind
    else {
        return None;
    };
    // A target's user-program code of the same number is not this code.
    let target = to
        .code(*letter, *code)
        .filter(|c| c.run != AuxRun::UserProgram);
    let source = from.code(*letter, *code);
    let harmless = source.is_some_and(|c| c.run == AuxRun::Pass);
    if target.is_some() || (*letter != 'M' && !harmless) || (!words.is_empty() && !harmless) {
        return None;
    }
    if from.is_machine_datum(&s.kind) && to.code_for(Meaning::MachineCoords).is_some() {
        return Some(StmtKind::MachineCoords);
    }
    if harmless || (source.is_none() && to.has(Capability::StrictMCodes)) {
        let what = source.map_or(String::new(), |c| format!(": {}", c.doc));
        return Some(StmtKind::Comment {
            text: format!("{letter}{}{what}", code.normalized()),
            style: CommentStyle::Paren,
        });
    }
    None
}

fn note(
    span: crate::span::Span,
    letter: char,
    code: crate::ir::Decimal,
    k: &StmtKind,
    from: &DialectSpec,
) -> Diagnostic {
    let m = format!("{letter}{}", code.normalized());
    let (msg, help) = match k {
        StmtKind::MachineCoords => (
            format!("{m} moves in machine coordinates from a datum of the machine builder: written in the target's machine coordinates"),
            "check the position on the target machine: its machine zero may not be the builder's datum of the source".to_string(),
        ),
        _ => (
            format!("{m} is a function of the {} machine the target does not list: written as a comment", from.name),
            "if the target machine has a code for the same function, write it there by hand".to_string(),
        ),
    };
    Diagnostic::new(Code::PortApproximate, msg)
        .primary(span, "not carried as a code")
        .help(help)
}
