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

#[cfg(test)]
mod tests {
    use super::super::run_named_drill_cycle;
    use super::super::testhost::RecHost;
    use crate::interp::host::SpindleDir;

    fn run(args: &[Option<f64>], spindle: SpindleDir) -> String {
        let mut h = RecHost::new();
        h.spindle = spindle;
        h.pos = [10.0, 20.0, 50.0, 0.0, 0.0, 0.0];
        match run_named_drill_cycle(&mut h, "CYCLE840", args) {
            Ok(()) => h.text(),
            Err(d) => format!("error: {}", d.message),
        }
    }

    #[test]
    fn feeds_in_reverses_and_feeds_out() {
        // RTP 10, RFP 0, SDIS 2, DP -8, DTB 0.5, SDR 0, SDAC 3, ENC 1.
        let a = [10.0, 0.0, 2.0, -8.0, 0.0, 0.5, 0.0, 3.0, 1.0].map(Some);
        let t = run(&a, SpindleDir::Cw);
        let want = [
            "STRAIGHT_FEED(10.0000, 20.0000, -8.0000",
            "DWELL(0.5000)",
            "STOP_SPINDLE_TURNING",
            "START_SPINDLE_COUNTERCLOCKWISE",
            "STRAIGHT_FEED(10.0000, 20.0000, 2.0000",
            "START_SPINDLE_CLOCKWISE",
        ];
        let mut at = 0;
        for w in want {
            let i = t[at..]
                .find(w)
                .unwrap_or_else(|| panic!("no {w} after {at} in\n{t}"));
            at += i + w.len();
        }
        assert!(!t.contains("SPEED_FEED_SYNC"), "{t}");
    }

    #[test]
    fn a_pitch_with_an_encoder_synchronises_and_a_stopped_spindle_is_an_error() {
        // ENC 0, PIT 1.25.
        let mut a = vec![
            Some(10.0),
            Some(0.0),
            Some(2.0),
            Some(-8.0),
            None,
            None,
            None,
            None,
        ];
        a.extend([Some(0.0), None, Some(1.25)]);
        let t = run(&a, SpindleDir::Cw);
        assert!(t.contains("START_SPEED_FEED_SYNC(1.2500"), "{t}");
        assert!(t.contains("STOP_SPEED_FEED_SYNCH()"), "{t}");
        let t = run(&a, SpindleDir::Stopped);
        assert!(t.starts_with("error: spindle not turning"), "{t}");
    }
}
