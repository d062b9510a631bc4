//! The subprograms a Klartext port calls, added to the written program:
//! every `CALL LBL n` whose label the program does not have loads the
//! numbered program n beside the source (`O1000.nc`), ports it with the
//! same options and writes it as `LBL n` ... `LBL 0` (its `M99`) just
//! before `END PGM`, then numbers all blocks again. Called programs that
//! call others bring those too (each once).
//!
//! Works on the written text because the called program is a program of
//! its own (its own expressions and spans): its written blocks without
//! its `BEGIN PGM` / `END PGM` lines are the subprogram's body.

use super::subprograms::called;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Family};
use crate::interp::flow::ProgramLoader;
use crate::ir::{CallTarget, Program};
use crate::port::{port_program, PortOptions};
use crate::span::Span;

/// How many subprograms one port brings in at most.
const MAX_SUBPROGRAMS: usize = 200;

/// `text` (the written port of `main`) with the called subprograms
/// added; errors go to `diags` (and the text is not complete).
pub fn append(
    main: &Program,
    text: String,
    from: &DialectSpec,
    to: &DialectSpec,
    opts: &PortOptions,
    loader: &mut dyn ProgramLoader,
    diags: &mut Vec<Diagnostic>,
) -> String {
    if to.family != Family::Klartext || from.family == Family::Klartext {
        return text;
    }
    let have = labels(main);
    let mut todo: Vec<(u32, Span)> = missing(main, &have);
    let mut done: Vec<u32> = have;
    let mut body = Vec::new();
    while let Some((n, span)) = todo.pop() {
        if done.contains(&n) {
            continue;
        }
        done.push(n);
        if done.len() > MAX_SUBPROGRAMS {
            diags.push(refusal(
                span,
                format!("more than {MAX_SUBPROGRAMS} subprograms"),
            ));
            break;
        }
        let Some(sub) = loader.load(&CallTarget::Number(n)) else {
            diags.push(refusal(
                span,
                format!("the called program {n} is not found beside the program"),
            ));
            continue;
        };
        let (ported, d) = port_program(&sub, from, to, opts);
        let failed = d.iter().any(Diagnostic::is_error);
        diags.extend(d);
        if failed {
            continue;
        }
        let written = match crate::emit::write_program(&ported, to) {
            Ok(t) => t,
            Err(errs) => {
                diags.extend(errs);
                continue;
            }
        };
        body.push(format!("0 LBL {n}"));
        body.extend(inner_lines(&written));
        if body.last().map(|l| strip_number(l).trim()) != Some("LBL 0") {
            body.push("0 LBL 0".into());
        }
        let inner = labels(&ported);
        todo.extend(missing(&ported, &inner));
    }
    if body.is_empty() {
        return text;
    }
    let mut lines: Vec<String> = text.lines().map(str::to_string).collect();
    let end = lines
        .iter()
        .rposition(|l| strip_number(l).starts_with("END PGM"))
        .unwrap_or(lines.len());
    lines.splice(end..end, body);
    renumber(&lines)
}

fn refusal(span: Span, msg: String) -> Diagnostic {
    Diagnostic::new(Code::PortSubprogram, msg)
        .primary(span, "called here")
        .help("put the subprogram file beside the program (O1000.nc for M98 P1000)")
}

/// The numeric labels `p` defines.
fn labels(p: &Program) -> Vec<u32> {
    p.blocks
        .iter()
        .filter_map(|b| b.label.as_ref().and_then(|l| l.node.parse().ok()))
        .collect()
}

/// The label calls of `p` to labels not in `have`, with the call's span.
fn missing(p: &Program, have: &[u32]) -> Vec<(u32, Span)> {
    let mut out = Vec::new();
    for n in called(p) {
        if have.contains(&n) {
            continue;
        }
        let span = p
            .blocks
            .iter()
            .flat_map(|b| &b.stmts)
            .find(|s| {
                matches!(&s.kind, crate::ir::StmtKind::Call {
                    target: CallTarget::Number(m), ..
                } if *m == n)
            })
            .map(|s| s.span);
        if let Some(span) = span {
            out.push((n, span));
        }
    }
    out.reverse();
    out
}

/// The blocks of a written program between `BEGIN PGM` and `END PGM`.
fn inner_lines(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| {
            let s = strip_number(l);
            !s.starts_with("BEGIN PGM") && !s.starts_with("END PGM")
        })
        .map(str::to_string)
        .collect()
}

/// A block line without its leading block number (continuation lines,
/// which start with blanks, as they are).
fn strip_number(l: &str) -> &str {
    match l.split_once(' ') {
        Some((n, rest)) if !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit()) => rest,
        _ => l,
    }
}

/// The lines with block numbers 0, 1, 2... again.
fn renumber(lines: &[String]) -> String {
    let mut out = String::new();
    let mut n = 0;
    for l in lines {
        if l.starts_with(|c: char| c.is_ascii_digit()) {
            out.push_str(&format!("{n} {}\n", strip_number(l)));
            n += 1;
        } else {
            out.push_str(l);
            out.push('\n');
        }
    }
    out
}
