//! Holes into ROUND_HOLE features and drilling operations (see [`hole`]
//! for what the moves tell). A later drilling operation at the same X Y
//! (ream after drill) is another operation of the same hole.
//!
//! * Diameter: the tool's diameter (the largest of the hole's tools;
//!   centre and spot drills and countersinks do not size a hole once
//!   another tool has, nor after).
//! * Depth, from the top surface at the hole: a hole whose full diameter
//!   reaches the stock's bottom is THROUGH with the stock's thickness as
//!   depth; else a drill (twist, tapered, centre, spot drill, or a tool
//!   whose kind is not known) leaves a CONICAL bottom, tip angle 118°
//!   (the common twist-drill point; the program does not tell it), and
//!   the depth excludes the cone (ISO 14649-10: the depth plane is at the
//!   end of the cylinder); other tools leave a FLAT bottom.
//! * `retract_plane`: where the first feed starts (the R plane), in the
//!   feature's frame.
//! * The hole starts at the top surface, or at the floor of a pocket or
//!   slot cut before round its centre (a hole drilled in a pocket floor);
//!   the placement is there. (A pocket's wall box is used for the test.)
//!
//! [`hole`]: super::hole

use super::build::{machine_functions, placement, plane, r6, technology, tol};
use super::hole::{hole_op, HoleCut, HoleOp};
use super::{Known, Raiser};
use crate::stepnc::model::*;
use crate::toolpath::Move;

/// The drill point angle assumed, degrees.
pub const TIP_ANGLE: f64 = 118.0;

pub fn raise(r: &mut Raiser, h: &HoleCut, t: i64, moves: &[Move]) {
    let Some(rad) = r.radius(t) else {
        return super::freeform::raise(r, t, moves, "the tool's diameter is unknown; the hole");
    };
    let tool_id = (r.tool)(t);
    if h.tapping {
        // A tool that taps is a tap, of the hand its spindle turned in.
        if let Some(tl) = r.project.tools.get_mut(tool_id.index()) {
            tl.body.kind = ToolBodyKind::Tap;
            tl.body.hand_of_cut = Some(if h.spindle < 0.0 {
                Hand::Left
            } else {
                Hand::Right
            });
        }
    }
    let kind = match h.tapping {
        true => Some(ToolBodyKind::Tap),
        false => r
            .project
            .tools
            .get(tool_id.index())
            .map(|tl| tl.body.kind.clone()),
    };
    if !h.tapping && matches!(kind, Some(ToolBodyKind::Tap)) {
        let what = "a tap's moves without the spindle reversed";
        return super::freeform::raise(r, t, moves, what);
    }
    // Holes by position on a 1 µm grid: programs drill thousands.
    let key = (
        (h.xy[0] * 1e3).round() as i64,
        (h.xy[1] * 1e3).round() as i64,
    );
    let sizing = sizes_hole(kind.as_ref());
    let (feature, name) = match r.holes.get(&key).copied() {
        Some((f, sized)) => {
            if sizing {
                deepen(r, f, h, rad, kind.as_ref(), !sized);
                r.holes.insert(key, (f, true));
            }
            (f, r.project.features[f.index()].id.clone())
        }
        None => {
            let name = r.name("HOLE");
            let f = new_hole(r, &name, h, rad, kind.as_ref());
            r.holes.insert(key, (f, sizing));
            (f, name)
        }
    };
    let (op_kind, verb) = operation(h, kind.as_ref(), surface_at(r, h.xy));
    let cuts: Vec<&Move> = moves.iter().filter(|m| m.is_feed()).collect();
    let mut technology = technology(&cuts[..1]);
    // Tapping: the pitch is the feed over the speed, the two synchronised.
    technology.synchronize_spindle_with_feed = h.tapping;
    let op = Operation {
        id: format!("{verb} {name}"),
        toolpath: None,
        tool_direction: None,
        retract_plane: Some(r6(h.start_z - surface_at(r, h.xy))),
        start_point: None,
        tool: (r.tool)(t),
        technology,
        machine_functions: machine_functions(&cuts),
        overcut_length: None,
        kind: op_kind,
    };
    r.add_operation(feature, op);
}

fn is_drill(kind: Option<&ToolBodyKind>) -> bool {
    matches!(
        kind,
        None | Some(
            ToolBodyKind::TwistDrill
                | ToolBodyKind::TaperedDrill
                | ToolBodyKind::CenterDrill
                | ToolBodyKind::Spotdrill
        )
    )
}

/// Depth below the top and bottom condition.
fn depth_and_bottom(
    r: &Raiser,
    h: &HoleCut,
    rad: f64,
    kind: Option<&ToolBodyKind>,
) -> (f64, HoleBottom) {
    let cone = if is_drill(kind) {
        rad / (TIP_ANGLE / 2.0).to_radians().tan()
    } else {
        0.0
    };
    let cylinder_end = h.bottom + cone;
    if let Some((_, zmin, _)) = r.stock_box() {
        if cylinder_end <= zmin + 1e-6 {
            return (surface_at(r, h.xy) - zmin, HoleBottom::Through);
        }
    }
    let bottom = if cone > 0.0 {
        HoleBottom::Conical {
            tip_angle: TIP_ANGLE,
            tip_radius: None,
        }
    } else {
        HoleBottom::Flat
    };
    (surface_at(r, h.xy) - cylinder_end, bottom)
}

