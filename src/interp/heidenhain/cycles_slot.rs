//! Heidenhain cycles 254 CIRCULAR SLOT (as the Siemens SLOT2 expansion)
//! and 256 RECTANGULAR STUD.
//!
//! 254 [K, parameter meanings]: Q375 pitch circle diameter, Q376 starting
//! angle, Q248 angular length, Q377 number of slots, Q378 stepping angle,
//! Q219 width, Q215 0 rough + finish, 1 rough, 2 finish (SLOT2's VARI
//! takes the same values), Q368 side allowance (FAL), Q202 plunging depth
//! (MID), Q206/Q207/Q385 plunging/milling/finishing feeds. Q367: 0 the
//! circle centre is Q216/Q217; 1, 2, 3 the tool stands on the centre of
//! the slot's start, middle or end [?: the manual's "left"/"right" slot
//! circle taken as the start and end of the angular length], and Q216/
//! Q217 are not used. A negative Q248 runs from Q376 + Q248 to Q376 [?].
//! Climb milling (Q351 +1) with M3 runs the slot's outline
//! counter-clockwise (SLOT2 CDIR 3) [K].
//!
//! 256: see [`stud`].

use super::cycles_geom::{geometry, need_radius, Place, Qs};
use super::cycles_run::Done;
use crate::canon::CanonUnits;
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

/// The SLOT2 arguments of a 254 definition, the tool at `here`.
pub(super) fn slot2_args(q: &Qs, here: (f64, f64)) -> Result<Vec<Option<f64>>, Diagnostic> {
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let _ = safe;
    let bottom = q.bottom("depth")?;
    let rad = q.need(375, "pitch circle diameter")?.abs() / 2.0;
    let len = q.need(248, "angular length")?;
    let start = q.need(376, "starting angle")? + len.min(0.0);
    let num = q.or(377, 1.0);
    if num < 1.0 || num.fract() != 0.0 {
        return Err(super::cycles_geom::bad_value(254, 377, num));
    }
    let centre = match q.choice(367, 0, &[0, 1, 2, 3])? {
        0 => (
            q.need(216, "centre in 1st axis")?,
            q.need(217, "centre in 2nd axis")?,
        ),
        k => {
            let a = (start + len.abs() * (k - 1) as f64 / 2.0).to_radians();
            (here.0 - rad * a.cos(), here.1 - rad * a.sin())
        }
    };
    let vari = q.choice(215, 0, &[0, 1, 2])?;
    let cdir = if q.or(351, 1.0) >= 0.0 { 3.0 } else { 2.0 };
    Ok(vec![
        Some(clear),
        Some(top),
        Some(q.need(200, "set-up clearance")?.abs()),
        Some(bottom),
        None,
        Some(num),
        Some(len.abs()),
        Some(q.need(219, "slot width")?.abs()),
        Some(centre.0),
        Some(centre.1),
        Some(rad),
        Some(start),
        Some(q.or(378, 0.0)),
        Some(q.feed(206, "feed rate for plunging")?),
        Some(q.feed(207, "feed rate for milling")?),
        q.get(202).map(f64::abs),
        Some(cdir),
        Some(q.or(368, 0.0).abs()),
        Some(vari as f64),
        q.get(338),
        q.get(385),
        None,
    ])
}

