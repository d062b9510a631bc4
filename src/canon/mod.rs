//! NIST canonical machining functions, as LinuxCNC's standalone `rs274`
//! prints them (its 2.9 form): the interpreter's output and the level
//! that STEP-NC is raised from.
//!
//! Positions are in the program frame (relative to the active G5x and G92
//! origins) and in the active length units, as the canon defines them.

mod print;

pub use print::{format_call, write_call};

/// Plane of an arc or cycle, as the canon names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonPlane {
    XY,
    YZ,
    XZ,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CanonUnits {
    Inches,
    Mm,
}

/// Path control modes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum MotionMode {
    ExactStop,
    ExactPath,
    /// Continuous with a blending tolerance (0 = none).
    Continuous(f64),
}

/// Six axis values: x y z a b c.
pub type Pose = [f64; 6];

/// A NURBS control point: X Y in program units and its weight.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NurbsPoint {
    pub x: f64,
    pub y: f64,
    pub w: f64,
}

/// One canonical call.
#[derive(Clone, Debug, PartialEq)]
pub enum Canon {
    UseLengthUnits(CanonUnits),
    SetG5xOffset {
        index: u32,
        offset: Pose,
    },
    SetG92Offset(Pose),
    SetXyRotation(f64),
    SetFeedReference,
    OnReset,
    Comment(String),
    Message(String),
    /// `(LOGOPEN,f)`, `(LOGAPPEND,f)`, `(LOG,text)`, `(LOGCLOSE)`.
    LogOpen(String),
    LogAppend(String),
    Log(String),
    LogClose,
    SetFeedRate(f64),
    /// Feed mode: 0 units/min, 1 units/rev (LinuxCNC prints spindle 0 first).
    SetFeedMode(u8),
    SelectPlane(CanonPlane),
    SelectTool(i64),
    StartChange,
    /// Argument: the tool table row (LinuxCNC 2.9).
    ChangeTool(i64),
    ChangeToolNumber(i64),
    StopSpindle,
    SpindleCw,
    SpindleCcw,
    SetSpindleSpeed(f64),
    /// Constant-surface-speed maximum (0: CSS off).
    SetSpindleMode(f64),
    OrientSpindle {
        angle: f64,
        mode: i64,
    },
    WaitOrientComplete(f64),
    /// Tool length offset: x y z, a b c, u v w.
    UseToolLengthOffset([f64; 9]),
    StraightTraverse(Pose),
    StraightFeed(Pose),
    StraightProbe(Pose),
    ArcFeed {
        first_end: f64,
        second_end: f64,
        first_axis: f64,
        second_axis: f64,
        rotation: i64,
        axis_end: f64,
        abc: [f64; 3],
    },
    Dwell(f64),
    SetMotionControlMode(MotionMode),
    SetNaivecamTolerance(f64),
    FloodOn,
    FloodOff,
    MistOn,
    MistOff,
    ProgramStop,
    OptionalProgramStop,
    ProgramEnd,
    PalletShuttle,
    Finish,
    EnableFeedOverride,
    DisableFeedOverride,
    EnableSpeedOverride,
    DisableSpeedOverride,
    EnableAdaptiveFeed,
    DisableAdaptiveFeed,
    EnableFeedHold,
    DisableFeedHold,
    StartSpeedFeedSync {
        pitch: f64,
        velocity_mode: bool,
    },
    StopSpeedFeedSync,
    RigidTap {
        x: f64,
        y: f64,
        z: f64,
    },
    /// NURBS_FEED: a NURBS curve in the XY plane at feed rate (LinuxCNC's
    /// G5 cubic and G5.1 quadratic splines as Bezier control polygons, and
    /// G5.2..G5.3 blocks). The control points are in program units; the
    /// first is where the tool starts. rs274 prints only their number.
    NurbsFeed {
        points: Vec<NurbsPoint>,
        order: u32,
    },
    TurnProbeOn,
    TurnProbeOff,
    /// SET_TOOL_TABLE_ENTRY(row, tool, 9 offsets, diameter, front, back, orientation).
    SetToolTableEntry {
        row: i64,
        tool: i64,
        offset: [f64; 9],
        diameter: f64,
        front: f64,
        back: f64,
        orientation: i64,
    },
    /// Digital/analog outputs M62..M68: kept as their printed text.
    Io(String),
}
