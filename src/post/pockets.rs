//! A closed pocket, rectangular or circular: POCKET1/POCKET2 (centre-
//! cutting tool) or POCKET3/POCKET4 (any tool, insertion strategy, floor
//! allowance) where the target has them (reference/posting.md, NIST
//! STEPNC++'s parameter mapping), else explicit contour-parallel
//! toolpaths from the inside out. A comment before the call says which
//! kind of cycle was chosen and why.

use super::frame::Frame;
use super::milling::{explicit_moves, layers, spindle_cw, Cut};
use super::paths::pocket::{self, PocketCut, Shape};
use super::plan::Step;
use super::step::{feed, spindle_rpm};
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    shape: &Shape,
    frame: &Frame,
    cycles: bool,
) -> Result<(), PostError> {
    let ccw = c.ccw(spindle_cw(s)?);
    // Finishing removes what an earlier roughing left.
    let (fal, fald) = match (c.finish, s.roughed_by) {
        (false, _) => (c.allow_side, c.allow_bottom),
        (true, Some(r)) => allowances(r),
        (true, None) => (0.0, 0.0),
    };
    let pcut = pocket_cut(s, c)?;
    pocket::check(shape, &pcut).map_err(|e| PostError::geometry(&s.feature.id, e))?;
    // Haas G12/G13 plunge at the centre: centre-cutting tools only.
    let g12 = cycles && w.post.has("pocket_circ_g12.j2") && cuts_across_centre(&s.tool.body.kind);
    if let (true, Shape::Circle { diameter }) = (g12, shape) {
        return super::pocket_g12::write(w, s, c, *diameter, frame, &pcut);
    }
    let centre_cutting = cuts_across_centre(&s.tool.body.kind);
    let (centre_cycle, any_cycle) = match shape {
        Shape::Rect(_) => ("pocket_rect.j2", "pocket_rect_any.j2"),
        Shape::Circle { .. } => ("pocket_circ.j2", "pocket_circ_any.j2"),
    };
    let use_p1 = cycles && w.post.has(centre_cycle) && centre_cutting;
    let use_p3 = cycles && w.post.has(any_cycle);
    if !use_p1 && !use_p3 {
        if !matches!(
            c.strategy,
            None | Some(Strategy::ContourParallel { .. }) | Some(Strategy::ContourSpiral { .. })
        ) {
            w.not_carried("the operation's strategy: the pocket is cleared contour-parallel")?;
        }
        return explicit_moves(w, s, frame, |sink| pocket::moves(shape, &pcut, sink));
    }
    let f = w.fmt.feed(feed(s)?);
    let v = Vals::new()
        .set("clear", w.fmt.len(s.clear))
        .set("top", w.fmt.len(s.top))
        .set("sdis", w.fmt.len(s.sdis))
        .set("bottom", w.fmt.len(s.bottom))
        .set("cx", w.fmt.len(frame.origin[0]))
        .set("cy", w.fmt.len(frame.origin[1]))
        .set("mid", w.fmt.len(c.ap.unwrap_or(s.top - s.bottom)))
        .set("fal", w.fmt.len(fal))
        .set("ffp1", f.clone())
        .set("ffd", f.clone())
        .set_derived("depth", w.fmt.len(s.bottom - s.top))
        .set_derived("clear_inc", w.fmt.len(s.clear - s.top));
    let v = match shape {
        Shape::Rect(r) => v
            .set("leng", w.fmt.len(r.length))
            .set("wid", w.fmt.len(r.width))
            .set("crad", w.fmt.len(r.corner_radius))
            .set("angle", w.fmt.angle(frame.angle_deg().rem_euclid(180.0))),
        Shape::Circle { diameter } => v
            .set("prad", w.fmt.len(diameter / 2.0))
            .set_derived("diameter", w.fmt.len(*diameter))
            .set_derived("plunge", if helical(c.approach) { "1" } else { "0" }),
    };
    let units = match (c.finish, s.roughed_by.is_some()) {
        (false, _) => 1,
        (true, true) => 2,
        (true, false) => 0,
    };
    if use_p1 {
        w.comment("the tool cuts across its centre: the cycle for centre-cutting tools")?;
        if !c.finish && c.allow_bottom > 0.0 {
            w.not_carried("the floor allowance of the roughing pass (the cycle has none)")?;
        }
        let v = v
            .set("cdir", if ccw { "3" } else { "2" })
            .set("vari", units.to_string())
            .set("midf", w.fmt.len(c.ap.unwrap_or(s.top - s.bottom)))
            .set("ffp2", f)
            .set("ssf", w.fmt.feed(spindle_rpm(s)?.abs()));
        return w.emit(centre_cycle, v);
    }
    w.comment("the tool does not cut across its centre: the cycle for any tool")?;
    let (tens, rad1, dp1) = insertion(c.approach);
    let cdir = match cutmode(c.strategy) {
        Some(CutMode::Climb) => "0",
        Some(CutMode::Conventional) => "1",
        None if ccw => "3",
        None => "2",
    };
    let v = v
        .set("fald", w.fmt.len(fald))
        .set("cdir", cdir)
        .set("vari", (tens * 10 + units).to_string())
        .set("mida", w.fmt.len(pcut.stepover))
        .set("rad1", w.fmt.len(rad1))
        .set("dp1", w.fmt.len(dp1));
    w.emit(any_cycle, v)
}

