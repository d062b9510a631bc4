//! The shape of a closed loop of moves: an axis-parallel rectangle (with
//! or without corner arcs of one radius), a circle, or else a polygon;
//! its orientation; and its offset (a tool-centre loop offset by the tool
//! radius is the wall the tool leaves). Rotated rectangles are kept as
//! polygons.

use super::level::points;
use crate::toolpath::{Move, MoveKind};

const TOL: f64 = 1e-3;

#[derive(Clone, Debug, PartialEq)]
pub enum Shape {
    /// Centre, size along X and Y, corner radius.
    Rect {
        c: [f64; 2],
        lx: f64,
        ly: f64,
        r: f64,
    },
    Circle {
        c: [f64; 2],
        r: f64,
    },
    /// Vertices of a closed polygon (not repeating the first).
    Poly(Vec<[f64; 2]>),
}

/// The loop's vertices (arcs flattened), first not repeated.
pub fn vertices(lp: &[Move]) -> Vec<[f64; 2]> {
    let mut v: Vec<[f64; 2]> = lp.iter().flat_map(points).map(|p| [p[0], p[1]]).collect();
    v.pop();
    v.insert(0, [lp[0].from[0], lp[0].from[1]]);
    v
}

/// Twice the signed area: positive for a counter-clockwise loop.
pub fn signed_area(v: &[[f64; 2]]) -> f64 {
    let n = v.len();
    (0..n)
        .map(|i| {
            let (a, b) = (v[i], v[(i + 1) % n]);
            a[0] * b[1] - b[0] * a[1]
        })
        .sum()
}

pub fn is_ccw(lp: &[Move]) -> bool {
    signed_area(&vertices(lp)) > 0.0
}

/// Recognises the loop's shape.
pub fn loop_shape(lp: &[Move]) -> Shape {
    if let Some(s) = circle(lp) {
        return s;
    }
    if let Some(s) = rect(lp) {
        return s;
    }
    Shape::Poly(vertices(lp))
}

fn circle(lp: &[Move]) -> Option<Shape> {
    let mut centre = None;
    let mut sweep = 0.0;
    for m in lp {
        let MoveKind::Arc(a) = &m.kind else {
            return None;
        };
        let (c, r) = ([a.centre[0], a.centre[1]], a.radius(m.from));
        match centre {
            None => centre = Some((c, r)),
            Some((c0, r0)) => {
                let off = (c[0] - c0[0]).hypot(c[1] - c0[1]);
                if off > TOL || (r - r0).abs() > TOL {
                    return None;
                }
            }
        }
        sweep += a.sweep(m.from, m.to);
    }
    let (c, r) = centre?;
    ((sweep.abs() - std::f64::consts::TAU).abs() < 1e-3).then_some(Shape::Circle { c, r })
}

fn rect(lp: &[Move]) -> Option<Shape> {
    let b = super::level::bbox(lp);
    let on_edge = |p: [f64; 3]| {
        (p[0] - b[0]).abs() < TOL
            || (p[0] - b[2]).abs() < TOL
            || (p[1] - b[1]).abs() < TOL
            || (p[1] - b[3]).abs() < TOL
    };
    let mut radius = None;
    let mut arcs = 0;
    for m in lp {
        match &m.kind {
            MoveKind::Line => {
                let axis = (m.to[0] - m.from[0]).abs() < TOL || (m.to[1] - m.from[1]).abs() < TOL;
                if !axis || !on_edge(m.from) || !on_edge(m.to) {
                    return None;
                }
            }
            MoveKind::Arc(a) => {
                let r = a.radius(m.from);
                let quarter = (a.sweep(m.from, m.to).abs() - std::f64::consts::FRAC_PI_2).abs();
                if quarter > 1e-3 || radius.is_some_and(|r0: f64| (r - r0).abs() > TOL) {
                    return None;
                }
                radius = Some(r);
                arcs += 1;
            }
            MoveKind::Rapid | MoveKind::Probe => return None,
        }
    }
    if arcs != 0 && arcs != 4 {
        return None;
    }
    Some(Shape::Rect {
        c: [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0],
        lx: b[2] - b[0],
        ly: b[3] - b[1],
        r: radius.unwrap_or(0.0),
    })
}

impl Shape {
    /// The shape grown outwards by `d` (shrunk for a negative `d`).
    pub fn offset(&self, d: f64) -> Shape {
        match self {
            Shape::Rect { c, lx, ly, r } => Shape::Rect {
                c: *c,
                lx: lx + 2.0 * d,
                ly: ly + 2.0 * d,
                r: (r + d).max(0.0),
            },
            Shape::Circle { c, r } => Shape::Circle { c: *c, r: r + d },
            Shape::Poly(v) => Shape::Poly(offset_poly(v, d)),
        }
    }

