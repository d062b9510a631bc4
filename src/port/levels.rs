//! The modal state the cycle passes need, followed statically block by
//! block in program order: distance mode, units, the last known tool-axis
//! level (Z), feed, speed, spindle direction, G98/G99 and the tool.
//!
//! It is a straight walk: jumps, loops and subprogram calls are not
//! followed (a call forgets the level). Where a value is not known here
//! the passes refuse with E0612 rather than guess.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{DimMode, LengthUnit, SpindleState, Stmt, StmtKind, ToolRef, Value};

#[derive(Clone, Debug)]
pub struct Modal {
    pub absolute: bool,
    pub unit: LengthUnit,
    /// The last known Z in program coordinates (None: not known here).
    pub z: Option<Value>,
    pub feed: Option<Value>,
    pub speed: Option<Value>,
    /// Spindle turning counter-clockwise (M4).
    pub ccw: bool,
    /// G98 (true) / G99 (false).
    pub return_initial: bool,
    pub tool: Option<Value>,
}

impl Modal {
    pub fn new(spec: &DialectSpec) -> Self {
        Modal {
            absolute: true,
            unit: LengthUnit::Mm,
            z: None,
            feed: None,
            speed: None,
            ccw: false,
            return_initial: !spec.has(Capability::CycleRetractRPlaneAtStart),
            tool: None,
        }
    }

    /// Follows one statement (cycles are followed by the passes themselves).
    pub fn see(&mut self, s: &Stmt) {
        match &s.kind {
            StmtKind::Distance(d) => self.absolute = *d == DimMode::Absolute,
            StmtKind::Units { unit, .. } => self.unit = *unit,
            StmtKind::Feed(v) => self.feed = Some(v.clone()),
            StmtKind::SpindleSpeed(v) => self.speed = Some(v.clone()),
            StmtKind::Spindle(SpindleState::Cw) => self.ccw = false,
            StmtKind::Spindle(SpindleState::Ccw) => self.ccw = true,
            StmtKind::ReturnToInitial(b) => self.return_initial = *b,
            StmtKind::ToolSelect(ToolRef::Number(v)) => self.tool = Some(v.clone()),
            StmtKind::Motion(m) => {
                if let Some(z) = &m.target.z {
                    self.z = if self.absolute && z.dim != Some(DimMode::Incremental) {
                        Some(z.value.clone())
                    } else {
                        None
                    };
                }
            }
            StmtKind::RefReturn { .. }
            | StmtKind::Call { .. }
            | StmtKind::MachineCoords
            | StmtKind::CoordShift { .. }
            | StmtKind::Transform(_)
            | StmtKind::WorkOffset { .. } => self.z = None,
            _ => {}
        }
    }

    /// Re-entry distance of a Fanuc-style G83 peck (LinuxCNC: 0.010 in).
    pub fn peck_clearance(&self) -> f64 {
        match self.unit {
            LengthUnit::Mm => 0.254,
            LengthUnit::Inch => 0.010,
        }
    }
}
