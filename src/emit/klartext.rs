//! The Heidenhain Klartext writer ([`write_klartext_warned`]), and how the other
//! families write (or refuse) the Heidenhain-only statements ([`foreign`]).
//!
//! Every block gets a number (0, 1, 2 ... as the control renumbers on
//! save); coordinates always carry their sign (`X+10`, `IY-2`); one IR
//! block may become several Klartext blocks (a Fanuc `T1 M6 G0 X10 S500 M3`
//! is a `TOOL CALL` and an `L`). Cycle definitions are written one Q
//! parameter per continuation line (`~`), with their labels. A program
//! without `BEGIN PGM`/`END PGM` gets them. What Klartext cannot say
//! (centre-offset arcs I J K, `#` variables, G-code modes without a Klartext
//! function) is an E0601 error naming it.

mod expr;
mod lines;
mod moves;
mod others;

use super::number::NumKind;
use super::writer::{Style, Writer};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{LengthUnit, Program, Stmt, StmtKind as K};

/// What the Klartext writer keeps between blocks.
#[derive(Default)]
pub(super) struct Out {
    /// Logical blocks; a continued block holds `~\n` inside.
    pub lines: Vec<String>,
    /// G91 in force (a word-address program): every coordinate gets `I`.
    pub incremental: bool,
    /// The last motion kind written (for implicit moves).
    pub modal: Option<crate::ir::MotionKind>,
    pub unit: Option<LengthUnit>,
    /// The motion line being written is a rapid (`FMAX`).
    pub rapid: bool,
    /// A feed set in a rapid block (`G81 .. F100` as `L .. FMAX M99`):
    /// FMAX and F cannot share a block, so it goes on the next feed move
    /// that has no feed of its own.
    pub pending_feed: Option<String>,
    /// G90.1: arc centres I J K are absolute.
    pub arc_absolute: bool,
}

/// Writes `p` as Klartext: the whole text and the warnings, or all the
/// diagnostics.
pub fn write_klartext_warned(
    p: &Program,
    spec: &DialectSpec,
) -> Result<(String, Vec<Diagnostic>), Vec<Diagnostic>> {
    let (lines, diags) = kept_lines(p, spec, &|_| true, true)?;
    Ok((number_lines(&lines), diags))
}

/// The logical blocks of the blocks `keep` selects (unnumbered), written
/// with the state the whole program gives them; `frame` adds `BEGIN PGM`
/// and `END PGM` where the program has none.
pub(super) fn kept_lines(
    p: &Program,
    spec: &DialectSpec,
    keep: &dyn Fn(&crate::ir::Block) -> bool,
    frame: bool,
) -> Result<(Vec<String>, Vec<Diagnostic>), Vec<Diagnostic>> {
    let mut w = Writer::new(p, spec, Style::Sinumerik);
    let mut out = Out::default();
    let stmts = || p.blocks.iter().flat_map(|b| b.stmts.iter());
    let unit = stmts().find_map(|s| match &s.kind {
        K::Units { unit, .. } => Some(*unit),
        _ => None,
    });
    out.unit = unit;
    w.units = Some(unit.unwrap_or(LengthUnit::Mm));
    let has_start = stmts().any(|s| matches!(s.kind, K::ProgramStart { .. }));
    let has_end = stmts().any(|s| matches!(s.kind, K::ProgramEnd { .. }));
    let unit_word = unit_word(unit);
    if frame && !has_start {
        out.lines.push(format!("BEGIN PGM PGM {unit_word}"));
    }
    for b in &p.blocks {
        let before = out.lines.len();
        lines::block(&mut w, &mut out, b);
        if !keep(b) {
            out.lines.truncate(before);
        }
    }
    if frame && !has_end {
        let name = first_name(p).unwrap_or_else(|| "PGM".into());
        out.lines.push(format!("END PGM {name} {unit_word}"));
    }
    if w.diags.iter().any(Diagnostic::is_error) {
        return Err(w.diags);
    }
    Ok((out.lines, w.diags))
}

