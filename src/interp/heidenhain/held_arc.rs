//! Plain arcs held back like straight lines, in case a rounding follows:
//! `C`, `CR`, `CP` and `CT` arcs in the XY plane (no helix, no turns, no
//! inverse-time feed, a frame that only shifts) are sent as the core would
//! send them (`ARC_FEED` round their centre) when the next block shows no
//! `RND`; with one, the arc is cut short for the rounding
//! ([`super::corner_arc`] has the geometry). Also the direction an arc
//! leaves its start in, for an `APPR` into it.

use super::super::motion as core_motion;
use super::super::target::{target, Frame};
use super::super::{siemens, Interp, Stop};
use super::corner::{no_fit, Held};
use super::corner_arc::{arc_centre, arc_to, fillet, shift_only};
use crate::canon::CanonPlane;
use crate::ir::{Arena, Block, CornerKind, Expr, FeedMode, Motion, MotionKind};
use crate::span::Span;

type P2 = (f64, f64);

/// The direction (unit, base) in which the arc `m` leaves `from`, for
/// an approach to it; `None` when it is not a C, CR or CP arc with a centre.
pub fn start_direction(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    from: &[f64; 9],
    exprs: &Arena<Expr>,
) -> Result<Option<P2>, Stop> {
    if !shift_only(it) {
        return Ok(None);
    }
    let e3 = target(it, &m.target, exprs, Frame::Program)?;
    let (s, e) = ((from[0], from[1]), (e3[0], e3[1]));
    let Some((c, ccw)) = arc_centre(it, m, s, e, exprs)? else {
        return Ok(None);
    };
    let r = (s.0 - c.0).hypot(s.1 - c.1);
    if r < 1e-9 {
        return Ok(None);
    }
    let (x, y) = ((s.0 - c.0) / r, (s.1 - c.1) / r);
    Ok(Some(if ccw { (-y, x) } else { (y, -x) }))
}

/// Holds the arc `m` (already rewritten) when it is a plain arc in the XY
/// plane; `false`: the core runs it.
pub fn hold_arc(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<bool, Stop> {
    let plain = matches!(m.kind, MotionKind::Arc(_) | MotionKind::ArcTangent)
        && m.arc.turns.is_none()
        && !it.heidenhain.modal_call
        && it.state.plane == CanonPlane::XY
        && it.state.feed_mode != FeedMode::InverseTime
        && shift_only(it)
        && !it.heidenhain.mirror.iter().any(|m| *m);
    if !plain {
        return Ok(false);
    }
    let s3 = it.state.pos;
    let e3 = target(it, &m.target, exprs, Frame::Program)?;
    if (2..9).any(|i| (e3[i] - s3[i]).abs() > 1e-12) {
        return Ok(false);
    }
    let (s, e) = ((s3[0], s3[1]), (e3[0], e3[1]));
    let found = match m.kind {
        // CT: the circle through both ends tangent to the last direction
        // (a straight CT, along that direction, is left to the core).
        MotionKind::ArcTangent => it
            .siemens
            .tangent
            .and_then(|t| siemens::arcs::tangent_circle(s, (t[0], t[1]), e)),
        _ => arc_centre(it, m, s, e, exprs)?,
    };
    let Some((c, ccw)) = found else {
        return Ok(false);
    };
    let (rs, re) = ((s.0 - c.0).hypot(s.1 - c.1), (e.0 - c.0).hypot(e.1 - c.1));
    // An end off the circle is left to the core, which reports it.
    if (rs - re).abs() > 1e-7 || rs < 1e-9 {
        return Ok(false);
    }
    core_motion::check_feed(
        it,
        block,
        "Cannot make arc with zero feed rate",
        "F word missing with inverse time arc move",
    )?;
    it.state.pos = e3;
    let d = siemens::arcs::end_direction(c, e, ccw);
    it.siemens.tangent = Some([d.0, d.1, 0.0]);
    it.heidenhain.held = Some(Held {
        from: s3,
        to: e3,
        span: it.span,
        corner: None,
        arc: Some((c, ccw)),
    });
    Ok(true)
}

/// Sends a held arc from `from` to `to` round `c`.
pub fn send_arc(
    it: &mut Interp<'_, '_>,
    from: &[f64; 9],
    to: &[f64; 9],
    c: P2,
    ccw: bool,
    span: Span,
) -> Result<(), Stop> {
    let saved = it.span;
    it.span = span;
    it.state.pos = *from;
    it.comp_block(span);
    let r = arc_to(it, to, c, ccw);
    it.span = saved;
    r
}

/// The held arc, the rounding waiting on it, and the start of the line to
/// `to` after it (returned: where that line now starts).
pub fn arc_then_line(it: &mut Interp<'_, '_>, h: Held, to: &[f64; 9]) -> Result<[f64; 9], Stop> {
    let Some((c, ccw)) = h.arc else {
        return Ok(h.to);
    };
    let Some((kind, size, cspan)) = h.corner else {
        send_arc(it, &h.from, &h.to, c, ccw, h.span)?;
        return Ok(h.to);
    };
    if matches!(kind, CornerKind::Chamfer | CornerKind::ChamferLeg) {
        return Err(no_fit(
            it,
            cspan,
            "a chamfer (CHF) joins two straight lines; the element before it is an arc",
        ));
    }
    if (h.to[2] - to[2]).abs() > 1e-9 {
        return Err(no_fit(
            it,
            cspan,
            "RND needs the arc and the line in the working plane",
        ));
    }
    // The same rounding on the path run backwards: the line from `to`
    // into the arc turning the other way, towards the arc's start.
    let (s, p1, p2) = ((h.from[0], h.from[1]), (h.to[0], h.to[1]), (to[0], to[1]));
    let (f, t_line, t_arc, left) =
        fillet(p2, p1, c, !ccw, size, s).map_err(|why| no_fit(it, cspan, why))?;
    let mut q_arc = h.to;
    (q_arc[0], q_arc[1]) = t_arc;
    let mut q_line = h.to;
    (q_line[0], q_line[1]) = t_line;
    send_arc(it, &h.from, &q_arc, c, ccw, h.span)?;
    let saved = it.span;
    it.span = cspan;
    it.comp_block(cspan);
    let r = arc_to(it, &q_line, f, !left);
    it.span = saved;
    r?;
    Ok(q_line)
}
