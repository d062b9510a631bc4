//! Haas G12/G13 (circular pocket) and G150 (general pocket) read as kept
//! codes (`Aux`, meanings `pocket.*`): a target without a code of that
//! meaning has no such
//! cycle, and writing the code through would change what it means (or
//! stop the target's reader). Each is refused (E0610), except that with
//! `--expand-cycles` a G12/G13 in G90 is left to [`super::expand`], which
//! writes the moves the interpreter makes for it. G12/G13 in G91 and
//! G150 (not expanded by the interpreter) are always refused there.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, MachineFn, Meaning};
use crate::interp::aux::machine_fn;
use crate::ir::{DimMode, Program, StmtKind};

/// The pocket function a statement is in the source, with its name.
fn pocket_code(k: &StmtKind, from: &DialectSpec) -> Option<(String, MachineFn)> {
    let StmtKind::Aux { letter, code, .. } = k else {
        return None;
    };
    let f = machine_fn(from, *letter, *code)?;
    let pocket = matches!(
        f,
        MachineFn::CircularPocket { .. } | MachineFn::GeneralPocket
    );
    pocket.then(|| (format!("{letter}{}", code.format(0, false)), f))
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
        let Some((g, f)) = pocket_code(&s.kind, from) else {
            continue;
        };
        if to.code_for(Meaning::Machine(f)).is_some() {
            continue;
        }
        let circular = matches!(f, MachineFn::CircularPocket { .. });
        let why = match (circular, expand, incremental) {
            (true, true, false) => continue,
            (true, true, true) => {
                "in G91 its moves cannot be expanded (expanded moves are absolute)"
            }
            (true, false, _) => {
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
