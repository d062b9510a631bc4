//! LinuxCNC's G76 threading cycle (a lathe cycle: X is the diameter or
//! radius axis, Z the thread axis), expanded into passes as rs274 2.9
//! expands it, so that its canonical calls match: each pass rapids back
//! and in, cuts under spindle synchronisation (with the override off),
//! optionally tapers in (L1) and out (L2) over E, and rapids out.
//!
//! Words: P pitch, I thread peak offset from the drive line (negative:
//! external; positive: boring), J first cut depth, K full thread depth,
//! R depth degression (pass n cuts to J * n^(1/R)), Q compound angle in
//! degrees, H spring passes, E taper length, L taper flags. The end point
//! is the block's X/Z (find-ends rules); the cycle ends with a rapid to it.
//! In G7 diameter mode I J K are halved. Behaviour pinned with the live
//! rs274 (tests/programs/linuxcnc/oracle/g76-*.ngc). G76 is modal: a later
//! block with axis words runs it again, with that block's words.

use super::comp::MoveKind;
use super::host::{MotionHost, SpindleDir};
use super::machine::pose6;
use super::state::ModalMotion;
use super::target::{target, Frame};
use super::{Interp, Stop};
use crate::canon::{Canon, Pose};
use crate::diag::Code;
use crate::ir::{Arena, Block, Expr, MotionKind, StmtKind, Word};

/// The modal motion of the spec's threading code (`cycle.lathe-thread`).
fn modal_code(it: &Interp<'_, '_>) -> Option<ModalMotion> {
    let m = crate::dialect::Meaning::Machine(crate::dialect::MachineFn::LatheThread);
    let c = it.spec.code_for(m)?;
    Some(ModalMotion::Move(MotionKind::Other(c.code)))
}

/// Is the threading cycle the modal motion (axis words alone run it again)?
pub fn is_modal(it: &Interp<'_, '_>) -> bool {
    modal_code(it).is_some_and(|m| it.state.motion == m)
}

/// The cycle's words, resolved.
struct Thread {
    pitch: f64,
    boring: bool,
    safe_x: f64,
    /// Peak offset, first depth, full height (radius, program units).
    i: f64,
    j: f64,
    k: f64,
    angle: f64,
    degression: f64,
    spring: u32,
    taper: f64,
    taper_pitch: f64,
    entry_taper: bool,
    exit_taper: bool,
    start: Pose,
    target_z: f64,
}

fn fail(it: &Interp<'_, '_>, code: Code, msg: &str) -> Stop {
    it.error_at(it.span, code, msg)
}

/// Runs G76 in the block (`words`: the G76 statement's own, if any).
pub fn exec(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let w = |it: &mut Interp<'_, '_>, c| super::aux::word_or_loose(it, words, block, c, exprs);
    let Some(pitch) = w(it, 'P')? else {
        let span = it.span;
        return Err(it.read_error(span, Code::CycleMissingWord, "P word missing with G76"));
    };
    let (Some(i), Some(j), Some(k)) = (w(it, 'I')?, w(it, 'J')?, w(it, 'K')?) else {
        let span = it.span;
        return Err(it.read_error(
            span,
            Code::CycleMissingWord,
            "I J or K words missing with G76",
        ));
    };
    if it.state.spindle == SpindleDir::Stopped {
        return Err(fail(
            it,
            Code::CycleSpindleState,
            "Chosen spindle (0) not turning in G76",
        ));
    }
    if it.comp.is_on() {
        return Err(fail(
            it,
            Code::CompStateChange,
            "Cannot use G76 threading cycle with cutter radius compensation on",
        ));
    }
    if i == 0.0 {
        return Err(fail(it, Code::CycleBadArgument, "In G76, I must not be 0"));
    }
    if j <= 0.0 {
        return Err(fail(
            it,
            Code::CycleBadArgument,
            "In G76, J must be greater than 0",
        ));
    }
    if k <= j {
        return Err(fail(
            it,
            Code::CycleBadArgument,
            "In G76, K must be greater than J",
        ));
    }
    let end = end_pose(it, block, exprs)?;
    let opt = |it: &mut Interp<'_, '_>, c| w(it, c);
    let q = opt(it, 'Q')?;
    let r = opt(it, 'R')?;
    let h = opt(it, 'H')?;
    let e = opt(it, 'E')?;
    let l = opt(it, 'L')?;
    let t = resolve(it, pitch, [i, j, k], [q, r, h, e, l], end[2]);
    passes(it, &t)?;
    it.straight_move(MoveKind::Rapid, end)?;
    it.cycles.cancel();
    if let Some(m) = modal_code(it) {
        it.state.motion = m;
    }
    Ok(())
}

