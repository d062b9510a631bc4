//! Rigid frames (an origin and orthonormal axes) for the STEP-NC placement
//! chain: setup → workpiece setup → feature → profile. The transforms
//! are nalgebra isometries; the fields are their origin and axes, for
//! the writers that set cycle parameters from them.

use crate::stepnc::model::{Axis2Placement, P3};
use nalgebra::{IsometryMatrix3, Matrix3, Point3, Rotation3, Translation3, Vector3};

/// A placement as a transform: `apply(p) = origin + x*p.x + y*p.y + z*p.z`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub origin: P3,
    pub x: P3,
    pub y: P3,
    pub z: P3,
}

impl Frame {
    pub fn identity() -> Self {
        Frame::from_iso(&IsometryMatrix3::identity())
    }

    /// From an `axis2_placement_3d` (axis default +Z, ref_direction +X;
    /// the x axis is made orthogonal to z as ISO 10303-42 does).
    pub fn from_placement(p: &Axis2Placement) -> Self {
        let z = p
            .axis
            .as_ref()
            .map(|d| v(d.ratios))
            .and_then(|a| a.try_normalize(1e-12))
            .unwrap_or_else(Vector3::z);
        let xr = p
            .ref_direction
            .as_ref()
            .map(|d| v(d.ratios))
            .unwrap_or_else(Vector3::x);
        let x = (xr - z * xr.dot(&z))
            .try_normalize(1e-9)
            .unwrap_or_else(|| any_orthogonal(&z));
        let y = z.cross(&x);
        let r = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[x, y, z]));
        Frame::from_iso(&IsometryMatrix3::from_parts(
            Translation3::from(v(p.location.xyz)),
            r,
        ))
    }

    /// The frame as a rigid transform (nalgebra).
    pub fn iso(&self) -> IsometryMatrix3<f64> {
        let r = Rotation3::from_matrix_unchecked(Matrix3::from_columns(&[
            v(self.x),
            v(self.y),
            v(self.z),
        ]));
        IsometryMatrix3::from_parts(Translation3::from(v(self.origin)), r)
    }

    pub fn from_iso(i: &IsometryMatrix3<f64>) -> Self {
        let m = i.rotation.matrix();
        let col = |k: usize| -> P3 { [m[(0, k)], m[(1, k)], m[(2, k)]] };
        let t = &i.translation.vector;
        Frame {
            origin: [t.x, t.y, t.z],
            x: col(0),
            y: col(1),
            z: col(2),
        }
    }

    /// `inner` placed in this frame.
    pub fn then(&self, inner: &Frame) -> Frame {
        Frame::from_iso(&(self.iso() * inner.iso()))
    }

    /// A point given in this frame, in the outer frame.
    pub fn apply(&self, p: P3) -> P3 {
        let q = self.iso() * Point3::from(v(p));
        [q.x, q.y, q.z]
    }

    /// A direction given in this frame, in the outer frame.
    pub fn rotate(&self, d: P3) -> P3 {
        let q = self.iso().rotation * v(d);
        [q.x, q.y, q.z]
    }

    /// True when the local z axis is the outer +Z.
    pub fn is_vertical(&self) -> bool {
        (self.z[2] - 1.0).abs() < 1e-9
    }

    /// The angle of the local x axis to the outer X, degrees (-180, 180].
    pub fn angle_deg(&self) -> f64 {
        self.x[1].atan2(self.x[0]).to_degrees()
    }
}

fn v(a: P3) -> Vector3<f64> {
    Vector3::new(a[0], a[1], a[2])
}

fn any_orthogonal(z: &Vector3<f64>) -> Vector3<f64> {
    let t = if z.x.abs() < 0.9 {
        Vector3::x()
    } else {
        Vector3::y()
    };
    (t - z * t.dot(z)).normalize()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stepnc::model::{Direction, Point};

    fn placement(at: P3, xdir: P3) -> Axis2Placement {
        Axis2Placement {
            name: String::new(),
            location: Point {
                name: String::new(),
                xyz: at,
            },
            axis: None,
            ref_direction: Some(Direction {
                name: String::new(),
                ratios: xdir,
            }),
        }
    }

    #[test]
    fn a_turned_placement_maps_its_x_onto_y() {
        let f = Frame::from_placement(&placement([70.0, 70.0, 0.0], [0.0, 1.0, 0.0]));
        assert!((f.angle_deg() - 90.0).abs() < 1e-9);
        let p = f.apply([40.0, 0.0, -30.0]);
        assert!((p[0] - 70.0).abs() < 1e-9 && (p[1] - 110.0).abs() < 1e-9);
        assert!((p[2] + 30.0).abs() < 1e-9);
        let g = Frame::from_placement(&placement([10.0, 0.0, 5.0], [1.0, 0.0, 0.0])).then(&f);
        assert_eq!(g.origin, [80.0, 70.0, 5.0]);
    }
}
