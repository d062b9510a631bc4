//! `DEP CT`/`DEP LCT`: leaving the contour on a tangent arc (geometry in
//! [`super::approach_arc`]), and running such a departure before the
//! `R0` of its own block, so that the arc is still cut compensated.

use super::super::target::{target, Frame};
use super::super::{Interp, Stop};
use super::approach::{exec, no_direction, side};
use super::approach_arc::{self as arc, ArcPart};
use crate::ir::{Approach, ApproachKind, Arena, Block, CompSide, Expr, StmtKind};
use crate::span::Span;

/// `DEP CT CCA.. R..` / `DEP LCT X.. Y.. R..` from where the contour ended.
pub(super) fn depart_arc(
    it: &mut Interp<'_, '_>,
    a: ArcPart,
    dep: &Approach,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let Some(t) = it.siemens.tangent else {
        return Err(no_direction(
            span,
            "DEP has no contour element before it to leave from",
        ));
    };
    let t = it.siemens.frame.dir_to_base(t);
    let l = t[0].hypot(t[1]);
    if l < 1e-9 {
        return Err(no_direction(
            span,
            "the element before DEP has no direction in the plane",
        ));
    }
    let d = (t[0] / l, t[1] / l);
    let pe = it.state.pos;
    let pn = match a.angle {
        None => Some(target(it, &dep.target, exprs, Frame::Program)?),
        Some(_) => None,
    };
    let s = arc::turn(side(it), a.radius);
    let Some(h) = arc::departure_point((pe[0], pe[1]), pn.map(|p| (p[0], p[1])), d, a, s) else {
        return Err(super::corner::no_fit(
            it,
            span,
            "the end point of DEP LCT lies inside the departure arc",
        ));
    };
    let mut ph = pe;
    ph[0] = h.0;
    ph[1] = h.1;
    let c = arc::centre((pe[0], pe[1]), d, a.radius.abs(), s);
    arc::arc_to(it, &ph, c, s)?;
    match pn {
        Some(pn) => arc::line_to(it, &pn),
        None => Ok(()),
    }
}

/// `DEP CT ... R0` / `DEP LCT ... R0`: the departure arc is still cut
/// with the compensation on (the TNC ends it at the departure's end
/// point), so it runs before the block's `R0`, after its feed; the later
/// `R0` makes the next move the exit move.
pub fn depart_before_comp_off(
    it: &mut Interp<'_, '_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let dep = block.stmts.iter().find_map(|s| match &s.kind {
        StmtKind::Approach(a)
            if a.depart
                && matches!(
                    a.kind,
                    ApproachKind::ArcTangent | ApproachKind::LineArcTangent
                ) =>
        {
            Some((a, s.span))
        }
        _ => None,
    });
    let off = block.stmts.iter().any(|s| {
        matches!(
            s.kind,
            StmtKind::RadiusComp {
                side: CompSide::Off,
                ..
            }
        )
    });
    let Some((a, span)) = dep.filter(|_| off && it.comp.is_on()) else {
        return Ok(());
    };
    let saved = it.span;
    for s in &block.stmts {
        if matches!(s.kind, StmtKind::Feed(_)) {
            it.span = s.span;
            super::super::modes::exec(it, s, block, exprs)?;
        }
    }
    it.span = span;
    let r = exec(it, a, span, exprs);
    it.span = saved;
    r?;
    it.heidenhain.departed = true;
    Ok(())
}
