//! Klartext path blocks: the pole (`CC`), `C`/`CP` round it, polar `LP`/
//! `CTP`, and `RND`/`CHF` corners between two straight lines.
//!
//! A straight feed move is held back until the next block that does
//! something on the machine: if that block is a `RND`/`CHF`, the corner is
//! cut between the held line and the next one (shortening both);
//! otherwise the held line is sent as it was. Corners join two straight
//! lines here; a corner next to an arc is reported (E0561) [?: the TNC
//! also rounds between lines and arcs].

use super::super::comp::MoveKind;
use super::super::machine::pose6;
use super::super::target::{target, Frame};
use super::super::{exec::phase, motion as core_motion, siemens, Interp, Stop};
use crate::canon::Pose;
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    Arena, Axes, Block, Coord, CornerKind, Decimal, DimMode, Expr, ExprKind, Motion, MotionKind,
    Stmt, StmtKind, Value,
};
use crate::span::Span;

/// A straight feed held back (base frame, mm).
#[derive(Clone, Debug, PartialEq)]
pub struct Held {
    pub from: [f64; 9],
    pub to: [f64; 9],
    pub span: Span,
    pub corner: Option<(CornerKind, f64, Span)>,
}

/// Before a block runs: a held line is sent unless the block is a corner
/// or only control flow.
pub fn flush_before(it: &mut Interp<'_, '_>, block: &Block) -> Result<(), Stop> {
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
    if machine && !corner && !moves {
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
    send_line(it, &h.from, &h.to, h.span)
}

fn send_line(
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

fn no_fit(it: &Interp<'_, '_>, span: Span, why: &str) -> Stop {
    let _ = it;
    Stop::Error(
        Diagnostic::new(Code::KlartextCornerCannotFit, why.to_string())
            .primary(span, "this corner")
            .help("a rounding or chamfer joins two straight lines in the working plane and must fit on both"),
    )
}

/// `CC X.. Y..`: the pole, in the programmed system (no axes: here).
pub fn pole(it: &mut Interp<'_, '_>, axes: &Axes, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let base = target(it, axes, exprs, Frame::Program)?;
    let p = siemens::from_base(it, [base[0], base[1], base[2]]);
    it.heidenhain.pole = Some(p);
    Ok(())
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
        _ => Err(no_fit(
            it,
            span,
            "RND/CHF needs a straight feed move in the working plane before it",
        )),
    }
}

fn num(v: f64, it: &Interp<'_, '_>) -> Value {
    Value::Number(Decimal::from_f64(it.state.to_prog(v), 6))
}

fn abs_coord(v: f64, it: &Interp<'_, '_>, span: Span) -> Coord {
    Coord {
        value: num(v, it),
        dim: Some(DimMode::Absolute),
        span,
    }
}

/// A polar value: (value in program units, incremental?).
fn polar_value(
    it: &mut Interp<'_, '_>,
    v: &Value,
    exprs: &Arena<Expr>,
) -> Result<(f64, bool), Stop> {
    let inc = matches!(v, Value::Expr(e) if matches!(exprs[*e].kind, ExprKind::Dimension(DimMode::Incremental, _)));
    Ok((it.value(v, exprs)?, inc))
}

/// The pole, or E0560.
fn the_pole(it: &Interp<'_, '_>) -> Result<[f64; 3], Stop> {
    it.heidenhain.pole.ok_or_else(|| {
        Stop::Error(
            Diagnostic::new(Code::KlartextNoCentre, "no circle centre (CC) is defined")
                .primary(it.span, "this block turns round the pole")
                .help("program `CC X.. Y..` before the first C, CP, LP or CTP block"),
        )
    })
}

/// Rewrites a Klartext move as the core runs it: polar → cartesian end
/// point, `C`/`CP` → an arc with its centre (absolute) at the pole.
fn rewrite(it: &mut Interp<'_, '_>, m: &Motion, exprs: &Arena<Expr>) -> Result<Motion, Stop> {
    let (a, b, _) = super::super::host::plane_axes(it.state.plane);
    let mut m2 = m.clone();
    let letters = ['X', 'Y', 'Z'];
    let span = it.span;
    let polar = m.polar_radius.is_some() || m.polar_angle.is_some();
    if polar {
        let p = the_pole(it)?;
        let cur = siemens::from_base(it, [it.state.pos[0], it.state.pos[1], it.state.pos[2]]);
        let (r0, a0) = (
            (cur[a] - p[a]).hypot(cur[b] - p[b]),
            (cur[b] - p[b]).atan2(cur[a] - p[a]).to_degrees(),
        );
        let r = match &m.polar_radius {
            Some(v) => {
                let (x, inc) = polar_value(it, v, exprs)?;
                let x = it.state.to_mm(x);
                if inc {
                    r0 + x
                } else {
                    x
                }
            }
            None => r0,
        };
        let ang = match &m.polar_angle {
            Some(v) => {
                let (x, inc) = polar_value(it, v, exprs)?;
                if inc {
                    a0 + x
                } else {
                    x
                }
            }
            None => a0,
        };
        let (s, c) = ang.to_radians().sin_cos();
        *m2.target.slot_mut(letters[a]).expect("axis") = Some(abs_coord(p[a] + r * c, it, span));
        *m2.target.slot_mut(letters[b]).expect("axis") = Some(abs_coord(p[b] + r * s, it, span));
        m2.polar_radius = None;
        m2.polar_angle = None;
    }
    if let MotionKind::Arc(_) = m.kind {
        if m.arc.radius.is_none() && m.arc.i.is_none() && m.arc.j.is_none() && m.arc.k.is_none() {
            let p = the_pole(it)?;
            let slots = [&mut m2.arc.i, &mut m2.arc.j, &mut m2.arc.k];
            for (i, slot) in slots.into_iter().enumerate() {
                if i == a || i == b {
                    *slot = Some(abs_coord(p[i], it, span));
                }
            }
        }
    }
    Ok(m2)
}

/// Statements that act after the block's move (a held line must go first).
fn after_move(k: &StmtKind) -> bool {
    use crate::ir::{Coolant, SpindleState};
    matches!(
        k,
        StmtKind::CycleRun(_)
            | StmtKind::Spindle(SpindleState::Stop)
            | StmtKind::Coolant(Coolant::Off)
    )
}

/// Runs a Klartext move (the block's `Motion`).
pub fn motion(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    m: &Motion,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.begin_block(block);
    let empty = m.target.is_empty() && m.polar_radius.is_none() && m.polar_angle.is_none();
    if empty
        && matches!(
            m.kind,
            MotionKind::Rapid | MotionKind::Linear | MotionKind::Implicit
        )
    {
        return Ok(());
    }
    let m2 = rewrite(it, m, exprs)?;
    let line = m2.kind == MotionKind::Linear;
    if let Some(ap) = it.heidenhain.approach.take() {
        if !line {
            return Err(super::approach::no_direction(
                ap.span,
                "APPR LT/LN needs a straight feed line after it [?]",
            ));
        }
        let to = target(it, &m2.target, exprs, Frame::Program)?;
        super::approach::before_line(it, ap, &to)?;
    }
    if line {
        let to = target(it, &m2.target, exprs, Frame::Program)?;
        let from = it.state.pos;
        let start = match it.heidenhain.held.take() {
            Some(h) => corner_join(it, h, &to)?,
            None => from,
        };
        // Hold the line while nothing else in its block must come after it.
        let holdable = block
            .stmts
            .iter()
            .all(|x| phase(&x.kind) <= 20 && !after_move(&x.kind));
        if holdable && !it.heidenhain.modal_call {
            core_motion::check_feed(
                it,
                block,
                "Cannot do g1 with zero feed rate",
                "F word missing with inverse time g1 move",
            )?;
            it.state.pos = to;
            siemens::arcs::note_straight(it, start);
            it.heidenhain.held = Some(Held {
                from: start,
                to,
                span: it.span,
                corner: None,
            });
            return Ok(());
        }
        send_line(it, &start, &to, it.span)?;
        siemens::arcs::note_straight(it, start);
        return after(it, s, block, exprs);
    }
    if let Some(h) = it.heidenhain.held.take() {
        if let Some((_, _, span)) = h.corner {
            return Err(no_fit(it, span, "RND/CHF between a line and an arc is not supported here [?]; the element after it must be a straight line"));
        }
        send_line(it, &h.from, &h.to, h.span)?;
    }
    let s2 = Stmt::new(StmtKind::Motion(Box::new(m2)), s.span);
    core_motion::exec(it, &s2, block, exprs)?;
    siemens::after_motion(it, &s2, block, exprs)?;
    after(it, s, block, exprs)
}

/// M89: the cycle after every positioning block.
fn after(
    it: &mut Interp<'_, '_>,
    s: &Stmt,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    if it.heidenhain.modal_call {
        let _ = s;
        return super::cycles::call_here(it, it.span, block, exprs);
    }
    Ok(())
}

/// Cuts the corner waiting on `h` before the line to `to` (base, mm):
/// sends the shortened held line and the rounding or chamfer; gives the
/// point the next line starts from.
fn corner_join(it: &mut Interp<'_, '_>, h: Held, to: &[f64; 9]) -> Result<[f64; 9], Stop> {
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
