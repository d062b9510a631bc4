//! Siemens 840D drilling cycles CYCLE81..CYCLE89 expanded into moves.
//!
//! Sources: parameter lists and meanings from `reference/dialects.md` §1.7
//! (classic SINUMERIK cycle documentation, Fusion post, real programs);
//! the move sequences follow the classic "Cycles" programming manual as
//! remembered, which is not at hand: every point not confirmed by the
//! parameter tables is marked `[?]`.
//!
//! Common to all: the cycle starts at the hole position in the plane;
//! rapid along the tool axis to RFP+SDIS, drill at the active feed to the
//! depth (DPR, unsigned, below RFP when given and not 0, else DP absolute
//! [?: DPR=0 counts as "not given", as programs write `CYCLE81(..,DP,0)`]),
//! and rapid back to RTP. The tool axis is the normal of the active plane
//! and drilling goes towards smaller values (RFP above the depth).

use super::frame::Frame;
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::host::{MotionHost, SpindleDir};

/// The common geometry of one call.
struct Hole {
    f: Frame,
    at: (f64, f64),
    rtp: f64,
    rfp: f64,
    safe: f64,
    depth: f64,
}

fn bad(msg: String) -> Diagnostic {
    Diagnostic::new(Code::CycleBadArgument, msg)
        .help("check the cycle's arguments: RTP, RFP, SDIS, DP, DPR, ...")
}

fn hole(
    host: &dyn MotionHost,
    name: &str,
    a: &dyn Fn(usize) -> Option<f64>,
) -> Result<Hole, Diagnostic> {
    let f = Frame::of(host);
    let (at, _) = f.here(host);
    let rtp = a(0).ok_or_else(|| bad(format!("{name}: RTP (retract plane) missing")))?;
    let rfp = a(1).ok_or_else(|| bad(format!("{name}: RFP (reference plane) missing")))?;
    let sdis = a(2).unwrap_or(0.0).abs();
    let depth = match (a(3), a(4)) {
        (_, Some(dpr)) if dpr != 0.0 => rfp - dpr.abs(),
        (Some(dp), _) => dp,
        _ => return Err(bad(format!("{name}: no depth (DP or DPR)"))),
    };
    if depth > rfp {
        return Err(bad(format!(
            "{name}: depth {depth} lies above the reference plane {rfp}"
        )));
    }
    Ok(Hole {
        f,
        at,
        rtp,
        rfp,
        safe: rfp + sdis,
        depth,
    })
}

/// Runs `CYCLE81`..`CYCLE89` at the current position. `args` are the
/// call's arguments in order (None: empty slot); extra ones are ignored.
pub fn run_named_drill_cycle(
    host: &mut dyn MotionHost,
    name: &str,
    args: &[Option<f64>],
) -> Result<(), Diagnostic> {
    let a = |i: usize| args.get(i).copied().flatten();
    let upper = name.to_ascii_uppercase();
    let h = hole(host, &upper, &a)?;
    let f = h.f;
    f.rapid(host, h.at, h.safe);
    match upper.as_str() {
        "CYCLE81" => f.feed(host, h.at, h.depth),
        "CYCLE82" => {
            f.feed(host, h.at, h.depth);
            dwell(host, a(5));
        }
        "CYCLE83" => deep_hole(host, &h, &a)?,
        "CYCLE84" => rigid_tap(host, &h, &a)?,
        "CYCLE840" => {
            let pitch = a(10)
                .filter(|p| *p != 0.0)
                .or_else(|| a(9).and_then(|m| metric_pitch(m.abs()).map(|p| p.copysign(m))));
            super::float_tap::run(host, f, h.at, h.safe, h.depth, &a, pitch)?
        }
        "CYCLE85" => bore_feed_out(host, &h, a(5), a(6), a(7)),
        "CYCLE86" => bore_oriented(host, &h, &a),
        "CYCLE87" | "CYCLE88" => bore_manual(host, &h, &a, upper == "CYCLE88"),
        "CYCLE89" => bore_feed_out(host, &h, a(5), None, None),
        _ => {
            return Err(bad(format!(
                "{name} is not a drilling cycle (CYCLE81..CYCLE89)"
            )))
        }
    }
    if f.here(host) != (h.at, h.rtp) {
        f.rapid(host, h.at, h.rtp);
    }
    Ok(())
}

fn dwell(host: &mut dyn MotionHost, t: Option<f64>) {
    if let Some(t) = t.filter(|t| *t > 0.0) {
        host.dwell(t);
    }
}

fn set_feed(host: &mut dyn MotionHost, feed: f64) {
    host.emit(Canon::SetFeedRate(feed));
}

