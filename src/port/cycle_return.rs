//! The retract level of canned cycles before any G98/G99: Fanuc and Haas
//! return to the initial level (G98 at power-on), LinuxCNC to the R plane
//! until G98 is programmed (capability `cycle-retract-r-plane-at-start`).
//! Where source and target differ, the first cycle that runs in that
//! power-on state gets the source's mode written before it (`G98 G82 ..`),
//! so the retracts between holes stay where the source made them.
//!
//! Written order [?: a cycle in a subprogram called before the main
//! program's first G98/G99 is not followed; verify would tell].

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, Stmt, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let cap = Capability::CycleRetractRPlaneAtStart;
    if from.has(cap) == to.has(cap) {
        return;
    }
    let initial = !from.has(cap);
    for b in &mut p.blocks {
        // `G81 .. G99`: a mode in the block of the first cycle is its own.
        if b.stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::ReturnToInitial(_)))
        {
            return;
        }
        for (i, s) in b.stmts.iter().enumerate() {
            match s.kind {
                StmtKind::ReturnToInitial(_) => return,
                StmtKind::Cycle(_) => {
                    let mode = Stmt::new(StmtKind::ReturnToInitial(initial), s.span);
                    b.stmts.insert(i, mode);
                    return;
                }
                _ => {}
            }
        }
    }
}
