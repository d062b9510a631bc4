//! Heidenhain cycles 204 BACK BORING, 209 TAPPING WITH CHIP BREAKING and
//! 241 SINGLE-LIP DEEP-HOLE DRILLING expanded into moves at the hole
//! centre (the tool position when called). Parameter meanings from the
//! TNC cycle manuals [K, 209 checked against the TNC 320/640 cycle
//! manuals' parameter pages]; move sequences as those manuals describe
//! them, every point they leave open marked `[?]` (also in
//! `docs/heidenhain-cycles.md`).

use super::cycles_geom::{geometry, Place, Qs};
use super::cycles_run::Done;
use crate::canon::Canon;
use crate::diag::Diagnostic;
use crate::interp::host::{MotionHost, SpindleDir};

/// Restarts the spindle as it was before the cycle.
pub(super) fn restore_spindle(host: &mut dyn MotionHost, before: SpindleDir) {
    host.emit(match before {
        SpindleDir::Cw => Canon::SpindleCw,
        SpindleDir::Ccw => Canon::SpindleCcw,
        SpindleDir::Stopped => Canon::StopSpindle,
    });
}

fn orient(host: &mut dyn MotionHost, angle: f64, before: SpindleDir) {
    host.emit(Canon::StopSpindle);
    let mode = match before {
        SpindleDir::Ccw => 3,
        SpindleDir::Cw | SpindleDir::Stopped => 2,
    };
    host.emit(Canon::OrientSpindle { angle, mode });
}

/// 204: in through the pre-bored hole with the spindle oriented and the
/// tool off centre, bore upwards from below, out the same way.
///
/// * Q249 counterbore depth above the workpiece underside (Q203 - Q250),
///   Q252 the height of the cutting edge above the tool tip: the tool tip
///   starts with the edge Q200 below the underside and bores up until the
///   edge is Q249 above it.
/// * Q214 disengaging direction: 1 -X, 2 -Y, 3 +X, 4 +Y (working plane
///   axes) by Q251; Q336 the orientation angle.
/// * [?] The orientation is written as a spindle stop and an oriented stop
///   in the spindle's direction (as LinuxCNC's G87); the moves to and from
///   the offset position at the bottom and the way out go at Q253, the
///   offset at the top is a rapid; the spindle restarts in its direction
///   before the cycle (clockwise if it was stopped) to bore, and is set as
///   it was before the cycle at the end, back over the centre.
pub(super) fn back_bore(host: &mut dyn MotionHost, q: &Qs) -> Result<Done, Diagnostic> {
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let depth = q.need(249, "depth of counterbore")?;
    let thick = q.need(250, "material thickness")?.abs();
    let off = q.need(251, "off-centre distance")?.abs();
    let edge = q.need(252, "tool edge height")?.abs();
    let pre = q.feed(253, "feed rate for pre-positioning")?;
    let bore = q.feed(254, "feed rate for counterboring")?;
    q.need(214, "disengaging direction")?;
    let dir = q.choice(214, 1, &[1, 2, 3, 4])?;
    let angle = q.or(336, 0.0);
    let under = top - thick;
    let low = under - q.need(200, "set-up clearance")?.abs() - edge;
    let high = under + depth - edge;
    if high <= low {
        return Err(geometry(format!(
            "cycle 204: the counterbore ends at {} below where the cutting edge starts ({})",
            under + depth,
            low + edge
        )));
    }
    let (du, dv) = match dir {
        1 => (-off, 0.0),
        2 => (0.0, -off),
        3 => (off, 0.0),
        _ => (0.0, off),
    };
    let mut done = Done::default();
    let p = Place::here(host);
    let before = host.spindle();
    p.rapid_w(host, safe);
    orient(host, angle, before);
    p.rapid(host, du, dv, safe);
    done.set_feed(host, pre);
    p.feed(host, du, dv, low);
    p.feed(host, 0.0, 0.0, low);
    host.emit(match before {
        SpindleDir::Ccw => Canon::SpindleCcw,
        _ => Canon::SpindleCw,
    });
    done.set_feed(host, bore);
    p.feed(host, 0.0, 0.0, high);
    let dwell = q.or(255, 0.0);
    if dwell > 0.0 {
        host.dwell(dwell);
    }
    done.set_feed(host, pre);
    p.feed(host, 0.0, 0.0, low);
    orient(host, angle, before);
    p.feed(host, du, dv, low);
    p.feed(host, du, dv, safe);
    p.rapid(host, du, dv, clear);
    p.rapid(host, 0.0, 0.0, clear);
    restore_spindle(host, before);
    Ok(done)
}

