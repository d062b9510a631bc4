//! Planar faces: a cut made only of parallel straight strokes (one or
//! more, at most a tool diameter apart, with links between them) whose swept envelope covers the stock's top (or,
//! when the stock is not known, the envelopes of every other cut of the
//! program). The face is placed at the stock's top (or at the cut level
//! when the stock is not known: depth 0) at the covered region's corner;
//! `course_of_travel` runs along the strokes over the region, the removal
//! boundary is the region's width across. Without the stock, the cut
//! must also lie at or above every other cut's levels. A later face cut over the same
//! region at a lower Z is its finishing operation; the earlier ones are
//! PLANE_ROUGH_MILLING with `allowance_bottom` the Z difference. A face
//! cut once is PLANE_FINISH_MILLING (as NIST's Example 1).

use super::build::{direction, milled_operation, placement, plane, r6};
use super::level::{contains, grow, split, MillCut};
use super::strategy::{approach, parallel, stroke_strategy, strokes, unit};
use super::{Known, Raiser};
use crate::stepnc::model::*;
use crate::toolpath::Move;

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64) -> bool {
    let only_strokes = m.levels.iter().all(|l| {
        let s = split(&l.moves);
        let st = strokes(&l.moves);
        s.loops.is_empty() && !st.is_empty() && parallel(&st) && no_ridges(&st, rad)
    });
    if !only_strokes {
        return false;
    }
    let env = grow(m.footprint(), rad);
    let target = match r.stock_box() {
        Some((b, _, _)) => b,
        None => {
            // Without the stock, a face is the highest cut, over all others.
            let z = m.levels.iter().map(|l| l.z).fold(f64::INFINITY, f64::min);
            let highest = r
                .tops
                .iter()
                .enumerate()
                .all(|(j, t)| j == r.current || *t <= z + 1e-6);
            match union(&r.other_envelopes()) {
                Some(b) if highest => b,
                _ => return false,
            }
        }
    };
    if !contains(env, target, 1e-3) {
        return false;
    }
    let z = m.deepest().z;
    let existing = r.known.iter().position(|k| matches!(k, Known::Face { .. }));
    let feature = match existing {
        Some(i) => finish_existing(r, i, z),
        None => new_face(r, m, target, z),
    };
    let level = &m.levels[0];
    let st = strokes(&level.moves);
    let cuts: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    let steps = layer_steps(m, r.top.max(m.levels[0].z));
    let name = r.project.features[feature.index()].id.clone();
    let face_top = r.project.features[feature.index()].placement.location.xyz[2];
    let op = milled_operation(
        r,
        m,
        format!("FACE {name}"),
        face_top,
        &cuts,
        OperationKind::PlaneMilling {
            finish: true,
            milling: MillingCommon {
                approach: approach(&m.moves),
                retract: None,
                strategy: Some(stroke_strategy(&st, rad)),
            },
            axial_cutting_depth: steps,
            allowance_bottom: None,
        },
    );
    let id = r.add_operation(feature, op);
    r.name_passes(feature, "FACE");
    if let Some(Known::Face { ops, .. }) = r
        .known
        .iter_mut()
        .find(|k| matches!(k, Known::Face { feature: f, .. } if *f == feature))
    {
        ops.push((id, z));
    } else {
        r.known.push(Known::Face {
            feature,
            ops: vec![(id, z)],
        });
    }
    r.top = z;
    true
}

/// Do neighbouring strokes lie at most a tool diameter apart (no ridge
/// left between them)?
fn no_ridges(strokes: &[&Move], rad: f64) -> bool {
    let d = unit(strokes[0]);
    let mut across: Vec<f64> = strokes
        .iter()
        .map(|m| (m.from[0] - strokes[0].from[0]) * d[1] - (m.from[1] - strokes[0].from[1]) * d[0])
        .collect();
    across.sort_by(f64::total_cmp);
    across.windows(2).all(|w| w[1] - w[0] <= 2.0 * rad + 1e-6)
}

/// The largest Z step between layers (from the top to the first).
pub fn layer_steps(m: &MillCut, top: f64) -> Option<f64> {
    let mut zs: Vec<f64> = m.levels.iter().map(|l| l.z).collect();
    zs.sort_by(|a, b| b.total_cmp(a));
    let mut prev = top;
    let mut best: f64 = 0.0;
    for z in zs {
        best = best.max(prev - z);
        prev = z;
    }
    (best > 1e-6).then(|| r6(best))
}

fn union(boxes: &[[f64; 4]]) -> Option<[f64; 4]> {
    boxes.iter().copied().reduce(|a, b| {
        [
            a[0].min(b[0]),
            a[1].min(b[1]),
            a[2].max(b[2]),
            a[3].max(b[3]),
        ]
    })
}

fn new_face(r: &mut Raiser, m: &MillCut, region: [f64; 4], z: f64) -> FeatureId {
    let name = r.name("PLANAR FACE");
    let top = if r.stock_box().is_some() { r.top } else { z };
    // The course is the face's, not the tool's: along +X or +Y (the
    // strategy keeps the direction the tool fed in).
    let d = unit(strokes(&m.levels[0].moves)[0]);
    let d = if d[0] < -1e-9 || (d[0].abs() <= 1e-9 && d[1] < 0.0) {
        [-d[0], -d[1]]
    } else {
        d
    };
    let (along, across) = if d[0].abs() >= d[1].abs() {
        (region[2] - region[0], region[3] - region[1])
    } else {
        (region[3] - region[1], region[2] - region[0])
    };
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [region[0], region[1], top], [1.0, 0.0]),
        depth: Some(plane(&format!("{name} DEPTH"), [0.0, 0.0, r6(z - top)])),
        kind: FeatureKind::PlanarFace {
            course_of_travel: TravelPath::Linear {
                placement: None,
                distance: super::build::tol(along),
                direction: direction("COURSE OF TRAVEL", [d[0], d[1], 0.0]),
            },
            removal_boundary: OpenProfile::Linear {
                placement: None,
                length: NumericParameter {
                    name: "PROFILE LENGTH".into(),
                    value: r6(across),
                    unit: "MM".into(),
                },
            },
            face_boundary: None,
            bosses: Vec::new(),
        },
    };
    r.add_feature(f)
}

/// A further face cut: earlier ones become roughing with their bottom
/// allowance; the face's depth goes down to `z`.
fn finish_existing(r: &mut Raiser, i: usize, z: f64) -> FeatureId {
    let Known::Face { feature, ops } = r.known[i].clone() else {
        unreachable!("position() found a face");
    };
    for (op, oz) in ops {
        if let OperationKind::PlaneMilling {
            finish,
            allowance_bottom,
            ..
        } = &mut r.project.operations[op.index()].kind
        {
            *finish = false;
            *allowance_bottom = Some(r6(oz - z));
        }
    }
    let f = &mut r.project.features[feature.index()];
    let top = f.placement.location.xyz[2];
    if let Some(d) = f.depth.as_mut() {
        d.position.location.xyz[2] = r6(z - top);
    }
    feature
}
