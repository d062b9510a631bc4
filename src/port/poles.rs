//! Heidenhain circle centres (`CC X Y`, modal) for a target without pole
//! paths (capability `pole-paths`): the `CC` goes and every arc without
//! centre words (`C X Y DR-`) gets its centre as I J, incremental from
//! the arc's start point (the targets' default arc distance mode). `CC`
//! without axes takes the current position. The start point and the
//! centre must be numbers known here (a straight walk through the blocks,
//! as [`super::levels`] follows them); otherwise E0612.

use super::levels::Modal;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Coord, DimMode, MotionKind, Program, StmtKind, Value};
use crate::span::Span;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::PolePaths) || !from.has(Capability::PolePaths) {
        return;
    }
    let mut modal = Modal::new(from);
    let mut pole: Option<(f64, f64)> = None;
    for b in &mut p.blocks {
        let mut keep = Vec::with_capacity(b.stmts.len());
        for mut s in std::mem::take(&mut b.stmts) {
            match &mut s.kind {
                StmtKind::Pole(axes) => {
                    let here = (num(&modal.x), num(&modal.y));
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
                    pole = match (at(axes.x.as_ref(), here.0), at(axes.y.as_ref(), here.1)) {
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
                    match (pole, num(&modal.x), num(&modal.y)) {
                        (Some((cx, cy)), Some(x0), Some(y0)) => {
                            m.arc.i = Some(coord(cx - x0, s.span));
                            m.arc.j = Some(coord(cy - y0, s.span));
                        }
                        _ => refuse(
                            diags,
                            s.span,
                            "an arc about CC whose centre or start point is not known here",
                        ),
                    }
                }
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
