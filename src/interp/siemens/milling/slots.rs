//! Slots on a circle: SLOT1 (radial slots), SLOT2 (circumferential
//! slots) and LONGHOLE (elongated holes as wide as the tool).
//!
//! SLOT1: RTP, RFP, SDIS, DP, DPR, NUM, LENG, WID, CPA, CPO, RAD, STA1,
//! INDA, FFD, FFP1, MID, CDIR, FAL, VARI, MIDF, FFP2, SSF [K] (the last
//! three, _FALD _STA2 _DP1, are not read [?]).
//! SLOT2: RTP, RFP, SDIS, DP, DPR, NUM, AFSL, WID, CPA, CPO, RAD, STA1,
//! INDA, FFD, FFP1, MID, CDIR, FAL, VARI, MIDF, FFP2, SSF [K] (_FFCP is not
//! read [?]).
//! LONGHOLE: RTP, RFP, SDIS, DP, DPR, NUM, LENG, CPA, CPO, RAD, STA1, INDA,
//! FFD, FFP1, MID [K].
//!
//! Choices, each [?] (the parameters are documented, the paths are not):
//! * element k lies at the angle STA1 + k·INDA about (CPA, CPO); INDA 0
//!   spreads the elements evenly over the full circle (as HOLES2);
//! * SLOT1 and LONGHOLE: RAD is the distance from the centre to the
//!   element's inner end; it reaches out LENG from there (round ends
//!   included). A SLOT1 slot is cut like a POCKET1 pocket of LENG × WID
//!   with corner radius WID/2; a LONGHOLE is cut by plunging FFD at one end
//!   and feeding FFP1 to the other, turning round at each depth level;
//! * SLOT2: the slot's centre line is the arc of radius RAD from STA1 over
//!   AFSL degrees (counter-clockwise; the sign of AFSL is ignored), its
//!   ends round. Per depth level the tool plunges at the start of the
//!   centre line and cuts closed rings from the centre line outwards, one
//!   tool radius apart, the last FAL inside the slot; finishing cuts the
//!   slot's outline at the full depth. CDIR 3 runs the outer arc G3, any
//!   other value G2. MIDF is not used.

use super::pen::Pen;
use super::pocket::{common, run, Pocket, Ring};
use super::{bad, levels, Args, MAX_PASSES};
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

/// The angles of the NUM elements.
fn angles(
    name: &str,
    a: &Args,
    num: usize,
    sta: usize,
    inda: usize,
) -> Result<Vec<f64>, Diagnostic> {
    let n = a.get(num);
    if n < 1.0 || n.fract() != 0.0 || n > 10_000.0 {
        return Err(bad(format!(
            "{name}: NUM must be a whole number from 1 to 10000, not {n}"
        )));
    }
    let inda = a.get(inda);
    let step = if inda == 0.0 { 360.0 / n } else { inda };
    Ok((0..n as usize)
        .map(|k| a.get(sta) + k as f64 * step)
        .collect())
}

/// SLOT1: radial slots, each a LENG × WID pocket with round ends.
pub fn slot1(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let p = common("SLOT1", a, 13)?;
    let (len, wid) = (a.get(6).abs(), a.get(7).abs());
    if wid > len {
        return Err(bad(format!(
            "SLOT1: the width {wid} is more than the length {len}"
        )));
    }
    let (cx, cy, rad) = (a.get(8), a.get(9), a.get(10).abs());
    for deg in angles("SLOT1", a, 5, 11, 12)? {
        let mid = rad + len / 2.0;
        let (s, c) = deg.to_radians().sin_cos();
        let pen = Pen::new(host, (cx + mid * c, cy + mid * s), deg);
        let (hu, hv) = (len / 2.0 - r, wid / 2.0 - r);
        let last = Ring {
            hu,
            hv,
            rc: hv.max(0.0).min(hu.max(0.0)),
            circle: false,
        };
        run(host, pen, &p, last, r)?;
    }
    Ok(())
}

/// LONGHOLE: radial holes as wide as the tool.
pub fn longhole(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let p = common("LONGHOLE", a, 12)?;
    if r <= 0.0 {
        return Err(bad(
            "LONGHOLE: no tool radius: activate a cutting edge (D1) first".into(),
        ));
    }
    let len = a.get(6).abs();
    if len < 2.0 * r {
        return Err(bad(format!(
            "LONGHOLE: the length {len} is less than the tool diameter"
        )));
    }
    let (cx, cy, rad) = (a.get(7), a.get(8), a.get(9).abs());
    let lv = levels(p.name, p.rfp, p.depth, p.mid)?;
    for deg in angles("LONGHOLE", a, 5, 10, 11)? {
        let mut pen = Pen::new(host, (cx, cy), deg);
        let ends = [rad + r, rad + len - r];
        let h = pen.depth(host);
        pen.rapid(host, ends[0], 0.0, h);
        pen.rapid_w(host, p.rfp + p.sdis);
        for (k, w) in lv.iter().enumerate() {
            let (from, to) = (ends[k % 2], ends[(k + 1) % 2]);
            pen.set_feed(host, p.ffd);
            pen.feed(host, from, 0.0, *w);
            pen.set_feed(host, p.ffp1);
            pen.feed(host, to, 0.0, *w);
        }
        pen.rapid_w(host, p.rtp);
        pen.restore(host);
    }
    Ok(())
}

