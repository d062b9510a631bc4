//! A dialect spec in memory: the data that says how one controller's
//! language differs from the others. Front ends, checks and writers read
//! it; none of them asks which dialect it is.

use super::meaning::Meaning;
use crate::ir::{Decimal, DwellUnit, Func};
use crate::span::Span;
use std::collections::HashMap;
use std::hash::{BuildHasherDefault, Hasher};

/// The syntax family: which grammar reads the dialect.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Family {
    /// ISO 6983 word address: Fanuc, Haas, LinuxCNC.
    WordAddress,
    /// Siemens Sinumerik.
    Sinumerik,
    /// Heidenhain Klartext.
    Klartext,
}

impl Family {
    pub fn parse(s: &str) -> Option<Family> {
        match s {
            "word-address" => Some(Family::WordAddress),
            "sinumerik" => Some(Family::Sinumerik),
            "klartext" => Some(Family::Klartext),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Family::WordAddress => "word-address",
            Family::Sinumerik => "sinumerik",
            Family::Klartext => "klartext",
        }
    }
}

/// Named yes/no differences between dialects of one family.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Capability {
    /// `( ... )` comments.
    ParenComments,
    /// `; ...` comments to the end of the line.
    SemicolonComments,
    /// Fanuc Custom Macro B: `#n`, `[ ]`, IF/GOTO, WHILE/DO/END, THEN.
    MacroB,
    /// LinuxCNC O-word subroutines and control flow.
    OWords,
    /// LinuxCNC `#<name>` parameters.
    NamedParameters,
    /// `**` power operator.
    PowerOperator,
    /// Fanuc-style `O1234` programs with `M98 P` / `M99`.
    NumberedPrograms,
    /// Haas `M97 P`: local subprogram at a sequence number.
    LocalSubprogramCall,
    /// An M code not in the table is an error (otherwise a warning: it is
    /// passed to the machine as a builder-defined function).
    StrictMCodes,
    /// The program must end with M2/M30 or a closing `%`.
    ProgramEndRequired,
    /// A word no code in its block uses is an error (otherwise a warning).
    StrictWords,
    /// LinuxCNC polar words `@` and `^`.
    PolarWords,
    /// Siemens R parameters.
    RParameters,
    /// Siemens DEF variables.
    DefVariables,
    /// Siemens labels, GOTOF/GOTOB, IF/WHILE/FOR/REPEAT/LOOP/CASE.
    StructuredControl,
    /// Siemens named cycle calls and MCALL.
    NamedCycles,
    /// Siemens programmable frames TRANS/ROT/SCALE/MIRROR.
    Frames,
    /// Fanuc G68/G51/G51.1 rotation, scaling, mirror.
    GCodeTransforms,
    /// Arithmetic allowed after a word without brackets (`X#1/2`), as some
    /// Fanuc-like controls accept.
    UnbracketedExpressions,
    /// LinuxCNC active comments `(MSG, text)` for operator messages.
    MessageComments,
    /// Fanuc `,C` (chamfer) and `,R` (corner rounding) words after a move.
    CommaCornerWords,
    /// EQ/NE compare within 0.0001 (LinuxCNC's TOLERANCE_EQUAL).
    EqTolerance,
    /// Arcs are built in the programmed system and mapped through the
    /// programmable frame, with the CIP/CT/AR= forms (Sinumerik).
    FrameArcs,
    /// Canned cycles start retracting to R (G99), as LinuxCNC's
    /// interpreter does; otherwise to the initial level (G98), as Fanuc,
    /// Haas and Siemens controls do at power-on.
    CycleRetractRPlaneAtStart,
    /// `;` is the end-of-block character (Fanuc, Haas): read as the start
    /// of a comment, never written as one (comments are written `( )`).
    SemicolonEndOfBlock,
    /// Heidenhain contours: circles round the pole `CC`, polar
    /// `LP`/`CP`/`CTP`, `RND`/`CHF` blocks between elements, `APPR`/`DEP`:
    /// a move may wait for the next block (its corner), so motion runs
    /// through the contour machinery.
    PolePaths,
    /// Cycles are defined (`CYCL DEF n.m` lines, some acting when defined)
    /// and called apart (Heidenhain); a port writes the old defining
    /// cycles in the target's own form where that is exact.
    CycleDefinitions,
    /// The tool change makes the new tool's length and radius (and the
    /// call's oversizes) active, with no length-offset code (Heidenhain
    /// `TOOL CALL ... DL DR`).
    ToolCallActivatesOffsets,
    /// Spindle stop and coolant off (with the program stops) act at the
    /// end of their block, after its move (Heidenhain M5, M9); elsewhere
    /// they act before the move.
    OffFunctionsAfterMove,
    /// A subprogram end met in the main program is passed over (Heidenhain
    /// `LBL 0`); elsewhere it returns, and in a main program starts it again.
    SubEndInMainContinues,
    /// The blank as a statement of the program (Heidenhain `BLK FORM
    /// 0.1/0.2`); elsewhere the port writes it as a comment.
    BlankForm,
    /// The motion mode at power-on and reset is G00: axis words without a
    /// motion code move at rapid (Fanuc parameter 3402#0 = 0, Haas).
    PowerOnRapid,
    /// The control holds its own tool data: a tool the tool table does not
    /// list is not an error; its sizes are unknown (Fanuc, Haas, Siemens,
    /// Heidenhain). Without it (LinuxCNC) the tool must be in the table.
    ControlHoldsTools,
    /// A program may select a tool by its name (Siemens `T="DRILL"`,
    /// Heidenhain `TOOL CALL "DRILL"`); without it a tool is a number.
    ToolsByName,
    /// The spindle speed word takes whole rpm only (Fanuc and Haas `S`:
    /// `S350.141` is an alarm or is truncated [K]). A post rounds to the
    /// nearest rpm and says so (W0900).
    IntegerSpindleSpeed,
    /// Cutter compensation's entry move must be longer than the tool
    /// radius (LinuxCNC's rule; Fanuc and Siemens start up otherwise).
    CompEntryLongerThanRadius,
    /// G41/G42 while compensation is on is an error (LinuxCNC); elsewhere
    /// it changes side or offset on the fly.
    CompOnWhenOnError,
    /// The motion mode at power-on and reset is G1 (Siemens: the SAG
    /// default of G group 1, machine data 20150 GCODE_RESET_VALUES): axis
    /// words without a motion code move at the feed, which must be given.
    PowerOnLinear,
    /// The first block of a canned cycle must give R, and P for a dwell
    /// cycle (LinuxCNC). Without it a missing R is the initial level [?]
    /// and a missing P no dwell (Fanuc, Haas).
    CycleWordsRequired,
    /// The R plane of a word-address cycle must not lie beyond its bottom
    /// along the drilling axis (LinuxCNC: "R less than Z in cycle").
    /// Without it the cycle feeds from R towards the bottom whichever way
    /// that is (Fanuc, Haas: a right-angle head drilling up the Y axis in
    /// G18 [?: no alarm for it is documented]).
    CycleRAboveBottom,
    /// `:` is the program number address as `O` is (ISO code, Fanuc,
    /// Fadal, Haas: `:0097` is program O0097).
    ColonProgramNumber,
    /// A `(` inside a `( )` comment is an error (LinuxCNC: "Nested
    /// comment found"); otherwise it is comment text.
    NoNestedComments,
    /// Cutter compensation takes the radius of the tool in the spindle and
    /// names no register (Klartext `RL`/`RR` on a positioning block, `R0`
    /// to cancel): a port drops a `D` that is the tool's own and puts a
    /// lone cancel on the next move.
    CompWithoutRegister,
    /// Q and QR parameters belong to the control, not to the program: they
    /// keep the values an earlier program left (TNC 640 / TNC7 manuals:
    /// "Q parameters affect all NC programs in the control's memory"; QR
    /// are kept even after a restart; QL are local to one program). A Q or
    /// QR parameter this run has not set is a value from outside (W0590),
    /// not 0. [?] iTNC 530 machine parameter MP7300 may reset Q parameters
    /// at the end of a program; the default is taken as keeping them.
    GlobalQParameters,
    /// The program itself must activate the tool length offset after a
    /// tool change (G43 H on Fanuc, Haas); elsewhere the tool call applies
    /// it (Siemens T/D, Heidenhain TOOL CALL), or the shop touches off each
    /// tool in the work offset (common on LinuxCNC). Lint W0702.
    LengthOffsetProgrammed,
    /// The length register of G43 names a tool: LinuxCNC reads tool H's
    /// table length; Fanuc and Haas shops number H as T by convention
    /// [?: the offset memory allows any numbering]. Lint W0703.
    LengthRegisterNamesTool,
    /// A tool change names the tool it loads (Klartext `TOOL CALL 2`):
    /// there is no change of the tool selected before, so a port gives a
    /// word-address `M6` alone the number of the tool the run selected.
    ChangeNamesTool,
    /// A `G0`/`G1` with no axis word moves to where the tool is (a feed
    /// move that needs a feed rate: rs274's "Cannot do G1 with zero feed
    /// rate"); elsewhere it only sets the motion mode.
    BareMotionCodeMoves,
    /// A block in machine coordinates moves at the motion mode in force,
    /// so it may feed (LinuxCNC `G53 G1`, Siemens `G1 SUPA`, Heidenhain
    /// `L .. F.. M91`); elsewhere it moves at rapid (Fanuc `G53` [?]) and
    /// a port writes only rapid machine-coordinate blocks there.
    MachineCoordsFeed,
    /// The program can show the operator a message without stopping
    /// (Siemens `MSG("..")`, LinuxCNC `(MSG,..)`); elsewhere a port
    /// writes a message as a comment (W0610).
    OperatorMessages,
    /// A dwell may share a block with a move and runs before it
    /// (LinuxCNC's order of execution); elsewhere a port moves the move to
    /// a block of its own after the dwell.
    DwellWithMove,
    /// The control can tilt its working plane (3+2 machining: a frame
    /// whose Z is a feature's axis, the rotary axes or head turning the
    /// tool onto it): Siemens CYCLE800, Heidenhain PLANE SPATIAL. A post
    /// machines a feature whose axis is not the machine's Z in such a
    /// plane; without it the feature is a located refusal.
    TiltedWorkingPlane,
    /// An N word may have a fraction, which is dropped: `N4567.789` is N4567
    /// (LinuxCNC, checked with rs274 2.9); elsewhere it is an error.
    FractionalSequenceNumbers,
    /// A program number given twice in one file is not an error: a call runs
    /// the first one (LinuxCNC rs274 searches from the top; `O0002` and `O2`
    /// are the same number, its 10-M98-P001 test).
    FirstProgramWins,
    /// LinuxCNC's own bug, matched on purpose: in G18/G19 the feed moves of
    /// G74/G84 have their axes permuted twice (rs274 2.9
    /// `convert_cycle_g74_g84` permutes for the plane and `cycle_feed` again),
    /// so `G18 G84 X1 Z1 Y-1` taps at X-1 Y1 Z1. Its g84 tests lock this in.
    /// Other dialects tap along the right axis.
    TapFeedAxesPermuted,
    /// The offset parameters #5211..#5399 (G92, work offsets) read in machine
    /// units, so G20/G21 leave them unchanged (LinuxCNC: they stay in the INI's
    /// user units; rs274 2.9, its unit-conversion test). Otherwise they read in
    /// the program's units.
    OffsetParametersInMachineUnits,
    /// An A, B or C word in a canned-cycle block is an error (LinuxCNC:
    /// "Cannot put an a in canned cycle"); elsewhere it moves with the
    /// positioning.
    CycleRotaryWordsRefused,
    /// Blanks inside words are dropped before a line is read, so `end sub`
    /// is `endsub` and `else if` is `elseif` (LinuxCNC rs274 drops every
    /// blank outside comments; its g72 tests write `o100 end sub`).
    BlanksInsideWords,
    /// Of several comments on one line only the last is the block's comment
    /// (LinuxCNC rs274 2.9 keeps one comment per block; its
    /// 12-M99-endless-main-program test). Elsewhere every comment counts.
    LastCommentOnly,
    /// An M99 in the main program ends the run as M2 does (the standalone
    /// LinuxCNC interpreter; task would loop). Elsewhere it starts the main
    /// program again.
    MainReturnEnds,
    /// Subroutine styles do not mix (LinuxCNC): an `O1 ... M99` program is
    /// called with M98 only, an `O1 sub` with `O1 call` only, and an M99 in
    /// an `O1 sub` is an error; and normal flow reaching a sub definition
    /// already known (called before it, or passed before, as in a loop) is
    /// "sub found in illegal location".
    StrictSubStyles,
    /// Nothing after the closing `%` is read (LinuxCNC: the useful contents
    /// of a file stop at the second `%`).
    StopAtClosingPercent,
    /// M19 orients only when R (angle) or P (direction) is given, and waits
    /// only when Q (timeout) is given (LinuxCNC); elsewhere M19 always
    /// orients and waits.
    OrientByWords,
    /// The interpreter takes a parameter file (LinuxCNC `.var`, kept
    /// between runs) and the `[RS274NGC]` settings of an INI file:
    /// `--var-file` and `--ini` apply (see `interp::config`).
    VarAndIniFiles,
    /// A length register word alone (`Z4. H2`) while G43/G44 is in force
    /// selects that register: its length is active from this block's
    /// moves on (Fanuc, Haas [K]: a new H number in G43 mode replaces the
    /// offset, it is not added). Elsewhere an H needs its G43.
    OffsetRegisterAlone,
    /// G41/G42 without a D uses the radius register last programmed, and
    /// before any, D0: no radius (Fanuc, Haas [K]: D is modal; the D00
    /// offset is always 0). Elsewhere it takes the radius of the tool in
    /// the spindle (LinuxCNC; the 840D's active edge, Klartext RL/RR).
    CompRegisterModal,
    /// A second T word in a tool-change block names the next tool:
    /// `T1 T2 M6` changes to T1 and makes T2 ready in the magazine
    /// (Mazak EIA/ISO and other Fanuc-family machines; NX and Mastercam
    /// posts write it [?: the Fanuc 0i manual shows one T per block; the
    /// machine builder's magazine logic decides]). Elsewhere a second T
    /// is a repeated word (E0205).
    SecondToolPreselects,
    /// A Macro B word may be written by its first two letters (`WH[..]DO1`
    /// for `WHILE`, `GO` for `GOTO`, `EN1` for `END1`): the control expands
    /// the abbreviation when the program is entered (Fanuc custom macro
    /// "abbreviations of macro words" [?: table as recalled from the 0i
    /// operator's manual; seen in 0i-MD shop programs]).
    MacroWordAbbreviations,
    /// The same code written twice in one block counts once
    /// (`G0 G90 G0 X0`): the control keeps the last code of a group
    /// (Fanuc, Haas [?: the Fanuc operator's manuals' G code notes, as
    /// recalled; not seen in a stored page]), elsewhere it is two codes of
    /// one group (LinuxCNC rs274: "Two G codes used from same modal group").
    RepeatedCodeOnce,
}

