//! The words of a path mode (`G64 P0.01 Q0.005`: LinuxCNC's blending and
//! naive-CAM tolerances) go only where the target's code for that mode
//! takes them (`uses=` in its spec). Fanuc's and the 840D's G64 take no
//! word: `P` there is something else (the 840D's subprogram pass count),
//! so a tolerance written after it would not be a tolerance. A word the
//! target's code does not take is left out with W0610; the blending is
//! then the machine's own setting. A target with no code for the mode
//! (Heidenhain: the tolerance cycle) is [`super::to_tnc::modes`]'s.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{Program, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::PathMode { mode, words } = &mut s.kind else {
            continue;
        };
        let Some(code) = to.code_for(Meaning::PathMode(*mode)) else {
            continue;
        };
        let (kept, left): (Vec<_>, Vec<_>) = std::mem::take(words)
            .into_iter()
            .partition(|w| code.uses.contains(&w.letter.to_ascii_uppercase()));
        *words = kept;
        for w in left {
            diags.push(
                Diagnostic::new(
                    Code::PortApproximate,
                    format!(
                        "`{}` of the path mode has no place in {}'s code for it: left out",
                        w.letter, to.name
                    ),
                )
                .primary(w.span, "not carried")
                .help("the target's code for this path mode takes no such word; its blending tolerance is the machine's setting (set it there, or in the target's own tolerance command)"),
            );
        }
    }
}
