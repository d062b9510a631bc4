//! What only the word-address writer (Fanuc, Haas, LinuxCNC) says its own
//! way: `(MSG,..)`, `O1234`, canned cycles `G83 X Y Z R Q K`, Macro B jumps
//! and `IF [..] THEN`, subprogram calls `M98 P L`, `G65 P A B`, `o100 call`.

use super::flow;
use super::number::NumKind;
use super::writer::Writer;
use crate::dialect::{Capability, Meaning};
use crate::ir::{
    CallArgs, CallKind, CallTarget, CannedCycle, ExprId, JumpDir, JumpTarget, Stmt, Value,
};
use crate::span::Span;

pub fn message(w: &mut Writer<'_>, text: Option<&str>, span: Span, words: &mut Vec<String>) {
    if !w.need(Capability::MessageComments, span, "an operator message") {
        return;
    }
    match text {
        Some(t) => {
            let t = w.safe_message(t, crate::dialect::text::TextForm::Paren, span);
            words.push(format!("(MSG,{t})"))
        }
        None => w.cannot(
            span,
            "clearing the operator message",
            "remove the statement",
        ),
    }
}

pub fn program_start(
    w: &mut Writer<'_>,
    number: Option<u32>,
    name: Option<&str>,
    span: Span,
    words: &mut Vec<String>,
) {
    if !w.need(Capability::NumberedPrograms, span, "a program number") {
        return;
    }
    let Some(n) = number else {
        return w.cannot(
            span,
            "a program known only by name",
            "give the program a number",
        );
    };
    words.push(format!("O{n:04}"));
    if let Some(name) = name {
        let t = w.safe_text(name, crate::dialect::text::TextForm::Paren, span);
        words.push(format!("({t})"));
    }
}

/// `G83 X Y Z R Q P I J K` and the repeat count under the spec's letter.
pub fn cycle(w: &mut Writer<'_>, c: &CannedCycle, span: Span, words: &mut Vec<String>) {
    if !same_oriented_boring(w, c, span) {
        return;
    }
    w.push_code(words, Meaning::Cycle(c.kind), span);
    w.push_axes(words, &c.target);
    let parts = [
        ("R", &c.r, NumKind::Length),
        ("Q", &c.q, NumKind::Length),
        ("P", &c.p, cycle_dwell_kind(w)),
        ("I", &c.i, NumKind::Length),
        ("J", &c.j, NumKind::Length),
        ("K", &c.k, NumKind::Length),
    ];
    for (addr, v, kind) in parts {
        if let Some(v) = v {
            w.push_word(words, addr, v, kind, span);
        }
    }
    if let Some(v) = &c.repeat {
        let letter = w.spec.repeat_letter.to_string();
        w.push_word(words, &letter, v, NumKind::Int, span);
    }
}

/// Fine and back boring are other cycles from one control to the next:
/// Fanuc's G87 shifts by the retained Q (`shift` in its spec), LinuxCNC's
/// takes I J K, Haas's G76/G77 take Q or I J. The target writes such a
/// cycle only when its code uses every word the block gives; otherwise
/// E0601 (the port also compares the two codes' `shift`).
fn same_oriented_boring(w: &mut Writer<'_>, c: &CannedCycle, span: Span) -> bool {
    use crate::ir::CycleKind;
    if !matches!(c.kind, CycleKind::FineBore | CycleKind::BackBore) {
        return true;
    }
    let meaning = Meaning::Cycle(c.kind);
    let Some(target) = w.spec.code_for(meaning) else {
        return true; // `push_code` says the target has none.
    };
    if target.uses.is_empty() {
        return true; // A spec that declares no words for it says nothing.
    }
    let written = [
        ('R', c.r.is_some()),
        ('Q', c.q.is_some()),
        ('P', c.p.is_some()),
        ('I', c.i.is_some()),
        ('J', c.j.is_some()),
        ('K', c.k.is_some()),
    ];
    let missing: Vec<char> = written
        .iter()
        .filter(|(l, given)| *given && !target.uses.contains(l))
        .map(|(l, _)| *l)
        .collect();
    if missing.is_empty() {
        return true;
    }
    let code = format!("{}{}", target.letter, target.code.format(0, false));
    let letters: String = missing.iter().collect();
    let what = format!(
        "the {letters} of this {} (its {code} does not take them)",
        meaning.name()
    );
    w.cannot(
        span,
        &what,
        "write the boring as the moves it makes in the source dialect, or choose a target whose cycle shifts the same way",
    );
    false
}

/// A cycle's `P` dwell is whole milliseconds where the target's dwell code
/// reads `P` as milliseconds (Fanuc), otherwise a plain number (LinuxCNC
/// seconds). The IR does not record the unit of a cycle's P.
fn cycle_dwell_kind(w: &Writer<'_>) -> NumKind {
    let p_unit = w.spec.code_for(Meaning::Dwell).and_then(|c| {
        c.dwell_units
            .iter()
            .find(|(l, _)| *l == 'P')
            .map(|(_, u)| *u)
    });
    match p_unit {
        Some(crate::ir::DwellUnit::Milliseconds) => NumKind::Int,
        Some(crate::ir::DwellUnit::Seconds | crate::ir::DwellUnit::Revolutions) | None => {
            NumKind::Plain
        }
    }
}

