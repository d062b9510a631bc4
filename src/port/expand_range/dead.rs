//! A subprogram the program never calls, carried as comments (W0613).
//!
//! When the target has no form for something inside a label subprogram
//! (Klartext `LBL`, LinuxCNC `o<name> sub`) that the run never reaches,
//! there are no moves to write it as, and dropping it would lose what the
//! program says. Such a subprogram can only be called from its own
//! program, so a run that reaches the program's end without calling it
//! shows that it never runs: its text goes to the target as comments, in
//! its place. A numbered program of its own (`O2000` in a Fanuc file) may
//! be called by other programs and is never treated so.

use super::trace::Trace;
use crate::diag::{Code, Diagnostic};
use crate::ir::{Block, CommentStyle, Program, Stmt, StmtKind};
use std::collections::HashSet;

/// Whether blocks `d.0..=d.1` are a label subprogram that never ran
/// (`ran`: the blocks of the main file that ran) in a run that reached
/// its end.
pub fn definition(p: &Program, t: &Trace, ran: &HashSet<usize>, d: (usize, usize)) -> bool {
    if t.stopped.is_some() || t.end.is_none() {
        return false;
    }
    let first = &p.blocks[d.0];
    let numbered = first
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::ProgramStart { .. }));
    let opens = first.label.is_some()
        || first
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::SubStart { .. }));
    opens && !numbered && !(d.0..=d.1).any(|i| ran.contains(&i))
}

/// The warning for carrying blocks `d` as comments.
pub fn note(p: &Program, d: (usize, usize)) -> Diagnostic {
    Diagnostic::new(
        Code::PortDeadSubprogram,
        "a subprogram this program never calls is carried as comments",
    )
    .primary(p.blocks[d.0].span, "never called: the run reached the program's end without it")
    .help("the target has no form for something in it; port it by hand or delete it in the source if it is wanted or not (see `cncc explain W0613`)")
}

/// Blocks `d` as comment blocks holding their source lines (a program
/// end among them stays a program end).
pub fn as_comments(p: &Program, source: &str, d: (usize, usize)) -> Vec<Block> {
    let (a, b) = (&p.blocks[d.0], &p.blocks[d.1]);
    let text = if a.span.file == p.file {
        source.get(a.span.start as usize..b.span.end as usize)
    } else {
        None
    };
    let mut out = vec![comment(a, "never called, carried as text:".into())];
    match text {
        Some(t) => out.extend(t.lines().map(|l| comment(a, l.trim_end().to_string()))),
        None => out.push(comment(a, "(its text is in another file)".into())),
    }
    out.extend(
        p.blocks[d.0..=d.1]
            .iter()
            .filter(|b| {
                b.stmts
                    .iter()
                    .any(|s| matches!(s.kind, StmtKind::ProgramEnd { .. }))
            })
            .cloned(),
    );
    out
}

fn comment(at: &Block, text: String) -> Block {
    Block {
        span: at.span,
        skip: None,
        number: None,
        label: None,
        stmts: vec![Stmt::new(
            StmtKind::Comment {
                text,
                style: CommentStyle::Paren,
            },
            at.span,
        )],
    }
}