pub const CAPABILITIES: &[(&str, Capability)] = &[
    ("paren-comments", Capability::ParenComments),
    ("semicolon-comments", Capability::SemicolonComments),
    ("macro-b", Capability::MacroB),
    ("o-words", Capability::OWords),
    ("named-parameters", Capability::NamedParameters),
    ("power-operator", Capability::PowerOperator),
    ("numbered-programs", Capability::NumberedPrograms),
    ("local-subprogram-call", Capability::LocalSubprogramCall),
    ("strict-m-codes", Capability::StrictMCodes),
    ("program-end-required", Capability::ProgramEndRequired),
    ("strict-words", Capability::StrictWords),
    ("polar-words", Capability::PolarWords),
    ("r-parameters", Capability::RParameters),
    ("def-variables", Capability::DefVariables),
    ("structured-control", Capability::StructuredControl),
    ("named-cycles", Capability::NamedCycles),
    ("frames", Capability::Frames),
    ("g-code-transforms", Capability::GCodeTransforms),
    (
        "unbracketed-expressions",
        Capability::UnbracketedExpressions,
    ),
    ("message-comments", Capability::MessageComments),
    ("comma-corner-words", Capability::CommaCornerWords),
    ("eq-tolerance", Capability::EqTolerance),
    ("frame-arcs", Capability::FrameArcs),
    (
        "cycle-retract-r-plane-at-start",
        Capability::CycleRetractRPlaneAtStart,
    ),
    ("semicolon-end-of-block", Capability::SemicolonEndOfBlock),
    ("pole-paths", Capability::PolePaths),
    ("cycle-definitions", Capability::CycleDefinitions),
    (
        "tool-call-activates-offsets",
        Capability::ToolCallActivatesOffsets,
    ),
    (
        "off-functions-after-move",
        Capability::OffFunctionsAfterMove,
    ),
    (
        "sub-end-in-main-continues",
        Capability::SubEndInMainContinues,
    ),
    ("blank-form", Capability::BlankForm),
    ("power-on-rapid", Capability::PowerOnRapid),
    ("control-holds-tools", Capability::ControlHoldsTools),
    ("tools-by-name", Capability::ToolsByName),
    ("integer-spindle-speed", Capability::IntegerSpindleSpeed),
    (
        "comp-entry-longer-than-radius",
        Capability::CompEntryLongerThanRadius,
    ),
    ("comp-on-when-on-error", Capability::CompOnWhenOnError),
    ("power-on-linear", Capability::PowerOnLinear),
    ("cycle-words-required", Capability::CycleWordsRequired),
    ("cycle-r-above-bottom", Capability::CycleRAboveBottom),
    ("colon-program-number", Capability::ColonProgramNumber),
    (
        "cycle-rotary-words-refused",
        Capability::CycleRotaryWordsRefused,
    ),
    (
        "offset-parameters-in-machine-units",
        Capability::OffsetParametersInMachineUnits,
    ),
    ("tap-feed-axes-permuted", Capability::TapFeedAxesPermuted),
    ("first-program-wins", Capability::FirstProgramWins),
    (
        "fractional-sequence-numbers",
        Capability::FractionalSequenceNumbers,
    ),
    ("no-nested-comments", Capability::NoNestedComments),
    ("global-q-parameters", Capability::GlobalQParameters),
    ("comp-without-register", Capability::CompWithoutRegister),
    (
        "length-offset-programmed",
        Capability::LengthOffsetProgrammed,
    ),
    (
        "length-register-names-tool",
        Capability::LengthRegisterNamesTool,
    ),
    ("blanks-inside-words", Capability::BlanksInsideWords),
    ("last-comment-only", Capability::LastCommentOnly),
    ("main-return-ends", Capability::MainReturnEnds),
    ("strict-sub-styles", Capability::StrictSubStyles),
    ("stop-at-closing-percent", Capability::StopAtClosingPercent),
    ("orient-by-words", Capability::OrientByWords),
    ("var-and-ini-files", Capability::VarAndIniFiles),
    ("change-names-tool", Capability::ChangeNamesTool),
    ("bare-motion-code-moves", Capability::BareMotionCodeMoves),
    ("machine-coords-feed", Capability::MachineCoordsFeed),
    ("operator-messages", Capability::OperatorMessages),
    ("dwell-with-move", Capability::DwellWithMove),
    ("tilted-working-plane", Capability::TiltedWorkingPlane),
    ("offset-register-alone", Capability::OffsetRegisterAlone),
    ("comp-register-modal", Capability::CompRegisterModal),
    ("second-tool-preselects", Capability::SecondToolPreselects),
    (
        "macro-word-abbreviations",
        Capability::MacroWordAbbreviations,
    ),
    ("repeated-code-once", Capability::RepeatedCodeOnce),
];

