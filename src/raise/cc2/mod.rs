//! CC2 feature recognition: a stub standing in for the recognisers being
//! written on branch `cc2` (whose file replaces this one). It recognises
//! nothing, so `cncc stepnc --cc2` gives the project skeleton and tools.

use crate::stepnc::model::{Project, ToolId};
use crate::toolpath::{Event, P3};

pub struct Cc2Context {
    pub tool_diameter: Box<dyn Fn(i64) -> Option<f64>>,
    /// min, max mm.
    pub stock: Option<(P3, P3)>,
    pub secplane_z: f64,
}

/// Appends the recognised workingsteps to `project.main_workplan`.
pub fn recognise(
    _events: &[Event],
    _project: &mut Project,
    _tool: &dyn Fn(i64) -> ToolId,
    _ctx: &Cc2Context,
) {
}
