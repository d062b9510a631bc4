//! Closed pockets: a cut whose deepest level has a closed loop with all
//! the level's moves inside it (contour-parallel loops, or a contour with
//! strokes inside, or a spiral ending in a contour), or only parallel
//! strokes (zig-zag), or a spiral (its wall: a circle when the spiral
//! is round, else its box). The wall is the
//! outermost loop grown by the tool radius: an axis-parallel rectangle
//! (corner radius = the loop's corner arcs + the tool radius, so a
//! sharp-cornered path gives the tool's radius), a circle, or a general
//! closed profile (a polygon, arcs flattened within 1 µm). Placement at
//! the wall's centre on the top surface, local X along the longer side
//! (ISO 14649-10 §4: the rectangle's length lies along local X); the
//! depth plane at the deepest level.
//!
//! A later pocket cut whose wall is the same shape grown evenly by 0 to
//! 2 mm, down to 0 to 2 mm deeper, is a further operation of the pocket:
//! the feature takes its wall and depth, it is the finishing operation
//! (BOTTOM_AND_SIDE_FINISH_MILLING) and each earlier one becomes
//! BOTTOM_AND_SIDE_ROUGH_MILLING with `allowance_side` = how far the
//! final wall lies outside the wall it left and `allowance_bottom` = how
//! far the final bottom lies below its bottom. A feature cut by one
//! operation gets the finishing one (its last operation is the one that
//! leaves the final size). A pocket whose wall leaves the stock is an
//! open pocket or a step ([`super::open`]).

use super::build::{milled_operation, placement, plane, point, r6, tol};
use super::face::layer_steps;
use super::level::{bbox, contains, split, MillCut};
use super::shape::{loop_shape, vertices, Shape};
use super::strategy::{
    approach, loop_stepover, pocket_strategy, stroke_stepover, strokes_along, winding,
};
use super::{Known, Raiser};
use crate::stepnc::model::*;
use crate::toolpath::Move;

/// How much a finishing pass may add to a pocket's wall and bottom, mm.
const MAX_ALLOWANCE: f64 = 2.0;

/// The tool-centre shape of a pocket level, if it is one.
pub fn path_shape(m: &MillCut) -> Option<Shape> {
    let deep = m.deepest();
    let s = split(&deep.moves);
    let outer = s.loops.iter().max_by(|a, b| {
        let (x, y) = (bbox(a), bbox(b));
        ((x[2] - x[0]) * (x[3] - x[1])).total_cmp(&((y[2] - y[0]) * (y[3] - y[1])))
    });
    let shape = match outer {
        Some(lp) => loop_shape(lp),
        None => {
            let st = strokes_along(&deep.moves);
            let zigzag = st.len() >= 2;
            let spiral = winding(&deep.moves).abs() >= std::f64::consts::TAU - 1e-3;
            if !zigzag && !spiral {
                return None;
            }
            let b = bbox(&deep.moves);
            let c = [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0];
            let (lx, ly) = (b[2] - b[0], b[3] - b[1]);
            let far = vertices(&deep.moves)
                .iter()
                .map(|p| (p[0] - c[0]).hypot(p[1] - c[1]))
                .fold(0.0, f64::max);
            if spiral && (lx - ly).abs() < 1e-3 && (far - lx / 2.0).abs() < 1e-3 {
                Shape::Circle { c, r: far }
            } else {
                Shape::Rect { c, lx, ly, r: 0.0 }
            }
        }
    };
    contains(shape.bbox(), m.footprint(), 1e-3).then_some(shape)
}

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64) -> bool {
    let Some(path) = path_shape(m) else {
        return false;
    };
    let wall = path.offset(rad);
    if let Some((b, _, _)) = r.stock_box() {
        if !contains(b, wall.bbox(), 1e-6) {
            return super::open::raise(r, m, rad, &wall, b);
        }
    }
    let bottom = m.deepest().z;
    let feature = match find_rough(r, &wall, bottom) {
        Some(i) => finish(r, i, &wall, bottom, m.tool),
        None => new_pocket(r, m, &wall, bottom),
    };
    let id = pocket_op(r, m, rad, feature);
    for k in r.known.iter_mut() {
        if let Known::Pocket { feature: f, ops } = k {
            if *f == feature {
                ops.push((id, wall, bottom));
                return true;
            }
        }
    }
    r.known.push(Known::Pocket {
        feature,
        ops: vec![(id, wall, bottom)],
    });
    true
}

