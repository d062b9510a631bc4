//! General outside profiles: a cut that follows one closed loop per level
//! (nothing inside it) around the rest of the part: the outline the loop
//! leaves (the loop shrunk by the tool radius) holds every other cut of
//! the program (but other passes round it) when the stock is not known;
//! when it is, the tool's envelope must go round the whole stock (a loop
//! inside the stock with nothing inside it is a pocket's contour). The boundary is that outline in the feature's
//! frame (placed at its centre on the top surface);
//! `profile_swept_shape` is a LINEAR_PATH down the tool axis over the
//! depth [?: ISO 14649-10 names it a linear_path without saying more;
//! this follows its use for swept profiles]. Operation SIDE_*_MILLING,
//! strategy CONTOUR_PARALLEL with the loop's rotation and the cut mode
//! for material inside the loop.
//!
//! A later loop whose outline is the same shape shrunk evenly by 0 to
//! 2 mm, down to the same depth or up to 2 mm deeper, finishes the
//! profile: the earlier operations become SIDE_ROUGH_MILLING with
//! `allowance_side` the difference (as for pockets, [`super::pocket`]).

use super::build::{direction, milled_operation, placement, plane, point, r6, tol};
use super::face::layer_steps;
use super::level::{contains, grow, split, MillCut};
use super::shape::{is_ccw, loop_shape, Shape};
use super::strategy::{approach, cutmode};
use super::{Known, Raiser};
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
    let bottom = m.deepest().z;
    let feature = match find_rough(r, &outline, bottom) {
        Some(i) => finish(r, i, &outline, bottom),
        None => {
            let own = m.footprint();
            let others: Vec<_> = r
                .other_envelopes()
                .into_iter()
                .filter(|b| !contains(*b, own, 1e-3))
                .collect();
            let holds_others =
                !others.is_empty() && others.iter().all(|b| contains(outline.bbox(), *b, 1e-3));
            let round_stock = r
                .stock_box()
                .is_some_and(|(b, _, _)| contains(grow(path.bbox(), rad), b, 1e-3));
            // With the stock known the loop must go round it (no material
            // is left outside the outline); without it, round the others.
            let outside = match r.stock_box() {
                Some(_) => round_stock,
                None => holds_others,
            };
            if !outside {
                return false;
            }
            let name = r.name("PROFILE");
            let f = profile_feature(&name, &outline, r.top, bottom);
            r.add_feature(f)
        }
    };
    let top = r.top;
    let name = r.project.features[feature.index()].id.clone();
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
    let op = milled_operation(
        r,
        m,
        format!("MILL {name}"),
        top,
        &cuts,
        OperationKind::SideMilling {
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
    );
    let id = r.add_operation(feature, op);
    r.name_passes(feature, "MILL");
    for k in r.known.iter_mut() {
        if let Known::Profile { feature: f, ops } = k {
            if *f == feature {
                ops.push((id, outline, bottom));
                return true;
            }
        }
    }
    r.known.push(Known::Profile {
        feature,
        ops: vec![(id, outline, bottom)],
    });
    true
}

fn find_rough(r: &Raiser, outline: &Shape, bottom: f64) -> Option<usize> {
    r.known.iter().position(|k| match k {
        Known::Profile { ops, .. } => ops.last().is_some_and(|(_, o, b)| {
            let shrink = outline.even_growth_to(o);
            shrink.is_some_and(|g| (-1e-6..=2.0).contains(&g))
                && (-1e-6..=2.0).contains(&(b - bottom))
        }),
        _ => false,
    })
}

fn finish(r: &mut Raiser, i: usize, outline: &Shape, bottom: f64) -> FeatureId {
    let Known::Profile { feature, ops } = r.known[i].clone() else {
        unreachable!("find_rough found a profile");
    };
    for (op, o, _) in ops {
        if let OperationKind::SideMilling {
            finish,
            allowance_side,
            ..
        } = &mut r.project.operations[op.index()].kind
        {
            *finish = false;
            *allowance_side = outline.even_growth_to(&o).map(r6);
        }
    }
    let name = r.project.features[feature.index()].id.clone();
    let fresh = profile_feature(&name, outline, r.top, bottom);
    let f = &mut r.project.features[feature.index()];
    f.depth = fresh.depth;
    f.kind = fresh.kind;
    feature
}

fn profile_feature(name: &str, outline: &Shape, top: f64, bottom: f64) -> Feature {
    let c = outline.centre();
    let boundary = match outline {
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
    let x_dir = match outline {
        Shape::Rect { lx, ly, .. } if ly > lx => [0.0, 1.0],
        _ => [1.0, 0.0],
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
        kind: FeatureKind::GeneralOutsideProfile {
            swept_shape: TravelPath::Linear {
                placement: None,
                distance: tol(top - bottom),
                direction: direction("SWEEP", [0.0, 0.0, -1.0]),
            },
            boundary: Profile::Closed(boundary),
        },
    }
}
