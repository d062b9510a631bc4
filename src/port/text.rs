//! Comments that the target would run as commands: a comment ported from
//! another dialect that opens with one of the target's active words
//! (LinuxCNC `(LOGOPEN,..)`, `(PY,..)`, `(MSG,..)`...) is neutralised, with
//! a located warning; for a 7-bit target, its other characters are
//! transliterated (W0691). The writer escapes the characters of every
//! text for the form it writes.

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Program, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if from.id == to.id {
        return;
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let span = s.span;
            if let StmtKind::Comment { text, .. } = &mut s.kind {
                if let Some(plain) = to.text.to_charset(text) {
                    let d = crate::emit::writer::text_warning(
                        &to.name,
                        &crate::dialect::text::Escaped {
                            text: plain.clone(),
                            transliterated: true,
                            ..Default::default()
                        },
                        Some(span),
                    );
                    diags.extend(d);
                    *text = plain;
                }
                // Only the active word is changed here; the writer escapes
                // the characters for the form it writes.
                // Control characters are written as spaces: the word is
                // looked for in the text as the target will read it.
                let mut kept: String = text
                    .chars()
                    .map(|c| if c.is_control() && c != '\t' { ' ' } else { c })
                    .collect();
                if let Some(word) = &to.text.neutralise(&mut kept) {
                    let d = crate::emit::writer::text_warning(
                        &to.name,
                        &crate::dialect::text::Escaped {
                            text: kept.clone(),
                            neutralised: Some(word.clone()),
                            ..Default::default()
                        },
                        Some(span),
                    );
                    diags.extend(d);
                    *text = kept;
                }
            }
        }
    }
}