/// SLOT2: slots along the circle.
pub fn slot2(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let p = common("SLOT2", a, 13)?;
    if r <= 0.0 {
        return Err(bad(
            "SLOT2: no tool radius: activate a cutting edge (D1) first".into(),
        ));
    }
    let (afsl, wid) = (a.get(6).abs(), a.get(7).abs());
    let (cx, cy, rad) = (a.get(8), a.get(9), a.get(10).abs());
    let h = wid / 2.0 - r;
    if h < 0.0 || rad <= wid / 2.0 || afsl <= 0.0 || afsl >= 360.0 {
        return Err(bad(format!(
            "SLOT2: a slot {wid} wide over {afsl} degrees on radius {rad} cannot be cut with a tool of radius {r}"
        )));
    }
    let rough = h - p.fal;
    if rough < 0.0 && p.vari != 2 {
        return Err(bad(
            "SLOT2: the finishing allowance FAL leaves no room for roughing".into(),
        ));
    }
    let count = (rough.max(0.0) / r + 1e-9).floor();
    if count > MAX_PASSES {
        return Err(bad(format!("SLOT2: more than {MAX_PASSES} rings")));
    }
    let widths: Vec<f64> = (0..=count as usize)
        .rev()
        .map(|k| rough - k as f64 * r)
        .collect();
    let lv = levels(p.name, p.rfp, p.depth, p.mid)?;
    for deg in angles("SLOT2", a, 5, 11, 12)? {
        let mut pen = Pen::new(host, (cx, cy), deg);
        let slot = Arc { rad, sweep: afsl };
        let top = pen.depth(host);
        pen.rapid(host, rad, 0.0, top);
        pen.rapid_w(host, p.rfp + p.sdis);
        if p.vari != 2 {
            for w in &lv {
                pen.set_feed(host, p.ffd);
                pen.feed(host, rad, 0.0, *w);
                pen.set_feed(host, p.ffp1);
                for hw in &widths {
                    slot.ring(host, &pen, hw.max(0.0), p.ccw);
                }
                pen.rapid_w(host, *w + p.sdis);
                pen.rapid(host, rad, 0.0, *w + p.sdis);
            }
        }
        if p.vari != 1 {
            finish(host, &mut pen, &p, &slot, h);
        }
        pen.rapid_w(host, p.rtp);
        pen.restore(host);
    }
    Ok(())
}

fn finish(host: &mut dyn MotionHost, pen: &mut Pen, p: &Pocket, slot: &Arc, h: f64) {
    pen.set_feed(host, p.ffd);
    pen.feed(host, slot.rad, 0.0, p.depth);
    pen.set_feed(host, if p.ffp2 > 0.0 { p.ffp2 } else { p.ffp1 });
    slot.ring(host, pen, h, p.ccw);
}

/// A circumferential slot's centre line in pen coordinates.
struct Arc {
    rad: f64,
    sweep: f64,
}

impl Arc {
    fn at(&self, radius: f64, deg: f64) -> (f64, f64) {
        let (s, c) = deg.to_radians().sin_cos();
        (radius * c, radius * s)
    }

    /// One closed ring `hw` either side of the centre line, from and back
    /// to its outer start point (the centre line there and back when 0).
    fn ring(&self, host: &mut dyn MotionHost, pen: &Pen, hw: f64, ccw: bool) {
        let w = pen.depth(host);
        let (ro, ri) = (self.rad + hw, self.rad - hw);
        let p0 = self.at(ro, 0.0);
        let p1 = self.at(ro, self.sweep);
        let p2 = self.at(ri, self.sweep);
        let p3 = self.at(ri, 0.0);
        let (e, s) = (self.at(self.rad, self.sweep), self.at(self.rad, 0.0));
        pen.feed(host, p0.0, p0.1, w);
        if hw < 1e-9 {
            pen.arc(host, p1.0, p1.1, 0.0, 0.0, true);
            pen.arc(host, p0.0, p0.1, 0.0, 0.0, false);
            return;
        }
        if ccw {
            pen.arc(host, p1.0, p1.1, 0.0, 0.0, true);
            pen.arc(host, p2.0, p2.1, e.0, e.1, true);
            pen.arc(host, p3.0, p3.1, 0.0, 0.0, false);
            pen.arc(host, p0.0, p0.1, s.0, s.1, true);
        } else {
            pen.arc(host, p3.0, p3.1, s.0, s.1, false);
            pen.arc(host, p2.0, p2.1, 0.0, 0.0, true);
            pen.arc(host, p1.0, p1.1, e.0, e.1, false);
            pen.arc(host, p0.0, p0.1, 0.0, 0.0, false);
        }
    }
}
