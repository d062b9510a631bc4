//! The Heidenhain Klartext writer (see [`write_klartext`]), and how the
//! other families write (or refuse) the Heidenhain-only statements.

use super::writer::Writer;
use crate::ir::{Stmt, StmtKind as K};

/// A Heidenhain-only statement in a word-address or Sinumerik program:
/// the blank and the program end are carried as comments; the rest cannot
/// be expressed and is reported by name.
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
        _ => return,
    };
    w.cannot(
        s.span,
        what,
        "translate it with `cncc port` (which maps Heidenhain cycles) or rewrite this part by hand",
    );
}
