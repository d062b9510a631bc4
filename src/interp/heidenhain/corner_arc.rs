//! `RND` between a straight line and an arc (`C`, `CR`, `CP`), either way,
//! and between two arcs ([`super::corner_arcs`]).
//!
//! Plain arcs are held back like lines in case a rounding follows
//! ([`super::held_arc`]); other arcs run through the core.
//!
//! The rounding is the circle of radius r tangent to both: its centre F
//! lies r off the line on the inside of the turn and R + r or |R - r| from
//! the arc's centre c; the line is cut short at F's foot on it, the
//! rounding runs to where F's direction from c meets the arc, and the
//! arc goes on from there to its end. The solution nearest the corner
//! that lies on both elements is taken.
//!
//! Not done [?]: a rounding next to a helix, a `CT` after it, chamfers next to arcs, and frames that rotate
//! or mirror: reported as not supported.

use super::super::machine::pose6;
use super::super::motion as core_motion;
use super::super::target::{target, Frame};
use super::super::{siemens, Interp, Stop};
use super::corner::{no_fit, send_line, Held};
use crate::diag::{Code, Diagnostic};
use crate::ir::{ArcDir, Arena, Block, CornerKind, Expr, Motion, MotionKind};
use crate::span::Span;

type P2 = (f64, f64);

pub(super) fn unsupported(span: Span, what: &str) -> Stop {
    Stop::Error(
        Diagnostic::new(Code::UnsupportedHere, format!("{what} is not run yet"))
            .primary(span, "this corner")
            .help("cncc rounds between lines and plain C, CR or CP arcs in the XY plane; program the rounding as its own arc"),
    )
}

/// Whether the programmable frame only shifts (no rotation, mirror or
/// scale), so base and programmed directions agree.
pub(super) fn shift_only(it: &Interp<'_, '_>) -> bool {
    let f = &it.siemens.frame;
    let x = f.dir_to_base([1.0, 0.0, 0.0]);
    let y = f.dir_to_base([0.0, 1.0, 0.0]);
    (x[0] - 1.0).abs() < 1e-12
        && x[1].abs() < 1e-12
        && y[0].abs() < 1e-12
        && (y[1] - 1.0).abs() < 1e-12
}

/// The centre (base, mm) and direction of the arc `m` from `s` to `e`.
pub(super) fn arc_centre(
    it: &mut Interp<'_, '_>,
    m: &Motion,
    s: P2,
    e: P2,
    exprs: &Arena<Expr>,
) -> Result<Option<(P2, bool)>, Stop> {
    let MotionKind::Arc(dir) = m.kind else {
        return Ok(None);
    };
    let ccw = dir == ArcDir::Ccw;
    if let Some(r) = &m.arc.radius {
        let r = it.value(r, exprs)?;
        let r = it.state.to_mm(r);
        return Ok(siemens::arcs::centre_from_radius(s, e, r, ccw).map(|c| (c, ccw)));
    }
    let (Some(i), Some(j)) = (&m.arc.i, &m.arc.j) else {
        return Ok(None);
    };
    let (ci, cj) = (it.value(&i.value, exprs)?, it.value(&j.value, exprs)?);
    let c = siemens::to_base(it, [it.state.to_mm(ci), it.state.to_mm(cj), 0.0]);
    Ok(Some(((c[0], c[1]), ccw)))
}

type Fillet = (P2, P2, P2, bool);

/// The rounding's centre, the points where it meets the line and the
/// arc, and whether it turns left; or why there is none.
pub(super) fn fillet(
    p0: P2,
    p1: P2,
    c: P2,
    ccw: bool,
    r: f64,
    e: P2,
) -> Result<Fillet, &'static str> {
    let l1 = (p1.0 - p0.0).hypot(p1.1 - p0.1);
    let rr = (p1.0 - c.0).hypot(p1.1 - c.1);
    if l1 < 1e-9 || rr < 1e-9 {
        return Err("the line or the arc beside RND has no length");
    }
    let u = ((p1.0 - p0.0) / l1, (p1.1 - p0.1) / l1);
    let radial = ((p1.0 - c.0) / rr, (p1.1 - c.1) / rr);
    let v = if ccw {
        (-radial.1, radial.0)
    } else {
        (radial.1, -radial.0)
    };
    let cross = u.0 * v.1 - u.1 * v.0;
    if cross.abs() < 1e-9 {
        return Err("the line runs into the arc tangentially: there is no corner to round");
    }
    let left = cross > 0.0;
    let n = if left { (-u.1, u.0) } else { (u.1, -u.0) };
    let w = (p1.0 + r * n.0 - c.0, p1.1 + r * n.1 - c.1);
    let wu = w.0 * u.0 + w.1 * u.1;
    let ww = w.0 * w.0 + w.1 * w.1;
    let sweep_to = |p: P2| {
        let a0 = radial.1.atan2(radial.0);
        let a = (p.1 - c.1).atan2(p.0 - c.0);
        let d = if ccw { a - a0 } else { a0 - a };
        d.rem_euclid(std::f64::consts::TAU)
    };
    let end_sweep = sweep_to(e);
    let mut best: Option<(f64, P2, P2, P2)> = None;
    for rho in [rr + r, (rr - r).abs()] {
        let disc = wu * wu - ww + rho * rho;
        if disc < 0.0 {
            continue;
        }
        for lam in [-wu + disc.sqrt(), -wu - disc.sqrt()] {
            if lam > 1e-9 || lam < -l1 - 1e-9 {
                continue;
            }
            let f = (p1.0 + r * n.0 + lam * u.0, p1.1 + r * n.1 + lam * u.1);
            let fd = (f.0 - c.0).hypot(f.1 - c.1);
            if fd < 1e-9 {
                continue;
            }
            let t2 = (c.0 + rr * (f.0 - c.0) / fd, c.1 + rr * (f.1 - c.1) / fd);
            let on_arc = sweep_to(t2);
            if on_arc > end_sweep + 1e-9 && end_sweep > 1e-9 {
                continue;
            }
            let t1 = (p1.0 + lam * u.0, p1.1 + lam * u.1);
            if best.as_ref().is_none_or(|b| lam > b.0) {
                best = Some((lam, f, t1, t2));
            }
        }
    }
    best.map(|(_, f, t1, t2)| (f, t1, t2, left))
        .ok_or("the rounding does not fit between the line and the arc")
}

