//! Comments that the target would run as commands: a comment ported from
//! another dialect that opens with one of the target's active words
//! (LinuxCNC `(LOGOPEN,..)`, `(PY,..)`, `(MSG,..)`...) is neutralised, with
//! a located warning; for a 7-bit target, the characters of comments,
//! operator messages and program names are transliterated (W0691). The writer escapes the
//! characters of every text for the form it writes.

use crate::diag::Diagnostic;
use crate::dialect::text::Escaped;
use crate::dialect::DialectSpec;
use crate::ir::{Program, StmtKind};
use crate::span::Span;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if from.id == to.id {
        return;
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let span = s.span;
            match &mut s.kind {
                StmtKind::Comment { text, .. } => {
                    to_charset(text, to, span, diags);
                    neutralise(text, to, span, diags);
                }
                // A message is a command by nature: only its characters.
                StmtKind::Message(Some(text)) => to_charset(text, to, span, diags),
                // A name a target cannot write as one is kept as a comment.
                StmtKind::ProgramStart {
                    name: Some(text), ..
                }
                | StmtKind::ProgramEnd { name: Some(text) } => to_charset(text, to, span, diags),
                _ => {}
            }
        }
    }
}

/// For a 7-bit target, the text's other characters as their nearest ASCII.
fn to_charset(text: &mut String, to: &DialectSpec, span: Span, diags: &mut Vec<Diagnostic>) {
    let Some(plain) = to.text.to_charset(text) else {
        return;
    };
    let e = Escaped {
        text: plain.clone(),
        transliterated: true,
        ..Default::default()
    };
    diags.extend(crate::emit::writer::text_warning(&to.name, &e, Some(span)));
    *text = plain;
}

/// Only the active word is changed here; the writer escapes the
/// characters for the form it writes. Control characters are written as
/// spaces: the word is looked for in the text as the target will read it.
fn neutralise(text: &mut String, to: &DialectSpec, span: Span, diags: &mut Vec<Diagnostic>) {
    let mut kept: String = text
        .chars()
        .map(|c| if c.is_control() && c != '\t' { ' ' } else { c })
        .collect();
    if let Some(word) = &to.text.neutralise(&mut kept) {
        let e = Escaped {
            text: kept.clone(),
            neutralised: Some(word.clone()),
            ..Default::default()
        };
        diags.extend(crate::emit::writer::text_warning(&to.name, &e, Some(span)));
        *text = kept;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::builtin::builtin;
    use crate::span::FileId;

    /// A Siemens program ported by this pass to LinuxCNC made 7-bit.
    fn ported(src: &str, ascii: bool) -> (Program, Vec<Diagnostic>) {
        let from = builtin("siemens840d").expect("siemens");
        let mut to = (*builtin("linuxcnc").expect("linuxcnc")).clone();
        to.text.ascii = ascii;
        let (mut p, read) = crate::driver::read_program(src, FileId(0), &from);
        assert!(!read.iter().any(Diagnostic::is_error), "{read:?}");
        let mut diags = Vec::new();
        run(&mut p, &from, &to, &mut diags);
        (p, diags)
    }

    fn messages(p: &Program) -> Vec<String> {
        let all = p.blocks.iter().flat_map(|b| &b.stmts);
        all.filter_map(|s| match &s.kind {
            StmtKind::Message(Some(t)) => Some(t.clone()),
            _ => None,
        })
        .collect()
    }

    #[test]
    fn a_message_to_a_7_bit_target_is_transliterated_with_a_warning() {
        let (p, diags) = ported("G0 X0\nMSG(\"Prüfen Ø10 für Öl\")\nM30\n", true);
        assert_eq!(messages(&p), ["Pruefen D10 fuer OEl"]);
        let d = diags.iter().find(|d| d.code.code() == "W0691");
        let d = d.unwrap_or_else(|| panic!("no W0691: {diags:?}"));
        assert_eq!(d.span().map(|s| s.start), Some(6), "located at the MSG");
    }

    #[test]
    fn a_message_to_an_8_bit_target_or_in_ascii_is_kept() {
        let (p, diags) = ported("MSG(\"Prüfen Ø10\")\nM30\n", false);
        assert_eq!(messages(&p), ["Prüfen Ø10"]);
        assert!(diags.is_empty(), "{diags:?}");
        let (p, diags) = ported("MSG(\"LOGOPEN,x\")\nM30\n", true);
        assert_eq!(messages(&p), ["LOGOPEN,x"], "a message is no comment");
        assert!(diags.is_empty(), "{diags:?}");
    }
}
