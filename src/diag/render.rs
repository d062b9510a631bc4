//! Renders diagnostics: for people with codespan-reporting, for tools as
//! one JSON object per line.

use super::{Diagnostic, Severity};
use crate::source::SourceMap;
use codespan_reporting::diagnostic as cs;
use codespan_reporting::term::{self, termcolor};
use serde::Serialize;

fn to_codespan(d: &Diagnostic, files: &SourceMap) -> cs::Diagnostic<usize> {
    let sev = match d.severity {
        Severity::Error => cs::Severity::Error,
        Severity::Warning => cs::Severity::Warning,
        Severity::Note => cs::Severity::Note,
    };
    let labels = d
        .labels
        .iter()
        .map(|l| {
            let f = l.span.file;
            let range =
                files.to_view(f, l.span.start as usize)..files.to_view(f, l.span.end as usize);
            let style = if l.primary {
                cs::LabelStyle::Primary
            } else {
                cs::LabelStyle::Secondary
            };
            cs::Label::new(style, f.0 as usize, range).with_message(l.message.clone())
        })
        .collect();
    let mut notes = d.notes.clone();
    if let Some(h) = &d.help {
        notes.push(format!("help: {h}"));
    }
    cs::Diagnostic::new(sev)
        .with_code(format!("{} {}", d.code.code(), d.code.name()))
        .with_message(d.message.clone())
        .with_labels(labels)
        .with_notes(notes)
}

/// Diagnostics of one code shown in one run; the rest are counted.
pub const MAX_PER_CODE: usize = 100;
/// Lines longer than this are shown as a window round the spot.
pub const LONG_LINE: usize = 240;

/// Renders for a person; `color` for a terminal. At most
/// [`MAX_PER_CODE`] diagnostics of one code, then one note with the count
/// of the others; a long line is shown as a window round the spot.
pub fn human(diags: &[Diagnostic], files: &SourceMap, color: bool) -> String {
    let mut buf = if color {
        termcolor::Buffer::ansi()
    } else {
        termcolor::Buffer::no_color()
    };
    let config = term::Config::default();
    let mut shown: std::collections::HashMap<super::Code, usize> = Default::default();
    for d in diags {
        let n = shown.entry(d.code).or_default();
        *n += 1;
        if *n > MAX_PER_CODE {
            continue;
        }
        if let Some(text) = windowed(d, files) {
            use std::io::Write;
            let _ = buf.write_all(text.as_bytes());
            continue;
        }
        // Rendering only fails on a label outside its file; fall back to a line.
        if term::emit_to_write_style(&mut buf, &config, files, &to_codespan(d, files)).is_err() {
            use std::io::Write;
            let _ = writeln!(
                buf,
                "{}[{}]: {}",
                d.severity_word(),
                d.code.code(),
                d.message
            );
        }
    }
    let mut more: Vec<_> = shown
        .into_iter()
        .filter(|(_, n)| *n > MAX_PER_CODE)
        .collect();
    more.sort();
    for (code, n) in more {
        use std::io::Write;
        let _ = writeln!(
            buf,
            "note: {} more {} {} diagnostics not shown\n",
            n - MAX_PER_CODE,
            code.code(),
            code.name()
        );
    }
    String::from_utf8_lossy(buf.as_slice()).into_owned()
}

/// A diagnostic whose primary label is on a line longer than
/// [`LONG_LINE`], shown with a window of that line round the spot (the
/// whole line would be printed for each diagnostic otherwise).
fn windowed(d: &Diagnostic, files: &SourceMap) -> Option<String> {
    let l = d.labels.iter().find(|l| l.primary).or(d.labels.first())?;
    let f = l.span.file;
    let text = files.text(f);
    let v = files.to_view(f, l.span.start as usize).min(text.len());
    let start = text[..v].rfind('\n').map_or(0, |i| i + 1);
    let end = text[v..].find('\n').map_or(text.len(), |i| v + i);
    if end - start <= LONG_LINE {
        return None;
    }
    let floor = |mut i: usize| {
        while !text.is_char_boundary(i) {
            i -= 1;
        }
        i
    };
    let from = floor(v.saturating_sub(60).max(start));
    let to = floor((v + 60).min(end));
    let (line, col) = files.line_col(f, l.span.start as usize);
    let lead = if from > start { "…" } else { "" };
    let tail = if to < end { "…" } else { "" };
    let window: String = text[from..to]
        .chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect();
    let caret = " ".repeat(lead.chars().count() + text[from..v].chars().count());
    let mut out = format!(
        "{}[{} {}]: {}\n  --> {}:{line}:{col}\n   | {lead}{window}{tail}\n   | {caret}^ {}\n",
        d.severity_word(),
        d.code.code(),
        d.code.name(),
        d.message,
        files.name(f),
        l.message
    );
    for n in &d.notes {
        out.push_str(&format!("   = {n}\n"));
    }
    if let Some(h) = &d.help {
        out.push_str(&format!("   = help: {h}\n"));
    }
    out.push('\n');
    Some(out)
}

impl Diagnostic {
    fn severity_word(&self) -> &'static str {
        match self.severity {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Note => "note",
        }
    }
}

#[derive(Serialize)]
struct JsonLabel<'a> {
    message: &'a str,
    primary: bool,
    line: usize,
    column: usize,
    end_line: usize,
    end_column: usize,
}

#[derive(Serialize)]
struct JsonDiagnostic<'a> {
    code: &'static str,
    name: &'static str,
    severity: Severity,
    message: &'a str,
    file: Option<&'a str>,
    line: Option<usize>,
    column: Option<usize>,
    end_line: Option<usize>,
    end_column: Option<usize>,
    labels: Vec<JsonLabel<'a>>,
    notes: &'a [String],
    help: Option<&'a str>,
}

/// One JSON object per line, for editors and CI.
pub fn json(diags: &[Diagnostic], files: &SourceMap) -> String {
    let mut out = String::new();
    for d in diags {
        let labels: Vec<JsonLabel> = d
            .labels
            .iter()
            .map(|l| {
                let (line, column) = files.line_col(l.span.file, l.span.start as usize);
                let (end_line, end_column) = files.line_col(l.span.file, l.span.end as usize);
                JsonLabel {
                    message: &l.message,
                    primary: l.primary,
                    line,
                    column,
                    end_line,
                    end_column,
                }
            })
            .collect();
        let main = labels.iter().find(|l| l.primary).or(labels.first());
        let j = JsonDiagnostic {
            code: d.code.code(),
            name: d.code.name(),
            severity: d.severity,
            message: &d.message,
            file: d.span().map(|s| files.name(s.file)),
            line: main.map(|l| l.line),
            column: main.map(|l| l.column),
            end_line: main.map(|l| l.end_line),
            end_column: main.map(|l| l.end_column),
            notes: &d.notes,
            help: d.help.as_deref(),
            labels,
        };
        out.push_str(&serde_json::to_string(&j).unwrap_or_default());
        out.push('\n');
    }
    out
}