/// Where the cycle ends: the block's axis words (program units).
fn end_pose(it: &mut Interp<'_, '_>, block: &Block, exprs: &Arena<Expr>) -> Result<Pose, Stop> {
    let motion = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Motion(m) => Some(&m.target),
        _ => None,
    });
    match motion {
        Some(axes) => {
            let to = target(it, axes, exprs, Frame::Program)?;
            Ok(pose6(&it.state, &to))
        }
        None => Ok(MotionHost::position(it)),
    }
}

/// The words turned into the pass geometry, as rs274 computes it.
fn resolve(
    it: &Interp<'_, '_>,
    pitch: f64,
    [i, j, k]: [f64; 3],
    [q, r, h, e, l]: [Option<f64>; 5],
    end_z: f64,
) -> Thread {
    let halve = if it.state.lathe_diameter { 0.5 } else { 1.0 };
    let (i, j, k) = (i * halve, j * halve, k * halve);
    let start = MotionHost::position(it);
    let reverse = end_z > start[2];
    let mut angle = q.unwrap_or(0.0).to_radians();
    if reverse {
        angle = -angle;
    }
    let degression = r.filter(|r| *r >= 1.0).unwrap_or(1.0);
    let taper = e.unwrap_or(0.0).max(0.0);
    let taper_pitch = if taper > 0.0 {
        pitch * taper.hypot(k.abs()) / taper
    } else {
        pitch
    };
    let flags = l.unwrap_or(0.0).max(0.0) as i64;
    Thread {
        pitch,
        boring: i > 0.0,
        safe_x: start[0],
        i: i.abs(),
        j: j.abs(),
        k: k.abs(),
        angle,
        degression,
        spring: h.unwrap_or(0.0).max(0.0) as u32,
        taper: if reverse { -taper } else { taper },
        taper_pitch,
        entry_taper: flags & 1 != 0,
        exit_taper: flags & 2 != 0,
        start,
        target_z: end_z + k.abs() * angle.tan(),
    }
}

/// All passes: deeper each time until the full depth, then the full
/// depth once more per spring pass. The pass count is bounded.
fn passes(it: &mut Interp<'_, '_>, t: &Thread) -> Result<(), Stop> {
    let end_depth = t.k + t.i;
    let mut depth = t.i + t.j;
    let mut pass = 1u32;
    while depth < end_depth {
        if pass > 100_000 {
            return Err(fail(it, Code::LimitExceeded, "G76 needs too many passes"));
        }
        one_pass(it, t, depth)?;
        pass += 1;
        depth = t.i + t.j * f64::from(pass).powf(1.0 / t.degression);
    }
    for _ in 0..=t.spring.min(100_000) {
        one_pass(it, t, end_depth)?;
    }
    Ok(())
}

/// One pass at `depth` below the drive line.
fn one_pass(it: &mut Interp<'_, '_>, t: &Thread, depth: f64) -> Result<(), Stop> {
    let end_depth = t.k + t.i;
    let x_at = |d: f64| {
        if t.boring {
            t.safe_x + d
        } else {
            t.safe_x - d
        }
    };
    let zoff = (depth - t.i) * t.angle.tan();
    let (z0, z1) = (t.start[2] - zoff, t.target_z - zoff);
    let clear = x_at(depth - end_depth);
    let crest = x_at(depth - t.k);
    let root = x_at(depth);
    let at = |x: f64, z: f64| {
        let mut p = t.start;
        p[0] = x;
        p[2] = z;
        p
    };
    let sync = |it: &mut Interp<'_, '_>, pitch: f64| {
        it.out(Canon::StartSpeedFeedSync {
            pitch,
            velocity_mode: false,
        })
    };
    it.straight_move(MoveKind::Rapid, at(clear, z0))?;
    if t.taper != 0.0 && t.entry_taper {
        it.out(Canon::DisableFeedOverride);
        sync(it, t.taper_pitch);
        it.straight_move(MoveKind::Feed, at(crest, z0))?;
        it.straight_move(MoveKind::Feed, at(root, z0 - t.taper))?;
        sync(it, t.pitch);
    } else {
        it.straight_move(MoveKind::Rapid, at(root, z0))?;
        it.out(Canon::DisableFeedOverride);
        sync(it, t.pitch);
    }
    if t.taper != 0.0 && t.exit_taper {
        it.straight_move(MoveKind::Feed, at(root, z1 + t.taper))?;
        sync(it, t.taper_pitch);
        it.straight_move(MoveKind::Feed, at(crest, z1))?;
    } else {
        it.straight_move(MoveKind::Feed, at(root, z1))?;
    }
    it.out(Canon::StopSpeedFeedSync);
    it.straight_move(MoveKind::Rapid, at(clear, z1))?;
    it.out(Canon::EnableFeedOverride);
    Ok(())
}