fn new_hole(
    r: &mut Raiser,
    name: &str,
    h: &HoleCut,
    rad: f64,
    kind: Option<&ToolBodyKind>,
) -> FeatureId {
    let (depth, bottom) = depth_and_bottom(r, h, rad, kind);
    let f = Feature {
        id: name.to_string(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(name, [h.xy[0], h.xy[1], surface_at(r, h.xy)], [1.0, 0.0]),
        depth: Some(plane(&format!("{name} DEPTH"), [0.0, 0.0, -r6(depth)])),
        kind: FeatureKind::RoundHole {
            diameter: tol(2.0 * rad),
            change_in_diameter: None,
            bottom,
        },
    };
    r.add_feature(f)
}

/// A further operation on a hole: a larger tool widens it, a deeper one
/// deepens it.
/// The surface a hole starts from: the floor of the deepest pocket or
/// slot already cut round its centre, else the top.
fn surface_at(r: &Raiser, xy: [f64; 2]) -> f64 {
    let inside = |b: [f64; 4]| xy[0] > b[0] && xy[0] < b[2] && xy[1] > b[1] && xy[1] < b[3];
    let mut z = r.top;
    for k in &r.known {
        let floor = match k {
            Known::Pocket { ops, .. } => ops
                .last()
                .filter(|(_, w, _)| inside(w.bbox()))
                .map(|(_, _, b)| *b),
            Known::Slot { ops, .. } => ops
                .last()
                .filter(|(_, g)| in_slot(g, xy))
                .map(|(_, g)| g.bottom),
            Known::Face { .. } | Known::Profile { .. } => None,
        };
        z = floor.map_or(z, |f| z.min(f));
    }
    z
}

fn in_slot(g: &super::slot::SlotGeom, xy: [f64; 2]) -> bool {
    let (dx, dy) = (xy[0] - g.start[0], xy[1] - g.start[1]);
    let along = dx * g.dir[0] + dy * g.dir[1];
    let across = dx * g.dir[1] - dy * g.dir[0];
    (0.0..=g.length).contains(&along) && across.abs() < g.width / 2.0
}

/// Does the tool give the hole its size? Centre and spot drills and
/// countersinks only mark or chamfer it.
fn sizes_hole(kind: Option<&ToolBodyKind>) -> bool {
    !matches!(
        kind,
        Some(ToolBodyKind::CenterDrill | ToolBodyKind::Spotdrill | ToolBodyKind::Countersink)
    )
}

/// `first`: the first operation that sizes the hole (after a spot
/// drill): its diameter and depth replace the spot's.
fn deepen(
    r: &mut Raiser,
    f: FeatureId,
    h: &HoleCut,
    rad: f64,
    kind: Option<&ToolBodyKind>,
    first: bool,
) {
    let (depth, bottom) = depth_and_bottom(r, h, rad, kind);
    let feat = &mut r.project.features[f.index()];
    if let FeatureKind::RoundHole {
        diameter,
        bottom: b,
        ..
    } = &mut feat.kind
    {
        if first || 2.0 * rad > diameter.nominal {
            *diameter = tol(2.0 * rad);
        }
        let z = feat
            .depth
            .as_ref()
            .map_or(0.0, |d| d.position.location.xyz[2]);
        if first || depth > -z + 1e-6 {
            if let Some(d) = feat.depth.as_mut() {
                d.position.location.xyz[2] = -r6(depth);
            }
            *b = bottom;
        }
    }
}

/// `surface`: the hole's top, from which MULTISTEP_DRILLING's
/// `first_depth` is measured (as the posts read it).
fn operation(
    h: &HoleCut,
    kind: Option<&ToolBodyKind>,
    surface: f64,
) -> (OperationKind, &'static str) {
    let drill = DrillCommon {
        dwell_time_bottom: h.dwell_bottom,
        feed_on_retract: h.feed_out.then_some(1.0),
        ..DrillCommon::default()
    };
    let boring = |reaming, drill| OperationKind::Boring {
        reaming,
        drill,
        spindle_stop_at_bottom: h.spindle_stop,
        depth_of_testcut: None,
        waiting_position: None,
    };
    if h.tapping {
        let drill = DrillCommon {
            feed_on_retract: None,
            ..drill
        };
        let op = OperationKind::Tapping {
            drill,
            compensation_chuck: false,
        };
        return (op, "TAP");
    }
    match kind {
        Some(ToolBodyKind::CenterDrill | ToolBodyKind::Spotdrill) => {
            return (OperationKind::CenterDrilling(drill), "CENTER DRILL")
        }
        Some(ToolBodyKind::Countersink) => {
            return (OperationKind::CounterSinking(drill), "COUNTERSINK")
        }
        Some(ToolBodyKind::Reamer | ToolBodyKind::TaperedReamer) => {
            return (boring(true, drill), "REAM")
        }
        _ => {}
    }
    match hole_op(h) {
        HoleOp::Drilling => (OperationKind::Drilling(drill), "DRILL"),
        HoleOp::Reaming => (boring(true, drill), "REAM"),
        HoleOp::Boring => (boring(false, drill), "BORE"),
        HoleOp::Multistep => {
            let (p0, p1) = (h.pecks[0], h.pecks[1]);
            let op = OperationKind::MultistepDrilling {
                drill,
                retract_distance: r6(h.first_retract_to.unwrap_or(p0) - p0),
                first_depth: r6(surface - p0),
                depth_of_step: r6(p0 - p1),
                dwell_time_step: None,
            };
            (op, "PECK DRILL")
        }
    }
}
