//! Heidenhain cycles 208 BORE MILLING and 262 THREAD MILLING: helices
//! about the hole centre (the tool position when called), the tool centre
//! on the circle of the nominal diameter less the tool radius.
//!
//! Both approach the circle from the centre on a semicircle of half its
//! radius, which meets it tangentially [K: "moves on a semicircle", TNC
//! cycle manuals], and 262 leaves it the same way. Climb milling (Q351
//! +1, the default when absent [?]) with the spindle turning M3 runs
//! counter-clockwise inside a hole [K]; up-cut (-1) clockwise. The
//! spindle is assumed to turn M3 [?].

use super::cycles_geom::{geometry, need_radius, Place, Qs};
use super::cycles_run::Done;
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

/// Most helix turns one call may produce.
const MAX_TURNS: f64 = 100_000.0;

fn turns_within(number: u32, n: f64) -> Result<(), Diagnostic> {
    if n > MAX_TURNS {
        return Err(geometry(format!(
            "cycle {number}: more than {MAX_TURNS} helix turns"
        )));
    }
    Ok(())
}

/// The semicircle from the centre onto the circle of radius `rp` at
/// (rp, 0), or back (`out`), turning `ccw`.
fn semicircle(host: &mut dyn MotionHost, p: &Place, rp: f64, ccw: bool, out: bool) {
    let w = p.w(host);
    let (u, v) = if out { (0.0, 0.0) } else { (rp, 0.0) };
    p.arc(host, u, v, w, rp / 2.0, 0.0, ccw);
}

/// 208: helical bore milling. From the set-up clearance the tool goes
/// down Q334 per turn to the depth [?: the helix starts at the set-up
/// clearance, not at the surface], ends the last turn where the depth is
/// reached (part of a turn), cuts one full circle at the depth, goes
/// straight back to the centre and rapid out.
///
/// Q335 nominal diameter; Q342 pre-drilled diameter: when 0, the TNC
/// refuses a nominal diameter over twice the tool diameter [K], and so
/// does this run (E0524). A tool as wide as the hole plunges straight.
pub(super) fn bore_mill(host: &mut dyn MotionHost, q: &Qs, r: f64) -> Result<Done, Diagnostic> {
    let r = need_radius(208, r)?;
    let (safe, clear) = (q.safe()?, q.clear()?);
    let bottom = q.bottom("depth")?;
    let d = q.need(335, "nominal diameter")?.abs();
    let infeed = q.need(334, "infeed per helix")?.abs();
    let feed = q.feed(206, "feed rate for plunging")?;
    let rp = d / 2.0 - r;
    if rp < -1e-9 {
        return Err(geometry(format!(
            "cycle 208: the tool (diameter {}) is wider than the hole (Q335={d})",
            2.0 * r
        )));
    }
    if q.or(342, 0.0) == 0.0 && d > 4.0 * r + 1e-9 {
        return Err(geometry(format!(
            "cycle 208: the hole (Q335={d}) is more than twice the tool diameter {} and no pre-drilled diameter Q342 is given",
            2.0 * r
        )));
    }
    if infeed == 0.0 {
        return Err(geometry("cycle 208: the infeed per helix Q334 is 0".into()));
    }
    let ccw = q.or(351, 1.0) >= 0.0;
    let mut done = Done::default();
    let p = Place::here(host);
    p.rapid_w(host, safe);
    done.set_feed(host, feed);
    if rp <= 1e-9 {
        p.feed_w(host, bottom);
        p.rapid_w(host, clear);
        return Ok(done);
    }
    semicircle(host, &p, rp, ccw, false);
    let turns = (safe - bottom) / infeed;
    turns_within(208, turns)?;
    let full = (turns - 1e-9).floor().max(0.0) as usize;
    for k in 1..=full {
        p.arc(host, rp, 0.0, safe - k as f64 * infeed, 0.0, 0.0, ccw);
    }
    let rest = turns - full as f64;
    let a = rest * std::f64::consts::TAU * if ccw { 1.0 } else { -1.0 };
    let (s, c) = a.sin_cos();
    let end = if rest >= 1.0 - 1e-9 {
        (rp, 0.0)
    } else {
        (rp * snap(c), rp * snap(s))
    };
    p.arc(host, end.0, end.1, bottom, 0.0, 0.0, ccw);
    p.arc(host, end.0, end.1, bottom, 0.0, 0.0, ccw);
    p.feed(host, 0.0, 0.0, bottom);
    p.rapid_w(host, clear);
    Ok(done)
}

