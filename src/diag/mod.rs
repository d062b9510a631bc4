//! Diagnostics: what went wrong or looks suspect, where, and what to do.
//!
//! Every diagnostic has a stable [`Code`] (`E0201`) and a kebab-case name
//! (`two-motion-codes`); `cncc explain CODE` prints the explanation kept in
//! [`codes`]. Rendering (human, via codespan, or JSON) is in [`render`].

pub mod codes;
pub mod render;
pub mod sarif;

pub use codes::Code;

use crate::span::Span;
use serde::Serialize;

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Note,
    Warning,
    Error,
}

/// A place a diagnostic points at, with what it says about that place.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Label {
    pub span: Span,
    pub message: String,
    pub primary: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Diagnostic {
    pub code: Code,
    pub severity: Severity,
    pub message: String,
    pub labels: Vec<Label>,
    pub notes: Vec<String>,
    pub help: Option<String>,
}

impl Diagnostic {
    /// A diagnostic of `code`, with the code's default severity.
    pub fn new(code: Code, message: impl Into<String>) -> Self {
        Diagnostic {
            code,
            severity: code.severity(),
            message: message.into(),
            labels: Vec::new(),
            notes: Vec::new(),
            help: None,
        }
    }

    /// The place the problem is, underlined.
    pub fn primary(mut self, span: Span, message: impl Into<String>) -> Self {
        self.labels.push(Label {
            span,
            message: message.into(),
            primary: true,
        });
        self
    }

    /// A related place (where a mode came from, the other word of a pair).
    pub fn secondary(mut self, span: Span, message: impl Into<String>) -> Self {
        self.labels.push(Label {
            span,
            message: message.into(),
            primary: false,
        });
        self
    }

    pub fn note(mut self, note: impl Into<String>) -> Self {
        self.notes.push(note.into());
        self
    }

    /// What to do about it.
    pub fn help(mut self, help: impl Into<String>) -> Self {
        self.help = Some(help.into());
        self
    }

    pub fn with_severity(mut self, severity: Severity) -> Self {
        self.severity = severity;
        self
    }

    pub fn is_error(&self) -> bool {
        self.severity == Severity::Error
    }

    /// The primary span, or the first label's.
    pub fn span(&self) -> Option<Span> {
        self.labels
            .iter()
            .find(|l| l.primary)
            .or(self.labels.first())
            .map(|l| l.span)
    }
}

/// How many diagnostics one run keeps before it only counts them.
pub const MAX_KEPT: usize = 2000;

/// Collects diagnostics, keeping at most [`MAX_KEPT`] of them.
#[derive(Debug, Default)]
pub struct Diagnostics {
    list: Vec<Diagnostic>,
    errors: usize,
    warnings: usize,
    dropped: usize,
}

impl Diagnostics {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn push(&mut self, d: Diagnostic) {
        match d.severity {
            Severity::Error => self.errors += 1,
            Severity::Warning => self.warnings += 1,
            Severity::Note => {}
        }
        if self.list.len() < MAX_KEPT {
            self.list.push(d);
        } else {
            self.dropped += 1;
        }
    }

    pub fn extend(&mut self, ds: impl IntoIterator<Item = Diagnostic>) {
        for d in ds {
            self.push(d);
        }
    }

    pub fn has_errors(&self) -> bool {
        self.errors > 0
    }

    pub fn error_count(&self) -> usize {
        self.errors
    }

    pub fn warning_count(&self) -> usize {
        self.warnings
    }

    /// How many were counted but not kept.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    pub fn is_empty(&self) -> bool {
        self.list.is_empty()
    }

    pub fn iter(&self) -> impl Iterator<Item = &Diagnostic> {
        self.list.iter()
    }

    /// The kept diagnostics, sorted by file and position.
    pub fn into_sorted(mut self) -> Vec<Diagnostic> {
        self.list
            .sort_by_key(|d| d.span().map(|s| (s.file, s.start)).unwrap_or_default());
        self.list
    }

    pub fn as_slice(&self) -> &[Diagnostic] {
        &self.list
    }
}

/// How many diagnostics of one code a long stream keeps (see [`PerCode`]).
pub const MAX_KEPT_PER_CODE: usize = 1000;

/// Keeps the first [`MAX_KEPT_PER_CODE`] diagnostics of each code of a
/// stream and counts the rest, so that a file with millions of the same
/// fault (ten million unknown Part 21 entities) holds a thousand
/// diagnostics, not millions. The first kept diagnostic of a code with
/// more gets a note with the full count ([`PerCode::finish`]).
#[derive(Debug, Default)]
pub struct PerCode {
    seen: std::collections::HashMap<Code, usize>,
}

impl PerCode {
    /// Keeps, of the diagnostics pushed since `from`, those under the cap.
    pub fn admit(&mut self, diags: &mut Vec<Diagnostic>, from: usize) {
        let mut kept = from;
        for i in from..diags.len() {
            let n = self.seen.entry(diags[i].code).or_default();
            *n += 1;
            if *n <= MAX_KEPT_PER_CODE {
                diags.swap(kept, i);
                kept += 1;
            }
        }
        diags.truncate(kept);
    }

    /// Notes the count on the first diagnostic of each code over the cap.
    pub fn finish(&self, diags: &mut [Diagnostic]) {
        for (code, &n) in &self.seen {
            if n <= MAX_KEPT_PER_CODE {
                continue;
            }
            if let Some(d) = diags.iter_mut().find(|d| d.code == *code) {
                d.notes.push(format!(
                    "{n} {} diagnostics in all; the first {MAX_KEPT_PER_CODE} are kept",
                    code.code()
                ));
            }
        }
    }
}
