//! Straight slots: a cut whose horizontal moves are straight passes along
//! one direction (one pass back and forth, in layers, or with side passes
//! at most a tool diameter apart, joined by stepovers across). Width =
//! the tool's diameter plus the spread of the passes; `course_of_travel`
//! is a LINEAR_PATH from the slot's first end (the end with the lower X,
//! or lower Y for a slot along Y) over the distance between the end
//! centres; the cross-section is a SQUARE_U_PROFILE with the tool's
//! corner radius (0 for a flat end mill) and upright walls (angles
//! written as 0: ISO 14649-10 measures them against the profile's local
//! z axis, as NIST STEPNC++'s attribute text says and real plans write).
//! An end whose tool envelope leaves the stock is OPEN, else RADIUSED (a
//! milled end is round with the tool's radius). A slot whose side wall
//! reaches the stock's side is left to [`super::open`] (a step). Strategy CENTER_MILLING
//! for one pass, BIDIRECTIONAL/UNIDIRECTIONAL with side passes.
//!
//! A later slot cut along the same centre line, 0 to 2 mm wider and
//! deeper, finishes the slot: as for pockets ([`super::pocket`]), the
//! earlier operations become BOTTOM_AND_SIDE_ROUGH_MILLING with their
//! allowances, the last one is the finishing one.

use super::build::{direction, milled_operation, placement, plane, r6, tol};
use super::face::layer_steps;
use super::level::{split, MillCut};
use super::strategy::{approach, stroke_strategy, unit};
use super::{Known, Raiser};
use crate::stepnc::model::*;
use crate::toolpath::{Move, MoveKind};

/// A slot's centre line and size, work coordinates.
#[derive(Clone, Debug, PartialEq)]
pub struct SlotGeom {
    pub start: [f64; 2],
    pub dir: [f64; 2],
    pub length: f64,
    pub width: f64,
    pub bottom: f64,
}

/// The slot the cut makes, if it is one.
pub fn geometry(m: &MillCut, rad: f64) -> Option<SlotGeom> {
    let moves: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    if !moves.iter().all(|mv| matches!(mv.kind, MoveKind::Line)) {
        return None;
    }
    if m.levels.iter().any(|l| !split(&l.moves).loops.is_empty()) {
        return None;
    }
    let longest = moves
        .iter()
        .max_by(|a, b| a.length().total_cmp(&b.length()))?;
    let d = unit(longest);
    let d = if d[0] < -1e-9 || (d[0].abs() <= 1e-9 && d[1] < 0.0) {
        [-d[0], -d[1]]
    } else {
        d
    };
    let o = longest.from;
    let along = |p: [f64; 3]| (p[0] - o[0]) * d[0] + (p[1] - o[1]) * d[1];
    let across = |p: [f64; 3]| (p[0] - o[0]) * d[1] - (p[1] - o[1]) * d[0];
    let lengthwise = |mv: &Move| (across(mv.to) - across(mv.from)).abs() < 1e-3;
    let crosswise = |mv: &Move| (along(mv.to) - along(mv.from)).abs() < 1e-3;
    if !moves.iter().all(|mv| lengthwise(mv) || crosswise(mv)) {
        return None;
    }
    let span = |f: &dyn Fn([f64; 3]) -> f64| {
        moves
            .iter()
            .flat_map(|mv| [f(mv.from), f(mv.to)])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), x| {
                (a.min(x), b.max(x))
            })
    };
    let ((lo, hi), (c0, c1)) = (span(&along), span(&across));
    if c1 - c0 > 2.0 * rad + 1e-6 || hi - lo <= c1 - c0 {
        return None;
    }
    let mid = (c0 + c1) / 2.0;
    // across(p) = (p - o) · n with n = (d.y, -d.x).
    let start = [o[0] + d[0] * lo + d[1] * mid, o[1] + d[1] * lo - d[0] * mid];
    Some(SlotGeom {
        start,
        dir: d,
        length: hi - lo,
        width: c1 - c0 + 2.0 * rad,
        bottom: m.deepest().z,
    })
}

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64) -> bool {
    let Some(g) = geometry(m, rad) else {
        return false;
    };
    if let Some((b, _, _)) = r.stock_box() {
        // A wall on or past the stock's side: a step, not a slot.
        let (c, h) = (g.start, g.width / 2.0);
        let past = |lo: f64, hi: f64, v: f64| v - h <= lo + 1e-6 || v + h >= hi - 1e-6;
        if (g.dir[0].abs() > 0.999 && past(b[1], b[3], c[1]))
            || (g.dir[1].abs() > 0.999 && past(b[0], b[2], c[0]))
        {
            return false;
        }
    }
    let feature = match find_rough(r, &g) {
        Some(i) => finish(r, i, &g, m.tool),
        None => new_slot(r, &g, r.tool_edge_radius(m.tool)),
    };
    let top = r.top;
    let cuts: Vec<&Move> = m.levels.iter().flat_map(|l| l.moves.iter()).collect();
    let name = r.project.features[feature.index()].id.clone();
    let passes: Vec<&Move> = cuts
        .iter()
        .copied()
        .filter(|mv| mv.length() > g.width - 2.0 * rad + 1e-6)
        .collect();
    let side_passes = g.width > 2.0 * rad + 1e-6 && passes.len() >= 2;
    let strategy = if side_passes {
        stroke_strategy(&passes, rad)
    } else {
        Strategy::CenterMilling {
            base: StrategyBase::default(),
        }
    };
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
                strategy: Some(strategy),
            },
            axial_cutting_depth: layer_steps(m, top),
            radial_cutting_depth: Some(r6(2.0 * rad)),
            allowance_side: None,
            allowance_bottom: None,
        },
    );
    let id = r.add_operation(feature, op);
    r.name_passes(feature, "MILL");
    for k in r.known.iter_mut() {
        if let Known::Slot { feature: f, ops } = k {
            if *f == feature {
                ops.push((id, g));
                return true;
            }
        }
    }
    r.known.push(Known::Slot {
        feature,
        ops: vec![(id, g)],
    });
    true
}