impl Capability {
    pub fn parse(s: &str) -> Option<Capability> {
        CAPABILITIES.iter().find(|(n, _)| *n == s).map(|(_, c)| *c)
    }

    pub fn name(self) -> &'static str {
        CAPABILITIES
            .iter()
            .find(|(_, c)| *c == self)
            .map(|(n, _)| *n)
            .unwrap_or("")
    }
}

/// How a length written without a decimal point is read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntegerLengths {
    /// `X10` is 10 mm (calculator type; LinuxCNC, Siemens).
    Units,
    /// `X10` is 10 least input increments (Fanuc with 3401#0 = 0).
    Increments,
}

/// Number reading and writing rules.
#[derive(Clone, Debug, PartialEq)]
pub struct NumberRules {
    pub integer_lengths: IntegerLengths,
    /// The least input increment in mm and in inches.
    pub increment_mm: Decimal,
    pub increment_inch: Decimal,
    /// Most decimal places written for lengths, in mm and in inches.
    pub length_places_mm: u8,
    pub length_places_inch: u8,
    /// Write `10.` for a whole-number length.
    pub point_on_lengths: bool,
    /// Most decimal places written for feeds and speeds.
    pub feed_places: u8,
    /// Most decimal places for angles.
    pub angle_places: u8,
    /// Most digits before the point a value may have (`integer-digits`):
    /// a post refuses a larger value (E0690).
    pub integer_digits: u8,
}

