//! `APPR`/`DEP`: approaching and leaving the contour.
//!
//! `APPR` needs the direction of the first contour element, so the
//! approach waits for the next block (a straight line, or a `C`/`CR`/`CP`
//! arc: its tangent at PA): the tool goes from where it is to the auxiliary
//! point PH, then to the first contour point PA. LT: PH lies `LEN` before
//! PA on the line's extension; LN: `LEN` off PA at right angles, on the
//! side the radius compensation puts the tool (left for RL and R0 [?]);
//! CT/LCT: PH and the arc to PA as [`super::approach_arc`] says.
//! `DEP LT` leaves along the last element's direction by `LEN`; `DEP LN`
//! at right angles to it; `DEP CT`/`LCT` on a tangent arc.
//! Source: `reference/dialects.md` §2.3, the corpus `PROFILE.h`, the TNC
//! user manuals (approach and departure).

use super::super::target::{target, Frame};
use super::super::{siemens, Interp, Stop};
use super::approach_arc::{self as arc, ArcPart};
use crate::diag::{Code, Diagnostic};
use crate::ir::{Approach, ApproachKind, Arena, CompSide, Expr};
use crate::span::Span;

/// An approach waiting for its first contour element (base frame, mm).
#[derive(Clone, Debug, PartialEq)]
pub struct PendingApproach {
    pub normal: bool,
    /// CT/LCT: the arc into PA.
    pub arc: Option<ArcPart>,
    pub start: [f64; 9],
    pub contour: [f64; 9],
    pub len: f64,
    pub span: Span,
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
    if a.depart && std::mem::take(&mut it.heidenhain.departed) {
        return Ok(());
    }
    super::corner::flush(it)?;
    let len = match &a.len {
        Some(v) => {
            let x = it.value(v, exprs)?;
            it.state.to_mm(x).abs()
        }
        None => 0.0,
    };
    let normal = a.kind == ApproachKind::LineNormal;
    let arc = arc_part(it, a, span, exprs)?;
    if a.depart {
        return match arc {
            Some(arc) => super::depart::depart_arc(it, arc, a, span, exprs),
            None => depart(it, normal, len, span),
        };
    }
    it.heidenhain.side = Some(it.state.comp_side);
    let contour = target(it, &a.target, exprs, Frame::Program)?;
    it.heidenhain.approach = Some(PendingApproach {
        normal,
        arc,
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
    before_dir(it, ap, (dx / l, dy / l))
}

/// Sends the approach to a first contour element leaving PA along `d`
/// (unit, base frame).
pub fn before_dir(it: &mut Interp<'_, '_>, ap: PendingApproach, d: (f64, f64)) -> Result<(), Stop> {
    let pa = ap.contour;
    if let Some(a) = ap.arc {
        return before_line_arc(it, ap, a, d);
    }
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
    let r = arc::line_to(it, &ph).and_then(|_| arc::line_to(it, &pa));
    it.span = saved;
    r?;
    siemens::arcs::note_straight(it, ph);
    Ok(())
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
    arc::line_to(it, &to)
}

/// The arc part of a CT/LCT approach or departure (mm, degrees).
fn arc_part(
    it: &mut Interp<'_, '_>,
    a: &Approach,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<Option<ArcPart>, Stop> {
    if !matches!(
        a.kind,
        ApproachKind::ArcTangent | ApproachKind::LineArcTangent
    ) {
        return Ok(None);
    }
    let radius = match &a.radius {
        Some(v) => {
            let r = it.value(v, exprs)?;
            it.state.to_mm(r)
        }
        None => 0.0,
    };
    if radius.abs() < 1e-9 {
        return Err(no_direction(
            span,
            "the arc of APPR/DEP CT or LCT needs a radius R",
        ));
    }
    let angle = match (&a.angle, a.kind) {
        (Some(v), ApproachKind::ArcTangent) => Some(it.value(v, exprs)?.abs()),
        (None, ApproachKind::ArcTangent) => Some(0.0),
        _ => None,
    };
    Ok(Some(ArcPart { radius, angle }))
}

/// The compensation side the approach or departure turns by.
pub(super) fn side(it: &Interp<'_, '_>) -> CompSide {
    match it.state.comp_side {
        CompSide::Off => it.heidenhain.side.unwrap_or(CompSide::Off),
        s => s,
    }
}

/// APPR CT/LCT before the first contour line (direction `d` at PA).
fn before_line_arc(
    it: &mut Interp<'_, '_>,
    ap: PendingApproach,
    a: ArcPart,
    d: (f64, f64),
) -> Result<(), Stop> {
    let (ps, pa) = (ap.start, ap.contour);
    let s = arc::turn(side(it), a.radius);
    let Some(h) = arc::approach_point((ps[0], ps[1]), (pa[0], pa[1]), d, a, s) else {
        return Err(super::corner::no_fit(
            it,
            ap.span,
            "APPR LCT starts inside the approach arc: no straight line can touch it",
        ));
    };
    let mut ph = pa;
    ph[0] = h.0;
    ph[1] = h.1;
    let c = arc::centre((pa[0], pa[1]), d, a.radius.abs(), s);
    let saved = it.span;
    it.span = ap.span;
    it.state.pos = ap.start;
    it.comp_block(ap.span);
    let r = arc::line_to(it, &ph).and_then(|_| arc::arc_to(it, &pa, c, s));
    it.span = saved;
    r?;
    siemens::arcs::note_straight(it, ph);
    Ok(())
}
