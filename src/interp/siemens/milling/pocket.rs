//! POCKET1 (rectangular) and POCKET2 (circular) with a centre-cutting
//! tool.
//!
//! POCKET1: RTP, RFP, SDIS, DP, DPR, LENG, WID, CRAD, CPA, CPO, STA1, FFD,
//! FFP1, MID, CDIR, FAL, VARI, MIDF, FFP2, SSF [S: parameter list].
//! POCKET2: RTP, RFP, SDIS, DP, DPR, PRAD, CPA, CPO, FFD, FFP1, MID, CDIR,
//! FAL, VARI, MIDF, FFP2, SSF [K].
//!
//! Strategy [?: the manual describes it only in outline]:
//! 1. rapid in the plane to the centre (at the current height), rapid to
//!    RFP+SDIS;
//! 2. roughing (VARI units 0 or 1), per depth level (steps of MID): feed
//!    FFD straight down at the centre, then at FFP1 contour-parallel rings
//!    from the centre out, one tool radius apart, the last one FAL inside
//!    the final contour; then rapid up SDIS and back over the centre;
//! 3. finishing (VARI units 0 or 2) at the final depth only (MIDF is not
//!    used [?]): feed down at the centre, out to the final contour and
//!    round it once at FFP2, spindle speed SSF if given (the speed before
//!    the cycle is set again after it [?]);
//! 4. rapid to RTP and back over the centre.
//!
//! Rings run G3 (CDIR 3) or G2 (CDIR 2, and any other value [?]); each
//! ring starts and ends on the positive abscissa of the pocket (the long
//! axis for POCKET1, rotated by STA1). Corner radii of rings are CRAD less
//! the distance of the ring from the final contour (not below 0).

use super::pen::Pen;
use super::{bad, levels, Args, MAX_PASSES};
use crate::canon::Canon;
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

/// The common part of the pockets (POCKET3/4 fill it in `pocket34`).
pub(super) struct Pocket {
    pub name: &'static str,
    pub rtp: f64,
    pub rfp: f64,
    pub sdis: f64,
    pub depth: f64,
    pub ffd: f64,
    pub ffp1: f64,
    pub mid: f64,
    pub ccw: bool,
    pub fal: f64,
    pub vari: i64,
    pub ffp2: f64,
    pub ssf: f64,
    /// Width infeed between rings (0: the tool radius).
    pub step: f64,
    /// Base allowance: roughing stops this far above the depth, and
    /// finishing then clears the base at the depth before the wall.
    pub fald: f64,
}

/// A ring: half sizes (hu, hv) and corner radius; a circle when `circle`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Ring {
    pub hu: f64,
    pub hv: f64,
    pub rc: f64,
    pub circle: bool,
}

/// The words POCKET1, POCKET2, SLOT1, SLOT2 and LONGHOLE share: RTP RFP
/// SDIS DP DPR first, FFD FFP1 MID CDIR FAL VARI MIDF FFP2 SSF from `i_ffd`.
pub(super) fn common(name: &'static str, a: &Args, i_ffd: usize) -> Result<Pocket, Diagnostic> {
    let rfp = a.get(1);
    let depth = match (a.opt(3), a.opt(4)) {
        (_, Some(dpr)) if dpr != 0.0 => rfp - dpr.abs(),
        (Some(dp), _) => dp,
        _ => return Err(bad(format!("{name}: no depth (DP or DPR)"))),
    };
    let k = |off: usize| a.get(i_ffd + off);
    Ok(Pocket {
        name,
        rtp: a
            .opt(0)
            .ok_or_else(|| bad(format!("{name}: RTP (retract plane) missing")))?,
        rfp,
        sdis: a.get(2).abs(),
        depth,
        ffd: k(0),
        ffp1: k(1),
        mid: k(2),
        ccw: k(3) as i64 == 3,
        fal: k(4).abs(),
        vari: (k(5).abs() as i64) % 10,
        ffp2: k(7),
        ssf: k(8),
        step: 0.0,
        fald: 0.0,
    })
}

/// POCKET1: rectangular pocket LENG × WID about (CPA, CPO) at STA1.
pub fn pocket1(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let p = common("POCKET1", a, 11)?;
    let (len, wid, crad) = (a.get(5).abs(), a.get(6).abs(), a.get(7).abs());
    let pen = Pen::new(host, (a.get(8), a.get(9)), a.get(10));
    let (hu, hv) = (len / 2.0 - r, wid / 2.0 - r);
    let final_ring = Ring {
        hu,
        hv,
        rc: (crad - r).max(0.0).min(hu.max(0.0)).min(hv.max(0.0)),
        circle: false,
    };
    run(host, pen, &p, final_ring, r)
}

/// POCKET2: circular pocket of radius PRAD about (CPA, CPO).
pub fn pocket2(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let p = common("POCKET2", a, 8)?;
    let prad = a.get(5).abs();
    let pen = Pen::new(host, (a.get(6), a.get(7)), 0.0);
    let final_ring = Ring {
        hu: prad - r,
        hv: prad - r,
        rc: 0.0,
        circle: true,
    };
    run(host, pen, &p, final_ring, r)
}

