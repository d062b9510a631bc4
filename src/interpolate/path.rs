//! The geometry of one move, by arc length: a straight line, or a
//! circular / helical arc (the radius changing linearly from the start's
//! to the end's when the end is slightly off the circle, as the
//! interpreter's arcs do).

use crate::toolpath::{ArcGeom, P3};
use nalgebra::Vector3;

/// One move's path.
#[derive(Clone, Copy, Debug)]
pub enum Path {
    Line {
        from: Vector3<f64>,
        to: Vector3<f64>,
    },
    Arc {
        from: Vector3<f64>,
        to: Vector3<f64>,
        geom: ArcGeom,
        /// Start angle and signed sweep, radians; start and end radius.
        a0: f64,
        sweep: f64,
        r0: f64,
        r1: f64,
    },
}

pub fn v3(p: P3) -> Vector3<f64> {
    Vector3::new(p[0], p[1], p[2])
}

impl Path {
    pub fn line(from: P3, to: P3) -> Self {
        Path::Line {
            from: v3(from),
            to: v3(to),
        }
    }

    pub fn arc(from: P3, to: P3, geom: ArcGeom) -> Self {
        let [u, v, _] = geom.axes;
        let a0 = (from[v] - geom.centre[v]).atan2(from[u] - geom.centre[u]);
        Path::Arc {
            from: v3(from),
            to: v3(to),
            geom,
            a0,
            sweep: geom.sweep(from, to),
            r0: geom.radius(from),
            r1: geom.radius(to),
        }
    }

    /// The path length, mm.
    pub fn length(&self) -> f64 {
        match self {
            Path::Line { from, to } => (to - from).norm(),
            Path::Arc {
                from,
                to,
                geom,
                sweep,
                r0,
                r1,
                ..
            } => {
                let w = geom.axes[2];
                (0.5 * (r0 + r1) * sweep.abs()).hypot(to[w] - from[w])
            }
        }
    }

    /// The point at fraction `f` (0 start, 1 end) of the path.
    pub fn point(&self, f: f64) -> Vector3<f64> {
        let f = f.clamp(0.0, 1.0);
        match self {
            Path::Line { from, to } => from + (to - from) * f,
            Path::Arc { to, .. } if f >= 1.0 => *to,
            Path::Arc {
                from,
                to,
                geom,
                a0,
                sweep,
                r0,
                r1,
            } => {
                let [u, v, w] = geom.axes;
                let (a, r) = (a0 + sweep * f, r0 + (r1 - r0) * f);
                let mut p = Vector3::zeros();
                p[u] = geom.centre[u] + r * a.cos();
                p[v] = geom.centre[v] + r * a.sin();
                p[w] = from[w] + (to[w] - from[w]) * f;
                p
            }
        }
    }

    /// The unit tangent (direction of travel) at fraction `f`; zero for a
    /// path of no length.
    pub fn tangent(&self, f: f64) -> Vector3<f64> {
        let d = match self {
            Path::Line { from, to } => to - from,
            Path::Arc {
                from,
                to,
                geom,
                a0,
                sweep,
                r0,
                r1,
            } => {
                let [u, v, w] = geom.axes;
                let (a, r) = (a0 + sweep * f, r0 + (r1 - r0) * f);
                let mut d = Vector3::zeros();
                d[u] = (r1 - r0) * a.cos() - r * a.sin() * sweep;
                d[v] = (r1 - r0) * a.sin() + r * a.cos() * sweep;
                d[w] = to[w] - from[w];
                d
            }
        };
        let n = d.norm();
        if n > 0.0 {
            d / n
        } else {
            Vector3::zeros()
        }
    }

    pub fn start(&self) -> Vector3<f64> {
        match self {
            Path::Line { from, .. } | Path::Arc { from, .. } => *from,
        }
    }

    pub fn end(&self) -> Vector3<f64> {
        match self {
            Path::Line { to, .. } | Path::Arc { to, .. } => *to,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_half_circle_by_fraction() {
        let g = ArcGeom {
            axes: [0, 1, 2],
            centre: [0.0, 0.0, 0.0],
            rotation: 1,
        };
        let p = Path::arc([10.0, 0.0, 0.0], [-10.0, 0.0, 4.0], g);
        let mid = p.point(0.5);
        assert!((mid - Vector3::new(0.0, 10.0, 2.0)).norm() < 1e-9);
        assert!((p.length() - (10.0 * std::f64::consts::PI).hypot(4.0)).abs() < 1e-9);
        // Counter-clockwise from +X: the tangent starts along +Y (and
        // climbs), ends along -Y.
        let (t0, t1) = (p.tangent(0.0), p.tangent(1.0));
        let k = (10.0 * std::f64::consts::PI).hypot(4.0);
        assert!((t0 - Vector3::new(0.0, 10.0 * std::f64::consts::PI, 4.0) / k).norm() < 1e-9);
        assert!((t1 - Vector3::new(0.0, -10.0 * std::f64::consts::PI, 4.0) / k).norm() < 1e-9);
    }
}
