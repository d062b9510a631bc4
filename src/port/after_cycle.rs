//! The motion mode after a canned cycle is cancelled, where source and
//! target keep it differently. On a control whose canned cycles are a
//! modal group of their own (Fanuc: group 09 apart from G00..G03), `G80`
//! leaves the motion mode that was in force before the cycle, so axis
//! words alone after it move at rapid or feed as before; on a control
//! whose cycles are motion codes (LinuxCNC: group 1), `G80` leaves no
//! motion mode and axis words alone are an error. So for such a target,
//! each move after a cancel that gives no motion code gets the mode the
//! source left (the last motion code written before, in program order),
//! until a motion code is written again. Where that mode is not known
//! here the move stays as it is (reading the port back refuses it).

use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{CycleKind, MotionKind, Program, StmtKind};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if !own_group(from) || own_group(to) {
        return;
    }
    let mut last: Option<MotionKind> = None;
    let mut cancelled = false;
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        match &mut s.kind {
            StmtKind::CycleCancel => cancelled = true,
            StmtKind::Cycle(_) => cancelled = false,
            StmtKind::Motion(m) => match m.kind {
                MotionKind::Implicit if cancelled => {
                    if let Some(k) = last {
                        m.kind = k;
                    }
                }
                MotionKind::Implicit => {}
                k => {
                    last = Some(k);
                    cancelled = false;
                }
            },
            _ => {}
        }
    }
}

/// Whether the spec's drilling cycle is in a modal group apart from the
/// rapid move's.
fn own_group(spec: &DialectSpec) -> bool {
    let group = |m| spec.code_for(m).map(|c| c.group.clone());
    match (
        group(Meaning::Cycle(CycleKind::Drill)),
        group(Meaning::Motion(MotionKind::Rapid)),
    ) {
        (Some(c), Some(r)) => c != r,
        _ => false,
    }
}
