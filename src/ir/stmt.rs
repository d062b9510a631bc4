//! Blocks and statements: what a program asks the machine to do, in
//! dialect-neutral terms. One [`Block`] per line (Klartext: per block);
//! a block holds statements in the order they were written.
//!
//! Modal state is not resolved here: a block `X10 Y5` is a
//! [`MotionKind::Implicit`] move, whose meaning comes from the modes in
//! force when the program runs (see the interpreter).

use super::expr::{DimMode, ExprId, Value, Var};
use super::num::Decimal;
use crate::span::{Span, Spanned};
use serde::Serialize;

/// One block (line) of a program.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Block {
    pub span: Span,
    /// Block delete: `/` is level 0, `/3` level 3.
    pub skip: Option<Spanned<u8>>,
    /// Sequence number `N10`.
    pub number: Option<Spanned<u32>>,
    /// Siemens `LABEL:` (or Heidenhain `LBL`). Boxed: few blocks have
    /// one, and a program with control flow holds every block.
    pub label: Option<Box<Spanned<String>>>,
    pub stmts: Vec<Stmt>,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Stmt {
    pub kind: StmtKind,
    pub span: Span,
}

impl Stmt {
    pub fn new(kind: StmtKind, span: Span) -> Self {
        Stmt { kind, span }
    }
}

/// A coordinate or other positional value; Siemens can force `AC()`/`IC()`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Coord {
    pub value: Value,
    /// `X=AC(10)` / `X=IC(5)`: overrides G90/G91 for this value.
    pub dim: Option<DimMode>,
    pub span: Span,
}

/// The axis words of a block (X Y Z A B C U V W).
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Axes {
    pub x: Option<Coord>,
    pub y: Option<Coord>,
    pub z: Option<Coord>,
    pub a: Option<Coord>,
    pub b: Option<Coord>,
    pub c: Option<Coord>,
    pub u: Option<Coord>,
    pub v: Option<Coord>,
    pub w: Option<Coord>,
}

pub const AXIS_LETTERS: [char; 9] = ['X', 'Y', 'Z', 'A', 'B', 'C', 'U', 'V', 'W'];

impl Axes {
    pub fn get(&self, axis: char) -> Option<&Coord> {
        self.slot(axis).and_then(|s| s.as_ref())
    }

    pub fn slot(&self, axis: char) -> Option<&Option<Coord>> {
        Some(match axis.to_ascii_uppercase() {
            'X' => &self.x,
            'Y' => &self.y,
            'Z' => &self.z,
            'A' => &self.a,
            'B' => &self.b,
            'C' => &self.c,
            'U' => &self.u,
            'V' => &self.v,
            'W' => &self.w,
            _ => return None,
        })
    }

    pub fn slot_mut(&mut self, axis: char) -> Option<&mut Option<Coord>> {
        Some(match axis.to_ascii_uppercase() {
            'X' => &mut self.x,
            'Y' => &mut self.y,
            'Z' => &mut self.z,
            'A' => &mut self.a,
            'B' => &mut self.b,
            'C' => &mut self.c,
            'U' => &mut self.u,
            'V' => &mut self.v,
            'W' => &mut self.w,
            _ => return None,
        })
    }

    /// The axes given, in X Y Z A B C U V W order.
    pub fn iter(&self) -> impl Iterator<Item = (char, &Coord)> {
        AXIS_LETTERS
            .iter()
            .filter_map(move |&a| self.get(a).map(|c| (a, c)))
    }