fn find_rough(r: &Raiser, g: &SlotGeom) -> Option<usize> {
    let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < 1e-3;
    r.known.iter().position(|k| match k {
        Known::Slot { ops, .. } => ops.last().is_some_and(|(_, s)| {
            let wider = (g.width - s.width) / 2.0;
            let deeper = s.bottom - g.bottom;
            near(s.start, g.start)
                && near(s.dir, g.dir)
                && (s.length - g.length).abs() < 1e-3
                && (-1e-6..=2.0).contains(&wider)
                && (-1e-6..=2.0).contains(&deeper)
        }),
        _ => false,
    })
}

fn finish(r: &mut Raiser, i: usize, g: &SlotGeom, tool: i64) -> FeatureId {
    let Known::Slot { feature, ops } = r.known[i].clone() else {
        unreachable!("find_rough found a slot");
    };
    for (op, s) in ops {
        if let OperationKind::BottomAndSideMilling {
            finish,
            allowance_side,
            allowance_bottom,
            ..
        } = &mut r.project.operations[op.index()].kind
        {
            *finish = false;
            *allowance_side = Some(r6((g.width - s.width) / 2.0));
            *allowance_bottom = Some(r6(s.bottom - g.bottom));
        }
    }
    let name = r.project.features[feature.index()].id.clone();
    let fresh = slot_feature(r, &name, g, r.tool_edge_radius(tool));
    let f = &mut r.project.features[feature.index()];
    f.depth = fresh.depth;
    f.kind = fresh.kind;
    feature
}

fn new_slot(r: &mut Raiser, g: &SlotGeom, edge: f64) -> FeatureId {
    let name = r.name("SLOT");
    let f = slot_feature(r, &name, g, edge);
    r.add_feature(f)
}

fn slot_feature(r: &Raiser, name: &str, g: &SlotGeom, edge: f64) -> Feature {
    let half = g.width / 2.0;
    let end_type = |p: [f64; 2], out: f64| match r.stock_box() {
        Some((b, _, _)) => {
            let q = [p[0] + out * g.dir[0] * half, p[1] + out * g.dir[1] * half];
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
    let end = [
        g.start[0] + g.dir[0] * g.length,
        g.start[1] + g.dir[1] * g.length,
    ];
    let top = r.top;
    Feature {
        id: name.to_string(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(name, [g.start[0], g.start[1], top], [1.0, 0.0]),
        depth: Some(plane(
            &format!("{name} DEPTH"),
            [0.0, 0.0, r6(g.bottom - top)],
        )),
        kind: FeatureKind::Slot {
            course_of_travel: TravelPath::Linear {
                placement: None,
                distance: tol(g.length),
                direction: direction("COURSE OF TRAVEL", [g.dir[0], g.dir[1], 0.0]),
            },
            swept_shape: OpenProfile::SquareU {
                placement: None,
                width: tol(g.width),
                first_radius: Some(tol(edge)),
                first_angle: Some(0.0),
                second_radius: Some(tol(edge)),
                second_angle: Some(0.0),
            },
            end_conditions: vec![end_type(g.start, -1.0), end_type(end, 1.0)],
        },
    }
}
