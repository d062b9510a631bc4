//! G5.2 / G5.3: NURBS control points gathered block by block and cut as
//! one curve (see the parent module for the rs274 behaviour kept).

use super::{end_xy, fail, feed, in_nurbs_mode, value, Words};
use crate::canon::NurbsPoint;
use crate::diag::{Code, Diagnostic};
use crate::interp::state::ModalMotion;
use crate::interp::{Interp, Stop};
use crate::ir::{Arena, Block, Expr, FeedMode};

/// A G5.2 block or continuation: checks, then one control point (or the
/// first point's weight).
pub(super) fn nurbs_point(
    it: &mut Interp<'_, '_>,
    w: &Words<'_>,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let ((x, y), hx, hy) = end_xy(it, w, exprs)?;
    if hx != hy {
        return Err(fail(
            it,
            "You must specify both X and Y coordinates for Control Points",
        ));
    }
    // rs274 reads a missing P as -1.
    let p = value(it, w, block, 'P', exprs)?.unwrap_or(-1.0);
    let l = value(it, w, block, 'L', exprs)?;
    let gathered = !it.splines.points.is_empty();
    if !hx && p > 0.0 && gathered {
        return Err(fail(
            it,
            "Can specify P without X and Y only for the first control point",
        ));
    }
    if p <= 0.0 && gathered {
        return Err(fail(
            it,
            "Must specify positive weight P for every Control Point",
        ));
    }
    if it.state.feed_mode == FeedMode::PerMinute && it.state.feed == 0.0 {
        return Err(it.error_at(
            it.span,
            Code::NoFeedRate,
            "Cannot make a NURBS with 0 feedrate",
        ));
    }
    if !in_nurbs_mode(it) {
        it.splines.points.clear();
    }
    if it.splines.points.is_empty() {
        let here = crate::interp::host::MotionHost::position(it);
        let weight = if !hx && p > 0.0 { p } else { 1.0 };
        it.splines.points.push(NurbsPoint {
            x: here[0],
            y: here[1],
            w: weight,
        });
        it.splines.order = 3;
        it.splines.started = Some(block.span);
    }
    if let Some(l) = l.filter(|l| *l > 3.0) {
        it.splines.order = l as u32;
    }
    if hx {
        it.splines.points.push(NurbsPoint { x, y, w: p });
    }
    it.cycles.cancel();
    // The modal motion is the spec's control-point code (G5.2).
    let point = crate::dialect::Meaning::Machine(crate::dialect::MachineFn::Spline(2));
    if let Some(c) = it.spec.code_for(point) {
        it.state.motion = ModalMotion::Move(crate::ir::MotionKind::Other(c.code));
    }
    Ok(())
}

/// G5.3: the gathered points as one NURBS_FEED.
pub(super) fn nurbs_end(it: &mut Interp<'_, '_>) -> Result<(), Stop> {
    if !in_nurbs_mode(it) {
        return Err(fail(it, "Cannot use G5.3 without G5.2 first"));
    }
    let order = it.splines.order;
    if it.splines.points.len() < order as usize {
        return Err(fail(
            it,
            format!(
                "You must specify a number of control points at least equal to the order L = {order}"
            ),
        ));
    }
    let points = std::mem::take(&mut it.splines.points);
    it.splines.started = None;
    feed(it, points, order);
    it.state.motion = ModalMotion::None;
    it.splines.no_motion_code = true;
    Ok(())
}

/// Called when a block sets another motion, or the program ends, while
/// G5.2 points are gathered: rs274 drops them silently; cncc says so.
pub fn leaving_nurbs(it: &mut Interp<'_, '_>) {
    if !in_nurbs_mode(it) {
        return;
    }
    if let Some(span) = it.splines.started.take() {
        let n = it.splines.points.len();
        it.diags.push(
            Diagnostic::new(
                Code::NurbsAbandoned,
                format!("{n} NURBS control points gathered by G5.2 are never cut"),
            )
            .primary(it.span, "G5.2 ends here without G5.3")
            .secondary(span, "the points start here")
            .help("end the G5.2 block with G5.3 to cut the curve"),
        );
    }
}