/// The held line or arc, the rounding waiting on it, then the arc `m`
/// (already rewritten: pole as centre, polar end as cartesian).
pub fn line_then_arc(
    it: &mut Interp<'_, '_>,
    h: Held,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
    holdable: bool,
) -> Result<(), Stop> {
    let Some((kind, size, cspan)) = h.corner else {
        return super::corner::send_held(it, &h);
    };
    if matches!(kind, CornerKind::Chamfer | CornerKind::ChamferLeg) {
        return Err(no_fit(
            it,
            cspan,
            "a chamfer (CHF) joins two straight lines; the element after it is an arc",
        ));
    }
    if m.kind == MotionKind::ArcTangent {
        return Err(unsupported(cspan, "a rounding before a tangent arc (CT)"));
    }
    if !shift_only(it) || it.heidenhain.mirror.iter().any(|m| *m) {
        return Err(unsupported(
            cspan,
            "a rounding under a rotated or mirrored frame",
        ));
    }
    let e3 = target(it, &m.target, exprs, Frame::Program)?;
    let flat = (h.from[2] - h.to[2]).abs() > 1e-9 || (h.to[2] - e3[2]).abs() > 1e-9;
    if flat {
        return Err(no_fit(
            it,
            cspan,
            "RND needs the line and the arc in the working plane",
        ));
    }
    let (p0, p1, e) = ((h.from[0], h.from[1]), (h.to[0], h.to[1]), (e3[0], e3[1]));
    let Some((c, ccw)) = arc_centre(it, m, p1, e, exprs)? else {
        return Err(no_fit(
            it,
            it.span,
            "the arc after RND has no centre that reaches its end point",
        ));
    };
    let found = match h.arc {
        None => fillet(p0, p1, c, ccw, size, e),
        Some(first) => super::corner_arcs::fillet(p0, p1, first, (c, ccw), e, size),
    };
    let (f, t1, t2, left) = found.map_err(|why| no_fit(it, cspan, why))?;
    let mut q1 = h.to;
    (q1[0], q1[1]) = t1;
    match h.arc {
        _ if (t1.0 - p0.0).hypot(t1.1 - p0.1) <= 1e-9 => it.state.pos = q1,
        Some((c1, ccw1)) => super::held_arc::send_arc(it, &h.from, &q1, c1, ccw1, h.span)?,
        None => send_line(it, &h.from, &q1, h.span)?,
    }
    let mut q2 = h.to;
    (q2[0], q2[1]) = t2;
    let saved = it.span;
    it.span = cspan;
    it.comp_block(cspan);
    let r = arc_to(it, &q2, f, left);
    it.span = saved;
    r?;
    core_motion::check_feed(
        it,
        block,
        "Cannot make arc with zero feed rate",
        "F word missing with inverse time arc move",
    )?;
    let d = siemens::arcs::end_direction(c, e, ccw);
    it.siemens.tangent = Some([d.0, d.1, 0.0]);
    if holdable && !it.heidenhain.modal_call {
        // Held in its turn: a rounding may follow the arc too.
        it.state.pos = e3;
        it.heidenhain.held = Some(Held {
            from: q2,
            to: e3,
            span: it.span,
            corner: None,
            arc: Some((c, ccw)),
        });
        return Ok(());
    }
    it.comp_block(it.span);
    arc_to(it, &e3, c, ccw)
}

pub(super) fn arc_to(it: &mut Interp<'_, '_>, to: &[f64; 9], c: P2, ccw: bool) -> Result<(), Stop> {
    let end = pose6(&it.state, to);
    let centre = (it.state.to_prog(c.0), it.state.to_prog(c.1));
    it.arc_move(end, centre, if ccw { 1 } else { -1 })?;
    it.state.pos = *to;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_into_a_clockwise_half_circle() {
        // Along +X to (10, 0), then clockwise round (15, 0) to (20, 0): the
        // arc starts upwards, a left turn of 90°. A rounding of 1 lies
        // outside the arc's circle: 5 + 1 from its centre, 1 above the line.
        let (f, t1, t2, left) = fillet(
            (0.0, 0.0),
            (10.0, 0.0),
            (15.0, 0.0),
            false,
            1.0,
            (20.0, 0.0),
        )
        .unwrap();
        assert!(left);
        let x = 15.0 - 35f64.sqrt();
        assert!((f.0 - x).abs() < 1e-9 && (f.1 - 1.0).abs() < 1e-9, "{f:?}");
        assert!((t1.0 - x).abs() < 1e-9 && t1.1.abs() < 1e-12, "{t1:?}");
        assert!(((t2.0 - 15.0).hypot(t2.1) - 5.0).abs() < 1e-9, "{t2:?}");
        assert!(((t2.0 - f.0).hypot(t2.1 - f.1) - 1.0).abs() < 1e-9);
    }

    #[test]
    fn no_corner_when_the_arc_continues_the_line() {
        assert!(fillet(
            (0.0, 0.0),
            (10.0, 0.0),
            (10.0, 5.0),
            true,
            1.0,
            (10.0, 10.0)
        )
        .is_err());
    }
}