    pub fn is_empty(&self) -> bool {
        self.iter().next().is_none()
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Plane {
    XY,
    ZX,
    YZ,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum LengthUnit {
    Inch,
    Mm,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum FeedMode {
    PerMinute,
    PerRevolution,
    InverseTime,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum ArcDir {
    Cw,
    Ccw,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum MotionKind {
    /// No motion code in the block: the modal motion (or modal cycle) applies.
    Implicit,
    Rapid,
    Linear,
    Arc(ArcDir),
    /// Siemens `CIP`: arc through an intermediate point.
    ArcThrough,
    /// Siemens `CT`: arc tangent to the previous path element.
    ArcTangent,
    /// G38.x probing: `toward` true for G38.2/3, `error` for G38.2/4.
    Probe {
        toward: bool,
        error: bool,
    },
    /// LinuxCNC G5/G5.1/G5.2 splines, G33 threading: kept by code.
    Other(Decimal),
}

/// How an arc's geometry is given, besides its end point.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct ArcData {
    /// Centre words I J K.
    pub i: Option<Coord>,
    pub j: Option<Coord>,
    pub k: Option<Coord>,
    /// Radius: `R` (word address) or `CR=` (Siemens); negative for > 180°.
    pub radius: Option<Value>,
    /// Siemens `AR=` opening angle.
    pub angle: Option<Value>,
    /// Turns: LinuxCNC `P`, Siemens `TURN=`.
    pub turns: Option<Value>,
    /// Siemens CIP intermediate point `I1= J1= K1=`.
    pub mid: Option<Box<Axes>>,
}

impl ArcData {
    pub fn is_empty(&self) -> bool {
        *self == ArcData::default()
    }
}

/// Contour corner elements attached to a move (Siemens `CHF=`, `RND=`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CornerKind {
    /// `CHF=`: chamfer length along the chamfer.
    Chamfer,
    /// `CHR=`: chamfer leg length.
    ChamferLeg,
    /// `RND=`: rounding radius.
    Round,
    /// `RNDM=`: modal rounding radius.
    RoundModal,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Motion {
    pub kind: MotionKind,
    pub target: Axes,
    pub arc: ArcData,
    /// LinuxCNC polar words `@` (radius) `^` (angle); Siemens `RP=`/`AP=`.
    pub polar_radius: Option<Value>,
    pub polar_angle: Option<Value>,
    pub corner: Option<(CornerKind, Value)>,
}

impl Motion {
    pub fn new(kind: MotionKind) -> Self {
        Motion {
            kind,
            target: Axes::default(),
            arc: ArcData::default(),
            polar_radius: None,
            polar_angle: None,
            corner: None,
        }
    }
}

/// The fixed (word-address) drilling cycles G73..G89.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CycleKind {
    /// G81.
    Drill,
    /// G82: dwell at the bottom.
    DrillDwell,
    /// G83: peck, full retract.
    Peck,
    /// G73: peck, chip-breaking back-off.
    ChipBreak,
    /// G84: right-hand tapping.
    Tap,
    /// G74: left-hand tapping.
    TapLeft,
    /// G85: bore, feed out.
    BoreFeedOut,
    /// G86: bore, spindle stop, rapid out.
    BoreStopRapidOut,
    /// G87: back boring.
    BackBore,
    /// G88: bore, dwell, spindle stop, manual out.
    BoreManual,
    /// G89: bore, dwell, feed out.
    BoreDwellFeedOut,
    /// Fanuc G76: fine boring (oriented stop, shift).
    FineBore,
}

/// A word-address canned cycle: `G98 G83 X Y Z R Q F K`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CannedCycle {
    pub kind: CycleKind,
    /// X Y (hole position), Z (bottom), and any other axes.
    pub target: Axes,
    pub r: Option<Value>,
    pub q: Option<Value>,
    pub p: Option<Value>,
    /// Repeats: `K` (Fanuc) or `L` (Haas, LinuxCNC).
    pub repeat: Option<Value>,
    /// Shift or variable-peck words I J K (G87, G76, Haas G83).
    pub i: Option<Value>,
    pub j: Option<Value>,
    pub k: Option<Value>,
}

/// One positional argument of a named cycle call; `None` = left empty.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Arg {
    pub value: Option<ExprId>,
    pub span: Span,
}

/// Which corner of the blank a Heidenhain `BLK FORM` gives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum StockCorner {
    /// `BLK FORM 0.1`: the minimum point, with the tool axis.
    Min,
    /// `BLK FORM 0.2`: the maximum point.
    Max,
}

/// Heidenhain approach and departure contours (`APPR`/`DEP`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum ApproachKind {
    /// `LT`: on a straight line tangent to the contour.
    LineTangent,
    /// `LN`: on a straight line normal to the contour.
    LineNormal,
    /// `CT`: on a tangent arc.
    ArcTangent,
    /// `LCT`: a straight line, then a tangent arc.
    LineArcTangent,
}