/// CYCLE85 (DTB, FFR in, RFF out) and CYCLE89 (DTB, feed out at the
/// active feed): feed in, dwell, feed back to RFP+SDIS. [?] FFR/RFF of 0
/// mean "the active feed"; the active feed is set again afterwards.
fn bore_feed_out(
    host: &mut dyn MotionHost,
    h: &Hole,
    dtb: Option<f64>,
    ffr: Option<f64>,
    rff: Option<f64>,
) {
    let active = host.feed_rate();
    let ffr = ffr.filter(|v| *v > 0.0);
    let rff = rff.filter(|v| *v > 0.0);
    if let Some(v) = ffr {
        set_feed(host, v);
    }
    h.f.feed(host, h.at, h.depth);
    dwell(host, dtb);
    if let Some(v) = rff {
        set_feed(host, v);
    }
    h.f.feed(host, h.at, h.safe);
    if ffr.is_some() || rff.is_some() {
        set_feed(host, active);
    }
}

fn spindle_call(sdir: Option<f64>, before: SpindleDir) -> Canon {
    match sdir.map(|v| v as i64) {
        Some(4) => Canon::SpindleCcw,
        Some(3) => Canon::SpindleCw,
        _ if before == SpindleDir::Ccw => Canon::SpindleCcw,
        _ => Canon::SpindleCw,
    }
}

/// CYCLE86 (RTP, RFP, SDIS, DP, DPR, DTB, SDIR, RPA, RPO, RPAP, POSS):
/// drill, dwell DTB, oriented stop at POSS, lift off by RPA/RPO/RPAP (one
/// rapid, incremental) [?], rapid to RTP, back to the hole centre in the
/// plane [?], restart the spindle in SDIR.
fn bore_oriented(host: &mut dyn MotionHost, h: &Hole, a: &dyn Fn(usize) -> Option<f64>) {
    let before = host.spindle();
    let v = |i| a(i).unwrap_or(0.0);
    h.f.feed(host, h.at, h.depth);
    dwell(host, a(5));
    let mode = if before == SpindleDir::Ccw { 3 } else { 2 };
    host.emit(Canon::OrientSpindle { angle: v(10), mode });
    let off = (h.at.0 + v(7), h.at.1 + v(8));
    h.f.rapid(host, off, h.depth + v(9));
    h.f.rapid(host, off, h.rtp);
    h.f.rapid(host, h.at, h.rtp);
    host.emit(spindle_call(a(6), before));
}

/// CYCLE87 (…, SDIR) and CYCLE88 (…, DTB, SDIR): drill, [88: dwell DTB],
/// spindle stop, program stop (the operator retracts); the rapid to RTP
/// follows after NC start. [?] The spindle is not restarted by the cycle;
/// SDIR only states the direction the boring was done in.
fn bore_manual(
    host: &mut dyn MotionHost,
    h: &Hole,
    a: &dyn Fn(usize) -> Option<f64>,
    with_dwell: bool,
) {
    h.f.feed(host, h.at, h.depth);
    if with_dwell {
        dwell(host, a(5));
    }
    host.emit(Canon::StopSpindle);
    host.emit(Canon::ProgramStop);
}

/// Metric coarse thread pitch of size M`d` (ISO 261), for MPIT.
fn metric_pitch(d: f64) -> Option<f64> {
    const T: [(f64, f64); 21] = [
        (3.0, 0.5),
        (4.0, 0.7),
        (5.0, 0.8),
        (6.0, 1.0),
        (8.0, 1.25),
        (10.0, 1.5),
        (12.0, 1.75),
        (14.0, 2.0),
        (16.0, 2.0),
        (18.0, 2.5),
        (20.0, 2.5),
        (22.0, 2.5),
        (24.0, 3.0),
        (27.0, 3.0),
        (30.0, 3.5),
        (33.0, 3.5),
        (36.0, 4.0),
        (39.0, 4.0),
        (42.0, 4.5),
        (45.0, 4.5),
        (48.0, 5.0),
    ];
    T.iter().find(|(s, _)| *s == d).map(|(_, p)| *p)
}

