//! The geometry of a circular or helical move: its plane, centre, turn
//! direction and number of turns, as the canonical `ARC_FEED` gives them,
//! with length and a polyline within a chord tolerance.

use super::P3;
use std::f64::consts::TAU;

/// A circular or helical move's geometry (the start and end are the move's).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ArcGeom {
    /// The in-plane axes (u, v) and the normal axis w, as indices into a
    /// point: XY plane (0, 1, 2), YZ (1, 2, 0), XZ (2, 0, 1); so that
    /// counter-clockwise is about the positive normal axis.
    pub axes: [usize; 3],
    /// The centre; its `w` coordinate is the start's.
    pub centre: P3,
    /// Canonical rotation: its sign is the direction (positive
    /// counter-clockwise), its magnitude 1 + the number of extra full turns.
    pub rotation: i64,
}

impl ArcGeom {
    pub fn ccw(&self) -> bool {
        self.rotation > 0
    }

    /// The radius at the start.
    pub fn radius(&self, from: P3) -> f64 {
        let [u, v, _] = self.axes;
        (from[u] - self.centre[u]).hypot(from[v] - self.centre[v])
    }

    fn angle(&self, p: P3) -> f64 {
        let [u, v, _] = self.axes;
        (p[v] - self.centre[v]).atan2(p[u] - self.centre[u])
    }

    /// The swept angle in radians, signed (positive counter-clockwise).
    /// A start equal to the end is a full circle.
    pub fn sweep(&self, from: P3, to: P3) -> f64 {
        let extra = (self.rotation.unsigned_abs().max(1) - 1) as f64 * TAU;
        let mut d = self.angle(to) - self.angle(from);
        if self.ccw() {
            while d <= 1e-9 {
                d += TAU;
            }
            d + extra
        } else {
            while d >= -1e-9 {
                d -= TAU;
            }
            d - extra
        }
    }

    /// The path length from `from` to `to` (a helix's, when the normal
    /// coordinate changes).
    pub fn length(&self, from: P3, to: P3) -> f64 {
        let w = self.axes[2];
        let planar = self.radius(from) * self.sweep(from, to).abs();
        planar.hypot(to[w] - from[w])
    }

    /// Points along the arc from `from` (excluded) to `to` (included), no
    /// chord further than `tol` from the true arc; the radius changes
    /// linearly from the start's to the end's (an end slightly off the
    /// circle stays on the path).
    pub fn points(&self, from: P3, to: P3, tol: f64) -> Vec<P3> {
        let [u, v, w] = self.axes;
        let (r0, r1) = (self.radius(from), self.radius(to));
        let sweep = self.sweep(from, to);
        let r = r0.max(r1).max(1e-9);
        let step = if tol >= r {
            std::f64::consts::FRAC_PI_2
        } else {
            (2.0 * (1.0 - tol / r).acos()).max(1e-4)
        };
        let n = ((sweep.abs() / step).ceil() as usize).clamp(1, 100_000);
        let a0 = self.angle(from);
        (1..=n)
            .map(|i| {
                let t = i as f64 / n as f64;
                if i == n {
                    return to;
                }
                let (a, rr) = (a0 + sweep * t, r0 + (r1 - r0) * t);
                let mut p = [0.0; 3];
                p[u] = self.centre[u] + rr * a.cos();
                p[v] = self.centre[v] + rr * a.sin();
                p[w] = from[w] + (to[w] - from[w]) * t;
                p
            })
            .collect()
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
    fn quarter_circles_and_full_circles() {
        let a = xy([0.0, 0.0, 0.0], 1);
        let (s, e) = ([10.0, 0.0, 0.0], [0.0, 10.0, 0.0]);
        assert!((a.sweep(s, e) - TAU / 4.0).abs() < 1e-12);
        let cw = xy([0.0, 0.0, 0.0], -1);
        assert!((cw.sweep(s, e) + 3.0 * TAU / 4.0).abs() < 1e-12);
        assert!((a.sweep(s, s) - TAU).abs() < 1e-12);
        let two = xy([0.0, 0.0, 0.0], 2);
        assert!((two.sweep(s, s) - 2.0 * TAU).abs() < 1e-12);
        assert!((a.length(s, e) - 5.0 * std::f64::consts::PI).abs() < 1e-9);
    }

    #[test]
    fn helix_length_and_points_stay_on_the_circle() {
        let a = xy([0.0, 0.0, 0.0], 1);
        let (s, e) = ([10.0, 0.0, 0.0], [10.0, 0.0, -3.0]);
        let planar = TAU * 10.0;
        assert!((a.length(s, e) - planar.hypot(3.0)).abs() < 1e-9);
        let pts = a.points(s, e, 0.01);
        assert_eq!(*pts.last().unwrap(), e);
        for p in &pts {
            assert!((p[0].hypot(p[1]) - 10.0).abs() < 1e-9);
        }
        assert!(pts.len() > 20);
    }
}
