//! Fine and back boring are other cycles from one control to the next:
//! Fanuc's G76/G87 shift by the retained Q at an oriented stop (`shift` in
//! the spec), LinuxCNC's G87 takes I J K. A port between two dialects
//! whose codes for such a cycle differ in that way is E0601: the words of
//! one do not say the other's moves. (The writer also refuses words the
//! target's code does not take.)

use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{CycleKind, Program, StmtKind};

pub fn run(p: &Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    for block in &p.blocks {
        for stmt in &block.stmts {
            let StmtKind::Cycle(c) = &stmt.kind else {
                continue;
            };
            if !matches!(c.kind, CycleKind::FineBore | CycleKind::BackBore) {
                continue;
            }
            let m = Meaning::Cycle(c.kind);
            let (Some(a), Some(b)) = (from.code_for(m), to.code_for(m)) else {
                continue;
            };
            if a.shift.is_some() == b.shift.is_some() {
                continue;
            }
            let code =
                |d: &crate::dialect::CodeDef| format!("{}{}", d.letter, d.code.format(0, false));
            let what = format!(
                "{} cannot express this {}: {}'s {} and {}'s {} are different cycles (shift by Q at an oriented stop, or I J K)",
                to.name,
                m.name(),
                from.name,
                code(a),
                to.name,
                code(b)
            );
            diags.push(
                Diagnostic::new(Code::CannotExpress, what)
                    .primary(stmt.span, "written here")
                    .help("write the boring as the moves it makes, or choose a target whose cycle shifts the same way"),
            );
        }
    }
}