/// One G or M code.
#[derive(Clone, Debug, PartialEq)]
pub struct CodeDef {
    /// `G` or `M`.
    pub letter: char,
    pub code: Decimal,
    /// Modal group id (`motion`, `plane`, ... or `non-modal`).
    pub group: String,
    pub meaning: Meaning,
    /// Words the code needs: each entry lists alternatives (`P|X`).
    pub requires: Vec<Vec<char>>,
    /// Words the code uses besides axis words (consumed by it).
    pub uses: Vec<char>,
    /// For dwell codes: the unit of each word that gives the time.
    pub dwell_units: Vec<(char, DwellUnit)>,
    /// Writers choose this code for its meaning when several share one.
    pub preferred: bool,
    /// For `aux` codes: what the canonical run does with it.
    pub run: AuxRun,
    /// For fine and back boring: the tool shifts by Q, in this direction,
    /// away from the wall at the oriented stop (Fanuc parameter 5101
    /// RD1/RD2, Haas setting 27). None: LinuxCNC's back boring (I J K).
    pub shift: Option<ShiftDir>,
    /// For `work-offset.extended` (G54.1 P, G154 P): the work offset P1
    /// selects (7: after G54..G59), the next P the next one.
    pub first_index: Option<u32>,
    pub doc: String,
    /// Where it is defined in the spec file.
    pub span: Span,
}