/// Numbers logical blocks 0, 1, 2 ... (a skipped block `/n`).
fn number_lines(lines: &[String]) -> String {
    let mut text = String::with_capacity(lines.iter().map(|l| l.len() + 8).sum());
    for (i, l) in lines.iter().enumerate() {
        push_numbered(&mut text, i, l);
    }
    text
}

/// Appends logical block `l` as block number `n`, with its line end.
pub fn push_numbered(text: &mut String, n: usize, l: &str) {
    use std::fmt::Write;
    let _ = match l.strip_prefix('/') {
        Some(rest) => writeln!(text, "/{n} {rest}"),
        None => writeln!(text, "{n} {l}"),
    };
}

pub(super) fn unit_word(u: Option<LengthUnit>) -> &'static str {
    match u {
        Some(LengthUnit::Inch) => "INCH",
        Some(LengthUnit::Mm) | None => "MM",
    }
}

/// The program's name (from `BEGIN PGM`, `O1234`, `%_N_NAME_MPF`).
pub(super) fn first_name(p: &Program) -> Option<String> {
    p.blocks
        .iter()
        .flat_map(|b| b.stmts.iter())
        .find_map(|s| match &s.kind {
            K::ProgramStart { number, name } => program_name(*number, name.as_deref()),
            _ => None,
        })
}

/// A name Klartext takes after `BEGIN PGM`: the program's name if it is
/// one word of letters, digits, `_` `-` `.`, else its number.
pub(super) fn program_name(number: Option<u32>, name: Option<&str>) -> Option<String> {
    let word = |n: &str| {
        !n.is_empty()
            && n.chars()
                .all(|c| c.is_ascii_alphanumeric() || "_-.".contains(c))
    };
    match (name, number) {
        (Some(n), _) if word(n) => Some(n.to_string()),
        (_, Some(n)) => Some(n.to_string()),
        (Some(n), None) => Some(
            n.split(|c: char| !c.is_ascii_alphanumeric())
                .filter(|s| !s.is_empty())
                .collect::<Vec<_>>()
                .join("_"),
        )
        .filter(|s| !s.is_empty()),
        (None, None) => None,
    }
}

/// A Heidenhain-only statement in a word-address or Sinumerik program:
/// reported by name (E0601); `port` maps the cycles before writing.
pub(super) fn foreign(w: &mut Writer<'_>, s: &Stmt, words: &mut Vec<String>) {
    let _ = words;
    let what = match &s.kind {
        K::ProgramEnd { .. } => "a Heidenhain `END PGM`",
        K::Stock { .. } => "a Heidenhain blank definition (`BLK FORM`)",
        K::ToolDef { .. } => "a tool definition in the program (`TOOL DEF`)",
        K::ToolOversize { .. } => "tool oversizes (`DL`/`DR` in `TOOL CALL`)",
        K::Pole(_) => "a circle centre / pole (`CC`)",
        K::Corner { .. } => "a corner element (`RND`/`CHF`) between blocks",
        K::Approach(_) => "an approach/departure contour (`APPR`/`DEP`)",
        K::CycleDef(_) => "a Heidenhain cycle definition (`CYCL DEF`)",
        K::CycleLine(_) => "an old-style Heidenhain cycle (`CYCL DEF n.m`)",
        K::CycleRun(_) => "a Heidenhain cycle call",
        K::PatternDef(_) => "a point pattern (`PATTERN DEF`)",
        K::TncFunction(_) => "a Heidenhain function (FN 14..20, `PLANE`, FK)",
        _ => return,
    };
    w.cannot(
        s.span,
        what,
        "translate it with `cncc port` (which maps Heidenhain cycles) or rewrite this part by hand",
    );
}

/// A number as Klartext writes it after an address (`+10`, `-2.5`).
pub(super) fn num_kind_for(addr: &str) -> NumKind {
    match addr {
        "F" | "S" => NumKind::Feed,
        "PA" | "IPA" | "CCA" => NumKind::Angle,
        _ => NumKind::Length,
    }
}
