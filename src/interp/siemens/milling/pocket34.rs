//! POCKET3 (rectangular) and POCKET4 (circular) pockets for any tool,
//! expanded with the strategy of POCKET1/2 (see `pocket.rs`).
//!
//! POCKET3: RTP, RFP, SDIS, DP, LENG, WID, CRAD, PA, PO, STA, MID, FAL,
//! FALD, FFP1, FFD, CDIR, VARI, MIDA, AP1, AP2, AD, RAD1, DP1 [S].
//! POCKET4: RTP, RFP, SDIS, DP, PRAD, PA, PO, MID, FAL, FALD, FFP1, FFD,
//! CDIR, VARI, MIDA, AP1, AD, RAD1, DP1 [S]. Arguments after these (the
//! Operate tail) make it an Operate call, whose words may mean other things
//! [?]: it is not expanded (W0510).
//!
//! Choices, each [?] (dialects.md §1.7 gives the parameters, not the path):
//! * PA, PO is the pocket centre (the classic default; Operate's reference
//!   point modes are in the tail, not read);
//! * CDIR: 0 climb = G3 and 1 conventional = G2 (inside a pocket, with the
//!   spindle turning M3), 2 = G2, 3 = G3;
//! * MIDA is the width infeed between rings (0, or more than the tool
//!   diameter: the tool radius / diameter);
//! * FALD: roughing stops FALD above DP; finishing (VARI units 0 or 2)
//!   clears the base at DP, then cuts the wall, both at FFP1 (the cycle has
//!   no finishing feed);
//! * insertion (VARI tens) 0 or 1 is a vertical plunge at FFD. Helical (2)
//!   and oscillating (3) insertion, and a pre-machined blank (AP1, AP2, AD
//!   not 0), are not defined well enough: the cycle is not expanded (W0510).

use super::pocket::{run, Pocket, Ring};
use super::{Args, Outcome};
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

/// Argument positions of the words both cycles share.
struct Layout {
    name: &'static str,
    mid: usize,
    fal: usize,
    fald: usize,
    ffp1: usize,
    ffd: usize,
    cdir: usize,
    vari: usize,
    mida: usize,
    blank: &'static [usize],
    /// The classic parameter count; a longer call is SINUMERIK Operate's.
    classic: usize,
}

fn pocket(a: &Args, l: &Layout) -> Result<Result<Pocket, String>, Diagnostic> {
    let name = l.name;
    if a.0.len() > l.classic {
        return Ok(Err(format!(
            "a SINUMERIK Operate call ({} arguments, the classic cycle has {}): the tail changes the meaning of the words [?]",
            a.0.len(),
            l.classic
        )));
    }
    let vari = a.get(l.vari).abs() as i64;
    let insertion = (vari / 10) % 10;
    if insertion >= 2 {
        let how = if insertion == 2 {
            "helical"
        } else {
            "oscillating"
        };
        return Ok(Err(format!(
            "{how} insertion (VARI {vari}) is not defined well enough to expand"
        )));
    }
    if l.blank.iter().any(|i| a.get(*i) != 0.0) {
        return Ok(Err(
            "a pre-machined blank (AP1, AP2, AD) is not defined well enough to expand".into(),
        ));
    }
    let depth = a
        .opt(3)
        .ok_or_else(|| super::bad(format!("{name}: no depth (DP)")))?;
    let ccw = matches!(a.get(l.cdir) as i64, 0 | 3);
    let ffp1 = a.get(l.ffp1);
    Ok(Ok(Pocket {
        name,
        rtp: a
            .opt(0)
            .ok_or_else(|| super::bad(format!("{name}: RTP (retract plane) missing")))?,
        rfp: a.get(1),
        sdis: a.get(2).abs(),
        depth,
        ffd: a.get(l.ffd),
        ffp1,
        mid: a.get(l.mid),
        ccw,
        fal: a.get(l.fal).abs(),
        vari: vari % 10,
        ffp2: ffp1,
        ssf: 0.0,
        step: a.get(l.mida).abs(),
        fald: a.get(l.fald).abs(),
    }))
}

/// POCKET3: LENG × WID about (PA, PO), long axis at STA.
pub fn pocket3(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<Outcome, Diagnostic> {
    let layout = Layout {
        name: "POCKET3",
        mid: 10,
        fal: 11,
        fald: 12,
        ffp1: 13,
        ffd: 14,
        cdir: 15,
        vari: 16,
        mida: 17,
        blank: &[18, 19, 20],
        classic: 23,
    };
    let p = match pocket(a, &layout)? {
        Ok(p) => p,
        Err(why) => return Ok(Outcome::NotExpanded(why)),
    };
    let (len, wid, crad) = (a.get(4).abs(), a.get(5).abs(), a.get(6).abs());
    let pen = super::pen::Pen::new(host, (a.get(7), a.get(8)), a.get(9));
    let (hu, hv) = (len / 2.0 - r, wid / 2.0 - r);
    let last = Ring {
        hu,
        hv,
        rc: (crad - r).max(0.0).min(hu.max(0.0)).min(hv.max(0.0)),
        circle: false,
    };
    run(host, pen, &p, last, r)?;
    Ok(Outcome::Done)
}

/// POCKET4: circle of radius PRAD about (PA, PO).
pub fn pocket4(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<Outcome, Diagnostic> {
    let layout = Layout {
        name: "POCKET4",
        mid: 7,
        fal: 8,
        fald: 9,
        ffp1: 10,
        ffd: 11,
        cdir: 12,
        vari: 13,
        mida: 14,
        blank: &[15, 16],
        classic: 19,
    };
    let p = match pocket(a, &layout)? {
        Ok(p) => p,
        Err(why) => return Ok(Outcome::NotExpanded(why)),
    };
    let prad = a.get(4).abs();
    let pen = super::pen::Pen::new(host, (a.get(5), a.get(6)), 0.0);
    let last = Ring {
        hu: prad - r,
        hv: prad - r,
        rc: 0.0,
        circle: true,
    };
    run(host, pen, &p, last, r)?;
    Ok(Outcome::Done)
}
