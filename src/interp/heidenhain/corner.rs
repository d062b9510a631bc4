//! `RND`/`CHF` corners between two straight lines (a rounding between a
//! line and an arc: [`super::corner_arc`]).
//!
//! A straight feed move is held back until the next block that does
//! something on the machine: if that block is a `RND`/`CHF`, the corner is
//! cut between the held line and the next one (shortening both);
//! otherwise the held line is sent as it was. A chamfer next to an arc is
//! E0561 (it joins two lines); a rounding after an arc that is not held
//! (CT, helix) is reported as not run yet [?: the TNC rounds there too].

use super::super::comp::MoveKind;
use super::super::machine::pose6;
use super::super::{exec::phase, Interp, Stop};
use crate::canon::Pose;
use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, Block, CornerKind, Expr, StmtKind, Value};
use crate::span::Span;

/// A straight feed held back (base frame, mm).
#[derive(Clone, Debug, PartialEq)]
pub struct Held {
    pub from: [f64; 9],
    pub to: [f64; 9],
    pub span: Span,
    pub corner: Option<(CornerKind, f64, Span)>,
    /// An arc (centre in base mm, counterclockwise?) rather than a line.
    pub arc: Option<((f64, f64), bool)>,
}

/// Sends a held element as it was.
pub(super) fn send_held(it: &mut Interp<'_, '_>, h: &Held) -> Result<(), Stop> {
    match h.arc {
        Some((c, ccw)) => super::held_arc::send_arc(it, &h.from, &h.to, c, ccw, h.span),
        None => send_line(it, &h.from, &h.to, h.span),
    }
}

/// Before a block runs: a held line is sent unless the block is a corner
/// or only control flow.
pub fn flush_before(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    super::depart::depart_before_comp_off(it, block, exprs)?;
    if let Some(ap) = &it.heidenhain.approach {
        let machine = block.stmts.iter().any(|s| phase(&s.kind) > 1);
        let moves = block
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::Motion(_)));
        if machine && !moves {
            return Err(super::approach::no_direction(
                ap.span,
                "APPR needs a contour element right after it",
            ));
        }
    }
    if it.heidenhain.held.is_none() {
        return Ok(());
    }
    let machine = block.stmts.iter().any(|s| phase(&s.kind) > 1);
    let corner = block
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::Corner { .. }));
    let moves = block
        .stmts
        .iter()
        .any(|s| matches!(s.kind, StmtKind::Motion(_)));
    // `CC` between a corner and the arc after it moves nothing.
    let pole_only = block
        .stmts
        .iter()
        .all(|s| phase(&s.kind) <= 1 || matches!(s.kind, StmtKind::Pole(_)));
    if machine && !corner && !moves && !pole_only {
        return flush(it);
    }
    if moves {
        // The motion itself decides (a corner may be waiting).
        if it
            .heidenhain
            .held
            .as_ref()
            .is_some_and(|h| h.corner.is_none())
        {
            return flush(it);
        }
    }
    Ok(())
}

/// Sends the held line; a corner still waiting on it had no element after it.
pub fn flush(it: &mut Interp<'_, '_>) -> Result<(), Stop> {
    let Some(h) = it.heidenhain.held.take() else {
        return Ok(());
    };
    if let Some((_, _, span)) = h.corner {
        return Err(no_fit(
            it,
            span,
            "RND/CHF needs a straight line after it in the working plane",
        ));
    }
    send_held(it, &h)
}

pub(super) fn send_line(
    it: &mut Interp<'_, '_>,
    from: &[f64; 9],
    to: &[f64; 9],
    span: Span,
) -> Result<(), Stop> {
    let saved = it.span;
    it.span = span;
    it.state.pos = *from;
    it.comp_block(span);
    let pose = pose6(&it.state, to);
    let r = it.straight_move(MoveKind::Feed, pose);
    it.span = saved;
    r
}

pub(super) fn no_fit(it: &Interp<'_, '_>, span: Span, why: &str) -> Stop {
    let _ = it;
    Stop::Error(
        Diagnostic::new(Code::KlartextCornerCannotFit, why.to_string())
            .primary(span, "this corner")
            .help("a rounding joins two lines, or a line and the arc after it, and a chamfer two lines, in the working plane; each must fit on both elements"),
    )
}

