//! Straight slots, posted as explicit toolpaths on every target: the slot
//! is the pocket its outline makes (radiused ends: a stadium; flat ends:
//! a rectangle with the end's corner radius; open ends: a rectangle run
//! out past the ends by the tool diameter), cleared contour-parallel
//! from its centre line outwards (a slot as wide as the tool is one pass
//! per layer along the centre line).
//!
//! Where the target has a slot cycle that fits (840D SLOT1/LONGHOLE,
//! [`super::slot_cycles`]) the slot is posted as that cycle instead, else
//! the comment before the moves says why not.
//! Uncertain [?]: whether a radiused slot's course of travel runs between
//! the centres of its end arcs (read so here: the outline is the travel
//! length plus the width) or spans the whole slot.

use super::frame::Frame;
use super::milling::Cut;
use super::paths::pocket::{RectPocket, Shape};
use super::plan::Step;
use super::slot_cycles::{try_cycle, SlotGeom};
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(w: &mut Writer<'_>, s: &Step<'_>, c: &Cut<'_>) -> Result<(), PostError> {
    let FeatureKind::Slot {
        course_of_travel,
        swept_shape,
        end_conditions,
    } = &s.feature.kind
    else {
        return Err(PostError::unsupported(&s.feature.id, "this feature"));
    };
    if !matches!(s.op.kind, OperationKind::BottomAndSideMilling { .. }) {
        return Err(PostError::unsupported(
            &s.op.id,
            "a slot not cut by bottom and side milling",
        ));
    }
    let TravelPath::Linear {
        placement,
        distance,
        direction,
    } = course_of_travel
    else {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a slot whose course of travel is not a straight path from its origin",
        ));
    };
    let width = match swept_shape {
        // The profile's placement only sets the cross-section on the path.
        OpenProfile::RoundedU { width, .. } => width.nominal,
        OpenProfile::SquareU {
            width,
            first_radius,
            first_angle,
            second_radius,
            second_angle,
            ..
        } => {
            if (first_angle - 90.0).abs() > 1e-9 || (second_angle - 90.0).abs() > 1e-9 {
                return Err(PostError::unsupported(
                    &s.feature.id,
                    "a slot with sloped walls",
                ));
            }
            if first_radius.nominal > 0.0 || second_radius.nominal > 0.0 {
                w.not_carried("the slot's floor fillets: the tool's corner makes them")?;
            }
            width.nominal
        }
        _ => {
            return Err(PostError::unsupported(
                &s.feature.id,
                "a slot whose cross-section is not a U profile",
            ))
        }
    };
    let d = s.tool.body.dimension.diameter;
    let (length, corner) = outline(w, s, end_conditions, distance.nominal, width, d)?;
    let u = direction.ratios;
    let n = (u[0] * u[0] + u[1] * u[1]).sqrt();
    if n < 1e-9 || u[2].abs() > 1e-9 {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a slot whose course of travel leaves the feature's plane",
        ));
    }
    let (ux, uy) = (u[0] / n, u[1] / n);
    let local = Frame {
        origin: [
            ux * distance.nominal / 2.0,
            uy * distance.nominal / 2.0,
            0.0,
        ],
        x: [ux, uy, 0.0],
        y: [-uy, ux, 0.0],
        z: [0.0, 0.0, 1.0],
    };
    let path = match placement {
        Some(p) => s.frame.then(&Frame::from_placement(p)),
        None => s.frame,
    };
    let frame = path.then(&local);
    let radiused = end_conditions.len() == 2
        && end_conditions
            .iter()
            .all(|e| matches!(e, SlotEnd::Radiused));
    let geom = SlotGeom {
        frame,
        travel: distance.nominal,
        width,
    };
    let why = match try_cycle(w, s, c, &geom, radiused)? {
        None => return Ok(()),
        Some(why) => why,
    };
    let shape = Shape::Rect(RectPocket {
        length,
        width,
        corner_radius: corner,
    });
    w.comment(&format!("slot: explicit toolpath ({why})"))?;
    super::pockets::write(w, s, c, &shape, &frame, false)
}

/// The outline's length and corner radius from the end conditions.
fn outline(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    ends: &[SlotEnd],
    travel: f64,
    width: f64,
    tool: f64,
) -> Result<(f64, f64), PostError> {
    let all = |f: fn(&SlotEnd) -> bool| ends.len() == 2 && ends.iter().all(f);
    if all(|e| matches!(e, SlotEnd::Radiused)) {
        return Ok((travel + width, width / 2.0));
    }
    if all(|e| matches!(e, SlotEnd::Open)) {
        // Open at both ends: the tool runs out past each end by its
        // diameter, where the square corners cut nothing.
        return Ok((travel + 2.0 * tool, 0.0));
    }
    let flat: Vec<(f64, f64)> = ends
        .iter()
        .filter_map(|e| match e {
            SlotEnd::Flat {
                corner_radius1,
                corner_radius2,
            } => Some((corner_radius1.nominal, corner_radius2.nominal)),
            _ => None,
        })
        .collect();
    if ends.len() == 2 && flat.len() == 2 {
        let r = flat[0].0;
        if flat
            .iter()
            .any(|(a, b)| (a - r).abs() > 1e-9 || (b - r).abs() > 1e-9)
        {
            w.not_carried("different corner radii at the slot's ends: the first is used")?;
        }
        return Ok((travel, r));
    }
    Err(PostError::unsupported(
        &s.feature.id,
        "a slot without two end conditions, or with woodruff, loop or mixed ends,",
    ))
}
