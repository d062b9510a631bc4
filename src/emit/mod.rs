//! Writers: meta-model to dialect text.
//!
//! [`write_program`] writes a whole program in a target dialect, or returns
//! every reason it cannot (never partial text). Codes come from the target
//! spec's tables; what differs by syntax family lives in [`word`] (Fanuc,
//! Haas, LinuxCNC) and [`sinumerik`] (Siemens 840D).

mod expr;
mod flow;
mod klartext;
mod motion;
pub mod number;
mod sinumerik;
mod stmt;
mod word;
pub(crate) mod writer;

#[cfg(test)]
pub(crate) mod tests;

use crate::diag::Diagnostic;
use crate::dialect::{DialectSpec, Family};
use crate::ir::{Block, Program};
use writer::{Style, Writer};

/// Writes `p` as `spec`'s dialect: the whole text, or all the diagnostics.
pub fn write_program(p: &Program, spec: &DialectSpec) -> Result<String, Vec<Diagnostic>> {
    write_program_warned(p, spec).map(|(t, _)| t)
}

/// [`write_program`] with the warnings (text the writer had to change).
pub fn write_program_warned(
    p: &Program,
    spec: &DialectSpec,
) -> Result<(String, Vec<Diagnostic>), Vec<Diagnostic>> {
    let style = match spec.family {
        Family::WordAddress => Style::Bracket,
        Family::Sinumerik => Style::Sinumerik,
        Family::Klartext => return klartext::write_klartext_warned(p, spec),
    };
    let (lines, diags) = word_lines(p, spec, style, &|_| true)?;
    let mut out = String::with_capacity(lines.iter().map(|l| l.len() + 1).sum());
    for line in &lines {
        out.push_str(line);
        out.push('\n');
    }
    Ok((out, diags))
}

/// The lines of the blocks `keep` selects, each written with the writer
/// state the whole of `p` gives it (the streamed port writes a piece of a
/// program in the context of what precedes it). Klartext lines are
/// logical blocks without their numbers and without the `BEGIN PGM` /
/// `END PGM` frame ([`push_written_line`] numbers them).
pub fn write_kept_lines(
    p: &Program,
    spec: &DialectSpec,
    keep: &dyn Fn(&Block) -> bool,
) -> Result<(Vec<String>, Vec<Diagnostic>), Vec<Diagnostic>> {
    match spec.family {
        Family::WordAddress => word_lines(p, spec, Style::Bracket, keep),
        Family::Sinumerik => word_lines(p, spec, Style::Sinumerik, keep),
        Family::Klartext => klartext::kept_lines(p, spec, keep, false),
    }
}

/// [`write_kept_lines`] with the Klartext frame (`BEGIN PGM`/`END PGM`
/// where the program has none) when `keep` selects every block.
pub fn write_framed_lines(
    p: &Program,
    spec: &DialectSpec,
    keep: &dyn Fn(&Block) -> bool,
) -> Result<(Vec<String>, Vec<Diagnostic>), Vec<Diagnostic>> {
    match spec.family {
        Family::Klartext => klartext::kept_lines(p, spec, keep, true),
        Family::WordAddress | Family::Sinumerik => write_kept_lines(p, spec, keep),
    }
}

/// Appends line `index` of [`write_kept_lines`] to `text` as the target's
/// writer ends it (and numbers it: Klartext).
pub fn push_written_line(spec: &DialectSpec, text: &mut String, index: usize, line: &str) {
    match spec.family {
        Family::Klartext => klartext::push_numbered(text, index, line),
        Family::WordAddress | Family::Sinumerik => {
            text.push_str(line);
            text.push('\n');
        }
    }
}

/// The word-address or Sinumerik lines of the kept blocks.
fn word_lines(
    p: &Program,
    spec: &DialectSpec,
    style: Style,
    keep: &dyn Fn(&Block) -> bool,
) -> Result<(Vec<String>, Vec<Diagnostic>), Vec<Diagnostic>> {
    let mut w = Writer::new(p, spec, style);
    let mut out = Vec::new();
    for b in &p.blocks {
        let line = block(&mut w, b);
        if keep(b) {
            out.push(line);
        }
    }
    if w.diags.iter().any(Diagnostic::is_error) {
        return Err(w.diags);
    }
    Ok((out, w.diags))
}

/// One block: `/1 N10 LABEL: words...`.
fn block(w: &mut Writer<'_>, b: &Block) -> String {
    let mut words = Vec::new();
    if let Some(skip) = &b.skip {
        words.push(if skip.node == 0 {
            "/".to_string()
        } else {
            format!("/{}", skip.node)
        });
    }
    if let Some(n) = &b.number {
        words.push(format!("N{}", n.node));
    }
    if let Some(label) = &b.label {
        match w.style {
            Style::Sinumerik => words.push(format!("{}:", label.node)),
            Style::Bracket => w.cannot(
                label.span,
                "a block label",
                "number the block and jump to its N number",
            ),
        }
    }
    let n = b.stmts.len();
    for (i, s) in b.stmts.iter().enumerate() {
        stmt::write_stmt(w, s, i + 1 == n, &mut words);
    }
    if !w.trailing.is_empty() {
        words.push(format!(";{}", w.trailing.join(" ")));
        w.trailing.clear();
    }
    words.join(" ")
}