/// The pocket this cut finishes, by index into `known`.
fn find_rough(r: &Raiser, wall: &Shape, bottom: f64) -> Option<usize> {
    r.known.iter().position(|k| match k {
        Known::Pocket { ops, .. } => ops.last().is_some_and(|(_, w, b)| {
            let grow = w.even_growth_to(wall);
            let deeper = b - bottom;
            grow.is_some_and(|g| (-1e-6..=MAX_ALLOWANCE).contains(&g))
                && (-1e-6..=MAX_ALLOWANCE).contains(&deeper)
        }),
        _ => false,
    })
}

fn finish(r: &mut Raiser, i: usize, wall: &Shape, bottom: f64, tool: i64) -> FeatureId {
    let Known::Pocket { feature, ops } = r.known[i].clone() else {
        unreachable!("find_rough found a pocket");
    };
    for (op, w, b) in ops {
        if let OperationKind::BottomAndSideMilling {
            finish,
            allowance_side,
            allowance_bottom,
            ..
        } = &mut r.project.operations[op.index()].kind
        {
            *finish = false;
            *allowance_side = w.even_growth_to(wall).map(r6);
            *allowance_bottom = Some(r6(b - bottom));
        }
    }
    let (top, edge) = (r.top, r.tool_edge_radius(tool));
    let name = r.project.features[feature.index()].id.clone();
    let fresh = pocket_feature(&name, wall, bottom, top, edge);
    let f = &mut r.project.features[feature.index()];
    f.placement = fresh.placement;
    f.depth = fresh.depth;
    f.kind = fresh.kind;
    feature
}

fn new_pocket(r: &mut Raiser, m: &MillCut, wall: &Shape, bottom: f64) -> FeatureId {
    let name = r.name("POCKET");
    let edge = r.tool_edge_radius(m.tool);
    let f = pocket_feature(&name, wall, bottom, r.top, edge);
    r.add_feature(f)
}

fn pocket_feature(name: &str, wall: &Shape, bottom: f64, top: f64, edge: f64) -> Feature {
    let c = wall.centre();
    let (x_dir, boundary, corner) = match wall {
        Shape::Rect { lx, ly, r, .. } => {
            let along_x = lx >= ly;
            let (length, width) = if along_x { (*lx, *ly) } else { (*ly, *lx) };
            let b = ClosedProfile::Rectangular {
                placement: None,
                width: tol(width),
                length: tol(length),
            };
            (
                if along_x { [1.0, 0.0] } else { [0.0, 1.0] },
                b,
                Some(tol(*r)),
            )
        }
        Shape::Circle { r, .. } => (
            [1.0, 0.0],
            ClosedProfile::Circular {
                placement: None,
                diameter: tol(2.0 * r),
            },
            None,
        ),
        Shape::Poly(v) => {
            let mut points: Vec<Point> = v
                .iter()
                .map(|p| point("", [p[0] - c[0], p[1] - c[1], 0.0]))
                .collect();
            points.push(points[0].clone());
            let shape = Curve::Polyline {
                name: format!("{name} BOUNDARY"),
                points,
            };
            (
                [1.0, 0.0],
                ClosedProfile::General {
                    placement: None,
                    shape,
                },
                None,
            )
        }
    };
    Feature {
        id: name.to_string(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(name, [c[0], c[1], top], x_dir),
        depth: Some(plane(
            &format!("{name} DEPTH"),
            [0.0, 0.0, r6(bottom - top)],
        )),
        kind: FeatureKind::ClosedPocket {
            pocket: PocketCommon {
                bosses: Vec::new(),
                slope: None,
                bottom: PocketBottom::Planar,
                planar_radius: (edge > 0.0).then(|| tol(edge)),
                orthogonal_radius: corner,
            },
            boundary,
        },
    }
}

/// A BOTTOM_AND_SIDE milling operation of `feature` (finishing until a
/// later operation finishes the feature) and its workingstep.
pub fn pocket_op(r: &mut Raiser, m: &MillCut, rad: f64, feature: FeatureId) -> OperationId {
    let top = r.top;
    let name = r.project.features[feature.index()].id.clone();
    let cuts: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    let spindle = cuts.first().map_or(0.0, |c| c.spindle);
    let op = milled_operation(
        r,
        m,
        format!("MILL {name}"),
        top,
        &cuts,
        OperationKind::BottomAndSideMilling {
            finish: true,
            milling: MillingCommon {
                approach: approach(&m.moves),
                retract: None,
                strategy: Some(pocket_strategy(m.deepest(), spindle, rad)),
            },
            axial_cutting_depth: layer_steps(m, top),
            radial_cutting_depth: loop_stepover(m.deepest())
                .or_else(|| stroke_stepover(m.deepest())),
            allowance_side: None,
            allowance_bottom: None,
        },
    );
    let id = r.add_operation(feature, op);
    r.name_passes(feature, "MILL");
    id
}