    pub fn centre(&self) -> [f64; 2] {
        match self {
            Shape::Rect { c, .. } | Shape::Circle { c, .. } => *c,
            Shape::Poly(v) => {
                let b = poly_box(v);
                [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0]
            }
        }
    }

    pub fn bbox(&self) -> [f64; 4] {
        match self {
            Shape::Rect { c, lx, ly, .. } => [
                c[0] - lx / 2.0,
                c[1] - ly / 2.0,
                c[0] + lx / 2.0,
                c[1] + ly / 2.0,
            ],
            Shape::Circle { c, r } => [c[0] - r, c[1] - r, c[0] + r, c[1] + r],
            Shape::Poly(v) => poly_box(v),
        }
    }

    /// How far `other` lies outside this shape on every side, if it is the
    /// same kind of shape grown evenly (rectangles, circles); else None.
    pub fn even_growth_to(&self, other: &Shape) -> Option<f64> {
        let near = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < TOL;
        match (self, other) {
            (
                Shape::Rect { c, lx, ly, .. },
                Shape::Rect {
                    c: c2,
                    lx: lx2,
                    ly: ly2,
                    ..
                },
            ) => {
                let (dx, dy) = ((lx2 - lx) / 2.0, (ly2 - ly) / 2.0);
                (near(*c, *c2) && (dx - dy).abs() < TOL).then_some(dx)
            }
            (Shape::Circle { c, r }, Shape::Circle { c: c2, r: r2 }) => {
                near(*c, *c2).then_some(r2 - r)
            }
            _ => None,
        }
    }
}

fn poly_box(v: &[[f64; 2]]) -> [f64; 4] {
    v.iter().fold(
        [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ],
        |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        },
    )
}

/// Mitred offset of a simple polygon; `d > 0` grows it.
fn offset_poly(v: &[[f64; 2]], d: f64) -> Vec<[f64; 2]> {
    let n = v.len();
    if n < 3 {
        return v.to_vec();
    }
    // Outward normal of edge a→b: right of the direction for a CCW polygon.
    let s = if signed_area(v) > 0.0 { 1.0 } else { -1.0 };
    let normal = |a: [f64; 2], b: [f64; 2]| {
        let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
        let l = dx.hypot(dy).max(1e-12);
        [s * dy / l, -s * dx / l]
    };
    (0..n)
        .map(|i| {
            let (p, q, r) = (v[(i + n - 1) % n], v[i], v[(i + 1) % n]);
            let (n1, n2) = (normal(p, q), normal(q, r));
            let bis = [n1[0] + n2[0], n1[1] + n2[1]];
            let k = (1.0 + n1[0] * n2[0] + n1[1] * n2[1]).max(1e-6);
            [q[0] + d * bis[0] / k, q[1] + d * bis[1] / k]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::super::segment::tests::{circle as circ, path};
    use super::*;
    use crate::toolpath::Event;

    fn moves(ev: Vec<Event>) -> Vec<Move> {
        ev.into_iter()
            .filter_map(|e| match e {
                Event::Move(m) => Some(m),
                _ => None,
            })
            .collect()
    }

    #[test]
    fn sharp_rectangle_offset_gets_the_tool_radius_corners() {
        let z = -2.0;
        let pts = [
            [0.0, 0.0, z],
            [30.0, 0.0, z],
            [30.0, 20.0, z],
            [0.0, 20.0, z],
            [0.0, 0.0, z],
        ];
        let lp = moves(path(&pts, &[false; 4], 1));
        assert!(is_ccw(&lp));
        let s = loop_shape(&lp);
        assert_eq!(
            s,
            Shape::Rect {
                c: [15.0, 10.0],
                lx: 30.0,
                ly: 20.0,
                r: 0.0
            }
        );
        assert_eq!(
            s.offset(5.0),
            Shape::Rect {
                c: [15.0, 10.0],
                lx: 40.0,
                ly: 30.0,
                r: 5.0
            }
        );
    }

    #[test]
    fn full_circle_and_polygon() {
        let lp = moves(vec![circ([5.0, 5.0], [8.0, 5.0, -1.0], false, 1)]);
        assert_eq!(
            loop_shape(&lp),
            Shape::Circle {
                c: [5.0, 5.0],
                r: 3.0
            }
        );
        assert!(!is_ccw(&lp));
        let z = 0.0;
        let tri = [[0.0, 0.0, z], [10.0, 0.0, z], [0.0, 10.0, z], [0.0, 0.0, z]];
        let s = loop_shape(&moves(path(&tri, &[false; 3], 1)));
        let Shape::Poly(v) = s.offset(1.0) else {
            panic!()
        };
        assert!((v[0][0] + 1.0).abs() < 1e-9 && (v[0][1] + 1.0).abs() < 1e-9);
    }
}
