//! Old Heidenhain cycles 2 TAPPING (floating tap holder) and 17 RIGID
//! TAPPING, by sub-number [K: the layout `2.1` set-up clearance, `2.2`
//! total depth, `2.3` dwell, `2.4` feed and `17.1` set-up clearance,
//! `17.2` depth, `17.3` pitch is the one real programs, a public TNC
//! simulator and the Fusion post write; one teaching sheet gives cycle 2
//! the layout of cycle 1, taken to be a slip]. Like cycle 1 they start
//! where the tool is, the set-up clearance above the surface; the signs of
//! set-up clearance and depth are not used (both count downwards).
//!
//! * 2: feed to the depth, dwell, spindle reversed, feed back to the
//!   starting height, spindle as before [K: TNC manuals]; the spindle must
//!   turn (E0544).
//! * 17: spindle-synchronised rigid tap to the depth and back to the
//!   starting height (LinuxCNC's `RIGID_TAP`); the pitch's sign gives the
//!   hand (M3 for +, M4 for -), the spindle is set as before afterwards.
//!
//! Cycles 3, 4, 5 are not run (E0510): their sub-number layouts could not
//! be confirmed [?].

use super::super::siemens::FramedHost;
use super::super::{Interp, Stop};
use super::cycles_bore::restore_spindle;
use super::cycles_geom::{geometry, Place};
use super::cycles_run::{finish, Done};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::{MotionHost, SpindleDir};
use crate::span::Span;

/// Does this module run old cycle `c`?
pub(super) fn expands(c: u32) -> bool {
    matches!(c, 2 | 17)
}

/// Runs old cycle 2 or 17 at the current position.
pub(super) fn call(it: &mut Interp<'_, '_>, span: Span, cycle: u32) -> Result<(), Stop> {
    let vals: Vec<(u32, f64)> = it
        .heidenhain
        .old
        .iter()
        .filter(|((c, _), _)| *c == cycle)
        .map(|((_, s), v)| (*s, *v))
        .collect();
    let get = |s: u32| vals.iter().find(|(k, _)| *k == s).map(|(_, v)| *v);
    let need = |s: u32, what: &str| {
        get(s).ok_or_else(|| {
            Diagnostic::new(
                Code::TncCycleParameterMissing,
                format!("the old cycle {cycle} is called without {cycle}.{s} ({what})"),
            )
            .help(format!(
                "add `CYCL DEF {cycle}.{s} ...` to the cycle definition"
            ))
        })
    };
    let args = (|| -> Result<[f64; 3], Diagnostic> {
        let setup = need(1, "set-up clearance")?.abs();
        let depth = need(2, "depth")?.abs();
        let third = if cycle == 2 {
            get(3).unwrap_or(0.0)
        } else {
            need(3, "thread pitch")?
        };
        Ok([setup, depth, third])
    })();
    let feed = if cycle == 2 { get(4) } else { None };
    let saved = it.state.feed;
    let (frame, scale) = (it.siemens.frame, it.state.scale());
    let mark = it.diags.len();
    let result = args.and_then(|[setup, depth, third]| {
        let host = &mut FramedHost::new(it, frame, scale);
        match cycle {
            2 => tap(host, setup, depth, third, feed),
            _ => rigid_tap(host, setup, depth, third),
        }
    });
    finish(it, span, saved, mark, result)
}

/// Old cycle 2.
fn tap(
    host: &mut dyn MotionHost,
    setup: f64,
    depth: f64,
    dwell: f64,
    feed: Option<f64>,
) -> Result<Done, Diagnostic> {
    let before = host.spindle();
    let reverse = match before {
        SpindleDir::Cw => Canon::SpindleCcw,
        SpindleDir::Ccw => Canon::SpindleCw,
        SpindleDir::Stopped => {
            return Err(Diagnostic::new(
                Code::CycleSpindleState,
                "the old cycle 2 (tapping) is called with the spindle stopped",
            )
            .help("start the spindle (M3 for a right-hand tap) before the cycle call"))
        }
    };
    let mut done = Done::default();
    let p = Place::here(host);
    let start = p.w(host);
    if let Some(f) = feed.filter(|f| *f > 0.0) {
        done.set_feed(host, f);
    }
    p.feed_w(host, start - setup - depth);
    if dwell > 0.0 {
        host.dwell(dwell);
    }
    host.emit(reverse);
    p.feed_w(host, start);
    restore_spindle(host, before);
    Ok(done)
}

/// Old cycle 17.
fn rigid_tap(
    host: &mut dyn MotionHost,
    setup: f64,
    depth: f64,
    pitch: f64,
) -> Result<Done, Diagnostic> {
    if pitch == 0.0 {
        return Err(geometry("the old cycle 17: the pitch 17.3 is 0".into()));
    }
    let before = host.spindle();
    let p = Place::here(host);
    let start = p.w(host);
    host.emit(if pitch > 0.0 {
        Canon::SpindleCw
    } else {
        Canon::SpindleCcw
    });
    host.emit(Canon::StartSpeedFeedSync {
        pitch: pitch.abs(),
        velocity_mode: false,
    });
    let mut at = host.position();
    let (_, _, n) = crate::interp::host::plane_axes(host.plane());
    at[n] = start - setup - depth;
    host.emit(Canon::RigidTap {
        x: at[0],
        y: at[1],
        z: at[2],
    });
    host.emit(Canon::StopSpeedFeedSync);
    restore_spindle(host, before);
    Ok(Done::default())
}
