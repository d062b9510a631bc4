//! `APPR`/`DEP`: approaching and leaving the contour.
//!
//! `APPR LT` and `APPR LN` need the direction of the first contour element,
//! so the approach waits for the next block (a straight line [?: the TNC
//! also approaches arcs]): the tool goes from where it is to the auxiliary
//! point PH, then to the first contour point PA. LT: PH lies `LEN` before
//! PA on the line's extension; LN: `LEN` off PA at right angles, on the
//! side the radius compensation puts the tool (left for RL and R0 [?]).
//! `DEP LT` leaves along the last element's direction by `LEN`; `DEP LN`
//! at right angles to it. CT and LCT (arcs) are not simulated yet.
//! Source: `reference/dialects.md` §2.3 and the corpus `PROFILE.h`.

use super::super::comp::MoveKind;
use super::super::machine::pose6;
use super::super::target::{target, Frame};
use super::super::{siemens, Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::ir::{Approach, ApproachKind, Arena, CompSide, Expr};
use crate::span::Span;

/// An approach waiting for its first contour element (base frame, mm).
#[derive(Clone, Debug, PartialEq)]
pub struct PendingApproach {
    pub normal: bool,
    pub start: [f64; 9],
    pub contour: [f64; 9],
    pub len: f64,
    pub span: Span,
}

fn unsupported(span: Span, what: &str) -> Stop {
    Stop::Error(
        Diagnostic::new(
            Code::UnsupportedHere,
            format!("{what} is not simulated yet"),
        )
        .primary(span, "here")
        .help("APPR/DEP LT and LN are run; use them, or program the approach with L/CT blocks"),
    )
}

pub fn no_direction(span: Span, why: &str) -> Stop {
    Stop::Error(
        Diagnostic::new(Code::KlartextTangentUndefined, why.to_string())
            .primary(span, "here")
            .help("program a straight line or an arc first: CT and DEP continue the element before them, APPR the line after it"),
    )
}

/// Runs an `APPR`/`DEP` statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    a: &Approach,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    super::corner::flush(it)?;
    let len = match &a.len {
        Some(v) => {
            let x = it.value(v, exprs)?;
            it.state.to_mm(x).abs()
        }
        None => 0.0,
    };
    let normal = match a.kind {
        ApproachKind::LineTangent => false,
        ApproachKind::LineNormal => true,
        ApproachKind::ArcTangent | ApproachKind::LineArcTangent => {
            return Err(unsupported(
                span,
                "an approach or departure on an arc (CT, LCT)",
            ))
        }
    };
    if a.depart {
        return depart(it, normal, len, span);
    }
    it.heidenhain.side = Some(it.state.comp_side);
    let contour = target(it, &a.target, exprs, Frame::Program)?;
    it.heidenhain.approach = Some(PendingApproach {
        normal,
        start: it.state.pos,
        contour,
        len,
        span,
    });
    it.state.pos = contour;
    Ok(())
}

/// The unit normal to `d` on the side the compensation puts the tool.
fn side_normal(it: &Interp<'_, '_>, d: (f64, f64)) -> (f64, f64) {
    let side = match it.state.comp_side {
        CompSide::Off => it.heidenhain.side.unwrap_or(CompSide::Off),
        s => s,
    };
    match side {
        CompSide::Right => (d.1, -d.0),
        CompSide::Left | CompSide::Off => (-d.1, d.0),
    }
}

/// Sends the approach before the first contour line, which goes to `to`.
pub fn before_line(
    it: &mut Interp<'_, '_>,
    ap: PendingApproach,
    to: &[f64; 9],
) -> Result<(), Stop> {
    let pa = ap.contour;
    let (dx, dy) = (to[0] - pa[0], to[1] - pa[1]);
    let l = dx.hypot(dy);
    if l < 1e-9 {
        return Err(no_direction(
            ap.span,
            "the element after APPR has no direction in the plane",
        ));
    }
    let d = (dx / l, dy / l);
    let off = if ap.normal {
        side_normal(it, d)
    } else {
        (-d.0, -d.1)
    };
    let mut ph = pa;
    ph[0] = pa[0] + off.0 * ap.len;
    ph[1] = pa[1] + off.1 * ap.len;
    let saved = it.span;
    it.span = ap.span;
    it.state.pos = ap.start;
    it.comp_block(ap.span);
    let r = feed_to(it, &ph).and_then(|_| feed_to(it, &pa));
    it.span = saved;
    r?;
    siemens::arcs::note_straight(it, ph);
    Ok(())
}

fn feed_to(it: &mut Interp<'_, '_>, p: &[f64; 9]) -> Result<(), Stop> {
    if *p == it.state.pos {
        return Ok(());
    }
    let pose = pose6(&it.state, p);
    it.straight_move(MoveKind::Feed, pose)
}

/// `DEP LT LEN..` / `DEP LN LEN..` from where the contour ended.
fn depart(it: &mut Interp<'_, '_>, normal: bool, len: f64, span: Span) -> Result<(), Stop> {
    let Some(t) = it.siemens.tangent else {
        return Err(no_direction(
            span,
            "DEP has no contour element before it to leave from",
        ));
    };
    let l = t[0].hypot(t[1]);
    if l < 1e-9 {
        return Err(no_direction(
            span,
            "the element before DEP has no direction in the plane",
        ));
    }
    let d = (t[0] / l, t[1] / l);
    let off = if normal { side_normal(it, d) } else { d };
    let p = it.state.pos;
    let prog = siemens::from_base(it, [p[0], p[1], p[2]]);
    let end = siemens::to_base(it, [prog[0] + off.0 * len, prog[1] + off.1 * len, prog[2]]);
    let mut to = p;
    to[..3].copy_from_slice(&end);
    feed_to(it, &to)
}
