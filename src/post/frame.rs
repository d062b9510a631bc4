//! Rigid frames (an origin and orthonormal axes) for the STEP-NC placement
//! chain: setup → workpiece setup → feature → profile. Composing,
//! applying and inverting them is the geometry kernel's
//! ([`crate::geom::Transform`]); the fields are the frame's origin and
//! axes, for the writers that set cycle parameters from them.

use crate::geom::{Transform, V3};
use crate::stepnc::model::{Axis2Placement, P3};

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
        Frame::from_transform(&Transform::identity())
    }

    /// From an `axis2_placement_3d` (axis default +Z, ref_direction +X;
    /// the x axis is made orthogonal to z as ISO 10303-42 does).
    pub fn from_placement(p: &Axis2Placement) -> Self {
        let z = p
            .axis
            .as_ref()
            .map(|d| V3::from(d.ratios))
            .and_then(|a| a.try_normalize(1e-12))
            .unwrap_or_else(V3::z);
        let xr = p
            .ref_direction
            .as_ref()
            .map(|d| V3::from(d.ratios))
            .unwrap_or_else(V3::x);
        let x = (xr - z * xr.dot(&z))
            .try_normalize(1e-9)
            .unwrap_or_else(|| any_orthogonal(&z));
        let y = z.cross(&x);
        Frame::from_transform(&Transform::from_axes(V3::from(p.location.xyz), x, y, z))
    }

    /// The frame as the kernel's transform.
    pub fn transform(&self) -> Transform {
        Transform::from_axes(
            V3::from(self.origin),
            V3::from(self.x),
            V3::from(self.y),
            V3::from(self.z),
        )
    }

    pub fn from_transform(t: &Transform) -> Self {
        let col = |k: usize| -> P3 { t.m.column(k).into_owned().into() };
        Frame {
            origin: t.t.into(),
            x: col(0),
            y: col(1),
            z: col(2),
        }
    }

    /// `inner` placed in this frame.
    pub fn then(&self, inner: &Frame) -> Frame {
        Frame::from_transform(&self.transform().then(&inner.transform()))
    }

    /// `other` seen from this frame (this frame's inverse, then `other`);
    /// `None` only for a degenerate frame.
    pub fn relative(&self, other: &Frame) -> Option<Frame> {
        let inv = self.transform().inverse()?;
        Some(Frame::from_transform(&inv.then(&other.transform())))
    }

    /// A point given in this frame, in the outer frame.
    pub fn apply(&self, p: P3) -> P3 {
        self.transform().to_base(p)
    }

    /// A direction given in this frame, in the outer frame.
    pub fn rotate(&self, d: P3) -> P3 {
        self.transform().dir_to_base(d)
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

fn any_orthogonal(z: &V3) -> V3 {
    let t = if z.x.abs() < 0.9 { V3::x() } else { V3::y() };
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
