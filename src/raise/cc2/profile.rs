//! General outside profiles: a cut that follows one closed loop per level
//! (nothing inside it) around the rest of the part: the outline the loop
//! leaves (the loop shrunk by the tool radius) holds every other cut of
//! the program, or the tool's envelope goes round the whole stock. The
//! boundary is that outline in the feature's frame (placed at its centre
//! on the top surface); `profile_swept_shape` is a LINEAR_PATH down the
//! tool axis over the depth [?: ISO 14649-10 names it a linear_path
//! without saying more; this follows its use for swept profiles].
//! Operation SIDE_FINISH_MILLING, strategy CONTOUR_PARALLEL with the
//! loop's rotation and the cut mode for material inside the loop.

use super::build::{direction, machine_functions, placement, plane, point, r6, technology, tol};
use super::face::layer_steps;
use super::level::{contains, grow, split, MillCut};
use super::shape::{is_ccw, loop_shape, Shape};
use super::strategy::{approach, cutmode};
use super::Raiser;
use crate::stepnc::model::*;
use crate::toolpath::Move;

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64) -> bool {
    let mut loops = Vec::new();
    for l in &m.levels {
        let s = split(&l.moves);
        if s.loops.len() != 1 {
            return false;
        }
        loops.push(s.loops[0].clone());
    }
    let lp = &loops[0];
    let path = loop_shape(lp);
    let outline = path.offset(-rad);
    let others = r.other_envelopes();
    let holds_others =
        !others.is_empty() && others.iter().all(|b| contains(outline.bbox(), *b, 1e-3));
    let round_stock = r
        .stock_box()
        .is_some_and(|(b, _, _)| contains(grow(path.bbox(), rad), b, 1e-3));
    if !(holds_others || round_stock) {
        return false;
    }
    let top = r.top;
    let bottom = m.deepest().z;
    let name = r.name("PROFILE");
    let c = outline.centre();
    let boundary = match &outline {
        Shape::Rect { lx, ly, .. } => ClosedProfile::Rectangular {
            placement: None,
            width: tol(lx.min(*ly)),
            length: tol(lx.max(*ly)),
        },
        Shape::Circle { r: cr, .. } => ClosedProfile::Circular {
            placement: None,
            diameter: tol(2.0 * cr),
        },
        Shape::Poly(v) => {
            let mut points: Vec<Point> = v
                .iter()
                .map(|p| point("", [p[0] - c[0], p[1] - c[1], 0.0]))
                .collect();
            points.push(points[0].clone());
            ClosedProfile::General {
                placement: None,
                shape: Curve::Polyline {
                    name: format!("{name} OUTLINE"),
                    points,
                },
            }
        }
    };
    let x_dir = match &outline {
        Shape::Rect { lx, ly, .. } if ly > lx => [0.0, 1.0],
        _ => [1.0, 0.0],
    };
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [c[0], c[1], top], x_dir),
        depth: plane(&format!("{name} DEPTH"), [0.0, 0.0, r6(bottom - top)]),
        kind: FeatureKind::GeneralOutsideProfile {
            swept_shape: TravelPath::Linear {
                placement: None,
                distance: tol(top - bottom),
                direction: direction("SWEEP", [0.0, 0.0, -1.0]),
            },
            boundary: Profile::Closed(boundary),
        },
    };
    let feature = r.add_feature(f);
    let cuts: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    let ccw = is_ccw(lp);
    let spindle = cuts.first().map_or(0.0, |c| c.spindle);
    let strategy = Strategy::ContourParallel {
        base: StrategyBase::default(),
        rotation: Some(if ccw {
            RotDirection::Ccw
        } else {
            RotDirection::Cw
        }),
        cutmode: Some(cutmode(ccw, spindle, false)),
    };
    let op = Operation {
        id: format!("MILL {name}"),
        toolpath: None,
        tool_direction: None,
        retract_plane: super::strategy::retract_plane(&m.moves, top),
        start_point: None,
        tool: (r.tool)(m.tool),
        technology: technology(&cuts),
        machine_functions: machine_functions(&cuts),
        overcut_length: None,
        kind: OperationKind::SideMilling {
            finish: true,
            milling: MillingCommon {
                approach: approach(&m.moves),
                retract: None,
                strategy: Some(strategy),
            },
            axial_cutting_depth: layer_steps(m, top),
            radial_cutting_depth: None,
            allowance_side: None,
        },
    };
    r.add_operation(feature, op);
    true
}
