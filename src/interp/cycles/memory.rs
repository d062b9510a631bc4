//! What stays in force between the blocks of a modal canned cycle.

use crate::ir::CycleKind;

/// Values that carry over from one cycle block to the next. The core owns
/// one for the whole run and calls [`CycleMemory::cancel`] on G80 or any
/// other motion code.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CycleMemory {
    /// The cycle that ran last (None after G80 / other motion).
    pub active: Option<CycleKind>,
    /// Initial level: the drilling-axis position before the first block of
    /// the cycle (G98 returns here).
    pub initial_level: Option<f64>,
    /// Bottom word (Z in G17) as last written.
    pub bottom: f64,
    /// R word as last written.
    pub r: f64,
    /// Q word (peck or shift) as last used.
    pub q: f64,
    /// Dwell in seconds as last used (LinuxCNC keeps it across cycles).
    pub dwell: f64,
    /// G87 I J K as last used (and Haas's I J shift of G76/G77).
    pub ijk: [f64; 3],
    /// The last oriented-boring shift came from I/J (in `ijk`), not Q.
    pub shift_ij: bool,
    /// The active cycle's R lies below the part by design (Fanuc back
    /// boring enters there through the hole): lints leave its R alone.
    pub r_below_part: bool,
    /// Fanuc: `K0` stores the cycle without drilling. LinuxCNC rejects
    /// zero repeats. The core sets this from the dialect.
    pub allow_zero_repeats: bool,
}

impl CycleMemory {
    pub fn new() -> Self {
        Self::default()
    }

    /// G80 or another motion code: the cycle ends; the next cycle block
    /// must give its bottom and R again and starts a new initial level.
    pub fn cancel(&mut self) {
        self.active = None;
        self.initial_level = None;
    }
}
