//! The body of each word-address cycle at one hole, after the tool has
//! been positioned at the hole on the R level. Sources: LinuxCNC 2.9's
//! interpreter (checked against `rs274`) for G73, G74, G81..G89; the Fanuc
//! operator's manual (0i-MF, "fine boring cycle") for G76, which LinuxCNC
//! does not have on mills.

use super::frame::Frame;
use super::word::{gcode, Params};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::cycle_io::CycleBlock;
use crate::interp::host::{MotionHost, SpindleDir};
use crate::ir::CycleKind;

/// The levels along the drilling axis, and the hole position.
pub(super) struct Levels {
    pub at: (f64, f64),
    pub r: f64,
    pub clear: f64,
    pub bottom: f64,
}

pub(super) fn run_body(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    use CycleKind::*;
    match p.kind {
        Drill => {
            f.feed(h, l.at, l.bottom);
            f.rapid(h, l.at, l.clear);
        }
        DrillDwell => {
            f.feed(h, l.at, l.bottom);
            h.dwell(p.dwell);
            f.rapid(h, l.at, l.clear);
        }
        Peck | ChipBreak => peck(h, f, l, p, block)?,
        Tap | TapLeft => tap(h, f, l, p, block)?,
        BoreFeedOut => {
            f.feed(h, l.at, l.bottom);
            f.feed(h, l.at, l.r);
            f.rapid(h, l.at, l.clear);
        }
        BoreStopRapidOut => {
            let dir = turning(h, block)?;
            f.feed(h, l.at, l.bottom);
            h.dwell(p.dwell);
            h.emit(Canon::StopSpindle);
            f.rapid(h, l.at, l.clear);
            h.emit(start(dir));
        }
        BackBore if p.shift.is_some() => super::oriented::back_bore(h, f, l, p, block)?,
        BackBore => back_bore(h, f, l, p, block)?,
        BoreManual => {
            let dir = turning(h, block)?;
            f.feed(h, l.at, l.bottom);
            h.dwell(p.dwell);
            h.emit(Canon::StopSpindle);
            // The operator retracts the tool by hand here.
            h.emit(Canon::ProgramStop);
            h.emit(start(dir));
            // LinuxCNC then takes the tool to be at the clear level.
            let p = f.pose(h, l.at, l.clear);
            h.assume_position(p);
        }
        BoreDwellFeedOut => {
            f.feed(h, l.at, l.bottom);
            h.dwell(p.dwell);
            f.feed(h, l.at, l.clear);
        }
        FineBore => fine_bore(h, f, l, p, block)?,
    }
    Ok(())
}

pub(super) fn start(dir: SpindleDir) -> Canon {
    match dir {
        SpindleDir::Ccw => Canon::SpindleCcw,
        SpindleDir::Cw | SpindleDir::Stopped => Canon::SpindleCw,
    }
}

/// `CANON_DIRECTION` as ORIENT_SPINDLE prints it (stopped 1, CW 2, CCW 3).
pub(super) fn orient_mode(dir: SpindleDir) -> i64 {
    match dir {
        SpindleDir::Stopped => 1,
        SpindleDir::Cw => 2,
        SpindleDir::Ccw => 3,
    }
}

pub(super) fn turning(h: &dyn MotionHost, block: &CycleBlock) -> Result<SpindleDir, Diagnostic> {
    match h.spindle() {
        SpindleDir::Stopped => {
            let msg = format!("spindle not turning in {}", gcode(block.kind));
            Err(Diagnostic::new(Code::CycleSpindleState, msg)
                .primary(block.span, "spindle stopped")
                .help("start the spindle (M3 or M4) before the cycle"))
        }
        d => Ok(d),
    }
}

/// G83 (full retract to R) and G73 (small back-off) pecking.
fn peck(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let q = p.q.unwrap_or(0.0);
    if q <= 0.0 {
        return Err(
            Diagnostic::new(Code::CycleBadPeck, "negative or zero Q value used")
                .primary(block.span, "peck depth Q must be positive")
                .help("give the depth of each peck as a positive Q"),
        );
    }
    let full_retract = p.kind == CycleKind::Peck;
    // Bounded: at most |r - bottom| / q pecks; refuse absurd counts.
    if (l.r - l.bottom).abs() / q > 1.0e6 {
        return Err(
            Diagnostic::new(Code::CycleBadPeck, "peck depth Q too small for this hole")
                .primary(block.span, "more than a million pecks")
                .help("use a larger Q"),
        );
    }
    // Downwards (s = -1) as usual; upwards where the dialect allows R
    // below the bottom (a right-angle head).
    let s = super::word::toward(l.r, l.bottom);
    let mut depth = l.r + s * q;
    while s * (l.bottom - depth) > 0.0 {
        f.feed(h, l.at, depth);
        if full_retract {
            f.rapid(h, l.at, l.r);
        }
        f.rapid(h, l.at, depth - s * p.rapid_delta);
        depth += s * q;
    }
    f.feed(h, l.at, l.bottom);
    f.rapid(h, l.at, l.clear);
    Ok(())
}