fn snap(v: f64) -> f64 {
    crate::geom::snap(v)
}

/// 262: internal thread milling.
///
/// Direction [K]: climb milling runs counter-clockwise (M3); a helix
/// counter-clockwise rising is right-hand, so a right-hand thread
/// (positive Q239) climb-milled goes up from the bottom, up-cut goes down
/// from the top; a left-hand thread the other way.
///
/// Q355 threads per step [K]: 0 one 360° helix over the thread depth (a
/// cutter as long as the thread); 1 one continuous helix over the whole
/// depth; n > 1 several 360° helices, n pitches apart, each approached
/// and left on its semicircle. [?] The passes cover the depth from the
/// bottom, the continuous helix a whole number of turns (it may end above
/// the surface); the tool moves at Q253 from the set-up clearance to each
/// pass's start at the centre, approaches at Q512 (Q207 when absent or 0
/// [?]), mills at Q207 (the tool centre's feed [?]).
pub(super) fn thread_mill(host: &mut dyn MotionHost, q: &Qs, r: f64) -> Result<Done, Diagnostic> {
    let r = need_radius(262, r)?;
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let bottom = q.bottom("thread depth")?;
    let d = q.need(335, "nominal diameter")?.abs();
    let pitch = q.need(239, "thread pitch")?;
    let per = q.or(355, 0.0);
    let pre = q.feed(253, "feed rate for pre-positioning")?;
    let mill = q.feed(207, "feed rate for milling")?;
    let approach = q.get(512).filter(|f| *f > 0.0).unwrap_or(mill);
    let rp = d / 2.0 - r;
    if rp <= 1e-9 || pitch == 0.0 {
        return Err(geometry(format!(
            "cycle 262: a thread of diameter {d} and pitch {pitch} cannot be milled with a tool of diameter {}",
            2.0 * r
        )));
    }
    if per < 0.0 || per.fract() != 0.0 {
        return Err(super::cycles_geom::bad_value(262, 355, per));
    }
    let (p_abs, depth) = (pitch.abs(), top - bottom);
    let ccw = q.or(351, 1.0) >= 0.0;
    let up = (pitch > 0.0) == ccw;
    let passes = thread_passes(per, p_abs, depth);
    turns_within(
        262,
        passes.len() as f64 * passes.first().map_or(1.0, |x| x.1 as f64),
    )?;
    let mut done = Done::default();
    let p = Place::here(host);
    p.rapid_w(host, safe);
    let order: Vec<(f64, usize)> = if up {
        passes.iter().map(|(s, n)| (bottom + s, *n)).collect()
    } else {
        passes.iter().rev().map(|(s, n)| (bottom + s, *n)).collect()
    };
    for (low, n) in order {
        let rise = p_abs * n as f64;
        let (from, to) = if up {
            (low, low + rise)
        } else {
            (low + rise, low)
        };
        done.set_feed(host, pre);
        p.feed(host, 0.0, 0.0, from);
        done.set_feed(host, approach);
        semicircle(host, &p, rp, ccw, false);
        done.set_feed(host, mill);
        for k in 1..=n {
            let w = from + (to - from) * k as f64 / n as f64;
            p.arc(host, rp, 0.0, w, 0.0, 0.0, ccw);
        }
        done.set_feed(host, approach);
        semicircle(host, &p, rp, ccw, true);
    }
    p.rapid_w(host, safe);
    p.rapid_w(host, clear);
    Ok(done)
}

/// The passes of 262 as (height of the lower end above the bottom, number
/// of turns).
fn thread_passes(per: f64, pitch: f64, depth: f64) -> Vec<(f64, usize)> {
    if per == 1.0 {
        let n = (depth / pitch - 1e-9).ceil().clamp(1.0, MAX_TURNS + 1.0);
        return vec![(0.0, n as usize)];
    }
    if per == 0.0 {
        return vec![(0.0, 1)];
    }
    let step = per * pitch;
    let m = (depth / step - 1e-9).ceil().clamp(1.0, MAX_TURNS + 1.0) as usize;
    (0..m).map(|i| (i as f64 * step, 1)).collect()
}
