//! Word checks of one block: required words (E0206), radius with centre
//! (E0207), negative values (E0210) and index words out of range (E0213).

use super::codes::CodeWord;
use super::words::Words;
use crate::diag::{Code, Diagnostic};
use crate::dialect::Meaning;
use crate::ir::CycleKind;
use crate::ir::{ArcDir, MotionKind, Value};
use crate::span::Span;
use crate::syntax::WordSyntax;

/// Words an arc needs one of when the spec lists no `requires`.
const ARC_WORDS: &[&str] = &["I", "J", "K", "R", "CR", "AR", "@", "^", "AP", "RP"];
const CIP_WORDS: &[&str] = &["I1", "J1", "K1"];

/// The alternatives a code needs, from the spec or built in by meaning.
enum Required<'s> {
    /// From the spec: each entry lists alternatives.
    Spec(&'s [Vec<char>]),
    /// Built in: one entry of these alternatives.
    Builtin(&'static [&'static str]),
    /// A dwell: one entry, the words its units name.
    Dwell(&'s [(char, crate::ir::DwellUnit)]),
    None,
}

fn required<'s>(cw: &CodeWord<'s>) -> Required<'s> {
    if let Some(d) = cw.def.filter(|d| !d.requires.is_empty()) {
        return Required::Spec(&d.requires);
    }
    let words: &'static [&'static str] = match cw.meaning {
        Some(Meaning::Motion(MotionKind::Arc(ArcDir::Cw | ArcDir::Ccw))) => ARC_WORDS,
        Some(Meaning::Motion(MotionKind::ArcThrough)) => CIP_WORDS,
        Some(Meaning::Cycle(CycleKind::Peck | CycleKind::ChipBreak)) => &["Q", "I"],
        Some(
            Meaning::SubCall | Meaning::LocalCall | Meaning::MacroCall | Meaning::ModalMacroCall,
        ) => &["P"],
        Some(Meaning::SetData) => &["L"],
        Some(Meaning::Dwell) => {
            return match cw.def {
                Some(d) if !d.dwell_units.is_empty() => Required::Dwell(&d.dwell_units),
                _ => Required::None,
            };
        }
        _ => &[],
    };
    if words.is_empty() {
        return Required::None;
    }
    Required::Builtin(words)
}

/// Reports each required word a code lacks (E0206). An arc code with no
/// word at all only sets the motion mode where a bare motion code does
/// not move (Fanuc, Haas, Siemens: capability `bare-motion-code-moves`
/// absent): the block that moves in that mode is the one that must give
/// the centre, and the run reports it there.
pub(super) fn check_required(
    cw: &CodeWord<'_>,
    words: &Words,
    spec: &crate::dialect::DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    let arc = matches!(
        cw.meaning,
        Some(Meaning::Motion(MotionKind::Arc(ArcDir::Cw | ArcDir::Ccw)))
    );
    if arc && !words.has_free_axes() && !spec.has(crate::dialect::Capability::BareMotionCodeMoves) {
        return;
    }
    let mut missing = |alts: Vec<String>| {
        let list = describe(&alts);
        diags.push(
            Diagnostic::new(Code::MissingWord, format!("`{}` needs {list}", cw.name()))
                .primary(cw.span, format!("needs {list}"))
                .help(format!("add {list} to this block")),
        );
    };
    match required(cw) {
        Required::Spec(entries) => {
            for alts in entries {
                if !alts.iter().any(|a| has_char(words, *a)) {
                    missing(alts.iter().map(|c| c.to_string()).collect());
                }
            }
        }
        Required::Builtin(alts) => {
            if !alts.iter().any(|a| words.has(*a)) {
                missing(alts.iter().map(|s| s.to_string()).collect());
            }
        }
        Required::Dwell(units) => {
            if !units.iter().any(|(c, _)| has_char(words, *c)) {
                missing(units.iter().map(|(c, _)| c.to_string()).collect());
            }
        }
        Required::None => {}
    }
}

/// Looked up as the text of the letter, as the spec writes it.
fn has_char(words: &Words, c: char) -> bool {
    words.has(&*c.encode_utf8(&mut [0u8; 4]))
}

/// The alternatives in words: `` `Q` ``, `` `P` or `X` ``, or an arc's forms.
fn describe(alts: &[String]) -> String {
    if alts.len() == ARC_WORDS.len() && alts.iter().zip(ARC_WORDS).all(|(a, b)| a == b) {
        return "a centre (`I` `J` `K`), a radius (`R`, `CR=`) or an opening angle (`AR=`)".into();
    }
    alts.iter()
        .map(|a| format!("`{a}`"))
        .collect::<Vec<_>>()
        .join(" or ")
}

/// An arc given both a radius and a centre (E0207).
pub(super) fn check_arc_format(words: &Words, diags: &mut Vec<Diagnostic>) {
    let radius = ["R", "CR"].iter().find_map(|a| words.get_free(*a));
    let centre = ["I", "J", "K"].iter().find_map(|a| words.get_free(*a));
    if let (Some(r), Some(c)) = (radius, centre) {
        diags.push(
            Diagnostic::new(
                Code::MixedArcFormat,
                "an arc is given both a radius and a centre",
            )
            .primary(r.span, "radius")
            .secondary(c.span, "centre")
            .help("give either the radius or the centre words, not both"),
        );
    }
}

/// A negative number where only positive ones mean something (E0210).
pub(super) fn check_not_negative(
    value: &Value,
    span: Span,
    what: &str,
    diags: &mut Vec<Diagnostic>,
) {
    if let Value::Number(d) = value {
        if d.is_negative() {
            diags.push(
                Diagnostic::new(Code::NegativeValue, format!("{what} cannot be negative"))
                    .primary(span, format!("negative {what}"))
                    .help("write the value without its sign"),
            );
        }
    }
}

/// The integer value of an index word (tool, register, program, repeat),
/// reporting a non-integer, negative or too large number (E0213).
pub(super) fn check_index(
    w: &WordSyntax,
    what: &str,
    max: Option<i64>,
    diags: &mut Vec<Diagnostic>,
) -> Option<i64> {
    let Value::Number(d) = w.value else {
        return None;
    };
    let n = d.as_int().filter(|n| *n >= 0);
    let ok = n.filter(|n| max.map(|m| *n <= m).unwrap_or(true));
    if ok.is_none() {
        let range = max
            .map(|m| format!("a whole number from 0 to {m}"))
            .unwrap_or("a whole number, 0 or more".into());
        diags.push(
            Diagnostic::new(
                Code::InvalidValue,
                format!("`{}{}` is not a valid {what}", w.address, d),
            )
            .primary(w.span, format!("{what} must be {range}"))
            .help("correct the number"),
        );
    }
    ok
}
