//! What the core hands the canned-cycle expansion: one block's cycle
//! words, evaluated to numbers but not yet resolved (absolute/incremental,
//! sticky values, retract plane are the cycle code's business).

use crate::dialect::ShiftDir;
use crate::ir::{CycleKind, DwellUnit};
use crate::span::Span;

/// A block that runs a word-address canned cycle (G73..G89): the block
/// with the G code, or a later block with axis words while the cycle is
/// the modal motion.
#[derive(Clone, Debug, PartialEq)]
pub struct CycleBlock {
    pub kind: CycleKind,
    /// X Y Z A B C as given in this block (None: not written).
    pub axes: [Option<f64>; 6],
    pub r: Option<f64>,
    pub q: Option<f64>,
    /// Dwell (or G76/G87 shift) word as written; see `p_unit`.
    pub p: Option<f64>,
    /// The unit of P for dwells in this dialect.
    pub p_unit: DwellUnit,
    /// K (Fanuc) or L (Haas, LinuxCNC) repeats.
    pub repeat: Option<f64>,
    pub i: Option<f64>,
    pub j: Option<f64>,
    pub k: Option<f64>,
    /// G91 in force.
    pub incremental: bool,
    /// G98 (true) or G99 (false) in force.
    pub return_initial: bool,
    /// The first block of a cycle must give R, and P for a dwell cycle
    /// (capability `cycle-words-required`, LinuxCNC); otherwise a missing
    /// R is the initial level and a missing P no dwell (Fanuc, Haas).
    pub words_required: bool,
    /// R beyond the bottom is an error (capability `cycle-r-above-bottom`,
    /// LinuxCNC); otherwise the cycle drills from R towards the bottom
    /// whichever way that is.
    pub r_above_bottom: bool,
    /// An A, B or C word in a cycle block is an error (capability
    /// `cycle-rotary-words-refused`, LinuxCNC).
    pub rotary_refused: bool,
    /// This block wrote the cycle's G code (not only axis words).
    pub code_in_block: bool,
    /// LinuxCNC polar words under G91: the distance and the angle
    /// (degrees) each repeat adds to the hole's polar position about the
    /// program origin (`G91 G81 ^60 L6` drills six holes round a circle).
    pub polar_step: Option<(f64, f64)>,
    /// Fine and back boring in the Fanuc manner (the `shift` attribute of
    /// the code in the dialect spec): the direction Q shifts the tool at
    /// the oriented stop. None: LinuxCNC's back boring with I J K.
    pub shift: Option<ShiftDir>,
    pub span: Span,
}