/// 209: rigid tapping in steps of Q257 from the surface; after each step
/// the spindle reverses and the tool backs off Q256 x pitch (Q256 = 0:
/// out to the set-up clearance), then goes on. [K: Q256's meaning from
/// the TNC 320/640 cycle manuals.]
///
/// Written as spindle-synchronised feed moves (`START_SPEED_FEED_SYNC`,
/// as LinuxCNC's G33) with the spindle reversed for each way out, since
/// LinuxCNC's `RIGID_TAP` always returns to its start [?]. The spindle
/// turns clockwise for a right-hand thread (Q239 > 0), else
/// counter-clockwise; Q336 orients it first when given [?: the TNC
/// orients it always, to the angle 0 when Q336 is absent on older
/// software]; Q403 (retraction speed factor) is not applied (W0514).
pub(super) fn tap_chip_breaking(host: &mut dyn MotionHost, q: &Qs) -> Result<Done, Diagnostic> {
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let bottom = q.bottom("depth of thread")?;
    let pitch = q.need(239, "thread pitch")?;
    if pitch == 0.0 {
        return Err(geometry("cycle 209: the pitch Q239 is 0".into()));
    }
    let step = q.or(257, 0.0).abs();
    let back = q.or(256, 0.0).abs() * pitch.abs();
    let before = host.spindle();
    let p = Place::here(host);
    p.rapid_w(host, safe);
    if let Some(a) = q.get(336) {
        orient(host, a, before);
    }
    let (fwd, rev) = if pitch > 0.0 {
        (Canon::SpindleCw, Canon::SpindleCcw)
    } else {
        (Canon::SpindleCcw, Canon::SpindleCw)
    };
    host.emit(fwd.clone());
    host.emit(Canon::StartSpeedFeedSync {
        pitch: pitch.abs(),
        velocity_mode: false,
    });
    if step > 0.0 && (top - bottom) / step > 10_000.0 {
        return Err(geometry(format!(
            "cycle 209: more than 10000 chip-breaking steps of Q257={step}"
        )));
    }
    let mut depths = Vec::new();
    if step > 0.0 {
        let mut d = top - step;
        while d > bottom + 1e-9 {
            depths.push(d);
            d -= step;
        }
    }
    for d in depths {
        p.feed_w(host, d);
        host.emit(rev.clone());
        p.feed_w(host, if back > 0.0 { d + back } else { safe });
        host.emit(fwd.clone());
    }
    p.feed_w(host, bottom);
    host.emit(rev);
    p.feed_w(host, safe);
    host.emit(Canon::StopSpeedFeedSync);
    restore_spindle(host, before);
    p.rapid_w(host, clear);
    Ok(Done::default())
}

/// 241: single-lip deep-hole drilling.
///
/// 1. rapid to the set-up clearance; spindle on at the entry speed Q427
///    in the direction Q426 (3 M3, 4 M4, 5 stopped);
/// 2. at Q253 down to the deepened starting point Q203 - Q379 [?: the
///    TNC stops the set-up clearance above it on some software versions];
/// 3. drilling speed Q428 (clockwise when Q426 is 5 [?]), coolant on
///    with Q429; drill at Q206 to the depth, dwelling Q211 at the dwell
///    depth Q435 (from the surface, when less than the depth) and at the
///    bottom [?: the bottom dwell is described for chip breaking];
/// 4. coolant off with Q430, exit speed Q427, out at Q208 (0: Q206 [?])
///    to the set-up clearance, rapid to the 2nd set-up clearance; the
///    spindle speed and direction before the cycle are set again [?].
pub(super) fn single_lip(host: &mut dyn MotionHost, q: &Qs) -> Result<Done, Diagnostic> {
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let bottom = q.bottom("depth")?;
    let drill = q.feed(206, "feed rate for plunging")?;
    let start = top - q.or(379, 0.0).abs();
    if start < bottom {
        return Err(geometry(format!(
            "cycle 241: the deepened starting point {start} lies below the depth {bottom}"
        )));
    }
    let dir = q.choice(426, 3, &[3, 4, 5])?;
    let (speed, before) = (host.spindle_speed(), host.spindle());
    let mut done = Done::default();
    let p = Place::here(host);
    p.rapid_w(host, safe);
    spin(host, q.get(427), dir);
    if start < safe {
        done.set_feed(host, q.feed(253, "feed rate for pre-positioning")?);
        p.feed_w(host, start);
    }
    spin(host, q.get(428), if dir == 5 { 3 } else { dir });
    done.coolant(host, q.or(429, 0.0));
    done.set_feed(host, drill);
    let dwell = q.or(211, 0.0);
    let stop = top - q.or(435, 0.0).abs();
    if q.or(435, 0.0) != 0.0 && stop > bottom && stop < start {
        p.feed_w(host, stop);
        if dwell > 0.0 {
            host.dwell(dwell);
        }
    }
    p.feed_w(host, bottom);
    if dwell > 0.0 {
        host.dwell(dwell);
    }
    done.coolant(host, q.or(430, 0.0));
    spin(host, q.get(427), if dir == 5 { 3 } else { dir });
    let out = q.or(208, 0.0);
    done.set_feed(host, if out > 0.0 { out } else { drill });
    p.feed_w(host, safe);
    p.rapid_w(host, clear);
    if speed > 0.0 && (q.get(427).is_some() || q.get(428).is_some()) {
        host.emit(Canon::SetSpindleSpeed(speed));
    }
    restore_spindle(host, before);
    Ok(done)
}

/// Spindle speed (when given and positive) and direction 3, 4 or 5.
fn spin(host: &mut dyn MotionHost, speed: Option<f64>, dir: i64) {
    if let Some(s) = speed.filter(|s| *s > 0.0) {
        host.emit(Canon::SetSpindleSpeed(s));
    }
    host.emit(match dir {
        4 => Canon::SpindleCcw,
        5 => Canon::StopSpindle,
        _ => Canon::SpindleCw,
    });
}