/// The explicit pocket path's parameters of a step and its cut.
pub(super) fn pocket_cut(s: &Step<'_>, c: &Cut<'_>) -> Result<PocketCut, PostError> {
    let d = s.tool.body.dimension.diameter;
    Ok(PocketCut {
        tool_radius: d / 2.0,
        stepover: c.stepover(d),
        allowance_side: if c.finish { 0.0 } else { c.allow_side },
        levels: layers(s, c, if c.finish { 0.0 } else { c.allow_bottom }),
        walls_only_above_bottom: c.finish && s.roughed_by.is_some(),
        ccw: c.ccw(spindle_cw(s)?),
        clear: s.clear,
        r_plane: s.top + s.sdis,
    })
}

fn allowances(op: &Operation) -> (f64, f64) {
    match &op.kind {
        OperationKind::BottomAndSideMilling {
            allowance_side,
            allowance_bottom,
            ..
        } => (
            allowance_side.unwrap_or(0.0),
            allowance_bottom.unwrap_or(0.0),
        ),
        _ => (0.0, 0.0),
    }
}

fn cutmode(s: Option<&Strategy>) -> Option<CutMode> {
    match s? {
        Strategy::ContourParallel { cutmode, .. }
        | Strategy::ContourSpiral { cutmode, .. }
        | Strategy::BidirectionalContour { cutmode, .. }
        | Strategy::Unidirectional { cutmode, .. } => *cutmode,
        _ => None,
    }
}

/// The approach enters on a helix.
fn helical(a: Option<&ApproachRetract>) -> bool {
    matches!(a, Some(ApproachRetract::PlungeHelix { .. }))
}

/// POCKET3 insertion (VARI tens): 1 vertical at feed, 2 helical (RAD1
/// helix radius, DP1 depth per turn), 3 oscillating (RAD1 the angle).
fn insertion(a: Option<&ApproachRetract>) -> (u32, f64, f64) {
    match a {
        Some(ApproachRetract::PlungeHelix { radius, angle, .. }) => (
            2,
            *radius,
            2.0 * std::f64::consts::PI * radius * angle.to_radians().tan(),
        ),
        Some(ApproachRetract::PlungeRamp { angle, .. })
        | Some(ApproachRetract::PlungeZigzag { angle, .. }) => (3, *angle, 0.0),
        _ => (1, 0.0, 0.0),
    }
}

/// End mills cut across their centre; face mills and the rest do not
/// (ISO 14649-111 has no such attribute: the body type decides).
pub(super) fn cuts_across_centre(k: &ToolBodyKind) -> bool {
    matches!(
        k,
        ToolBodyKind::Endmill
            | ToolBodyKind::TaperedEndmill
            | ToolBodyKind::BallEndmill
            | ToolBodyKind::BullnoseEndmill
    )
}
