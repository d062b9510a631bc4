//! Errors of cutter radius compensation, worded as LinuxCNC's interpreter
//! words them, with the block they concern.

use crate::diag::Code;

/// A caller-chosen tag for the block a move came from (e.g. its index).
pub type BlockTag = u64;

/// What went wrong.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompErrorKind {
    /// A held-back straight feed would have to run backwards.
    StraightFeedGouge,
    /// A held-back straight traverse would have to run backwards.
    StraightTraverseGouge,
    /// A held-back arc would have to sweep further than programmed, or an
    /// arc cannot meet the previous line.
    ArcGouge,
    ArcToStraightGouge,
    ArcToArcGouge,
    ArcsSameCentre,
    ZeroDegreeCorner,
    /// The tool does not fit inside the arc.
    ToolRadiusNotLessThanArcRadius,
    EntryMoveTooShort,
    EntryArcTooShort,
    AlreadyOn,
    NotXyPlane,
    PlaneChange,
    ArcAfterExit,
    /// Internal inconsistency (an arc whose radii no longer match).
    Bug,
}

impl CompErrorKind {
    /// The message, as rs274 prints it where it has one.
    pub fn message(self) -> &'static str {
        use CompErrorKind::*;
        match self {
            StraightFeedGouge => "Straight feed in concave corner cannot be reached by the tool without gouging",
            StraightTraverseGouge => "Straight traverse in concave corner cannot be reached by the tool without gouging",
            ArcGouge => "Arc move in concave corner cannot be reached by the tool without gouging",
            ArcToStraightGouge => "Arc to straight motion makes a corner the compensated tool can't fit in without gouging",
            ArcToArcGouge => "Arc to arc motion makes a corner the compensated tool can't fit in without gouging",
            ArcsSameCentre => "Arc to arc motion is invalid because the arcs have the same center",
            ZeroDegreeCorner => "Zero degree inside corner is invalid for cutter compensation",
            ToolRadiusNotLessThanArcRadius => "Tool radius not less than arc radius with comp",
            EntryMoveTooShort => "Length of cutter compensation entry move is not greater than the tool radius",
            EntryArcTooShort => "Radius of cutter compensation entry arc is not greater than the tool radius",
            AlreadyOn => "Cannot turn cutter radius comp on when on",
            NotXyPlane => "Cutter radius compensation allowed only in XY, XZ planes",
            PlaneChange => "Cannot change planes with cutter radius compensation on",
            ArcAfterExit => "The move just after exiting cutter compensation mode must be straight, not an arc",
            Bug => "BUG: cutter compensation has generated an invalid arc with mismatched radii",
        }
    }

    /// The hint a diagnostic shows.
    pub fn hint(self) -> &'static str {
        use CompErrorKind::*;
        match self {
            StraightFeedGouge | StraightTraverseGouge | ArcGouge | ArcToStraightGouge | ArcToArcGouge
            | ZeroDegreeCorner => "the inside corner is tighter than the tool: use a smaller tool or open up the corner",
            ArcsSameCentre => "join concentric arcs with a line, or program them as one arc",
            ToolRadiusNotLessThanArcRadius => "the tool cuts inside this arc: its radius must be larger than the tool radius",
            EntryMoveTooShort | EntryArcTooShort => "make the first move after G41/G42 longer than the tool radius",
            AlreadyOn => "cancel compensation with G40 before switching side",
            NotXyPlane => "select G17 (or G18) before G41/G42",
            PlaneChange => "cancel compensation with G40 before changing plane",
            ArcAfterExit => "program a straight exit move after G40",
            Bug => "please report this program",
        }
    }

    /// The diagnostic code for it.
    pub fn code(self) -> Code {
        use CompErrorKind::*;
        match self {
            StraightFeedGouge
            | StraightTraverseGouge
            | ArcGouge
            | ArcToStraightGouge
            | ArcToArcGouge
            | ZeroDegreeCorner
            | ArcsSameCentre => Code::CompGouge,
            ToolRadiusNotLessThanArcRadius => Code::CompArcTooSmall,
            EntryMoveTooShort | EntryArcTooShort => Code::CompEntryTooShort,
            NotXyPlane => Code::CompNotXyPlane,
            AlreadyOn | PlaneChange => Code::CompStateChange,
            ArcAfterExit => Code::CompExitArc,
            Bug => Code::CompGouge,
        }
    }
}

/// An error with the block it was found at and, when it concerns a move
/// held back from an earlier block, that block too.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompError {
    pub kind: CompErrorKind,
    /// The block being processed when it was found (LinuxCNC reports this one).
    pub block: BlockTag,
    /// The earlier block whose held-back move could not be fixed, if any.
    pub held: Option<BlockTag>,
}

impl std::fmt::Display for CompError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.kind.message())
    }
}