/// 256: a rectangular stud Q218 x Q219 (corner radius Q220) left standing
/// in a blank Q424 x Q425, turned by Q224 about the tool position.
///
/// * Q367 where the tool stands: 0 the centre, 1..4 the lower left, lower
///   right, upper right, upper left corner [K];
/// * per depth level (steps of Q202 from the surface, plunged at Q206 at
///   the start point 2 mm to the right of the blank [K; 2/25.4 in for inch
///   programs]) rings round the stud from the blank inwards, equal
///   stepovers of at most Q370 x tool radius [K], the last one Q368 from
///   the stud, all at Q207; each ring is reached from the start point on
///   a semicircle meeting it tangentially in the middle of its right side
///   and left on the other half of that circle back to the start point
///   [K: TNC 640 manual; the semicircle's size is not given: here its
///   diameter spans the start point and the ring [?]];
/// * climb milling (Q351 +1) runs clockwise round the stud (M3) [K];
/// * Q215 (TNC 640 software) 0 or 2: a finishing ring on the stud at the
///   depth at Q385 (Q207 when absent) when Q368 leaves something [?];
///   2 leaves out the roughing;
/// * Q437 (approach position) other than 0 is not applied (W0514).
pub(super) fn stud(host: &mut dyn MotionHost, q: &Qs, r: f64) -> Result<Done, Diagnostic> {
    let r = need_radius(256, r)?;
    let (safe, clear, top) = (q.safe()?, q.clear()?, q.surface()?);
    let bottom = q.bottom("depth")?;
    let (l, w) = (
        q.need(218, "first side length")?.abs(),
        q.need(219, "second side length")?.abs(),
    );
    let (bl, bw) = (
        q.need(424, "workpiece blank side length 1")?.abs(),
        q.need(425, "workpiece blank side length 2")?.abs(),
    );
    let (rc, allow) = (q.or(220, 0.0).abs(), q.or(368, 0.0).abs());
    if bl < l || bw < w || rc > l.min(w) / 2.0 {
        return Err(geometry(format!(
            "cycle 256: a stud {l} x {w} (corner radius {rc}) cannot be cut from a blank {bl} x {bw}"
        )));
    }
    let overlap = q.or(370, 1.0).abs();
    let step = if overlap > 0.0 { overlap } else { 1.0 } * r;
    let material = ((bl - l) / 2.0).max((bw - w) / 2.0) - allow;
    let n = (material / step - 1e-9).ceil().clamp(1.0, 10_000.0) as usize;
    let offsets: Vec<f64> = (0..n)
        .rev()
        .map(|k| r + allow + material.max(0.0) * k as f64 / n as f64)
        .collect();
    let levels = super::super::siemens::milling::levels("256", top, bottom, q.or(202, 0.0))
        .map_err(|d| geometry(format!("cycle {}", d.message)))?;
    if (levels.len() * offsets.len()) as f64 > super::super::siemens::milling::MAX_PASSES {
        return Err(geometry(format!(
            "cycle 256: {} depth levels of {} rings each are more passes than cncc runs",
            levels.len(),
            offsets.len()
        )));
    }
    let corner = [
        (0.0, 0.0),
        (1.0, 1.0),
        (-1.0, 1.0),
        (-1.0, -1.0),
        (1.0, -1.0),
    ];
    let (su, sv) = corner[q.choice(367, 0, &[0, 1, 2, 3, 4])? as usize];
    let rot = q.or(224, 0.0);
    let here = Place::here(host).origin();
    let turned = Place::new(host, here, rot);
    let centre = turned.point(su * l / 2.0, sv * w / 2.0);
    let p = Place::new(host, centre, rot);
    let two_mm = match host.units() {
        CanonUnits::Inches => 2.0 / 25.4,
        _ => 2.0,
    };
    let (start, ccw) = (bl / 2.0 + r + two_mm, q.or(351, 1.0) < 0.0);
    let ops = q.choice(215, 1, &[0, 1, 2])?;
    let mut done = Done::default();
    let h = p.w(host);
    p.rapid(host, start, 0.0, h);
    p.rapid_w(host, safe);
    let (plunge, mill) = (
        q.feed(206, "feed rate for plunging")?,
        q.feed(207, "feed rate for milling")?,
    );
    if ops != 2 {
        for lv in &levels {
            done.set_feed(host, plunge);
            p.feed(host, start, 0.0, *lv);
            done.set_feed(host, mill);
            for o in &offsets {
                let r = Ring {
                    hu: l / 2.0 + o,
                    hv: w / 2.0 + o,
                    rc: rc + o,
                };
                r.cut_from(host, &p, start, ccw);
            }
        }
    }
    if ops != 1 && (allow > 0.0 || ops == 2) {
        done.set_feed(host, plunge);
        p.feed(host, start, 0.0, bottom);
        done.set_feed(host, q.get(385).filter(|f| *f > 0.0).unwrap_or(mill));
        let fin = Ring {
            hu: l / 2.0 + r,
            hv: w / 2.0 + r,
            rc: rc + r,
        };
        fin.cut_from(host, &p, start, ccw);
    }
    p.rapid_w(host, clear);
    Ok(done)
}

/// A ring round the stud: half sizes and corner radius.
struct Ring {
    hu: f64,
    hv: f64,
    rc: f64,
}

impl Ring {
    /// From the start point (`start`, 0) on a semicircle that meets the
    /// ring tangentially in the middle of its right side, once round, and
    /// back to the start point on the other half of that circle.
    fn cut_from(&self, host: &mut dyn MotionHost, p: &Place, start: f64, ccw: bool) {
        let w = p.w(host);
        let c = (start + self.hu) / 2.0;
        p.arc(host, self.hu, 0.0, w, c, 0.0, !ccw);
        ring(host, p, self.hu, self.hv, self.rc, ccw);
        p.arc(host, start, 0.0, w, c, 0.0, !ccw);
    }
}

/// One rounded rectangle ring from and back to (hu, 0).
fn ring(host: &mut dyn MotionHost, p: &Place, hu: f64, hv: f64, rc: f64, ccw: bool) {
    let w = p.w(host);
    let s = if ccw { 1.0 } else { -1.0 };
    p.feed(host, hu, 0.0, w);
    // The corners in the order met, as signs of (u, v).
    let corners = [(1.0, s), (-1.0, s), (-1.0, -s), (1.0, -s)];
    for (k, (cu, cv)) in corners.iter().enumerate() {
        let (ccu, ccv) = (cu * (hu - rc), cv * (hv - rc));
        let along_v = k % 2 == 0;
        let (iu, iv, ou, ov) = if along_v {
            (cu * hu, ccv, ccu, cv * hv)
        } else {
            (ccu, cv * hv, cu * hu, ccv)
        };
        p.feed(host, iu, iv, w);
        if rc > 0.0 {
            p.arc(host, ou, ov, w, ccu, ccv, ccw);
        }
    }
    p.feed(host, hu, 0.0, w);
}
