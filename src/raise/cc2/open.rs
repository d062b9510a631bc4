//! Cuts that leave the stock on some sides (the stock must be known):
//! a wall box (tool-centre box grown by the tool radius) crossing the
//! stock on both ends along one axis and on one side across it is a STEP;
//! a rectangular wall crossing one side, or two adjacent sides, is an
//! OPEN_POCKET.
//!
//! * STEP: `open_boundary` is a LINEAR_PATH along the step's wall over
//!   the stock's length; the placement sits on the wall line at the
//!   stock's edge where the path starts (local X along the path), the
//!   removed material lying on the side of the stock edge the cut
//!   crossed [?: ISO 14649-10 defines the step by its open boundary and
//!   an optional wall profile only; this placement follows the linear
//!   path convention of slots]. No wall profile (upright wall).
//! * OPEN_POCKET: the walls that remain (the wall box clipped to the
//!   stock, without the sides on the stock's boundary) as a GENERAL
//!   open profile (polyline, in the frame placed at the clipped box's
//!   centre), corner radius as for closed pockets. Open pockets of other
//!   shapes, or open on two opposite sides, are not recognised.

use super::build::{direction, placement, plane, point, r6, tol};
use super::level::{Box2, MillCut};
use super::pocket::pocket_op;
use super::shape::Shape;
use super::Raiser;
use crate::stepnc::model::*;

pub fn raise(r: &mut Raiser, m: &MillCut, rad: f64, wall: &Shape, s: Box2) -> bool {
    let w = wall.bbox();
    let e = 1e-6;
    let [left, bottom_side, right, top_side] = [
        w[0] <= s[0] + e,
        w[1] <= s[1] + e,
        w[2] >= s[2] - e,
        w[3] >= s[3] - e,
    ];
    let (top, bottom) = (r.top, m.deepest().z);
    let feature = if left && right && (bottom_side != top_side) {
        let y = if bottom_side { w[3] } else { w[1] };
        step(r, [s[0], y], [1.0, 0.0], s[2] - s[0], top, bottom)
    } else if bottom_side && top_side && (left != right) {
        let x = if left { w[2] } else { w[0] };
        step(r, [x, s[1]], [0.0, 1.0], s[3] - s[1], top, bottom)
    } else if let Shape::Rect { r: corner, .. } = wall {
        let open = [bottom_side, right, top_side, left];
        match open_pocket(r, w, s, open, *corner, top, bottom) {
            Some(f) => f,
            None => return false,
        }
    } else {
        return false;
    };
    pocket_op(r, m, rad, feature);
    true
}

fn step(
    r: &mut Raiser,
    at: [f64; 2],
    dir: [f64; 2],
    length: f64,
    top: f64,
    bottom: f64,
) -> FeatureId {
    let name = r.name("STEP");
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [at[0], at[1], top], dir),
        depth: Some(plane(
            &format!("{name} DEPTH"),
            [0.0, 0.0, r6(bottom - top)],
        )),
        kind: FeatureKind::Step {
            open_boundary: TravelPath::Linear {
                placement: None,
                distance: tol(length),
                direction: direction("COURSE OF TRAVEL", [dir[0], dir[1], 0.0]),
            },
            wall_boundary: None,
            bosses: Vec::new(),
        },
    };
    r.add_feature(f)
}

/// `open`: bottom, right, top, left side of the wall box on or past the
/// stock's edge.
fn open_pocket(
    r: &mut Raiser,
    w: Box2,
    s: Box2,
    open: [bool; 4],
    corner: f64,
    top: f64,
    bottom: f64,
) -> Option<FeatureId> {
    let n_open = open.iter().filter(|o| **o).count();
    if n_open == 0 || n_open > 2 || (open[0] && open[2]) || (open[1] && open[3]) {
        return None;
    }
    let c = [
        w[0].max(s[0]),
        w[1].max(s[1]),
        w[2].min(s[2]),
        w[3].min(s[3]),
    ];
    let centre = [(c[0] + c[2]) / 2.0, (c[1] + c[3]) / 2.0];
    let corners = [[c[0], c[1]], [c[2], c[1]], [c[2], c[3]], [c[0], c[3]]];
    // Side i runs from corner i to corner i + 1; start after the last open side.
    let last_open = (0..4)
        .rev()
        .find(|i| open[*i] && !open[(*i + 1) % 4])
        .unwrap_or(0);
    let mut points = Vec::new();
    let mut i = (last_open + 1) % 4;
    points.push(corners[i]);
    while !open[i] {
        i = (i + 1) % 4;
        points.push(corners[i]);
    }
    let name = r.name("OPEN POCKET");
    let pts = points
        .iter()
        .map(|p| point("", [p[0] - centre[0], p[1] - centre[1], 0.0]))
        .collect();
    let f = Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [centre[0], centre[1], top], [1.0, 0.0]),
        depth: Some(plane(
            &format!("{name} DEPTH"),
            [0.0, 0.0, r6(bottom - top)],
        )),
        kind: FeatureKind::OpenPocket {
            pocket: PocketCommon {
                bosses: Vec::new(),
                slope: None,
                bottom: PocketBottom::Planar,
                planar_radius: None,
                orthogonal_radius: Some(tol(corner)),
            },
            open_boundary: OpenProfile::General {
                placement: None,
                shape: Curve::Polyline {
                    name: format!("{name} WALLS"),
                    points: pts,
                },
            },
            wall_boundary: None,
        },
    };
    Some(r.add_feature(f))
}
