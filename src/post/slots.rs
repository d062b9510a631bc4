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

/// A straight slot read from its feature: where it lies and how it ends.
pub struct Parts<'p> {
    pub geom: SlotGeom,
    pub ends: &'p [SlotEnd],
    /// The profile has floor fillets (the tool's corner makes them).
    pub fillets: bool,
}

impl Parts<'_> {
    pub fn radiused(&self) -> bool {
        self.ends.len() == 2 && self.ends.iter().all(|e| matches!(e, SlotEnd::Radiused))
    }
}

/// The slot's geometry in workpiece coordinates, or why it cannot be
/// posted at all.
/// A `SQUARE_U_PROFILE` wall angle that means an upright wall. ISO
/// 14649-10 measures it against the profile's local z axis (NIST
/// STEPNC++'s attribute text), so 0 is upright, and real plans write 0.0;
/// 90 (measured from the floor, as cncc's raiser wrote before) is read
/// as upright too [?: a wall at 90 degrees to z would be no wall]; unset
/// is upright (W0803 at reading).
pub fn upright(angle: Option<f64>) -> bool {
    angle.is_none_or(|a| a.abs() < 1e-9 || (a - 90.0).abs() < 1e-9)
}

pub fn parts<'p>(s: &Step<'p>) -> Result<Parts<'p>, PostError> {
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
    let (width, fillets) = match swept_shape {
        // The profile's placement only sets the cross-section on the path.
        OpenProfile::RoundedU { width, .. } => (width.nominal, false),
        OpenProfile::SquareU {
            width,
            first_radius,
            first_angle,
            second_radius,
            second_angle,
            ..
        } => {
            let radius = |r: &Option<Toleranced>| r.as_ref().map_or(0.0, |t| t.nominal);
            if !upright(*first_angle) || !upright(*second_angle) {
                return Err(PostError::unsupported(
                    &s.feature.id,
                    "a slot with sloped walls",
                ));
            }
            (
                width.nominal,
                radius(first_radius) > 0.0 || radius(second_radius) > 0.0,
            )
        }
        _ => {
            return Err(PostError::unsupported(
                &s.feature.id,
                "a slot whose cross-section is not a U profile",
            ))
        }
    };
    let frame = line_frame(s, placement, direction, distance.nominal / 2.0, LEAVES)?;
    Ok(Parts {
        geom: SlotGeom {
            frame,
            travel: distance.nominal,
            width,
        },
        ends: end_conditions,
        fillets,
    })
}

/// A straight slot's frame (origin at the middle of its course of
/// travel, x along it, y to its left) and its length, whatever its
/// cross-section.
pub fn slot_frame(s: &Step<'_>) -> Result<(Frame, f64), PostError> {
    let FeatureKind::Slot {
        course_of_travel:
            TravelPath::Linear {
                placement,
                distance,
                direction,
            },
        ..
    } = &s.feature.kind
    else {
        return Err(PostError::unsupported(
            &s.feature.id,
            "a slot whose course of travel is not a straight path from its origin",
        ));
    };
    Ok((
        line_frame(s, placement, direction, distance.nominal / 2.0, LEAVES)?,
        distance.nominal,
    ))
}

const LEAVES: &str = "a slot whose course of travel leaves the feature's plane";

/// The frame of a straight path in the feature's plane: x along
/// `direction`, y to its left, z up, origin `along` mm from the
/// placement's origin on x; `what` is the refusal when the path leaves
/// the plane.
pub(super) fn line_frame(
    s: &Step<'_>,
    placement: &Option<Axis2Placement>,
    direction: &Direction,
    along: f64,
    what: &str,
) -> Result<Frame, PostError> {
    let u = direction.ratios;
    let n = (u[0] * u[0] + u[1] * u[1]).sqrt();
    if n < 1e-9 || u[2].abs() > 1e-9 {
        return Err(PostError::unsupported(&s.feature.id, what));
    }
    let (ux, uy) = (u[0] / n, u[1] / n);
    let local = Frame {
        origin: [ux * along, uy * along, 0.0],
        x: [ux, uy, 0.0],
        y: [-uy, ux, 0.0],
        z: [0.0, 0.0, 1.0],
    };
    let path = match placement {
        Some(p) => s.frame.then(&Frame::from_placement(p)),
        None => s.frame,
    };
    Ok(path.then(&local))
}

/// Slots that the grouping found alike (same size, depth and operation):
/// one SLOT1/LONGHOLE call when they form a circle the cycle places
/// radially ([`super::slot_circle`]) and the cycle fits, else each slot
/// on its own.
pub fn write_group(w: &mut Writer<'_>, steps: &[&Step<'_>], c: &Cut<'_>) -> Result<(), PostError> {
    if steps.len() > 1 {
        let all: Result<Vec<Parts<'_>>, PostError> = steps.iter().map(|s| parts(s)).collect();
        let all = all?;
        let why = match super::slot_circle::circle(&all) {
            None => "the slots do not lie radially on one circle".to_string(),
            Some(circle) => {
                let first = &all[0];
                note_fillets(w, first)?;
                match try_cycle(w, steps[0], c, &first.geom, first.radiused(), Some(&circle))? {
                    None => return Ok(()),
                    Some(why) => why,
                }
            }
        };
        w.comment(&format!("{} alike slots, one by one: {why}", steps.len()))?;
    }
    for s in steps {
        write(w, s, c)?;
    }
    Ok(())
}

fn note_fillets(w: &mut Writer<'_>, p: &Parts<'_>) -> Result<(), PostError> {
    if p.fillets {
        w.not_carried("the slot's floor fillets: the tool's corner makes them")?;
    }
    Ok(())
}

pub fn write(w: &mut Writer<'_>, s: &Step<'_>, c: &Cut<'_>) -> Result<(), PostError> {
    let p = parts(s)?;
    note_fillets(w, &p)?;
    let d = s.tool.body.dimension.diameter;
    let g = &p.geom;
    let (length, corner) = outline(w, s, p.ends, g.travel, g.width, d)?;
    let why = match try_cycle(w, s, c, g, p.radiused(), None)? {
        None => return Ok(()),
        Some(why) => why,
    };
    let shape = Shape::Rect(RectPocket {
        length,
        width: g.width,
        corner_radius: corner,
    });
    w.comment(&format!("slot: explicit toolpath ({why})"))?;
    super::pockets::write(w, s, c, &shape, &g.frame, false)
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

#[cfg(test)]
mod tests {
    use super::upright;

    #[test]
    fn square_u_wall_angles_read_against_the_tool_axis() {
        // 0: along the profile's z axis (ISO 14649-10); unset; 90 as cncc
        // wrote it before [?].
        assert!(upright(None) && upright(Some(0.0)) && upright(Some(90.0)));
        // A draft of 30 degrees (or GRIMA's 0.5236, radians) is a slope.
        assert!(!upright(Some(30.0)) && !upright(Some(0.5235987755982988)));
    }
}
