//! The interface between the interpreter's core and the parts that turn
//! one statement into many moves (canned cycles, named Siemens cycles,
//! cutter compensation). They see the machine only through [`MotionHost`]:
//! positions in the program frame, in the active length units.

use crate::canon::{Canon, CanonPlane, CanonUnits, MotionMode, Pose};
use crate::diag::Diagnostic;

/// Where moves go. The core implements it: it updates the current position,
/// and passes the calls on (through compensation when that is on).
pub trait MotionHost {
    /// The current position: x y z a b c, program frame, active units.
    fn position(&self) -> Pose;
    fn plane(&self) -> CanonPlane;
    fn units(&self) -> CanonUnits;
    /// The active feed rate (units per minute, or per revolution).
    fn feed_rate(&self) -> f64;
    fn rapid(&mut self, to: Pose);
    fn feed(&mut self, to: Pose);
    /// An arc in the active plane: end point, centre (in plane axes
    /// first/second), turns with sign (+ CCW, - CW), axis end.
    fn arc(&mut self, to: Pose, center: (f64, f64), rotation: i64);
    fn dwell(&mut self, seconds: f64);
    /// Any other call (spindle, overrides, motion control mode, messages).
    fn emit(&mut self, call: Canon);
    /// Reports a problem found while expanding (with the statement's span
    /// already attached by the caller's context).
    fn report(&mut self, diag: Diagnostic);
    fn spindle(&self) -> SpindleDir;
    fn spindle_speed(&self) -> f64;
    /// The path control mode in force and the naive-CAM tolerance (G64 P Q),
    /// which canned cycles restore after running in exact-path mode.
    /// Default: LinuxCNC's start-up state (continuous, no tolerances).
    fn path_mode(&self) -> (MotionMode, f64) {
        (MotionMode::Continuous(0.0), 0.0)
    }
    /// The tool was moved outside the program (G88: the operator retracts
    /// it by hand); from now on assume it is at `to`. Emits nothing.
    /// The default ignores it: a core should override it to update its
    /// current position, as LinuxCNC does.
    fn assume_position(&mut self, to: Pose) {
        let _ = to;
    }
    /// Whether feed and spindle-speed overrides are enabled (M48/M49/M50/M51);
    /// tapping cycles disable them and re-enable only those that were on.
    fn overrides_enabled(&self) -> (bool, bool) {
        (true, true)
    }
    /// Whether the dialect has a capability (default: none).
    fn has(&self, c: crate::dialect::Capability) -> bool {
        let _ = c;
        false
    }
}

/// Maps a plane's (first, second, normal) axis indices into a pose.
/// XY: (x, y, z); XZ: (z, x, y) as the canon's ARC_FEED orders it; YZ: (y, z, x).
pub fn plane_axes(plane: CanonPlane) -> (usize, usize, usize) {
    match plane {
        CanonPlane::XY => (0, 1, 2),
        CanonPlane::XZ => (2, 0, 1),
        CanonPlane::YZ => (1, 2, 0),
    }
}

/// Spindle state as the cycles need it (tapping and boring reverse or stop it).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpindleDir {
    Cw,
    Ccw,
    Stopped,
}