/// The direction of the shift of an oriented boring cycle (the `shift`
/// attribute of `<code>`), named as in G17: the first (X) or second (Y)
/// axis of the plane. In G18 the first axis is Z, in G19 Y, as Fanuc's
/// RD1/RD2 table gives them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShiftDir {
    PlusFirst,
    MinusFirst,
    PlusSecond,
    MinusSecond,
}

impl ShiftDir {
    pub fn parse(s: &str) -> Option<ShiftDir> {
        match s {
            "+X" => Some(ShiftDir::PlusFirst),
            "-X" => Some(ShiftDir::MinusFirst),
            "+Y" => Some(ShiftDir::PlusSecond),
            "-Y" => Some(ShiftDir::MinusSecond),
            _ => None,
        }
    }

    /// The shift of length `q` (its sign ignored) in plane terms.
    pub fn vector(self, q: f64) -> (f64, f64) {
        let q = q.abs();
        match self {
            ShiftDir::PlusFirst => (q, 0.0),
            ShiftDir::MinusFirst => (-q, 0.0),
            ShiftDir::PlusSecond => (0.0, q),
            ShiftDir::MinusSecond => (0.0, -q),
        }
    }
}

/// What the canonical run does with an `aux` code it has no function for
/// (the `run` attribute of `<code>`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum AuxRun {
    /// The run stops there (W0511 in `check`): the code may change what
    /// the run computes.
    #[default]
    Stop,
    /// Passed to the machine; nothing the canonical run computes depends
    /// on it (rotary axes' shortest path, TCPM off ...).
    Pass,
    /// A function of the machine's kinematics (TCPM on): kept, not made,
    /// reported once (W0518); the run goes on.
    Kinematics,
    /// The block's positions are machine coordinates from a datum the
    /// machine builder sets (Heidenhain M92, a machine parameter): run as
    /// machine coordinates (the machine datum, as M91), said once (W0517).
    MachineDatum,
    /// Runs a program the machine's user wrote for that number (LinuxCNC
    /// M100..M199): not run; the run stops there as for `Stop`. No other
    /// control's code of the same number means the same.
    UserProgram,
}

