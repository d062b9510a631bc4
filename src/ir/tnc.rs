//! Heidenhain functions that no other dialect has a statement for: the
//! FN functions 14..20 (error, print, system data, PLC), `PLANE` (tilting
//! the working plane), `FUNCTION` blocks (TCPM ...), the `MB` retract of
//! `M140` and the FK free contour blocks.
//!
//! Each keeps its text as written (the Klartext writer writes it back
//! unchanged; other writers report it as a construct they cannot express)
//! and what it asks, for the interpreter.

use super::{Value, Var};
use serde::Serialize;

/// One Heidenhain function block: its text as written and its meaning.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TncFunction {
    pub text: String,
    pub kind: TncFunctionKind,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum TncFunctionKind {
    /// `FN 14: ERROR= 1005`: the program stops with its own error number.
    Error(Value),
    /// `FN 15: PRINT +Q1 "text"`: a message of texts and values.
    Print(Vec<PrintItem>),
    /// `FN 16: F-PRINT mask/output`: a formatted output driven by a mask
    /// file; `spec` is the text after `F-PRINT`.
    FormattedPrint { spec: String },
    /// `FN 18: SYSREAD Q23 = ID270 NR1 IDX3`: reads a system datum.
    SysRead {
        var: Var,
        id: u32,
        nr: u32,
        idx: Option<Value>,
    },
    /// `FN 17 SYSWRITE`, `FN 19 PLC`, `FN 20 WAIT FOR`, and other FN
    /// functions the run only reports: the function number.
    MachineOnly(u32),
    /// `PLANE RESET` / `PLANE SPATIAL SPA+0 SPB+0 SPC+0 TURN ..`.
    Plane(Box<TiltPlane>),
    /// `R+` / `R-` in `L X+10 R+`: the one-axis move is lengthened
    /// (`true`) or shortened by the tool radius (paraxial compensation).
    Paraxial(bool),
    /// `FL`, `FC`, `FPOL`, `FSELECT` ...: FK free contour programming,
    /// which is kept but not interpreted; the block's keyword.
    FreeContour(String),
    /// `FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS`, `FUNCTION RESET
    /// TCPM`, `FUNCTION MODE MILL` ...: a `FUNCTION` block; the words after
    /// `FUNCTION`, upper case, one space apart.
    Function(String),
    /// `MB MAX` / `MB 50` after `M140` (with its `F`, if any): retract in
    /// the tool axis by a distance, or to the end of travel (`None`).
    Retract(Option<Value>),
    /// `TCH PROBE 417 DATUM IN TS AXIS ~ Q263=..`: a touch probe cycle,
    /// run at once by the TNC: it measures the workpiece or the tool and
    /// may set the datum or the tool table; the cycle number as written.
    TouchProbe(String),
}

/// One item of `FN 15: PRINT`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum PrintItem {
    Text(String),
    Value(Value),
}

/// `PLANE <how> <angles> <positioning>`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct TiltPlane {
    /// `RESET`, `SPATIAL`, `PROJECTED`, `EULER`, `VECTOR`, `POINTS`,
    /// `RELATIV`, `AXIAL`.
    pub how: String,
    /// The definition words (`SPA`, `SPB`, `SPC`, `B`, `NX` ...) with
    /// their values (degrees, or vector components for VECTOR/POINTS).
    pub values: Vec<(String, Value)>,
    /// `MOVE`, `TURN` or `STAY` (how the rotary axes go), if written.
    pub positioning: Option<String>,
}

impl TncFunctionKind {
    /// A short name for the meta-model text (`cncc ir`).
    pub fn name(&self) -> &'static str {
        match self {
            TncFunctionKind::Error(_) => "error",
            TncFunctionKind::Print(_) => "print",
            TncFunctionKind::FormattedPrint { .. } => "formatted-print",
            TncFunctionKind::SysRead { .. } => "sysread",
            TncFunctionKind::MachineOnly(_) => "machine-only",
            TncFunctionKind::Plane(_) => "plane",
            TncFunctionKind::Paraxial(_) => "paraxial",
            TncFunctionKind::FreeContour(_) => "free-contour",
            TncFunctionKind::Function(_) => "function",
            TncFunctionKind::Retract(_) => "retract",
            TncFunctionKind::TouchProbe(_) => "touch-probe",
        }
    }
}