pub fn goto(
    w: &mut Writer<'_>,
    target: &JumpTarget,
    dir: JumpDir,
    cond: Option<ExprId>,
    span: Span,
    words: &mut Vec<String>,
) {
    if !w.need(Capability::MacroB, span, "a GOTO jump") {
        return;
    }
    if dir != JumpDir::Either {
        return w.cannot(
            span,
            &format!("a directed jump ({})", flow::jump_kw(dir)),
            "use GOTO with a sequence number",
        );
    }
    let JumpTarget::Sequence(v) = target else {
        return w.cannot(
            span,
            "a jump to a label",
            "number the target block and jump to its N number",
        );
    };
    let mut out = Vec::new();
    if let Some(c) = cond {
        let Some(c) = flow::cond(w, c) else { return };
        out.extend(["IF".to_string(), c]);
    }
    let Some(n) = w.word("", v, NumKind::Int, span) else {
        return;
    };
    out.extend(["GOTO".to_string(), n]);
    words.extend(out);
}

pub fn if_then(w: &mut Writer<'_>, cond: ExprId, then: &Stmt, span: Span, words: &mut Vec<String>) {
    if !w.need(Capability::MacroB, span, "IF ... THEN") {
        return;
    }
    let Some(c) = flow::cond(w, cond) else { return };
    let mut inner = Vec::new();
    super::stmt::write_stmt(w, then, false, &mut inner);
    words.extend(["IF".to_string(), c, "THEN".to_string()]);
    words.extend(inner);
}

pub fn call(
    w: &mut Writer<'_>,
    kind: CallKind,
    target: &CallTarget,
    args: &CallArgs,
    repeat: Option<&Value>,
    span: Span,
    words: &mut Vec<String>,
) {
    let meaning = match kind {
        CallKind::OWord => return oword_call(w, target, args, repeat, span, words),
        CallKind::Subprogram | CallKind::Named => Meaning::SubCall,
        CallKind::Local => Meaning::LocalCall,
        CallKind::Macro => Meaning::MacroCall,
        CallKind::ModalMacro => Meaning::ModalMacroCall,
        CallKind::Label => {
            return w.cannot(
                span,
                "a Heidenhain label call (`CALL LBL`)",
                "make the labelled section a numbered subprogram",
            )
        }
    };
    let p = match target {
        CallTarget::Number(n) => Value::Number(crate::ir::Decimal::from_int(*n as i64)),
        CallTarget::Computed(e) => Value::Expr(*e),
        CallTarget::Name(n) => {
            return w.cannot(
                span,
                &format!("a call to the named subprogram `{n}`"),
                "number the subprogram (O-number) and call it by number",
            );
        }
    };
    w.push_code(words, meaning, span);
    w.push_word(words, "P", &p, NumKind::Int, span);
    letter_args(w, args, span, words);
    if let Some(r) = repeat {
        w.push_word(words, "L", r, NumKind::Int, span);
    }
}

fn letter_args(w: &mut Writer<'_>, args: &CallArgs, span: Span, words: &mut Vec<String>) {
    match args {
        CallArgs::None => {}
        CallArgs::Positional(list) if list.is_empty() => {}
        CallArgs::Positional(_) => w.cannot(
            span,
            "positional subprogram arguments",
            "pass values in #-variables or use G65 letter arguments",
        ),
        CallArgs::Letters(list) => {
            // Every argument with its point, as a length: a Fanuc control
            // reads an argument written without one in the address's
            // least input increment (`A20` can be 0.020), `A20.` is 20.
            for (letter, v) in list {
                w.push_word(words, &letter.to_string(), v, NumKind::Length, span);
            }
        }
    }
}

/// `o100 call [a] [b]`, `o<name> call`.
fn oword_call(
    w: &mut Writer<'_>,
    target: &CallTarget,
    args: &CallArgs,
    repeat: Option<&Value>,
    span: Span,
    words: &mut Vec<String>,
) {
    if !w.need(Capability::OWords, span, "an o-word subroutine call") {
        return;
    }
    let head = match target {
        CallTarget::Number(n) => flow::oword(&n.to_string()),
        CallTarget::Name(n) => flow::oword(n),
        CallTarget::Computed(_) => {
            return w.cannot(
                span,
                "an o-word call to a computed target",
                "call the subroutine by name",
            )
        }
    };
    if repeat.is_some() {
        return w.cannot(
            span,
            "a repeated o-word call",
            "wrap the call in `o.. repeat [n]`",
        );
    }
    let mut out = vec![head, "call".to_string()];
    match args {
        CallArgs::None => {}
        CallArgs::Positional(list) => {
            for a in list {
                let Some(e) = a else {
                    return w.cannot(
                        span,
                        "an empty o-word call argument",
                        "give every argument a value",
                    );
                };
                let Some(s) = w.expr(*e) else { return };
                out.push(format!("[{s}]"));
            }
        }
        CallArgs::Letters(_) => {
            return w.cannot(
                span,
                "letter arguments to an o-word call",
                "pass them positionally",
            )
        }
    }
    words.extend(out);
}
