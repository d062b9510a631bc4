//! The program frame of a Klartext source for a target of another family:
//!
//! * `TOOL CALL` gets `D1` for a Siemens target (the tool's edge), and
//!   `G43 H<tool>` for a target with length-offset codes (Fanuc, Haas,
//!   LinuxCNC), on the first move in Z after the call (`G0 Z20. G43 H5`),
//!   as Fanuc programs apply it: `TOOL CALL` applies the tool's length,
//!   and G43 alone would move Z by the offset where the tool stands.
//! * Block numbers go (every Klartext block has one; jumps use labels).
//! * `BEGIN PGM name` is a program known only by name; a target that
//!   numbers its programs (capability `numbered-programs`) gets the name
//!   as a comment (the number comes from the file, as the source's did).
//! * `END PGM` marks the end of the program text: outside Klartext the end
//!   of the file does that, so it goes (the program's M30/M2 stays).
//!
//! Units with their feeds (`BEGIN PGM .. MM`, Siemens `G700`/`G710`: the
//! feeds in the same unit) become, for any source, the plain units code
//! of a target that has no such form: its units code sets the feed unit
//! too (Fanuc, LinuxCNC `G20`/`G21` [K]).

use crate::dialect::{Capability, DialectSpec, Family, Meaning};
use crate::ir::{CommentStyle, Program, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    plain_units(p, to);
    if to.family == Family::Klartext || from.family != Family::Klartext {
        return;
    }
    for b in &mut p.blocks {
        // Klartext numbers every block; nothing refers to the numbers
        // (jumps go to `LBL`s), so the target numbers its own way.
        b.number = None;
        // `TOOL CALL` activates the tool's (one) cutting edge: Siemens
        // needs `D1` for that (as the Klartext writer reads `D1`) [?].
        if to.family == Family::Sinumerik
            && b.stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::ToolChange))
            && !b
                .stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::CuttingEdge(_)))
        {
            let span = b.span;
            b.stmts.push(crate::ir::Stmt::new(
                StmtKind::CuttingEdge(crate::ir::Value::Number(crate::ir::Decimal::from_int(1))),
                span,
            ));
        }
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::ProgramEnd { .. }));
        for s in &mut b.stmts {
            match &mut s.kind {
                StmtKind::ProgramStart {
                    number: None,
                    name: Some(name),
                } if to.has(Capability::NumberedPrograms) => {
                    s.kind = StmtKind::Comment {
                        text: name.clone(),
                        style: CommentStyle::Paren,
                    };
                }
                _ => {}
            }
        }
    }
    length_offsets(p, to);
    // Blocks left empty (`END PGM`, a cycle definition mapped away) go.
    p.blocks
        .retain(|b| !b.stmts.is_empty() || b.label.is_some());
}

/// `G43 H<tool>` on the first Z move after each `TOOL CALL` (not after a
/// `TOOL DEF` preselection), for a target
/// with the length-offset code (Siemens has none: its `D1` carries the
/// length).
fn length_offsets(p: &mut Program, to: &DialectSpec) {
    let g43 = Meaning::LengthComp(crate::ir::LengthComp::Positive);
    if to.code_for(g43).is_none() {
        return;
    }
    let mut pending: Option<crate::ir::Value> = None;
    for b in &mut p.blocks {
        // The tool a `TOOL CALL` loads (a `TOOL DEF` alone only preselects).
        let changes = b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ToolChange));
        for s in b.stmts.iter().filter(|_| changes) {
            if let StmtKind::ToolSelect(crate::ir::ToolRef::Number(v)) = &s.kind {
                pending = Some(v.clone());
            }
        }
        if b.stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::LengthComp { .. }))
        {
            pending = None;
            continue;
        }
        let Some(at) = b
            .stmts
            .iter()
            .position(|s| matches!(&s.kind, StmtKind::Motion(m) if m.target.z.is_some()))
        else {
            continue;
        };
        let Some(register) = pending.take() else {
            continue;
        };
        let span = b.stmts[at].span;
        b.stmts.insert(
            at,
            crate::ir::Stmt::new(
                StmtKind::LengthComp {
                    mode: crate::ir::LengthComp::Positive,
                    register: Some(register),
                    axes: Box::default(),
                },
                span,
            ),
        );
    }
}

/// `G700` as `G20` where the target has no units-with-feeds code.
fn plain_units(p: &mut Program, to: &DialectSpec) {
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        if let StmtKind::Units {
            unit,
            with_feeds: with_feeds @ true,
        } = &mut s.kind
        {
            let form = Meaning::Units {
                unit: *unit,
                with_feeds: true,
            };
            if to.code_for(form).is_none() {
                *with_feeds = false;
            }
        }
    }
}
