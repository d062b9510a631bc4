//! Heidenhain circle centres (`CC X Y`, modal) for a target without pole
//! paths (capability `pole-paths`): the `CC` goes and every arc without
//! centre words (`C X Y DR-`) gets its centre as I J, incremental from
//! the arc's start point (the targets' default arc distance mode), in
//! the active plane (`TOOL CALL X`: Y Z, and J K; `TOOL CALL Y`: Z X, and
//! K I). `CC` without axes takes the current position. The start point and the
//! centre must be numbers known here (a straight walk through the blocks,
//! as [`super::levels`] follows them); otherwise E0612.

use super::levels::Modal;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{ArcData, Axes, Coord, DimMode, MotionKind, Plane, Program, StmtKind, Value};
use crate::span::Span;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::PolePaths) || !from.has(Capability::PolePaths) {
        return;
    }
    let mut modal = Modal::new(from);
    let mut pole: Option<(f64, f64)> = None;
    let mut plane = Plane::XY;
    for b in &mut p.blocks {
        let mut keep = Vec::with_capacity(b.stmts.len());
        for mut s in std::mem::take(&mut b.stmts) {
            match &mut s.kind {
                StmtKind::Pole(axes) => {
                    let (a, b) = in_plane(plane);
                    let here = (num(position(&modal, a)), num(position(&modal, b)));
                    // `CC IX+0 IY-10`: from the current position.
                    let at = |c: Option<&Coord>, here: Option<f64>| match c {
                        None => here,
                        Some(c) => {
                            let v = num(&Some(c.value.clone()))?;
                            match c.dim {
                                Some(DimMode::Incremental) => Some(here? + v),
                                Some(DimMode::Absolute) => Some(v),
                                None if modal.absolute => Some(v),
                                None => Some(here? + v),
                            }
                        }
                    };
                    let (ca, cb) = (axis(axes, a), axis(axes, b));
                    pole = match (at(ca, here.0), at(cb, here.1)) {
                        (Some(x), Some(y)) => Some((x, y)),
                        _ => None,
                    };
                    if pole.is_none() {
                        refuse(
                            diags,
                            s.span,
                            "a circle centre (CC) that is not a number known here",
                        );
                    }
                    continue;
                }
                StmtKind::Motion(m) if matches!(m.kind, MotionKind::Arc(_)) && m.arc.is_empty() => {
                    let (a, b) = in_plane(plane);
                    let start = (num(position(&modal, a)), num(position(&modal, b)));
                    match (pole, start) {
                        (Some((cx, cy)), (Some(x0), Some(y0))) => {
                            *centre(&mut m.arc, a) = Some(coord(cx - x0, s.span));
                            *centre(&mut m.arc, b) = Some(coord(cy - y0, s.span));
                        }
                        _ => refuse(
                            diags,
                            s.span,
                            "an arc about CC whose centre or start point is not known here",
                        ),
                    }
                }
                StmtKind::Plane(p) => plane = *p,
                _ => {}
            }
            modal.see(&s);
            keep.push(s);
        }
        b.stmts = keep;
    }
    p.blocks
        .retain(|b| !b.stmts.is_empty() || b.label.is_some() || b.number.is_some());
}

/// The plane's first and second axes (0 X, 1 Y, 2 Z), as G17/G18/G19
/// name them: the centre words of the arcs in it (I J, K I, J K).
fn in_plane(p: Plane) -> (usize, usize) {
    match p {
        Plane::XY => (0, 1),
        Plane::ZX => (2, 0),
        Plane::YZ => (1, 2),
    }
}

fn position(m: &Modal, axis: usize) -> &Option<Value> {
    [&m.x, &m.y, &m.z][axis]
}

fn axis(a: &Axes, axis: usize) -> Option<&Coord> {
    [&a.x, &a.y, &a.z][axis].as_ref()
}

fn centre(arc: &mut ArcData, axis: usize) -> &mut Option<Coord> {
    match axis {
        0 => &mut arc.i,
        1 => &mut arc.j,
        _ => &mut arc.k,
    }
}

fn num(v: &Option<Value>) -> Option<f64> {
    v.as_ref().and_then(Value::number).map(|d| d.to_f64())
}

fn coord(v: f64, span: Span) -> Coord {
    Coord {
        value: Value::Number(super::decimal(v)),
        dim: None,
        span,
    }
}

fn refuse(diags: &mut Vec<Diagnostic>, span: Span, msg: &str) {
    diags.push(
        Diagnostic::new(Code::PortRunTimeValue, msg.to_string())
            .primary(span, "the target needs the centre as numbers (I J)")
            .help("give CC and the point before the arc as absolute numbers"),
    );
}
