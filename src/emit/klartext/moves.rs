//! Klartext moves: `L`/`LP` (with `FMAX` for rapids), `C`/`CP` round the
//! pole (a `CC` block first when the arc gives its centre as I J K), `CR`
//! by radius, `CT`/`CTP` tangent; a Siemens corner on a move becomes a
//! `RND`/`CHF` block after it.

use super::super::number::NumKind;
use super::super::writer::Writer;
use super::expr::signed;
use super::lines::axes;
use super::{num_kind_for, Out};
use crate::ir::{ArcDir, CornerKind, ExprKind, MotionKind, Stmt, StmtKind as K, Value};
use crate::span::Span;

/// `PA+30` or `IPA+30` (an `IC(..)` value is incremental).
fn polar(w: &mut Writer<'_>, addr: &str, v: &Value, span: Span) -> Option<String> {
    let inc = matches!(v, Value::Expr(e) if matches!(w.prog.exprs[*e].kind, ExprKind::Dimension(crate::ir::DimMode::Incremental, _)));
    let v = match v {
        Value::Expr(e) => match &w.prog.exprs[*e].kind {
            ExprKind::Dimension(_, inner) => Value::Expr(*inner),
            _ => v.clone(),
        },
        _ => v.clone(),
    };
    let kind = num_kind_for(addr);
    let v = match &v {
        Value::Expr(e) => match w.prog.exprs[*e].kind {
            ExprKind::Number(d) => Value::Number(d),
            _ => v.clone(),
        },
        _ => v,
    };
    Some(format!(
        " {}{addr}{}",
        if inc { "I" } else { "" },
        signed(w, &v, kind, span)?
    ))
}

fn dir(d: ArcDir) -> &'static str {
    match d {
        ArcDir::Ccw => " DR+",
        ArcDir::Cw => " DR-",
    }
}

pub(super) fn motion(
    w: &mut Writer<'_>,
    out: &mut Out,
    m: &crate::ir::Motion,
    span: Span,
) -> Option<String> {
    let kind = match m.kind {
        MotionKind::Implicit => match out.modal {
            Some(k @ (MotionKind::Rapid | MotionKind::Linear)) => k,
            _ if m.target.is_empty() => MotionKind::Linear,
            _ => {
                w.cannot(
                    span,
                    "a move whose kind comes from an earlier block's arc",
                    "write the arc's G2/G3 in the block",
                );
                return None;
            }
        },
        k => k,
    };
    out.modal = Some(kind);
    let polar_words = m.polar_radius.is_some() || m.polar_angle.is_some();
    let a = axes(w, out, &m.target)?;
    let mut pw = String::new();
    if let Some(r) = &m.polar_radius {
        pw.push_str(&polar(w, "PR", r, span)?);
    }
    if let Some(v) = &m.polar_angle {
        pw.push_str(&polar(w, "PA", v, span)?);
    }
    let arc_centre = m.arc.i.is_some() || m.arc.j.is_some() || m.arc.k.is_some();
    let extra = m.arc.angle.is_some() || m.arc.turns.is_some() || m.arc.mid.is_some();
    if extra || (arc_centre && (m.arc.radius.is_some() || !matches!(kind, MotionKind::Arc(_)))) {
        w.cannot(
            span,
            "an arc given by an opening angle, turns or an intermediate point",
            "give the centre with CC and write C, or write CR with the radius",
        );
        return None;
    }
    if arc_centre {
        // I J K: the centre, as a CC block before the C block (`CC IX..`
        // is relative to the arc's start, as I J K are by default).
        let mut cc = "CC".to_string();
        for (letter, c) in [('X', &m.arc.i), ('Y', &m.arc.j), ('Z', &m.arc.k)] {
            let Some(c) = c else { continue };
            let inc = match c.dim {
                Some(d) => d == crate::ir::DimMode::Incremental,
                None => !out.arc_absolute,
            };
            let v = signed(w, &c.value, NumKind::Length, c.span)?;
            cc.push_str(&format!(" {}{letter}{v}", if inc { "I" } else { "" }));
        }
        out.lines.push(cc);
    }
    let line = match kind {
        MotionKind::Rapid | MotionKind::Linear => {
            out.rapid = kind == MotionKind::Rapid;
            if polar_words {
                format!("LP{pw}{a}")
            } else {
                format!("L{a}")
            }
        }
        MotionKind::Arc(d) => match &m.arc.radius {
            Some(r) => format!("CR{a} R{}{}", signed(w, r, NumKind::Length, span)?, dir(d)),
            None if polar_words => format!("CP{pw}{a}{}", dir(d)),
            None => format!("C{a}{}", dir(d)),
        },
        MotionKind::ArcTangent if polar_words => format!("CTP{pw}{a}"),
        MotionKind::ArcTangent => format!("CT{a}"),
        MotionKind::Implicit
        | MotionKind::ArcThrough
        | MotionKind::Probe { .. }
        | MotionKind::Other(_) => {
            w.cannot(
                span,
                &format!("the motion {:?}", kind),
                "Klartext moves are L, C, CR, CT and their polar forms",
            );
            return None;
        }
    };
    Some(line)
}

/// A Siemens `RND=`/`CHF=` on a move: a Klartext RND/CHF block after it.
pub(super) fn corner_after(w: &mut Writer<'_>, out: &mut Out, s: &Stmt) {
    let K::Motion(m) = &s.kind else { return };
    let Some((kind, v)) = &m.corner else { return };
    let line = match kind {
        CornerKind::Round => signed(w, v, NumKind::Length, s.span)
            .map(|t| format!("RND R{}", t.trim_start_matches('+'))),
        CornerKind::Chamfer => signed(w, v, NumKind::Length, s.span)
            .map(|t| format!("CHF {}", t.trim_start_matches('+'))),
        CornerKind::ChamferLeg | CornerKind::RoundModal => {
            w.cannot(
                s.span,
                "a chamfer by leg length or a modal rounding",
                "use RND R.. or CHF length after the move",
            );
            None
        }
    };
    out.lines.extend(line);
}