impl DialectSpec {
    /// Does the block's statement `k` put the block's positions in machine
    /// coordinates from a machine-builder datum ([`AuxRun::MachineDatum`])?
    pub fn is_machine_datum(&self, k: &crate::ir::StmtKind) -> bool {
        matches!(k, crate::ir::StmtKind::Aux { letter, code, .. }
            if self.code(*letter, *code).is_some_and(|c| c.run == AuxRun::MachineDatum))
    }

    /// Does statement `k` put its block's positions in machine
    /// coordinates: `G53`, a machine-datum code (M92), or a command the
    /// spec gives that meaning (Siemens `SUPA`)?
    pub fn in_machine_coords(&self, k: &crate::ir::StmtKind) -> bool {
        use crate::ir::StmtKind as K;
        match k {
            K::MachineCoords => true,
            K::Command { name, args: None } => {
                self.command_meaning(name) == Some(Meaning::MachineCoords)
            }
            _ => self.is_machine_datum(k),
        }
    }
}

/// The kind of value a cycle parameter takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamType {
    Real,
    Int,
    String,
    /// Not modelled: any value is kept.
    Any,
}

#[derive(Clone, Debug, PartialEq)]
pub struct ParamSig {
    pub name: String,
    pub ty: ParamType,
    pub doc: String,
}

/// A named cycle's signature (Siemens `CYCLE83`, `POCKET1`, `HOLES1`).
#[derive(Clone, Debug, PartialEq)]
pub struct CycleSig {
    pub name: String,
    /// What kind of cycle: `drill`, `peck`, `pocket-rect`, `pattern-row`...
    pub kind: String,
    pub params: Vec<ParamSig>,
    pub doc: String,
    pub span: Span,
}

impl CycleSig {
    pub fn param_index(&self, name: &str) -> Option<usize> {
        self.params
            .iter()
            .position(|p| p.name.eq_ignore_ascii_case(name))
    }
}

#[derive(Clone, Debug, PartialEq)]
pub struct FunctionDef {
    pub name: String,
    pub func: Func,
    /// Number of arguments.
    pub arity: usize,
}

/// A modal group declared by a spec: codes name it in `group=`.
#[derive(Clone, Debug, PartialEq)]
pub struct GroupDef {
    pub name: String,
    /// Two codes of an exclusive group may not share a block (E0202);
    /// codes of a non-exclusive group (machine M codes) may.
    pub exclusive: bool,
    /// Codes of an exclusive group that may still share a block with each
    /// other, by meaning (LinuxCNC: mist M7 and flood M8 together).
    pub together: Vec<crate::dialect::Meaning>,
    pub doc: String,
}

/// What a range of numbered variables is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum VarClass {
    /// Per macro call level (Fanuc #1-#33).
    Local,
    /// Cleared at power off.
    Common,
    /// Kept across power off.
    Retained,
    /// Controller data (positions, offsets, modes).
    System,
}

#[derive(Clone, Debug, PartialEq)]
pub struct VarRange {
    /// `#` (numbered parameters) or `R` (Siemens R parameters).
    pub prefix: char,
    pub first: u32,
    pub last: u32,
    pub class: VarClass,
    pub writable: bool,
}

/// What an address letter is for (the letters a dialect reads).
#[derive(Clone, Debug, PartialEq)]
pub struct AddressDef {
    pub letter: char,
    pub role: String,
    /// A length (decimal-point rule applies).
    pub length: bool,
}

