//! An axis-aligned box that grows to hold points, arcs included (their
//! extent, not just their end points).

use crate::toolpath::{Move, MoveKind, P3};
use serde::Serialize;

/// A box in millimetres; empty until a point is added.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Bounds {
    pub min: P3,
    pub max: P3,
}

impl Default for Bounds {
    fn default() -> Self {
        Bounds {
            min: [f64::INFINITY; 3],
            max: [f64::NEG_INFINITY; 3],
        }
    }
}

impl Bounds {
    pub fn is_empty(&self) -> bool {
        self.min[0] > self.max[0]
    }

    pub fn add(&mut self, p: P3) {
        for (k, v) in p.into_iter().enumerate() {
            self.min[k] = self.min[k].min(v);
            self.max[k] = self.max[k].max(v);
        }
    }

    pub fn merge(&mut self, other: &Bounds) {
        if !other.is_empty() {
            self.add(other.min);
            self.add(other.max);
        }
    }

    /// Adds a move's path: its ends, and an arc's extremes within its sweep.
    pub fn add_move(&mut self, m: &Move) {
        self.add(m.from);
        self.add(m.to);
        if let MoveKind::Arc(a) = &m.kind {
            let [u, v, _] = a.axes;
            let r = a.radius(m.from).max(a.radius(m.to));
            let sweep = a.sweep(m.from, m.to);
            let start = (m.from[v] - a.centre[v]).atan2(m.from[u] - a.centre[u]);
            // The four axis directions the sweep passes.
            for q in 0..4 {
                let ang = q as f64 * std::f64::consts::FRAC_PI_2;
                if passes(start, sweep, ang) {
                    let mut p = m.from;
                    p[u] = a.centre[u] + r * ang.cos();
                    p[v] = a.centre[v] + r * ang.sin();
                    self.add(p);
                }
            }
        }
    }

    /// The size along each axis (0 when empty).
    pub fn size(&self) -> P3 {
        if self.is_empty() {
            return [0.0; 3];
        }
        [
            self.max[0] - self.min[0],
            self.max[1] - self.min[1],
            self.max[2] - self.min[2],
        ]
    }
}

/// Does a sweep from `start` by `sweep` radians pass the angle `ang`?
fn passes(start: f64, sweep: f64, ang: f64) -> bool {
    use std::f64::consts::TAU;
    if sweep.abs() >= TAU {
        return true;
    }
    let d = if sweep >= 0.0 {
        (ang - start).rem_euclid(TAU)
    } else {
        (start - ang).rem_euclid(TAU)
    };
    d <= sweep.abs()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::toolpath::{ArcGeom, CoolantState, FeedMode};

    #[test]
    fn a_half_circle_reaches_its_top() {
        let m = Move {
            kind: MoveKind::Arc(ArcGeom {
                axes: [0, 1, 2],
                centre: [0.0, 0.0, 0.0],
                rotation: 1,
            }),
            from: [10.0, 0.0, 0.0],
            to: [-10.0, 0.0, 0.0],
            feed: 1.0,
            feed_mode: FeedMode::PerMinute,
            tool: 1,
            spindle: 0.0,
            coolant: CoolantState::default(),
            span: Default::default(),
        };
        let mut b = Bounds::default();
        b.add_move(&m);
        assert_eq!(b.max[1], 10.0);
        assert!(b.min[1].abs() < 1e-12);
    }
}