/// Rings from the centre out; the last is `last` (already inside FAL).
fn rings(name: &str, last: Ring, step: f64) -> Result<Vec<Ring>, Diagnostic> {
    let j = (last.hu.min(last.hv) / step + 1e-9).floor();
    if j > MAX_PASSES {
        return Err(bad(format!("{name}: more than {MAX_PASSES} rings")));
    }
    let j = j as usize;
    let ring = |k: usize| {
        let d = k as f64 * step;
        let (hu, hv) = (last.hu - d, last.hv - d);
        Ring {
            hu,
            hv,
            rc: (last.rc - d).max(0.0).min(hu).min(hv),
            circle: last.circle,
        }
    };
    Ok((0..=j)
        .rev()
        .map(ring)
        .filter(|r| r.hu > 1e-9 || r.hv > 1e-9)
        .collect())
}

pub(super) fn run(
    host: &mut dyn MotionHost,
    mut pen: Pen,
    p: &Pocket,
    last: Ring,
    r: f64,
) -> Result<(), Diagnostic> {
    if r <= 0.0 {
        return Err(bad(format!(
            "{}: no tool radius: activate a cutting edge (D1) first",
            p.name
        )));
    }
    if last.hu < 0.0 || last.hv < 0.0 {
        return Err(bad(format!(
            "{}: the tool (radius {r}) is larger than the pocket",
            p.name
        )));
    }
    let (hu, hv) = (last.hu - p.fal, last.hv - p.fal);
    let rc = (last.rc - p.fal).max(0.0).min(hu.max(0.0)).min(hv.max(0.0));
    let rough = Ring {
        hu,
        hv,
        rc,
        circle: last.circle,
    };
    let step = if p.step > 0.0 { p.step.min(2.0 * r) } else { r };
    let lv = levels(p.name, p.rfp, p.depth + p.fald, p.mid)?;
    let h = pen.depth(host);
    pen.rapid(host, 0.0, 0.0, h);
    pen.rapid_w(host, p.rfp + p.sdis);
    if p.vari != 2 {
        if rough.hu < 0.0 || rough.hv < 0.0 {
            return Err(bad(format!(
                "{}: the finishing allowance FAL leaves no room for roughing",
                p.name
            )));
        }
        let rs = rings(p.name, rough, step)?;
        for w in &lv {
            plunge(host, &mut pen, p.ffd, *w);
            pen.set_feed(host, p.ffp1);
            for ring in &rs {
                cut_ring(host, &pen, ring, p.ccw);
            }
            pen.rapid_w(host, *w + p.sdis);
            pen.rapid(host, 0.0, 0.0, *w + p.sdis);
        }
    }
    if p.vari != 1 {
        let speed = host.spindle_speed();
        if p.ssf > 0.0 {
            host.emit(Canon::SetSpindleSpeed(p.ssf));
        }
        plunge(host, &mut pen, p.ffd, p.depth);
        pen.set_feed(host, if p.ffp2 > 0.0 { p.ffp2 } else { p.ffp1 });
        if p.fald > 0.0 {
            for ring in &rings(p.name, rough, step)? {
                cut_ring(host, &pen, ring, p.ccw);
            }
        }
        cut_ring(host, &pen, &last, p.ccw);
        if p.ssf > 0.0 && p.ssf != speed {
            host.emit(Canon::SetSpindleSpeed(speed));
        }
    }
    pen.rapid_w(host, p.rtp);
    pen.rapid(host, 0.0, 0.0, p.rtp);
    pen.restore(host);
    Ok(())
}

fn plunge(host: &mut dyn MotionHost, pen: &mut Pen, ffd: f64, w: f64) {
    pen.set_feed(host, ffd);
    pen.feed(host, 0.0, 0.0, w);
}

/// Feeds out to the ring's start and cuts it once round.
fn cut_ring(host: &mut dyn MotionHost, pen: &Pen, r: &Ring, ccw: bool) {
    let w = pen.depth(host);
    pen.feed(host, r.hu, 0.0, w);
    if r.circle {
        pen.arc(host, r.hu, 0.0, 0.0, 0.0, ccw);
        return;
    }
    // Corners in the order met going round: ccw visits +v first.
    let s = if ccw { 1.0 } else { -1.0 };
    let (hu, hv, rc) = (r.hu, r.hv * s, r.rc);
    let corners = [
        (hu, hv, -1.0, -s),
        (-hu, hv, 1.0, -s),
        (-hu, -hv, 1.0, s),
        (hu, -hv, -1.0, s),
    ];
    for (k, (cu, cv, du, dv)) in corners.iter().enumerate() {
        // Arrive at the corner along the side, then round it.
        let along_v = k % 2 == 0;
        let (iu, iv) = if along_v {
            (*cu, cv + dv * rc)
        } else {
            (cu + du * rc, *cv)
        };
        pen.feed(host, iu, iv, w);
        if rc > 0.0 {
            let (ou, ov) = if along_v {
                (cu + du * rc, *cv)
            } else {
                (*cu, cv + dv * rc)
            };
            pen.arc(host, ou, ov, cu + du * rc, cv + dv * rc, ccw);
        }
    }
    pen.feed(host, hu, 0.0, w);
}