/// A whole dialect, with everything inherited from the specs it extends.
#[derive(Clone, Debug)]
pub struct DialectSpec {
    pub id: String,
    pub name: String,
    pub family: Family,
    pub extends: Option<String>,
    /// The specs this one extends, nearest first (`haas`: fanuc, iso6983):
    /// where the post looks for the built-in templates it inherits.
    pub ancestors: Vec<String>,
    pub aliases: Vec<String>,
    /// File extensions (lower case, no dot) that suggest this dialect.
    pub extensions: Vec<String>,
    pub numbers: NumberRules,
    pub addresses: Vec<AddressDef>,
    /// The modal groups codes may name.
    pub groups: Vec<GroupDef>,
    pub codes: Vec<CodeDef>,
    pub cycles: Vec<CycleSig>,
    pub functions: Vec<FunctionDef>,
    /// Keyword commands (Siemens `SOFT`, `FFWON`), kept by name.
    pub commands: Vec<String>,
    /// The neutral function a command has where the spec names one
    /// (`<command name="SUPA" meaning="machine-coords"/>`).
    pub command_meanings: Vec<(String, Meaning)>,
    /// Names every program can read, with their values (`<constant>`:
    /// Siemens `_ROUGH` = 3), upper case.
    pub constants: Vec<(String, Decimal)>,
    /// Commands nothing the canonical run computes depends on
    /// (`run="pass"`: `FNORM`, `SOFT`).
    pub passing_commands: Vec<String>,
    pub variables: Vec<VarRange>,
    pub capabilities: Capabilities,
    /// What comments and messages may hold (`<text>`).
    pub text: super::text::TextRules,
    /// The post templates the target can fill (`<post-template>`): what
    /// `cncc post` can write for it.
    pub post_templates: Vec<super::post_templates::PostTemplateDecl>,
    /// The letter for canned-cycle repeats (`K` or `L`).
    pub repeat_letter: char,
    /// Block number increment when writing (0: keep the program's numbers).
    pub doc: String,
    index: CodeIndex,
}

#[derive(Clone, Debug, Default)]
struct CodeIndex {
    by_code: HashMap<(char, Decimal), usize, BuildHasherDefault<Fx>>,
    by_meaning: HashMap<Meaning, usize, BuildHasherDefault<Fx>>,
}

/// A small multiplicative hasher for the code index (looked up per word;
/// the keys come from the spec, so no flooding to guard against).
#[derive(Clone, Copy, Default)]
struct Fx(u64);

impl Fx {
    fn add(&mut self, w: u64) {
        self.0 = (self.0.rotate_left(5) ^ w).wrapping_mul(0x517c_c1b7_2722_0a95);
    }
}

impl Hasher for Fx {
    fn finish(&self) -> u64 {
        self.0
    }
    fn write(&mut self, bytes: &[u8]) {
        for chunk in bytes.chunks(8) {
            let mut b = [0u8; 8];
            b[..chunk.len()].copy_from_slice(chunk);
            self.add(u64::from_le_bytes(b));
        }
    }
    fn write_u8(&mut self, i: u8) {
        self.add(u64::from(i));
    }
    fn write_u16(&mut self, i: u16) {
        self.add(u64::from(i));
    }
    fn write_u32(&mut self, i: u32) {
        self.add(u64::from(i));
    }
    fn write_u64(&mut self, i: u64) {
        self.add(i);
    }
    fn write_usize(&mut self, i: usize) {
        self.add(i as u64);
    }
}

/// A set of capabilities as bits (asked per statement): a set with the
/// `BTreeSet` calls the loader and the tests use, iterated in the enum's
/// order.
#[derive(Clone, Copy, Default, PartialEq, Eq, Hash)]
pub struct Capabilities(u128);

impl Capabilities {
    fn bit(c: Capability) -> u128 {
        1u128 << (c as u32)
    }
    pub fn contains(&self, c: &Capability) -> bool {
        self.0 & Self::bit(*c) != 0
    }
    /// Adds `c`; whether it was absent.
    pub fn insert(&mut self, c: Capability) -> bool {
        let absent = !self.contains(&c);
        self.0 |= Self::bit(c);
        absent
    }
    /// Removes `c`; whether it was present.
    pub fn remove(&mut self, c: &Capability) -> bool {
        let present = self.contains(c);
        self.0 &= !Self::bit(*c);
        present
    }
    pub fn retain(&mut self, mut keep: impl FnMut(&Capability) -> bool) {
        for c in self.iter().collect::<Vec<_>>() {
            if !keep(&c) {
                self.remove(&c);
            }
        }
    }
    pub fn len(&self) -> usize {
        self.0.count_ones() as usize
    }
    pub fn is_empty(&self) -> bool {
        self.0 == 0
    }
    /// The capabilities in the enum's order (every one has a name in
    /// [`CAPABILITIES`]).
    pub fn iter(&self) -> impl Iterator<Item = Capability> + '_ {
        let mut all: Vec<Capability> = CAPABILITIES.iter().map(|(_, c)| *c).collect();
        all.sort_by_key(|c| *c as u32);
        all.into_iter().filter(|c| self.contains(c))
    }
}

impl std::fmt::Debug for Capabilities {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_set().entries(self.iter()).finish()
    }
}

impl FromIterator<Capability> for Capabilities {
    fn from_iter<I: IntoIterator<Item = Capability>>(it: I) -> Self {
        let mut s = Capabilities::default();
        for c in it {
            s.insert(c);
        }
        s
    }
}

