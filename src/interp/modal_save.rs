//! M70 (save the modal state), M71 (forget it), M72 (restore it) and M73
//! (save it, restore it when the current subroutine returns), as LinuxCNC
//! does: a restore emits the calls for what changed.

use super::host::SpindleDir;
use super::state::State;
use super::Interp;
use crate::canon::{Canon, CanonUnits, MotionMode};
use crate::ir::{FeedMode, LengthUnit};

/// M70 / M73: saves the state; `auto` restores it when the call level
/// the statement runs at is left.
pub fn save(it: &mut Interp<'_, '_>, auto: bool) {
    let s = Box::new(it.state.clone());
    if auto {
        let depth = it.params.depth();
        it.auto_restore.retain(|(d, _)| *d < depth);
        it.auto_restore.push((depth, s));
    } else {
        it.saved_modal = Some(s);
    }
}

/// M71.
pub fn invalidate(it: &mut Interp<'_, '_>) {
    it.saved_modal = None;
}

/// M72: false when nothing was saved.
pub fn restore_saved(it: &mut Interp<'_, '_>) -> bool {
    match it.saved_modal.clone() {
        Some(s) => {
            restore(it, &s);
            true
        }
        None => false,
    }
}

/// Restores M73 states whose call level has been left (called as each
/// block starts).
pub fn check_auto(it: &mut Interp<'_, '_>) {
    let depth = it.params.depth();
    while it.auto_restore.last().is_some_and(|(d, _)| *d > depth) {
        if let Some((_, s)) = it.auto_restore.pop() {
            restore(it, &s);
        }
    }
}

fn restore(it: &mut Interp<'_, '_>, s: &State) {
    let cur = it.state.clone();
    if s.units != cur.units {
        it.state.units = s.units;
        it.out(Canon::UseLengthUnits(if s.units == LengthUnit::Mm {
            CanonUnits::Mm
        } else {
            CanonUnits::Inches
        }));
    }
    if s.feed_mode != cur.feed_mode {
        it.state.feed_mode = s.feed_mode;
        it.out(Canon::SetFeedMode(u8::from(
            s.feed_mode == FeedMode::PerRevolution,
        )));
    }
    if s.feed != cur.feed {
        it.state.feed = s.feed;
        it.out(Canon::SetFeedRate(s.feed));
    }
    if s.speed != cur.speed {
        it.state.speed = s.speed;
        it.out(Canon::SetSpindleSpeed(s.speed));
    }
    if s.spindle != cur.spindle {
        it.state.spindle = s.spindle;
        it.out(match s.spindle {
            SpindleDir::Cw => Canon::SpindleCw,
            SpindleDir::Ccw => Canon::SpindleCcw,
            SpindleDir::Stopped => Canon::StopSpindle,
        });
    }
    // rs274 2.9 turns back on the coolant that was on when saved and is
    // off now, and turns none off (probed: saved mist, now flood: MIST_ON
    // only, the flood stays on). [?] Where these come among the other
    // restores was not probed together with them.
    if s.mist && !cur.mist {
        it.state.mist = true;
        it.out(Canon::MistOn);
    }
    if s.flood && !cur.flood {
        it.state.flood = true;
        it.out(Canon::FloodOn);
    }
    if s.plane != cur.plane {
        it.state.plane = s.plane;
        it.out(Canon::SelectPlane(s.plane));
    }
    if s.absolute != cur.absolute {
        let what = if s.absolute {
            "absolute"
        } else {
            "incremental"
        };
        it.out(Canon::Comment(format!(
            "interpreter: distance mode changed to {what}"
        )));
        it.state.absolute = s.absolute;
    }
    it.state.arc_absolute = s.arc_absolute;
    it.state.retract_initial = s.retract_initial;
    if s.path != cur.path {
        it.state.path = s.path;
        let (mode, naive) = super::host::MotionHost::path_mode(it);
        it.out(Canon::SetMotionControlMode(mode));
        if let MotionMode::Continuous(_) = mode {
            it.out(Canon::SetNaivecamTolerance(naive));
        }
    }
}
