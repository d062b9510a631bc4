//! What raising could not carry exactly, counted and reported once each
//! (a 30 MB program must not give a million warnings).

use crate::diag::{Code, Diagnostic};
use crate::span::Span;

#[derive(Default)]
pub struct Losses {
    comments: (usize, Option<Span>),
    helices: (usize, Option<Span>),
    cycles: (usize, Option<Span>),
}

fn count(slot: &mut (usize, Option<Span>), span: Span, n: usize) {
    slot.0 += n;
    slot.1.get_or_insert(span);
}

impl Losses {
    /// A comment that names no workingstep.
    pub fn comment(&mut self, _text: String, span: Span) {
        count(&mut self.comments, span, 1);
    }

    /// `n` helical moves written as polylines.
    pub fn helix(&mut self, span: Span, n: usize) {
        count(&mut self.helices, span, n);
    }

    /// A cycle kept as explicit toolpaths.
    pub fn cycle(&mut self, span: Span) {
        count(&mut self.cycles, span, 1);
    }

    pub fn diagnostics(&self) -> Vec<Diagnostic> {
        let mut out = Vec::new();
        let mut add = |slot: &(usize, Option<Span>), code: Code, what: &str, help: &str| {
            if slot.0 == 0 {
                return;
            }
            let mut d = Diagnostic::new(code, format!("{} {what}", slot.0)).help(help);
            if let Some(span) = slot.1.filter(|s| !s.is_empty()) {
                d = d.primary(span, "the first one");
            }
            out.push(d);
        };
        add(
            &self.comments,
            Code::RaiseCommentsNotCarried,
            "comment(s) not carried into STEP-NC (only the comment before a cut names its workingstep)",
            "STEP-NC has no comments; put the text you need in the comment just before the cut it describes",
        );
        add(
            &self.helices,
            Code::RaiseHelixAsPolyline,
            "helical move(s) written as polylines within 0.001 mm",
            "the STEP-NC model has no HELIX entity yet; the path is kept, as points",
        );
        add(
            &self.cycles,
            Code::RaiseCycleAsToolpath,
            "canned cycle(s) kept as explicit toolpaths, not as hole features",
            "back-boring cycles (and other unrecognised vertical runs) have no hole operation in cncc's STEP-NC model yet",
        );
        out
    }
}
