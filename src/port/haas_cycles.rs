//! Haas G12/G13 (circular pocket) and G150 (general pocket) read as kept
//! codes (`Aux`): a target without the matching capability has no such
//! cycle, and writing the code through would change what it means (or
//! stop the target's reader). Each is refused (E0610), except that with
//! `--expand-cycles` a G12/G13 in G90 is left to [`super::expand`], which
//! writes the moves the interpreter makes for it. G12/G13 in G91 and
//! G150 (not expanded by the interpreter) are always refused there.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::interp::{haas_g150, haas_pocket};
use crate::ir::{DimMode, Program, StmtKind};

/// Which Haas pocket code a statement is, if any.
fn haas_code(k: &StmtKind) -> Option<(&'static str, Capability)> {
    let StmtKind::Aux { letter, code, .. } = k else {
        return None;
    };
    if haas_pocket::is_circular_pocket(*letter, *code) {
        let g = if code.to_f64() < 12.5 { "G12" } else { "G13" };
        return Some((g, Capability::CircularPocketCycle));
    }
    if haas_g150::is_general_pocket(*letter, *code) {
        return Some(("G150", Capability::GeneralPocketCycle));
    }
    None
}

pub fn run(
    p: &Program,
    from: &DialectSpec,
    to: &DialectSpec,
    expand: bool,
    diags: &mut Vec<Diagnostic>,
) {
    let mut incremental = false;
    for s in p.blocks.iter().flat_map(|b| b.stmts.iter()) {
        if let StmtKind::Distance(d) = &s.kind {
            incremental = *d == DimMode::Incremental;
        }
        let Some((g, cap)) = haas_code(&s.kind) else {
            continue;
        };
        if !from.has(cap) || to.has(cap) {
            continue;
        }
        let why = match (cap, expand, incremental) {
            (Capability::CircularPocketCycle, true, false) => continue,
            (Capability::CircularPocketCycle, true, true) => {
                "in G91 its moves cannot be expanded (expanded moves are absolute)"
            }
            (Capability::CircularPocketCycle, false, _) => {
                "the target has no circular pocket cycle; --expand-cycles writes its moves"
            }
            _ => "the target has no general pocket cycle, and cncc does not expand G150",
        };
        diags.push(
            Diagnostic::new(
                Code::PortCycle,
                format!("{g} cannot be ported to {}: {why}", to.id),
            )
            .primary(s.span, format!("Haas {g}"))
            .help("program the pocket with the target's own cycle or moves"),
        );
    }
}
