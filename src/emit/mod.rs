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
    let mut w = Writer::new(p, spec, style);
    let mut out = String::new();
    for b in &p.blocks {
        let line = block(&mut w, b);
        out.push_str(&line);
        out.push('\n');
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
