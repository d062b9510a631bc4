//! The geometry of one cutter-location trajectory, built move by move:
//! consecutive straight moves make one POLYLINE, a circular arc a
//! TRIMMED_CURVE of a CIRCLE ([`Curve::Arc`]), and a run mixing them a
//! COMPOSITE_CURVE of those, in order.
//!
//! Arcs of more than half a turn are cut into equal parts of at most half
//! a turn, so that no trimmed circle starts and ends at the same point (a
//! full circle trimmed at one point is ambiguous). Helical moves (an arc
//! whose axis coordinate changes) have no CIRCLE: the model has no HELIX,
//! so they are written as polyline points within [`HELIX_TOLERANCE`] of the
//! true path, and counted so that the caller can say so.

use crate::stepnc::model::{Axis2Placement, CompositeSegment, Curve, Direction, Point};
use crate::toolpath::{ArcGeom, P3};
use std::f64::consts::PI;

/// The chord tolerance for helices written as polylines, mm.
pub const HELIX_TOLERANCE: f64 = 0.001;

/// Points closer than this are the same point, mm.
const SAME: f64 = 1e-9;

pub fn point(xyz: P3) -> Point {
    Point {
        name: String::new(),
        xyz,
    }
}

fn unit(axis: usize) -> [f64; 3] {
    let mut v = [0.0; 3];
    v[axis] = 1.0;
    v
}

/// A curve under construction.
#[derive(Default)]
pub struct CurveBuilder {
    pieces: Vec<Curve>,
    /// The open polyline at the end, if any.
    line: Vec<Point>,
    /// Helical moves approximated so far.
    pub helices: usize,
}

impl CurveBuilder {
    /// A straight move.
    pub fn line(&mut self, from: P3, to: P3) {
        if self.line.is_empty() {
            self.line.push(point(from));
        } else if self.line.last().is_some_and(|p| p.xyz == to) {
            return; // a move that goes nowhere adds no point
        }
        self.line.push(point(to));
    }

    /// A circular or helical move.
    pub fn arc(&mut self, from: P3, to: P3, g: &ArcGeom) {
        let w = g.axes[2];
        if (to[w] - from[w]).abs() > SAME {
            self.helices += 1;
            if self.line.is_empty() {
                self.line.push(point(from));
            }
            let pts = g.points(from, to, HELIX_TOLERANCE);
            self.line.extend(pts.into_iter().map(point));
            return;
        }
        self.close_line();
        let sweep = g.sweep(from, to);
        let parts = if sweep.abs() > PI + 1e-9 {
            (sweep.abs() / PI).ceil() as usize
        } else {
            1
        };
        let [u, v, _] = g.axes;
        let r = g.radius(from);
        let a0 = (from[v] - g.centre[v]).atan2(from[u] - g.centre[u]);
        let mut start = from;
        for i in 1..=parts {
            let end = if i == parts {
                to
            } else {
                let a = a0 + sweep * i as f64 / parts as f64;
                let mut p = from;
                p[u] = g.centre[u] + r * a.cos();
                p[v] = g.centre[v] + r * a.sin();
                p
            };
            self.pieces.push(arc_curve(start, end, g, r));
            start = end;
        }
    }

    fn close_line(&mut self) {
        if self.line.len() >= 2 {
            self.pieces.push(Curve::Polyline {
                name: String::new(),
                points: std::mem::take(&mut self.line),
            });
        }
        self.line.clear();
    }

    /// The finished curve: one piece, or a composite of them.
    pub fn finish(mut self) -> Option<Curve> {
        self.close_line();
        match self.pieces.len() {
            0 => None,
            1 => self.pieces.pop(),
            _ => Some(Curve::Composite {
                name: String::new(),
                segments: self
                    .pieces
                    .into_iter()
                    .map(|curve| CompositeSegment {
                        transition: "CONTINUOUS".into(),
                        same_sense: true,
                        curve,
                    })
                    .collect(),
                self_intersect: Some(false),
            }),
        }
    }
}

fn arc_curve(from: P3, to: P3, g: &ArcGeom, radius: f64) -> Curve {
    let [u, _, w] = g.axes;
    Curve::Arc {
        name: String::new(),
        circle: Axis2Placement {
            name: String::new(),
            location: point(g.centre),
            axis: Some(Direction {
                name: String::new(),
                ratios: unit(w),
            }),
            ref_direction: Some(Direction {
                name: String::new(),
                ratios: unit(u),
            }),
        },
        circle_name: String::new(),
        radius,
        start: point(from),
        end: point(to),
        sense: g.ccw(),
    }
}

/// The number of points a curve holds (an arc counts its two ends).
pub fn point_count(c: &Curve) -> usize {
    match c {
        Curve::Polyline { points, .. } => points.len(),
        Curve::Arc { .. } | Curve::Line { .. } => 2,
        Curve::Composite { segments, .. } => segments.iter().map(|s| point_count(&s.curve)).sum(),
        Curve::Other(_) => 0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn xy(centre: P3, rotation: i64) -> ArcGeom {
        ArcGeom {
            axes: [0, 1, 2],
            centre,
            rotation,
        }
    }

    #[test]
    fn lines_then_an_arc_make_a_composite() {
        let mut b = CurveBuilder::default();
        b.line([0.0; 3], [10.0, 0.0, 0.0]);
        b.line([10.0, 0.0, 0.0], [10.0, 10.0, 0.0]);
        b.arc(
            [10.0, 10.0, 0.0],
            [0.0, 10.0, 0.0],
            &xy([5.0, 10.0, 0.0], 1),
        );
        let c = b.finish().unwrap();
        let Curve::Composite { segments, .. } = &c else {
            panic!("{c:?}")
        };
        assert_eq!(segments.len(), 2);
        assert!(matches!(&segments[0].curve, Curve::Polyline { points, .. } if points.len() == 3));
        let Curve::Arc { radius, sense, .. } = &segments[1].curve else {
            panic!()
        };
        assert!((radius - 5.0).abs() < 1e-12 && *sense);
    }

    #[test]
    fn full_circles_are_cut_and_helices_become_points() {
        let mut b = CurveBuilder::default();
        let s = [10.0, 0.0, 0.0];
        b.arc(s, s, &xy([0.0; 3], -1));
        let c = b.finish().unwrap();
        let Curve::Composite { segments, .. } = &c else {
            panic!("{c:?}")
        };
        assert_eq!(segments.len(), 2);
        let Curve::Arc { end, sense, .. } = &segments[0].curve else {
            panic!()
        };
        assert!((end.xyz[0] + 10.0).abs() < 1e-9 && !sense);
        let mut h = CurveBuilder::default();
        h.arc(s, [10.0, 0.0, -2.0], &xy([0.0; 3], 1));
        assert_eq!(h.helices, 1);
        let c = h.finish().unwrap();
        assert!(matches!(&c, Curve::Polyline { points, .. } if points.len() > 50));
    }
}