impl<const N: usize> From<[Capability; N]> for Capabilities {
    fn from(a: [Capability; N]) -> Self {
        a.into_iter().collect()
    }
}

impl Extend<Capability> for Capabilities {
    fn extend<I: IntoIterator<Item = Capability>>(&mut self, it: I) {
        for c in it {
            self.insert(c);
        }
    }
}

impl DialectSpec {
    /// Builds the lookup tables; call after filling the fields.
    #[allow(clippy::too_many_arguments)]
    pub fn new(id: String, name: String, family: Family, numbers: NumberRules) -> Self {
        DialectSpec {
            id,
            name,
            family,
            extends: None,
            ancestors: Vec::new(),
            aliases: Vec::new(),
            extensions: Vec::new(),
            numbers,
            addresses: Vec::new(),
            groups: Vec::new(),
            codes: Vec::new(),
            cycles: Vec::new(),
            functions: Vec::new(),
            commands: Vec::new(),
            command_meanings: Vec::new(),
            constants: Vec::new(),
            passing_commands: Vec::new(),
            variables: Vec::new(),
            capabilities: Capabilities::default(),
            text: Default::default(),
            post_templates: Vec::new(),
            repeat_letter: 'K',
            doc: String::new(),
            index: CodeIndex::default(),
        }
    }

    /// Rebuilds the code index after `codes` changed.
    pub fn reindex(&mut self) {
        let mut idx = CodeIndex::default();
        for (i, c) in self.codes.iter().enumerate() {
            idx.by_code.insert((c.letter, c.code.normalized()), i);
            let m = c.meaning;
            if m != Meaning::Aux && (c.preferred || !idx.by_meaning.contains_key(&m)) {
                idx.by_meaning.insert(m, i);
            }
        }
        self.index = idx;
    }

    pub fn has(&self, cap: Capability) -> bool {
        self.capabilities.contains(&cap)
    }

    /// The G or M code definition, if the dialect has it.
    pub fn code(&self, letter: char, code: Decimal) -> Option<&CodeDef> {
        self.index
            .by_code
            .get(&(letter, code.normalized()))
            .map(|&i| &self.codes[i])
    }

    /// The code a writer uses for a meaning.
    pub fn code_for(&self, meaning: Meaning) -> Option<&CodeDef> {
        self.index.by_meaning.get(&meaning).map(|&i| &self.codes[i])
    }

    pub fn cycle(&self, name: &str) -> Option<&CycleSig> {
        self.cycles
            .iter()
            .find(|c| c.name.eq_ignore_ascii_case(name))
    }

    pub fn function(&self, name: &str) -> Option<&FunctionDef> {
        self.functions
            .iter()
            .find(|f| f.name.eq_ignore_ascii_case(name))
    }

    /// The dialect's name for a function meaning (for writers).
    pub fn function_name(&self, func: Func) -> Option<&str> {
        self.functions
            .iter()
            .find(|f| f.func == func)
            .map(|f| f.name.as_str())
    }

    /// Is `dialect` this dialect's id or one of its aliases (so text kept
    /// verbatim in that dialect may be written back here)?
    pub fn answers_to(&self, dialect: &str) -> bool {
        self.id == dialect || self.aliases.iter().any(|a| a == dialect)
    }

    pub fn is_command(&self, name: &str) -> bool {
        self.commands.iter().any(|c| c.eq_ignore_ascii_case(name))
    }

    /// The neutral function of command `name`, where the spec gives one.
    pub fn command_meaning(&self, name: &str) -> Option<Meaning> {
        self.command_meanings
            .iter()
            .find(|(c, _)| c.eq_ignore_ascii_case(name))
            .map(|x| x.1)
    }

    /// The value of the control's constant `name` (`<constant>`), if any.
    pub fn constant(&self, name: &str) -> Option<Decimal> {
        self.constants
            .iter()
            .find(|(c, _)| c.eq_ignore_ascii_case(name))
            .map(|x| x.1)
    }

    /// Does nothing the canonical run computes depend on command `name`?
    pub fn command_passes(&self, name: &str) -> bool {
        self.passing_commands
            .iter()
            .any(|c| c.eq_ignore_ascii_case(name))
    }

    pub fn address(&self, letter: char) -> Option<&AddressDef> {
        self.addresses
            .iter()
            .find(|a| a.letter == letter.to_ascii_uppercase())
    }

    pub fn is_length_address(&self, letter: char) -> bool {
        self.address(letter).map(|a| a.length).unwrap_or(false)
    }

    pub fn group(&self, name: &str) -> Option<&GroupDef> {
        self.groups.iter().find(|g| g.name == name)
    }

    pub fn var_range(&self, prefix: char, n: u32) -> Option<&VarRange> {
        self.variables
            .iter()
            .find(|v| v.prefix == prefix && (v.first..=v.last).contains(&n))
    }
}