/// CYCLE84 rigid tapping (RTP, RFP, SDIS, DP, DPR, DTB, SDAC, MPIT, PIT,
/// POSS, SST, SST1): pitch from PIT, else from MPIT (metric size); the sign
/// gives the hand (negative: left hand, M4). Expanded as LinuxCNC's G33.1
/// (`START_SPEED_FEED_SYNC`, `RIGID_TAP`, `STOP_SPEED_FEED_SYNCH`), which
/// reverses at the bottom and returns to RFP+SDIS. [?] SST sets the speed
/// before tapping; SST1 (retract speed) and POSS (oriented stop before
/// tapping) are not expressed; DTB dwells after the tap; SDAC (3/4/5)
/// sets the spindle afterwards.
fn rigid_tap(
    host: &mut dyn MotionHost,
    h: &Hole,
    a: &dyn Fn(usize) -> Option<f64>,
) -> Result<(), Diagnostic> {
    let pit = match (a(8).filter(|v| *v != 0.0), a(7).filter(|v| *v != 0.0)) {
        (Some(p), _) => p,
        (None, Some(m)) => metric_pitch(m.abs())
            .map(|p| p.copysign(m))
            .ok_or_else(|| {
                bad(format!(
                    "CYCLE84: MPIT {m} is not a metric coarse thread size (3..48)"
                ))
            })?,
        _ => return Err(bad("CYCLE84: no pitch (MPIT or PIT)".into())),
    };
    if let Some(s) = a(10).filter(|v| *v > 0.0) {
        host.emit(Canon::SetSpindleSpeed(s));
    }
    host.emit(if pit < 0.0 {
        Canon::SpindleCcw
    } else {
        Canon::SpindleCw
    });
    host.emit(Canon::StartSpeedFeedSync {
        pitch: pit.abs(),
        velocity_mode: false,
    });
    let p = h.f.pose(host, h.at, h.depth);
    host.emit(Canon::RigidTap {
        x: p[0],
        y: p[1],
        z: p[2],
    });
    host.emit(Canon::StopSpeedFeedSync);
    dwell(host, a(5));
    match a(6).map(|v| v as i64) {
        Some(3) => host.emit(Canon::SpindleCw),
        Some(4) => host.emit(Canon::SpindleCcw),
        Some(5) => host.emit(Canon::StopSpindle),
        _ => {}
    }
    Ok(())
}

/// CYCLE83 deep-hole drilling (RTP, RFP, SDIS, DP, DPR, FDEP, FDPR, DAM,
/// DTB, DTS, FRF, VARI, _AXN, _MDEP, _VRT, _DTD, _DIS1).
///
/// * First depth FDPR (relative to RFP, wins if not 0) or FDEP, drilled at
///   F×FRF (FRF 0 = 1); later infeeds at F.
/// * DAM > 0: each infeed DAM less than the one before, never below DAM
///   [?]; DAM < 0: each infeed |DAM| % of the one before [?], not below
///   _MDEP (or 0.1 units when _MDEP is 0) [?]; DAM = 0: equal infeeds.
/// * VARI 0 (chip breaking): after each infeed back off _VRT (1 when 0)
///   at the feed [?]. VARI 1 (swarf removal): rapid out to RFP+SDIS, dwell
///   DTS, rapid back to _DIS1 above the last depth (when 0: 0.6, or
///   depth/50 up to 7, for holes deeper than 30 [?]).
/// * DTB dwells at each depth reached; _DTD at the final depth if given
///   (else DTB) [?].
fn deep_hole(
    host: &mut dyn MotionHost,
    h: &Hole,
    a: &dyn Fn(usize) -> Option<f64>,
) -> Result<(), Diagnostic> {
    let v = |i| a(i).unwrap_or(0.0);
    let first = match (a(6).filter(|x| *x != 0.0), a(5)) {
        (Some(fdpr), _) => h.rfp - fdpr.abs(),
        (None, Some(fdep)) => fdep,
        _ => h.depth,
    };
    let first_step = (h.safe - first).max(0.0);
    if first_step <= 0.0 && first > h.depth {
        return Err(bad(
            "CYCLE83: the first depth lies above the safety plane".into()
        ));
    }
    let plan = infeeds(h, first, v(7), v(13))?;
    let frf = if v(10) > 0.0 && v(10) < 1.0 {
        Some(v(10))
    } else {
        None
    };
    let active = host.feed_rate();
    let swarf = v(11) as i64 == 1;
    let vrt = if v(14) > 0.0 { v(14) } else { 1.0 };
    let dis1 = if v(16) > 0.0 {
        v(16)
    } else {
        auto_advance(h.rfp - h.depth)
    };
    for (n, depth) in plan.iter().enumerate() {
        if n == 0 {
            if let Some(k) = frf {
                host.emit(Canon::SetFeedRate(active * k));
            }
        }
        h.f.feed(host, h.at, *depth);
        if n == 0 && frf.is_some() {
            host.emit(Canon::SetFeedRate(active));
        }
        let last = n + 1 == plan.len();
        if last {
            dwell(host, a(15).filter(|t| *t > 0.0).or(a(8)));
            break;
        }
        dwell(host, a(8));
        if swarf {
            h.f.rapid(host, h.at, h.safe);
            dwell(host, a(9));
            h.f.rapid(host, h.at, depth + dis1);
        } else {
            h.f.feed(host, h.at, depth + vrt);
        }
    }
    Ok(())
}

