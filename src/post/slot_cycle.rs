//! A straight slot with radiused ends as the target's slot cycle
//! (`slot.j2`, Heidenhain CYCL DEF 253 SLOT MILLING) where it has one:
//! the cycle mills a slot with full-round ends, centred on the position
//! it is called at (Q367 0), turned by Q374. Its length is the whole
//! slot: the course of travel plus the width, read as in [`super::slots`]
//! ([?] whether STEP-NC's travel runs between the end arcs' centres).
//! Slots the cycle cannot make (flat or open ends, sloped walls, curved
//! travel, a width the tool does not leave room in) fall back to the
//! explicit toolpath.

use super::frame::Frame;
use super::milling::{spindle_cw, Cut};
use super::plan::Step;
use super::step::feed;
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::*;

/// Why the slot cycle does not make this slot; None when it does.
pub fn why_not(s: &Step<'_>) -> Option<&'static str> {
    let Some((_, _, width)) = geometry(s) else {
        return Some(
            "the slot cycle cuts straight slots with both ends radiused, square to the tool",
        );
    };
    if width <= s.tool.body.dimension.diameter + 1e-9 {
        return Some("the slot cycle needs a slot wider than the tool");
    }
    if !matches!(s.op.kind, OperationKind::BottomAndSideMilling { .. }) {
        return Some("the slot cycle is posted for bottom and side milling only");
    }
    None
}

/// Writes the slot cycle; `Ok(false)` when the slot is not one it makes
/// ([`why_not`] says why).
pub fn write(w: &mut Writer<'_>, s: &Step<'_>, c: &Cut<'_>) -> Result<bool, PostError> {
    if why_not(s).is_some() {
        return Ok(false);
    }
    let Some((frame, length, width)) = geometry(s) else {
        return Ok(false);
    };
    let (fal, fald) = match (c.finish, s.roughed_by) {
        (false, _) => (c.allow_side, c.allow_bottom),
        (true, Some(r)) => left_by(r),
        (true, None) => (0.0, 0.0),
    };
    let vari = match (c.finish, s.roughed_by.is_some()) {
        (false, _) => "1",
        (true, true) => "2",
        (true, false) => "0",
    };
    let ccw = c.ccw(spindle_cw(s)?);
    let f = &w.fmt;
    let infeed = f.len(c.ap.unwrap_or(s.top - s.bottom));
    let speed = f.feed(feed(s)?);
    let v = Vals::new()
        .set("clear", f.len(s.clear))
        .set("top", f.len(s.top))
        .set("sdis", f.len(s.sdis))
        .set("bottom", f.len(s.bottom))
        .set("cx", f.len(frame.origin[0]))
        .set("cy", f.len(frame.origin[1]))
        .set("leng", f.len(length))
        .set("wid", f.len(width))
        .set("angle", f.angle(frame.angle_deg()))
        .set("vari", vari)
        .set("fal", f.len(fal))
        .set("fald", f.len(fald))
        .set("mid", infeed.clone())
        .set("midf", infeed)
        .set("feed", speed.clone())
        .set("plunge_feed", speed)
        .set("climb", if ccw { "1" } else { "0" })
        .set_derived("depth", f.len(s.bottom - s.top))
        .set_derived("clear_inc", f.len(s.clear - s.top));
    if !c.finish && c.allow_bottom > 0.0 && w.post.ignores("slot.j2", "fald") {
        w.not_carried("the floor allowance of the roughing pass (the cycle has none)")?;
    }
    w.comment("slot with radiused ends: the slot cycle, called at its centre")?;
    w.emit("slot.j2", v)?;
    Ok(true)
}

/// The slot's centre frame (x along the travel), whole length and width,
/// when it is straight, in the feature's plane, U-shaped with vertical
/// walls and radiused at both ends.
fn geometry(s: &Step<'_>) -> Option<(Frame, f64, f64)> {
    let FeatureKind::Slot {
        course_of_travel:
            TravelPath::Linear {
                placement,
                distance,
                direction,
            },
        swept_shape,
        end_conditions,
    } = &s.feature.kind
    else {
        return None;
    };
    let width = match swept_shape {
        OpenProfile::RoundedU { width, .. } => width.nominal,
        OpenProfile::SquareU {
            width,
            first_radius,
            first_angle,
            second_radius,
            second_angle,
            ..
        } if super::slots::upright(*first_angle)
            && super::slots::upright(*second_angle)
            && first_radius.as_ref().map_or(0.0, |t| t.nominal) <= 0.0
            && second_radius.as_ref().map_or(0.0, |t| t.nominal) <= 0.0 =>
        {
            width.nominal
        }
        _ => return None,
    };
    let radiused = end_conditions.len() == 2
        && end_conditions
            .iter()
            .all(|e| matches!(e, SlotEnd::Radiused));
    let u = direction.ratios;
    let n = (u[0] * u[0] + u[1] * u[1]).sqrt();
    if !radiused || n < 1e-9 || u[2].abs() > 1e-9 || width <= 0.0 {
        return None;
    }
    let (ux, uy) = (u[0] / n, u[1] / n);
    let half = distance.nominal / 2.0;
    let local = Frame {
        origin: [ux * half, uy * half, 0.0],
        x: [ux, uy, 0.0],
        y: [-uy, ux, 0.0],
        z: [0.0, 0.0, 1.0],
    };
    let path = match placement {
        Some(p) => s.frame.then(&Frame::from_placement(p)),
        None => s.frame,
    };
    let frame = path.then(&local);
    frame
        .is_vertical()
        .then_some((frame, distance.nominal + width, width))
}

/// The side and floor allowances a roughing operation left.
fn left_by(op: &Operation) -> (f64, f64) {
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
