//! CYCLE71 face milling: RTP, RFP, SDIS, DP, PA, PO, LENG, WID, STA, MID,
//! MIDA, FDP, FALD, FFP1, VARI, FDP1 [S: parameter list].
//!
//! The face is the rectangle from the corner (PA, PO), LENG along the
//! abscissa and WID along the ordinate (a negative value extends it the
//! other way [S]), turned by STA about the corner. VARI units: 1 roughing
//! (levels of at most MID from RFP down to DP+FALD), 2 finishing (one pass
//! at DP) [S]; tens: 1 lines along the abscissa one way, 2 along the
//! ordinate one way, 3 along the abscissa alternating (zigzag), 4 along the
//! ordinate alternating [S].
//!
//! Path [?: geometry details not in our sources]: cutting lines MIDA apart
//! (0: the tool radius), the first with the tool centre on the starting
//! edge, the last on the far edge; each line runs from one tool radius
//! plus FDP before the face to one tool radius plus FDP past it. Zigzag
//! steps over at the feed; one-way lines lift SDIS, rapid back and feed
//! down again. FDP1 (overrun in the infeed direction) is not used [?].
//! Ends with a rapid to RTP.

use super::pen::Pen;
use super::{bad, levels, Args, MAX_PASSES};
use crate::diag::Diagnostic;
use crate::interp::host::MotionHost;

pub fn cycle71(host: &mut dyn MotionHost, a: &Args, r: f64) -> Result<(), Diagnostic> {
    let (rtp, rfp, sdis, dp) = (a.get(0), a.get(1), a.get(2).abs(), a.get(3));
    let (leng, wid, mid, mida, fdp, fald, ffp1) = (
        a.get(6),
        a.get(7),
        a.get(9),
        a.get(10),
        a.get(11),
        a.get(12),
        a.get(13),
    );
    let vari = a.get(14).abs() as i64;
    let (units, tens) = (vari % 10, vari / 10 % 10);
    if !(1..=2).contains(&units) || !(1..=4).contains(&tens) {
        return Err(bad(format!(
            "CYCLE71: VARI {vari}: units 1 or 2, tens 1 to 4"
        )));
    }
    let step = if mida.abs() > 0.0 { mida.abs() } else { r };
    if step <= 0.0 {
        return Err(bad(
            "CYCLE71: no width infeed (MIDA) and no tool radius (D1)".into(),
        ));
    }
    let along_u = tens % 2 == 1;
    // Work in (u, v) with u the cutting direction.
    let (cut, across) = if along_u {
        (leng.abs(), wid.abs())
    } else {
        (wid.abs(), leng.abs())
    };
    let n = (across / step - 1e-9).ceil().max(0.0);
    if n > MAX_PASSES {
        return Err(bad(format!("CYCLE71: more than {MAX_PASSES} lines")));
    }
    let lines: Vec<f64> = (0..=n as usize)
        .map(|k| (k as f64 * step).min(across))
        .collect();
    let lv = if units == 1 {
        levels("CYCLE71", rfp, dp + fald.abs(), mid)?
    } else {
        vec![dp]
    };
    let mut pen = Pen::new(host, (a.get(4), a.get(5)), a.get(8));
    let (su, sv) = (leng.signum_or_one(), wid.signum_or_one());
    // Cycle (u along cut, v across) to the face's own axes.
    let to_uv = |c: f64, x: f64| {
        if along_u {
            (su * c, sv * x)
        } else {
            (su * x, sv * c)
        }
    };
    let (start, end) = (-(r + fdp.abs()), cut + r + fdp.abs());
    let zigzag = tens >= 3;
    for w in lv {
        let (u0, v0) = to_uv(start, lines[0]);
        let h = pen.depth(host);
        pen.rapid(host, u0, v0, h);
        pen.rapid_w(host, w + sdis);
        pen.set_feed(host, ffp1);
        pen.feed(host, u0, v0, w);
        for (k, x) in lines.iter().enumerate() {
            let fwd = !zigzag || k % 2 == 0;
            let (c0, c1) = if fwd { (start, end) } else { (end, start) };
            let (p0, q0) = to_uv(c0, *x);
            if k > 0 && !zigzag {
                pen.rapid_w(host, w + sdis);
                pen.rapid(host, p0, q0, w + sdis);
            }
            pen.feed(host, p0, q0, w);
            let (p1, q1) = to_uv(c1, *x);
            pen.feed(host, p1, q1, w);
        }
        pen.rapid_w(host, w + sdis);
    }
    pen.rapid_w(host, rtp);
    pen.restore(host);
    Ok(())
}

trait SignumOrOne {
    fn signum_or_one(self) -> f64;
}

impl SignumOrOne for f64 {
    /// -1 for negative values, else 1 (0 counts as positive).
    fn signum_or_one(self) -> f64 {
        if self < 0.0 {
            -1.0
        } else {
            1.0
        }
    }
}