/// `APPR LT X.. Y.. LEN10 RR F300`, `DEP CT CCA90 R+5`: `target` is the
/// first contour point (APPR) or the end point (DEP, LN/LCT only).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Approach {
    pub depart: bool,
    pub kind: ApproachKind,
    pub target: Axes,
    /// `LEN`: length of the straight part.
    pub len: Option<Value>,
    /// `R`: radius of the arc part (sign: side, as written).
    pub radius: Option<Value>,
    /// `CCA`: opening angle of the arc part.
    pub angle: Option<Value>,
}

/// One `Qnnn=value ;LABEL` line of a Heidenhain cycle definition.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QParam {
    pub q: u32,
    pub value: Value,
    /// The language-dependent label after `;` (no meaning, kept).
    pub label: Option<String>,
    pub span: Span,
}

/// A Heidenhain cycle definition `CYCL DEF 200 DRILLING ~ Q200=2 ;.. ~ ...`.
///
/// `number` selects the cycle (200 drilling, 203 universal drilling, 251
/// rectangular pocket, 252 circular pocket, ...); `params` keep every Q
/// parameter in the order written, by number, with its value as written and
/// its label, unknown ones included. The definition is modal and runs only
/// when called ([`CycleRunKind`]).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CycleDef {
    pub number: u32,
    /// The name written after the number (`DRILLING`), language-dependent.
    pub name: String,
    pub params: Vec<QParam>,
}

impl CycleDef {
    /// The value given to `Qn`.
    pub fn param(&self, q: u32) -> Option<&Value> {
        self.params.iter().find(|p| p.q == q).map(|p| &p.value)
    }
}

/// One word of an old-style Heidenhain cycle line: `DIST25.000`, `X+0`,
/// `ROT+30`, a bare keyword (`DATUM`, value `None`) or a bare value (empty name).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CycleWord {
    pub name: String,
    pub value: Option<Value>,
    pub span: Span,
}

/// One block of an old-style (sub-numbered) cycle: `CYCL DEF 7.1 X+10`,
/// `CYCL DEF 1.2 DEPTH-20`: cycle 7, sub-number 1. The keywords vary by
/// control version and language, so the sub-number carries the meaning.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CycleLine {
    pub cycle: u32,
    pub sub: u32,
    pub words: Vec<CycleWord>,
}

/// How a Heidenhain cycle defined by `CYCL DEF` is run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum CycleRunKind {
    /// `CYCL CALL`: once, at the current position.
    Call,
    /// `CYCL CALL POS X.. Y.. Z..`: once, at the given point; `rapid`:
    /// `FMAX` written (the interpreter positions at rapid either way).
    Pos { axes: Box<Axes>, rapid: bool },
    /// `CYCL CALL PAT`: at every point of the last `PATTERN DEF`; `rapid`:
    /// `FMAX` written.
    Pattern { rapid: bool },
    /// `M99` in a positioning block: once, at the block's end point.
    Block,
    /// `M89`: after every following positioning block (older controls).
    Modal,
}

/// One item of a `PATTERN DEF`: `POS1 (X+25 Y+33.5 Z+0)`, `ROW1 (...)`.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct PatternItem {
    /// `POS1`, `ROW1`, `PAT1`, `FRAME1`, `CIRC1`, `CIRC2`.
    pub name: String,
    /// Words inside the parentheses, in order (`X+25`, `NUMX5`, `ROT+0`).
    pub words: Vec<CycleWord>,
    pub span: Span,
}

