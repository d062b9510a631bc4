//! Keyword commands of the source (Siemens `SUPA`, `FNORM`) on a target
//! that does not list them, by what the source spec says of them:
//!
//! * a command with a neutral meaning (`meaning="machine-coords"`: `SUPA`
//!   puts its block in machine coordinates) becomes the statement of that
//!   meaning, which the target writes in its own form (`G53`, Klartext
//!   `M91`) where it has a code for it; where its machine-coordinate
//!   blocks move at rapid only (no capability `machine-coords-feed`:
//!   Fanuc `G53` [?]), only a block that is a rapid (or moves nothing)
//!   is carried, and the writer names the others (E0601);
//! * a command nothing the run computes depends on (`run="pass"`: `FNORM`
//!   the default feed profile, `SOFT` acceleration, `STOPRE`) becomes a
//!   comment naming it, with a W0610 note once per command.
//!
//! Any other command stays, and the writer names it (E0601).

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{Block, MotionKind, Program, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let mut said: Vec<String> = Vec::new();
    for b in &mut p.blocks {
        let carried = machine_block_carried(b, to);
        for s in &mut b.stmts {
            let StmtKind::Command { name, args: None } = &s.kind else {
                continue;
            };
            if to.is_command(name) {
                continue;
            }
            let name = name.to_ascii_uppercase();
            let meaning = from.command_meaning(&name);
            let first = !said.contains(&name);
            if meaning == Some(Meaning::MachineCoords)
                && to.code_for(Meaning::MachineCoords).is_some()
                && carried
            {
                s.kind = StmtKind::MachineCoords;
                if first {
                    diags.push(
                        Diagnostic::new(
                            Code::PortApproximate,
                            format!("{name} is written as the target's move in machine coordinates"),
                        )
                        .primary(s.span, "the block in machine coordinates")
                        .help(format!(
                            "{name} also suppresses offsets the run does not model (on the 840D: DRF, handwheel and external zero offsets, the basic frame); check the target machine has none in force"
                        )),
                    );
                }
            } else if from.command_passes(&name) {
                s.kind = StmtKind::Comment {
                    text: format!("{name}: a {} command that changes nothing cut", from.name),
                    style: super::comment_style(to),
                };
                if first {
                    diags.push(
                        Diagnostic::new(
                            Code::PortApproximate,
                            format!(
                                "{name} changes nothing the program cuts and {} has no such command: written as a comment",
                                to.name
                            ),
                        )
                        .primary(s.span, "not carried as a command")
                        .help("if the target machine has the same function, write its code there by hand"),
                    );
                }
            } else {
                continue;
            }
            if first {
                said.push(name);
            }
        }
    }
}

/// Can the target carry this block's machine-coordinate move: it feeds
/// in machine coordinates, or the block moves at rapid or not at all.
fn machine_block_carried(b: &Block, to: &DialectSpec) -> bool {
    if to.has(Capability::MachineCoordsFeed) {
        return true;
    }
    b.stmts.iter().all(|s| match &s.kind {
        StmtKind::Motion(m) => m.kind == MotionKind::Rapid,
        StmtKind::Cycle(_) => false,
        _ => true,
    })
}
