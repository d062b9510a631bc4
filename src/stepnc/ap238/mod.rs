//! AP238 ed.1 AIM files (FILE_SCHEMA `INTEGRATED_CNC_SCHEMA`), read as
//! far as their explicit toolpaths go, into the same model the ISO 14649
//! ARM reader fills (so that `post`, `canon`, `plot`... run them).
//!
//! The AIM maps each ARM object onto generic STEP resources joined by
//! relationship instances; the reader descends them:
//!
//! - project: `MACHINING_PROJECT`; workpieces through
//!   `MACHINING_PROJECT_WORKPIECE_RELATIONSHIP` → `PRODUCT_DEFINITION` →
//!   `PRODUCT`;
//! - workplan: the `MACHINING_WORKPLAN` no sequence relationship lists,
//!   its elements by `MACHINING_PROCESS_SEQUENCE_RELATIONSHIP` (in the
//!   order of their sequence position);
//! - workingstep (`MACHINING_WORKINGSTEP`): its operation by
//!   `MACHINING_OPERATION_RELATIONSHIP`, its feature by
//!   `MACHINING_FEATURE_RELATIONSHIP` → `PROPERTY_PROCESS` →
//!   `PROCESS_PROPERTY_ASSOCIATION` → `INSTANCED_FEATURE` (its placement
//!   through its shape representation), a security plane by an
//!   `ACTION_PROPERTY` named so;
//! - operation: its tool is the `MACHINING_TOOL` whose usage lists it
//!   (body values by `RESOURCE_PROPERTY` → `..._REPRESENTATION` →
//!   measure), technology and machine functions by their relationships
//!   and `ACTION_PROPERTY` → `ACTION_PROPERTY_REPRESENTATION` →
//!   representation items; toolpaths by
//!   `MACHINING_TOOLPATH_SEQUENCE_RELATIONSHIP`;
//! - toolpath (`MACHINING_TOOLPATH` described as a cutter location
//!   trajectory): its `basic curve` property's representation item, a
//!   `POLYLINE`, `COMPOSITE_CURVE` or `TRIMMED_CURVE` of a `LINE` or
//!   `CIRCLE`, in the length unit its representation context assigns.
//!
//! Units are those the file assigns, each value by its own declared unit
//! (a tool size by its measure's unit, a point by its context's, a feed
//! by its derived unit's length and time: any length over any time unit
//! becomes mm/min); a length in a unit cncc cannot resolve is named
//! (W0807), never taken as mm. Where the declared units make a feed or a
//! cutting speed implausible and millimetres would not, `W0808
//! ap238-units-doubtful` says so [?] (see `plausible`). Spindle speeds follow ISO 14649's sign (positive =
//! counter-clockwise, M4) as the ARM reader does [?: STEP Tools files may
//! mean positive as the usual clockwise cut]. What is not read (feature
//! geometry, operation strategies, B-spline curves, other properties and
//! executables) is named in a `W0807 ap238-not-read` warning, never
//! dropped silently.

mod graph;
mod read;

use crate::diag::Diagnostic;
use crate::stepnc::model::Project;
use crate::stepnc::part21::P21File;

/// Whether a FILE_SCHEMA name is the AP238 ed.1 AIM this reader reads.
pub fn is_aim_schema(name: &str) -> bool {
    name.split_whitespace().next() == Some("INTEGRATED_CNC_SCHEMA")
}

/// Reads an AP238 AIM file's plan: the project (None on errors) and the
/// diagnostics.
pub fn read_project(file: &P21File) -> (Option<Project>, Vec<Diagnostic>) {
    read::Reader::new(file).project()
}
