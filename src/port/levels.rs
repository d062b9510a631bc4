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
    /// The last known X and Y in program coordinates (None: not known).
    pub x: Option<Value>,
    pub y: Option<Value>,
    /// The last known Z in program coordinates (None: not known here).
    pub z: Option<Value>,
    /// The active plane is XY (G17).
    pub plane_xy: bool,
    pub feed: Option<Value>,
    pub speed: Option<Value>,
    /// Spindle turning counter-clockwise (M4).
    pub ccw: bool,
    /// G98 (true) / G99 (false).
    pub return_initial: bool,
    pub tool: Option<Value>,
    /// G53 in this block: its move is in machine coordinates.
    machine: bool,
}

impl Modal {
    pub fn new(spec: &DialectSpec) -> Self {
        Modal {
            absolute: true,
            unit: LengthUnit::Mm,
            x: None,
            y: None,
            z: None,
            plane_xy: true,
            feed: None,
            speed: None,
            ccw: false,
            return_initial: !spec.has(Capability::CycleRetractRPlaneAtStart),
            tool: None,
            machine: false,
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
            StmtKind::Plane(p) => self.plane_xy = *p == crate::ir::Plane::XY,
            StmtKind::Motion(_) if self.machine => {
                self.machine = false;
                self.forget();
            }
            StmtKind::Motion(m) => self.follow(&m.target),
            StmtKind::Cycle(c) => {
                // The hole position; the level after it is set by the passes.
                self.follow(&crate::ir::Axes {
                    x: c.target.x.clone(),
                    y: c.target.y.clone(),
                    ..Default::default()
                })
            }
            StmtKind::MachineCoords => {
                self.machine = true;
                self.forget();
            }
            StmtKind::RefReturn { .. }
            | StmtKind::Call { .. }
            | StmtKind::CoordShift { .. }
            | StmtKind::Transform(_)
            | StmtKind::WorkOffset { .. } => self.forget(),
            _ => {}
        }
    }

    /// The position is not known any more.
    fn forget(&mut self) {
        self.x = None;
        self.y = None;
        self.z = None;
    }

    /// Follows the end point of a move.
    pub fn follow(&mut self, t: &crate::ir::Axes) {
        let absolute = self.absolute;
        let set = |slot: &mut Option<Value>, c: &Option<crate::ir::Coord>| {
            if let Some(c) = c {
                *slot = if absolute && c.dim != Some(DimMode::Incremental) {
                    Some(c.value.clone())
                } else {
                    None
                };
            }
        };
        set(&mut self.x, &t.x);
        set(&mut self.y, &t.y);
        set(&mut self.z, &t.z);
    }

    /// Re-entry distance of a Fanuc-style G83 peck (LinuxCNC: 0.010 in).
    pub fn peck_clearance(&self) -> f64 {
        match self.unit {
            LengthUnit::Mm => 0.254,
            LengthUnit::Inch => 0.010,
        }
    }
}
