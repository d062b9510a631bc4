//! Axis words before any motion code: Fanuc and Haas move them at rapid
//! (capability `power-on-rapid`), the 840D at the feed
//! (`power-on-linear`, where a missing feed is an alarm), LinuxCNC not at
//! all ("Cannot use axis values without a g code that uses them"). Where
//! the target's power-on mode differs from the source's, the first moves
//! without a motion code get the source's one (`G43 H1 Z50.` →
//! `G0 Z50 D1`).
//!
//! Written order [?: a subprogram called before the main program's first
//! motion code is not followed; verify would tell].

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{MotionKind, Program, StmtKind};

fn power_on(spec: &DialectSpec) -> Option<MotionKind> {
    if spec.has(Capability::PowerOnRapid) {
        Some(MotionKind::Rapid)
    } else if spec.has(Capability::PowerOnLinear) {
        Some(MotionKind::Linear)
    } else {
        None
    }
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let Some(kind) = power_on(from) else { return };
    if power_on(to) == Some(kind) {
        return;
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            match &mut s.kind {
                StmtKind::Motion(m) if m.kind == MotionKind::Implicit => {
                    let moves =
                        !m.target.is_empty() || m.polar_radius.is_some() || m.polar_angle.is_some();
                    if moves {
                        m.kind = kind;
                        return;
                    }
                }
                StmtKind::Motion(_) | StmtKind::Cycle(_) => return,
                _ => {}
            }
        }
    }
}
