//! Siemens `CYCLE840` (RTP, RFP, SDIS, DP, DPR, DTB, SDR, SDAC, ENC, MPIT,
//! PIT, ...): tapping with a compensating (floating) chuck. Heidenhain's
//! `CYCL DEF 206` runs through it (see `heidenhain::mapping`).
//!
//! The moves, after the pattern of G84: feed from RFP+SDIS to the depth,
//! dwell DTB, stop the spindle and turn it the other way (SDR 3 or 4, or
//! 0: the reverse of the direction it turned in), feed back to RFP+SDIS,
//! then the spindle as SDAC says (3, 4, 5; else the direction before).
//! With an encoder (ENC 0) and a pitch (PIT, or MPIT as a metric coarse
//! size) the feed is synchronised with the spindle, one pitch a
//! revolution [?: the control's own choice of feed]; without (ENC 1, or
//! no pitch) the feed is the active F, as a floating chuck takes it.
//! A spindle that is not turning is an error, as for G84.

use super::frame::Frame;
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::{MotionHost, SpindleDir};

/// Runs the cycle at `at`, from `safe` (RFP + SDIS) down to `depth`.
pub(super) fn run(
    host: &mut dyn MotionHost,
    f: Frame,
    at: (f64, f64),
    safe: f64,
    depth: f64,
    a: &dyn Fn(usize) -> Option<f64>,
    pitch: Option<f64>,
) -> Result<(), Diagnostic> {
    let before = host.spindle();
    if before == SpindleDir::Stopped {
        return Err(Diagnostic::new(
            Code::CycleSpindleState,
            "spindle not turning in CYCLE840",
        )
        .help("start the spindle (M3 for a right-hand tap, M4 for a left-hand one) before the cycle"));
    }
    let encoder = a(8).is_none_or(|v| v == 0.0);
    let sync = pitch.filter(|p| encoder && *p != 0.0);
    if let Some(p) = sync {
        host.emit(Canon::StartSpeedFeedSync {
            pitch: p.abs(),
            velocity_mode: false,
        });
    }
    f.feed(host, at, depth);
    if let Some(t) = a(5).filter(|t| *t > 0.0) {
        host.dwell(t);
    }
    host.emit(Canon::StopSpindle);
    host.emit(match (a(6).map(|v| v as i64), before) {
        (Some(3), _) => Canon::SpindleCw,
        (Some(4), _) => Canon::SpindleCcw,
        (_, SpindleDir::Ccw) => Canon::SpindleCw,
        _ => Canon::SpindleCcw,
    });
    f.feed(host, at, safe);
    if sync.is_some() {
        host.emit(Canon::StopSpeedFeedSync);
    }
    host.emit(Canon::StopSpindle);
    host.emit(match (a(7).map(|v| v as i64), before) {
        (Some(5), _) => return Ok(()),
        (Some(3), _) | (_, SpindleDir::Cw) => Canon::SpindleCw,
        _ => Canon::SpindleCcw,
    });
    Ok(())
}
