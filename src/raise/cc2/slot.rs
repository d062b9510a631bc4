//! Straight slots: a cut whose horizontal moves all run along one line
//! (one pass, back and forth, in layers). Width = the tool's diameter;
//! `course_of_travel` is a LINEAR_PATH from the slot's first end (the end
//! with the lower X, or lower Y for a slot along Y) over the distance
//! between the end centres; the cross-section is a SQUARE_U_PROFILE with
//! the tool's corner radius (0 for a flat end mill) and upright walls
//! (angles written as 90° [?: ISO 14649-10 gives the walls' angles but
//! the samples we have show no SQUARE_U_PROFILE to confirm the
//! convention]). An end whose tool envelope leaves the stock is OPEN,
//! else RADIUSED (a milled end is round with the tool's radius). Strategy
//! CENTER_MILLING; a slot cut by one operation gets
//! BOTTOM_AND_SIDE_FINISH_MILLING (a feature's last operation is its
//! finishing one, see [`super::pocket`]).

use super::build::{direction, machine_functions, placement, plane, r6, technology, tol};
use super::face::layer_steps;
use super::level::{split, MillCut};
use super::strategy::{approach, unit};
use super::Raiser;
use crate::stepnc::model::*;
use crate::toolpath::{Move, MoveKind};

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64) -> bool {
    let moves: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    let Some(first) = moves.first() else {
        return false;
    };
    let d = unit(first);
    let o = first.from;
    let off_line = |p: [f64; 3]| ((p[0] - o[0]) * d[1] - (p[1] - o[1]) * d[0]).abs() > 1e-3;
    let straight = moves
        .iter()
        .all(|mv| matches!(mv.kind, MoveKind::Line) && !off_line(mv.from) && !off_line(mv.to));
    if !straight || m.levels.iter().any(|l| !split(&l.moves).loops.is_empty()) {
        return false;
    }
    let d = if d[0] < -1e-9 || (d[0].abs() <= 1e-9 && d[1] < 0.0) {
        [-d[0], -d[1]]
    } else {
        d
    };
    let t = |p: [f64; 3]| (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1];
    let ts = moves.iter().flat_map(|mv| [t(mv.from), t(mv.to)]);
    let (lo, hi) = ts.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
        (a.min(x), b.max(x))
    });
    let at = |s: f64| [o[0] + d[0] * s, o[1] + d[1] * s];
    let (start, end) = (at(lo), at(hi));
    let bottom = m.deepest().z;
    let top = r.top;
    let name = r.name("SLOT");
    let edge = r.tool_edge_radius(m.tool);
    let end_type = |p: [f64; 2], out: f64| match r.stock_box() {
        Some((b, _, _)) => {
            let q = [p[0] + out * d[0] * rad, p[1] + out * d[1] * rad];
            let outside = q[0] < b[0] - 1e-6
                || q[0] > b[2] + 1e-6
                || q[1] < b[1] - 1e-6
                || q[1] > b[3] + 1e-6;
            if outside {
                SlotEnd::Open
            } else {
                SlotEnd::Radiused
            }
        }
        None => SlotEnd::Radiused,
    };
    let ends = vec![end_type(start, -1.0), end_type(end, 1.0)];
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [start[0], start[1], top], [1.0, 0.0]),
        depth: plane(&format!("{name} DEPTH"), [0.0, 0.0, r6(bottom - top)]),
        kind: FeatureKind::Slot {
            course_of_travel: TravelPath::Linear {
                placement: None,
                distance: tol(hi - lo),
                direction: direction("COURSE OF TRAVEL", [d[0], d[1], 0.0]),
            },
            swept_shape: OpenProfile::SquareU {
                placement: None,
                width: tol(2.0 * rad),
                first_radius: tol(edge),
                first_angle: 90.0,
                second_radius: tol(edge),
                second_angle: 90.0,
            },
            end_conditions: ends,
        },
    };
    let feature = r.add_feature(f);
    let op = Operation {
        id: format!("MILL {name}"),
        toolpath: None,
        tool_direction: None,
        retract_plane: super::strategy::retract_plane(&m.moves, top),
        start_point: None,
        tool: (r.tool)(m.tool),
        technology: technology(&moves),
        machine_functions: machine_functions(&moves),
        overcut_length: None,
        kind: OperationKind::BottomAndSideMilling {
            finish: true,
            milling: MillingCommon {
                approach: approach(&m.moves),
                retract: None,
                strategy: Some(Strategy::CenterMilling {
                    base: StrategyBase::default(),
                }),
            },
            axial_cutting_depth: layer_steps(m, top),
            radial_cutting_depth: Some(r6(2.0 * rad)),
            allowance_side: None,
            allowance_bottom: None,
        },
    };
    r.add_operation(feature, op);
    true
}
