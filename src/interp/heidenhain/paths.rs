//! Klartext path blocks: the pole (`CC`), `C`/`CP` round it, polar `LP`/
//! `CTP`; straight feeds are held for a following corner ([`super::corner`]).

use super::super::target::{target, Frame};
use super::super::{exec::phase, motion as core_motion, siemens, Interp, Stop};
use super::corner::{corner_join, send_held, send_line, Held};
use crate::diag::{Code, Diagnostic};
use crate::ir::{
    Arena, Axes, Block, Coord, Decimal, DimMode, Expr, ExprKind, Motion, MotionKind, Stmt,
    StmtKind, Value,
};
use crate::span::Span;
use std::borrow::Cow;

/// `CC X.. Y..`: the pole, in the programmed system (no axes: here).
pub fn pole(it: &mut Interp<'_, '_>, axes: &Axes, exprs: &Arena<Expr>) -> Result<(), Stop> {
    let base = target(it, axes, exprs, Frame::Program)?;
    let p = siemens::from_base(it, [base[0], base[1], base[2]]);
    it.heidenhain.pole = Some(p);
    Ok(())
}

fn num(v: f64, it: &Interp<'_, '_>) -> Value {
    Value::Number(Decimal::from_f64(it.state.to_prog(v), 6))
}

pub(super) fn abs_coord(v: f64, it: &Interp<'_, '_>, span: Span) -> Coord {
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
/// The move with polar words and a pole-centred arc made Cartesian; the
/// move itself (no copy) when it has neither.
fn rewrite<'m>(
    it: &mut Interp<'_, '_>,
    m: &'m Motion,
    exprs: &Arena<Expr>,
) -> Result<Cow<'m, Motion>, Stop> {
    let (a, b, _) = super::super::host::plane_axes(it.state.plane);
    let polar = m.polar_radius.is_some() || m.polar_angle.is_some();
    let pole_arc = matches!(m.kind, MotionKind::Arc(_))
        && m.arc.radius.is_none()
        && m.arc.i.is_none()
        && m.arc.j.is_none()
        && m.arc.k.is_none();
    if !polar && !pole_arc {
        return Ok(Cow::Borrowed(m));
    }
    let mut m2 = m.clone();
    let letters = ['X', 'Y', 'Z'];
    let span = it.span;
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
    Ok(Cow::Owned(m2))
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
    let m2 = super::paraxial::apply(it, block, m2, exprs)?;
    let line = m2.kind == MotionKind::Linear;
    if let Some(ap) = it.heidenhain.approach.take() {
        if line {
            let to = target(it, &m2.target, exprs, Frame::Program)?;
            super::approach::before_line(it, ap, &to)?;
        } else {
            let Some(d) = super::held_arc::start_direction(it, &m2, &ap.contour, exprs)? else {
                return Err(super::approach::no_direction(
                    ap.span,
                    "APPR needs a straight feed line or a C, CR or CP arc after it",
                ));
            };
            super::approach::before_dir(it, ap, d)?;
        }
    }
    it.heidenhain.after_arc = !line && m2.kind != MotionKind::Rapid;
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
                arc: None,
            });
            return Ok(());
        }
        send_line(it, &start, &to, it.span)?;
        siemens::arcs::note_straight(it, start);
        return after(it, s, block, exprs);
    }
    let holdable = block
        .stmts
        .iter()
        .all(|x| phase(&x.kind) <= 20 && !after_move(&x.kind));
    if let Some(h) = it.heidenhain.held.take() {
        if h.corner.is_some() {
            super::corner_arc::line_then_arc(it, h, &m2, block, exprs, holdable)?;
            return after(it, s, block, exprs);
        }
        send_held(it, &h)?;
    }
    if holdable && super::held_arc::hold_arc(it, &m2, block, exprs)? {
        return Ok(());
    }
    if m2.kind == MotionKind::ArcTangent && it.siemens.tangent.is_none() {
        return Err(super::approach::no_direction(
            it.span,
            "CT/CTP has no path element before it to be tangent to",
        ));
    }
    // Unchanged, the move is the statement itself.
    let owned;
    let s2 = match m2 {
        Cow::Borrowed(_) => s,
        Cow::Owned(m2) => {
            owned = Stmt::new(StmtKind::Motion(Box::new(m2)), s.span);
            &owned
        }
    };
    core_motion::exec(it, s2, block, exprs)?;
    siemens::after_motion(it, s2, block, exprs)?;
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