/// `RND R..` / `CHF ..` after a held straight line.
pub fn corner(
    it: &mut Interp<'_, '_>,
    kind: CornerKind,
    size: &Value,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let v = it.value(size, exprs)?;
    let v = it.state.to_mm(v).abs();
    match it.heidenhain.held.as_mut() {
        Some(h) if h.corner.is_none() => {
            h.corner = Some((kind, v, span));
            Ok(())
        }
        None if it.heidenhain.after_arc && matches!(kind, CornerKind::Round | CornerKind::RoundModal) => Err(Stop::Error(
            Diagnostic::new(
                Code::UnsupportedHere,
                "a rounding after this arc (a helix, a straight CT, a tilted or mirrored frame) is not run yet",
            )
            .primary(span, "this corner")
            .help("cncc rounds between lines and plain C, CR or CP arcs in the XY plane; program the rounding as its own arc"),
        )),
        _ => Err(no_fit(
            it,
            span,
            "RND/CHF needs a straight feed move in the working plane before it",
        )),
    }
}

/// Cuts the corner waiting on `h` before the line to `to` (base, mm):
/// sends the shortened held line and the rounding or chamfer; gives the
/// point the next line starts from.
pub(super) fn corner_join(
    it: &mut Interp<'_, '_>,
    h: Held,
    to: &[f64; 9],
) -> Result<[f64; 9], Stop> {
    if h.arc.is_some() {
        return super::held_arc::arc_then_line(it, h, to);
    }
    let Some((kind, size, cspan)) = h.corner else {
        send_line(it, &h.from, &h.to, h.span)?;
        return Ok(h.to);
    };
    let (p0, p1, p2) = ((h.from[0], h.from[1]), (h.to[0], h.to[1]), (to[0], to[1]));
    let (l1, l2) = (
        (p1.0 - p0.0).hypot(p1.1 - p0.1),
        (p2.0 - p1.0).hypot(p2.1 - p1.1),
    );
    let flat = (h.from[2] - h.to[2]).abs() > 1e-9 || (h.to[2] - to[2]).abs() > 1e-9;
    if l1 < 1e-9 || l2 < 1e-9 || flat {
        return Err(no_fit(
            it,
            cspan,
            "RND/CHF needs straight lines in the working plane on both sides",
        ));
    }
    let u = ((p1.0 - p0.0) / l1, (p1.1 - p0.1) / l1);
    let v = ((p2.0 - p1.0) / l2, (p2.1 - p1.1) / l2);
    let cross = u.0 * v.1 - u.1 * v.0;
    let dot = u.0 * v.0 + u.1 * v.1;
    if cross.abs() < 1e-9 {
        return Err(no_fit(
            it,
            cspan,
            "the lines on both sides of RND/CHF are in line: there is no corner",
        ));
    }
    // The angle the path turns through at the corner.
    let turn = cross.atan2(dot).abs();
    let d = match kind {
        CornerKind::Round | CornerKind::RoundModal => size * (turn / 2.0).tan(),
        // [?] CHF gives the length cut off each line from the corner.
        CornerKind::Chamfer | CornerKind::ChamferLeg => size,
    };
    if d > l1 + 1e-9 || d > l2 + 1e-9 {
        return Err(no_fit(
            it,
            cspan,
            "the rounding/chamfer is larger than the lines beside it",
        ));
    }
    let mut t1 = h.to;
    t1[0] = p1.0 - u.0 * d;
    t1[1] = p1.1 - u.1 * d;
    let mut t2 = h.to;
    t2[0] = p1.0 + v.0 * d;
    t2[1] = p1.1 + v.1 * d;
    if t1[..3] != h.from[..3] {
        send_line(it, &h.from, &t1, h.span)?;
    } else {
        it.state.pos = t1;
    }
    let saved = it.span;
    it.span = cspan;
    it.comp_block(cspan);
    let end: Pose = pose6(&it.state, &t2);
    let r = match kind {
        CornerKind::Round | CornerKind::RoundModal => {
            let n = if cross > 0.0 {
                (-u.1, u.0)
            } else {
                (u.1, -u.0)
            };
            let c = (t1[0] + n.0 * size, t1[1] + n.1 * size);
            let centre = (it.state.to_prog(c.0), it.state.to_prog(c.1));
            it.arc_move(end, centre, if cross > 0.0 { 1 } else { -1 })
        }
        CornerKind::Chamfer | CornerKind::ChamferLeg => it.straight_move(MoveKind::Feed, end),
    };
    it.span = saved;
    r?;
    it.state.pos = t2;
    Ok(t2)
}