/// A feed of G74/G84. Where the dialect keeps LinuxCNC's bug
/// (capability tap-feed-axes-permuted), a feed outside G17 goes to the
/// point whose (x, y, z) are the plane-ordered coordinates permuted once
/// more, as rs274 2.9 prints it; the position then is the right one again
/// (rs274 keeps its own current point apart from the call).
fn tap_feed(h: &mut dyn MotionHost, f: Frame, at: (f64, f64), depth: f64) {
    let right = f.pose(h, at, depth);
    if f.n == 2 || !h.has(crate::dialect::Capability::TapFeedAxesPermuted) {
        return h.feed(right);
    }
    let mut wrong = right;
    let (x, y, z) = (right[0], right[1], right[2]);
    // G18 prints (y, z, x) and G19 (z, x, y) of the right point.
    let p = if f.n == 1 { [y, z, x] } else { [z, x, y] };
    wrong[..3].copy_from_slice(&p);
    h.feed(wrong);
    h.assume_position(right);
}

/// G84 (spindle CW, reversed at the bottom) and G74 (the mirror image).
fn tap(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let right = p.kind == CycleKind::Tap;
    let (want, wrong) = if right {
        (SpindleDir::Cw, SpindleDir::Ccw)
    } else {
        (SpindleDir::Ccw, SpindleDir::Cw)
    };
    let dir = h.spindle();
    if dir != want {
        let what = if dir == wrong {
            format!(
                "spindle turning {} in {}",
                if right {
                    "counterclockwise"
                } else {
                    "clockwise"
                },
                gcode(p.kind)
            )
        } else {
            format!("spindle not turning in {}", gcode(p.kind))
        };
        return Err(Diagnostic::new(Code::CycleSpindleState, what)
            .primary(block.span, "tapping cycle")
            .help(if right {
                "G84 needs M3 (clockwise)"
            } else {
                "G74 needs M4 (counterclockwise)"
            }));
    }
    let (feed_ovr, speed_ovr) = h.overrides_enabled();
    h.emit(Canon::DisableFeedOverride);
    h.emit(Canon::DisableSpeedOverride);
    tap_feed(h, f, l.at, l.bottom);
    h.emit(Canon::StopSpindle);
    h.emit(if right {
        Canon::SpindleCcw
    } else {
        Canon::SpindleCw
    });
    h.dwell(p.dwell);
    tap_feed(h, f, l.at, l.clear);
    h.emit(Canon::StopSpindle);
    h.emit(if right {
        Canon::SpindleCw
    } else {
        Canon::SpindleCcw
    });
    if feed_ovr {
        h.emit(Canon::EnableFeedOverride);
    }
    if speed_ovr {
        h.emit(Canon::EnableSpeedOverride);
    }
    Ok(())
}

/// G87 back boring: in through the hole shifted by I/J with the spindle
/// oriented, bore upwards to the middle level, out the same way.
fn back_bore(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let dir = turning(h, block)?;
    let ijk = p.ijk_words.unwrap_or([0.0; 3]);
    let off = (l.at.0 + ijk[f.a], l.at.1 + ijk[f.b]);
    let orient = Canon::OrientSpindle {
        angle: 0.0,
        mode: orient_mode(dir),
    };
    f.rapid(h, off, l.r);
    h.emit(Canon::StopSpindle);
    h.emit(orient.clone());
    f.rapid(h, off, l.bottom);
    f.rapid(h, l.at, l.bottom);
    h.emit(start(dir));
    f.feed(h, l.at, p.middle);
    f.feed(h, l.at, l.bottom);
    h.emit(Canon::StopSpindle);
    h.emit(orient);
    f.rapid(h, off, l.bottom);
    f.rapid(h, off, l.clear);
    f.rapid(h, l.at, l.clear);
    h.emit(start(dir));
    Ok(())
}

/// Fanuc G76 fine boring (0i-MF manual): feed to the bottom, dwell P if
/// given, oriented spindle stop, shift by Q away from the wall, rapid out to
/// the clear level, shift back, restart the spindle.
///
/// The shift is the dialect's (`shift` of the code, resolved in
/// `oriented`); a code without one shifts by Q along +first axis.
/// Assumptions [?]: the orientation angle is the controller's fixed M19
/// position, written here as 0; the shift back is a rapid at the clear
/// level; the spindle restarts in its old direction.
fn fine_bore(
    h: &mut dyn MotionHost,
    f: Frame,
    l: &Levels,
    p: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let dir = turning(h, block)?;
    let s = match p.shift {
        Some(s) => s.by,
        None => (p.q.unwrap_or(0.0).abs(), 0.0),
    };
    let off = (l.at.0 + s.0, l.at.1 + s.1);
    f.feed(h, l.at, l.bottom);
    if p.dwell > 0.0 {
        h.dwell(p.dwell);
    }
    h.emit(Canon::StopSpindle);
    h.emit(Canon::OrientSpindle {
        angle: 0.0,
        mode: orient_mode(dir),
    });
    f.rapid(h, off, l.bottom);
    f.rapid(h, off, l.clear);
    f.rapid(h, l.at, l.clear);
    h.emit(start(dir));
    Ok(())
}