/// A named cycle call `CYCLE81(10,0,2,-5)`, `MCALL CYCLE83(...)`.
/// Arguments are kept positionally, empty slots and unknown tails included;
/// the dialect spec's signature names them.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CycleCall {
    pub name: String,
    pub args: Vec<Arg>,
    /// `MCALL`: called after every following positioning block.
    pub modal: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum StopKind {
    /// M0.
    Program,
    /// M1.
    Optional,
    /// M2.
    End,
    /// M30.
    EndRewind,
    /// M60: pallet change and stop.
    PalletStop,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum SpindleState {
    Cw,
    Ccw,
    Stop,
    /// M19 / SPOS: oriented stop, angle if given.
    Orient(Option<Value>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Coolant {
    Mist,
    Flood,
    ThroughTool,
    Off,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CompSide {
    Off,
    Left,
    Right,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum LengthComp {
    /// G43.
    Positive,
    /// G44.
    Negative,
    /// G49.
    Cancel,
    /// LinuxCNC G43.1: the offset given by axis words.
    Dynamic,
    /// LinuxCNC G43.2: add another tool's offset.
    Additive,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum DwellUnit {
    Seconds,
    Milliseconds,
    Revolutions,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum PathMode {
    /// Exact stop, modal (G61; Siemens G60).
    ExactStop,
    /// Exact stop in this block only (G9).
    ExactStopBlock,
    /// LinuxCNC G61.1.
    ExactPath,
    /// Continuous path (G64; Siemens G64/G641..G645), tolerances as words.
    Continuous,
    /// Fanuc G62 automatic corner override, G63 tapping mode.
    CornerOverride,
    Tapping,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CoordShift {
    /// G92: set the current position.
    Set,
    /// G92.1: cancel and zero.
    Reset,
    /// G92.2: suspend.
    Suspend,
    /// G92.3: restore.
    Restore,
    /// G52: local coordinate system.
    Local,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum FrameOp {
    Trans,
    Rot,
    Scale,
    Mirror,
}

/// Coordinate transformations beyond work offsets.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum Transform {
    /// Siemens programmable frame `TRANS`/`ATRANS`, `ROT`/`AROT` (with
    /// `RPL=`), `SCALE`/`ASCALE`, `MIRROR`/`AMIRROR`; no axes clears.
    Frame {
        op: FrameOp,
        additive: bool,
        axes: Axes,
        rpl: Option<Value>,
    },
    /// Fanuc G68: rotation about a centre by R degrees.
    RotateOn {
        center: Axes,
        angle: Option<Value>,
    },
    RotateOff,
    /// Fanuc G51: scaling about a centre by P (or per axis I J K).
    ScaleOn {
        center: Axes,
        factor: Option<Value>,
        per_axis: Vec<(char, Value)>,
    },
    ScaleOff,
    /// Fanuc G51.1: mirror about the given axis positions.
    MirrorOn {
        axes: Axes,
    },
    MirrorOff,
}

/// What a subprogram call names.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum CallTarget {
    /// Program or subroutine number: `M98 P1000`, `L123`, `o100 call`.
    Number(u32),
    /// Named: `o<name> call`, Siemens `NAME(...)`.
    Name(String),
    /// Chosen at run time: `M98 P#146`.
    Computed(ExprId),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CallKind {
    /// `M98 P` (Fanuc, Haas, LinuxCNC Fanuc-style).
    Subprogram,
    /// Haas `M97 P`: a local subprogram at a sequence number.
    Local,
    /// `G65 P`: macro call with letter arguments.
    Macro,
    /// `G66 P`: modal macro call.
    ModalMacro,
    /// LinuxCNC `o.. call`.
    OWord,
    /// Siemens `L123`, `NAME(...)`, `CALL "NAME"`; Heidenhain `CALL PGM`.
    Named,
    /// Heidenhain `CALL LBL n`: runs from the block labelled n to `LBL 0`.
    Label,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum CallArgs {
    None,
    /// `o100 call [1] [2]`, Siemens `NAME(1,,3)` (`None` = empty slot).
    Positional(Vec<Option<ExprId>>),
    /// `G65 P9010 A1. B2.`: letter arguments in the order written.
    Letters(Vec<(char, Value)>),
}

/// What a jump goes to.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum JumpTarget {
    /// A sequence number (Fanuc `GOTO 10`, `GOTO #1`).
    Sequence(Value),
    /// A label (Siemens).
    Label(String),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum JumpDir {
    /// Fanuc GOTO; Siemens GOTO (forward, then backward).
    Either,
    Forward,
    Backward,
    /// Siemens GOTOC: no alarm when the label is missing.
    EitherNoAlarm,
}

/// The kind of control-flow structure an opener starts (matched to its
/// closers by the structure checker and the interpreter's flow index).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FlowKind {
    If,
    While,
    Do,
    Repeat,
    For,
    Loop,
    RepeatUntil,
    Sub,
}

impl FlowKind {
    /// Loops (what `break` and `continue` act on).
    pub fn is_loop(self) -> bool {
        !matches!(self, FlowKind::If | FlowKind::Sub)
    }
}

/// Identifies which opener a closer belongs to.
#[derive(Clone, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum FlowId {
    /// Structured keywords (Siemens IF/ENDIF): matched by nesting.
    Nested,
    /// LinuxCNC `o100`/`o<name>`: matched by the o-word.
    OWord(String),
    /// Fanuc `DO 1` / `END 1`.
    Do(u8),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum VarType {
    Real,
    Int,
    Bool,
    Char,
    String,
    Axis,
    Frame,
}

/// One variable of a DEF statement.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct VarDecl {
    pub name: String,
    /// Array dimensions; for STRING its length.
    pub dims: Vec<u32>,
    /// Dimensions written as a name (a Siemens DEFINE macro or GUD
    /// constant of the machine's definition files), by their index in
    /// `dims` (which holds 0 there): the size is the machine's.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub dim_names: Vec<(usize, String)>,
    pub init: Option<ExprId>,
    pub span: Span,
}

impl VarDecl {
    /// Dimension `i` as written: its number, or the name that gives it.
    pub fn dim_text(&self, i: usize) -> String {
        match self.dim_names.iter().find(|(j, _)| *j == i) {
            Some((_, n)) => n.clone(),
            None => self.dims.get(i).map(u32::to_string).unwrap_or_default(),
        }
    }
}

/// One arm of a Siemens CASE.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct CaseArm {
    pub value: ExprId,
    pub target: String,
    pub dir: JumpDir,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum CommentStyle {
    /// `( ... )`.
    Paren,
    /// `; ...` to the end of the line.
    Semicolon,
    /// Heidenhain structure item `* - heading`.
    Heading,
}

/// A letter-value word kept as written where no statement takes it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Word {
    pub letter: char,
    /// What follows the letter in a longer address (`1` of Siemens `M1=`),
    /// usually empty.
    pub suffix: String,
    pub value: Value,
    pub span: Span,
}

impl Word {
    pub fn new(letter: char, value: Value, span: Span) -> Self {
        Word {
            letter,
            suffix: String::new(),
            value,
            span,
        }
    }

    /// The address as written: `X`, `M1`.
    pub fn address(&self) -> String {
        format!("{}{}", self.letter, self.suffix)
    }
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum ToolRef {
    Number(Value),
    Name(String),
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum StmtKind {
    // ---- program content
    Comment {
        text: String,
        style: CommentStyle,
    },
    /// An operator message: Siemens `MSG("...")`, LinuxCNC `(MSG,...)`.
    Message(Option<String>),
    /// `%` tape marker.
    Tape,
    /// A program's start: Fanuc `O1234`, Siemens `%_N_NAME_MPF`.
    ProgramStart {
        number: Option<u32>,
        name: Option<String>,
    },
    /// Heidenhain `END PGM name MM`: the end of the program text.
    ProgramEnd {
        name: Option<String>,
    },
    /// Heidenhain `BLK FORM 0.1 Z X.. Y.. Z..` / `0.2 ...`: a corner of
    /// the blank (raw stock); `axis` is the tool axis given with 0.1.
    Stock {
        corner: StockCorner,
        axis: Option<char>,
        axes: Box<Axes>,
    },
    /// Heidenhain `TOOL DEF 1 L+0 R+5`: a tool's length and radius.
    ToolDef {
        tool: ToolRef,
        length: Option<Value>,
        radius: Option<Value>,
    },
    /// Heidenhain `DL`/`DR` in `TOOL CALL`: length/radius oversizes.
    ToolOversize {
        length: Option<Value>,
        radius: Option<Value>,
    },
    /// Text understood only as text, writable back only into its dialect.
    Raw {
        dialect: String,
        text: String,
    },
    /// A word no statement takes, kept (and reported as a warning).
    Word(Word),

    // ---- modes
    Units {
        unit: LengthUnit,
        with_feeds: bool,
    },
    Plane(Plane),
    Distance(DimMode),
    ArcDistance(DimMode),
    FeedMode(FeedMode),
    Feed(Value),
    SpindleSpeed(Value),
    /// G96 (constant surface speed, optional max RPM D) / G97.
    SpindleCss {
        on: bool,
        max_rpm: Option<Value>,
    },
    Spindle(SpindleState),
    Coolant(Coolant),
    ToolSelect(ToolRef),
    ToolChange,
    /// The next tool, named after the change in the change block
    /// (`T1 T2 M6`: T2): selected once the change is made.
    ToolPreselect(ToolRef),
    /// Siemens `D1`: cutting edge, activating its length and radius.
    CuttingEdge(Value),
    /// G40/G41/G42 D (a tool or register number); `diameter`: LinuxCNC
    /// G41.1/G42.1, where D is the tool diameter itself.
    RadiusComp {
        side: CompSide,
        register: Option<Value>,
        #[serde(default, skip_serializing_if = "std::ops::Not::not")]
        diameter: bool,
    },
    LengthComp {
        mode: LengthComp,
        register: Option<Value>,
        axes: Box<Axes>,
    },
    /// A register word standing alone: `H1` or `D2` without G43/G41.
    OffsetRegister {
        letter: char,
        value: Value,
    },
    /// Work offset: 1 = G54 … 6 = G59, 7..9 = G59.1..3 (LinuxCNC),
    /// Siemens G505.. as 5..; 0 = Siemens G500 (none). `extended` is the
    /// P of G54.1 / G154.
    WorkOffset {
        index: u32,
        extended: Option<Value>,
    },
    /// G53 / SUPA: this block in machine coordinates.
    MachineCoords,
    CoordShift {
        kind: CoordShift,
        axes: Box<Axes>,
    },
    /// G10 data setting: L, P and the other words as written.
    SetData {
        l: Value,
        words: Vec<Word>,
    },
    /// G28/G30 (index 1/2) return via the given axes; `store` for G28.1/G30.1.
    /// `direct`: Siemens `G74 Z1=0`, straight home along the named machine
    /// axes (their values are not read).
    RefReturn {
        index: u8,
        axes: Box<Axes>,
        store: bool,
        direct: bool,
    },
    PathMode {
        mode: PathMode,
        words: Vec<Word>,
    },
    /// G98 (true: initial level) / G99 (false: R plane).
    ReturnToInitial(bool),
    Transform(Box<Transform>),
    Dwell {
        value: Value,
        unit: DwellUnit,
    },
    Stop(StopKind),
    /// A machine function that has no neutral meaning (most M codes beyond
    /// the standard ones, G codes a spec marks `aux`), kept by code.
    Aux {
        letter: char,
        code: Decimal,
        words: Vec<Word>,
    },
    /// A G or M word whose number is an expression (`G#143`, `M[#1]`): it
    /// cannot be looked up before the program runs. `words` are the block's
    /// words that nothing else took (the code may use them).
    DynamicCode {
        letter: char,
        value: ExprId,
        words: Vec<Word>,
    },
    /// Siemens keyword commands with no neutral meaning (`SOFT`, `FFWON`,
    /// `TRAORI`), with their arguments if written with parentheses.
    Command {
        name: String,
        args: Option<Vec<Arg>>,
    },

    // ---- motion and cycles
    Motion(Box<Motion>),
    /// Heidenhain `CC X.. Y..`: circle centre and pole (modal); no axes:
    /// the current position.
    Pole(Box<Axes>),
    /// Heidenhain `RND R5` / `CHF 2`: a corner between the neighbouring
    /// path elements (before and after this statement).
    Corner {
        kind: CornerKind,
        size: Value,
    },
    /// Heidenhain `APPR ..` / `DEP ..`.
    Approach(Box<Approach>),
    /// Heidenhain `CYCL DEF 200 ...` (see [`CycleDef`]).
    CycleDef(Box<CycleDef>),
    /// Heidenhain old-style cycle block `CYCL DEF 7.1 X+10`.
    CycleLine(Box<CycleLine>),
    /// Heidenhain `CYCL CALL`, `M99`, `M89`, `CYCL CALL PAT`, `CYCL CALL POS`.
    CycleRun(CycleRunKind),
    /// Heidenhain `PATTERN DEF`.
    PatternDef(Vec<PatternItem>),
    /// Heidenhain FN 14..20, `PLANE`, FK blocks (see [`super::tnc`]).
    TncFunction(Box<super::tnc::TncFunction>),
    Cycle(Box<CannedCycle>),
    /// G80.
    CycleCancel,
    CycleCall(CycleCall),
    /// `MCALL` alone: cancel the modal cycle call.
    ModalCallCancel,

    // ---- variables and control flow
    Assign {
        var: Var,
        value: ExprId,
    },
    Declare {
        ty: VarType,
        vars: Vec<VarDecl>,
    },
    Goto {
        target: JumpTarget,
        dir: JumpDir,
        cond: Option<ExprId>,
    },
    /// Fanuc `IF [c] THEN stmt`.
    IfThen {
        cond: ExprId,
        then: Box<Stmt>,
    },
    If {
        cond: ExprId,
        id: FlowId,
    },
    ElseIf {
        cond: ExprId,
        id: FlowId,
    },
    Else {
        id: FlowId,
    },
    EndIf {
        id: FlowId,
    },
    While {
        cond: ExprId,
        id: FlowId,
    },
    EndWhile {
        id: FlowId,
    },
    /// LinuxCNC `o.. do`.
    Do {
        id: FlowId,
    },
    /// LinuxCNC `o.. while [c]` closing a `do`.
    DoWhile {
        cond: ExprId,
        id: FlowId,
    },
    /// LinuxCNC `o.. repeat [n]`.
    Repeat {
        count: ExprId,
        id: FlowId,
    },
    EndRepeat {
        id: FlowId,
    },
    For {
        var: Var,
        from: ExprId,
        to: ExprId,
    },
    EndFor,
    Loop,
    EndLoop,
    /// Siemens `REPEAT` opening a REPEAT ... UNTIL loop.
    RepeatUntil,
    Until {
        cond: ExprId,
    },
    Case {
        selector: ExprId,
        arms: Vec<CaseArm>,
        default: Option<(String, JumpDir)>,
    },
    /// Siemens section repeat `REPEAT START [END] P=n` (REPEATB for one block).
    SectionRepeat {
        start: String,
        end: Option<String>,
        count: Option<ExprId>,
        single: bool,
    },
    Break {
        id: FlowId,
    },
    Continue {
        id: FlowId,
    },
    /// Subroutine definition start: LinuxCNC `o100 sub`, Siemens `PROC`.
    SubStart {
        name: String,
        params: Vec<VarDecl>,
        id: FlowId,
    },
    SubEnd {
        id: FlowId,
        value: Option<ExprId>,
    },
    Return {
        id: FlowId,
        value: Option<ExprId>,
    },
    Call {
        kind: CallKind,
        target: CallTarget,
        args: CallArgs,
        repeat: Option<Value>,
    },
    /// Fanuc M99 (LinuxCNC Fanuc-style too); `P` returns to a sequence number.
    SubReturn {
        to: Option<Value>,
    },
    /// G67: cancel the modal macro call.
    ModalMacroCancel,
}
