//! `G41` without a D from a source where it takes the radius of the tool
//! in the spindle (LinuxCNC, the 840D's edge, Klartext `RL`), for a
//! target where it takes the D last programmed, D0 (no radius) before any
//! (capability `comp-register-modal`: Fanuc, Haas). The port names the
//! register of the tool selected last, `D` = `T` (the shop convention
//! `length-register-names-tool` assumes for H too), so the machine
//! compensates by the same tool's radius.
//!
//! Written order, after the subprograms moved behind the main program
//! [?: a subprogram called with several tools gets the
//! tool selected last before it in the file; verify would tell].

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, StmtKind, ToolRef, Value};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let cap = Capability::CompRegisterModal;
    if from.has(cap) || !to.has(cap) {
        return;
    }
    let mut tool: Option<Value> = None;
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            match &mut s.kind {
                // T0 empties the spindle: nothing compensates by it.
                StmtKind::ToolSelect(ToolRef::Number(Value::Number(n))) if n.to_f64() == 0.0 => {}
                StmtKind::ToolSelect(ToolRef::Number(v @ Value::Number(_))) => {
                    tool = Some(v.clone())
                }
                StmtKind::ToolSelect(_) => tool = None,
                StmtKind::RadiusComp {
                    side,
                    register: register @ None,
                    diameter: false,
                } if *side != crate::ir::CompSide::Off => {
                    *register = tool.clone();
                }
                _ => {}
            }
        }
    }
}