fn auto_advance(total: f64) -> f64 {
    if total <= 30.0 {
        0.6
    } else {
        (total / 50.0).min(7.0)
    }
}

/// The depths reached, from the first to the final one.
fn infeeds(h: &Hole, first: f64, dam: f64, mdep: f64) -> Result<Vec<f64>, Diagnostic> {
    let mut out = Vec::new();
    let mut depth = first.max(h.depth);
    let mut step = (h.safe - depth).max(0.0);
    let min_step = if mdep > 0.0 { mdep } else { 0.1 };
    out.push(depth);
    while depth > h.depth {
        if out.len() > 100_000 {
            return Err(bad("CYCLE83: more than 100000 infeeds".into()));
        }
        step = if dam > 0.0 {
            (step - dam).max(dam)
        } else if dam < 0.0 {
            (step * dam.abs() / 100.0).max(min_step)
        } else {
            step
        };
        if step <= 0.0 {
            return Err(bad("CYCLE83: the first depth gives no infeed".into()));
        }
        depth = (depth - step).max(h.depth);
        out.push(depth);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interp::cycles::testhost::RecHost;

    fn run(name: &str, args: &[Option<f64>]) -> String {
        let mut h = RecHost::new();
        h.pos = [10.0, 20.0, 50.0, 0.0, 0.0, 0.0];
        match run_named_drill_cycle(&mut h, name, args) {
            Ok(()) => h.text(),
            Err(d) => format!("{}\nerror: {}", h.text(), d.message),
        }
    }

    fn s(v: &[f64]) -> Vec<Option<f64>> {
        v.iter()
            .map(|x| if x.is_nan() { None } else { Some(*x) })
            .collect()
    }

    #[test]
    fn siemens_drilling_cycles() {
        let e = f64::NAN;
        let cases: Vec<(&str, Vec<Option<f64>>)> = vec![
            // RTP 10, RFP 0, SDIS 2, DP -5 (DPR 0 = not given)
            ("CYCLE81", s(&[10.0, 0.0, 2.0, -5.0, 0.0])),
            // DPR 8 wins over DP -5; dwell 1.5 s
            ("CYCLE82", s(&[10.0, 0.0, 2.0, -5.0, 8.0, 1.5])),
            // deep hole, chip breaking: DP -10, FDEP -4, DAM 1, DTB 0, FRF 0.5, VARI 0, _VRT 0.5
            (
                "CYCLE83",
                s(&[
                    10.0, 0.0, 2.0, -10.0, e, -4.0, e, 1.0, 0.0, 0.0, 0.5, 0.0, e, e, 0.5,
                ]),
            ),
            // deep hole, swarf removal: FDPR 5, DAM 0, DTS 0.2, VARI 1, _DIS1 1
            (
                "CYCLE83",
                s(&[
                    10.0, 0.0, 2.0, -12.0, e, e, 5.0, 0.0, 0.0, 0.2, 1.0, 1.0, e, e, e, e, 1.0,
                ]),
            ),
            // rigid tap M6 (pitch 1), SDAC 5, SST 300
            (
                "CYCLE84",
                s(&[10.0, 0.0, 2.0, -8.0, 0.0, 0.0, 5.0, 6.0, 0.0, 0.0, 300.0]),
            ),
            ("CYCLE85", s(&[10.0, 0.0, 2.0, -6.0, 0.0, 0.5, 50.0, 200.0])),
            (
                "CYCLE86",
                s(&[10.0, 0.0, 2.0, -6.0, 0.0, 0.0, 3.0, -0.5, 0.0, 1.0, 90.0]),
            ),
            ("CYCLE88", s(&[10.0, 0.0, 2.0, -6.0, 0.0, 1.0, 3.0])),
            ("CYCLE89", s(&[10.0, 0.0, 2.0, -6.0, 0.0, 2.0])),
            ("CYCLE81", s(&[10.0, 0.0, 2.0])),
        ];
        let mut out = String::new();
        for (name, args) in cases {
            out.push_str(&format!("== {name}\n{}\n", run(name, &args)));
        }
        insta::assert_snapshot!("siemens_drilling_cycles", out);
    }
}
