//! Rigid frames (an origin and orthonormal axes) for the STEP-NC placement
//! chain: setup → workpiece setup → feature → profile.

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
        Frame {
            origin: [0.0; 3],
            x: [1.0, 0.0, 0.0],
            y: [0.0, 1.0, 0.0],
            z: [0.0, 0.0, 1.0],
        }
    }

    /// From an `axis2_placement_3d` (axis default +Z, ref_direction +X;
    /// the x axis is made orthogonal to z as ISO 10303-42 does).
    pub fn from_placement(p: &Axis2Placement) -> Self {
        let z = p
            .axis
            .as_ref()
            .map(|d| unit(d.ratios))
            .unwrap_or([0.0, 0.0, 1.0]);
        let xr = p
            .ref_direction
            .as_ref()
            .map(|d| d.ratios)
            .unwrap_or([1.0, 0.0, 0.0]);
        let x = unit(sub(xr, scale(z, dot(xr, z))));
        let x = if norm(x) < 0.5 { any_orthogonal(z) } else { x };
        let y = cross(z, x);
        Frame {
            origin: p.location.xyz,
            x,
            y,
            z,
        }
    }

    /// `inner` placed in this frame.
    pub fn then(&self, inner: &Frame) -> Frame {
        Frame {
            origin: self.apply(inner.origin),
            x: self.rotate(inner.x),
            y: self.rotate(inner.y),
            z: self.rotate(inner.z),
        }
    }

    /// A point given in this frame, in the outer frame.
    pub fn apply(&self, p: P3) -> P3 {
        add(self.origin, self.rotate(p))
    }

    /// A direction given in this frame, in the outer frame.
    pub fn rotate(&self, v: P3) -> P3 {
        add(
            add(scale(self.x, v[0]), scale(self.y, v[1])),
            scale(self.z, v[2]),
        )
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

fn add(a: P3, b: P3) -> P3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: P3, b: P3) -> P3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn scale(a: P3, k: f64) -> P3 {
    [a[0] * k, a[1] * k, a[2] * k]
}
fn dot(a: P3, b: P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: P3, b: P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm(a: P3) -> f64 {
    dot(a, a).sqrt()
}
fn unit(a: P3) -> P3 {
    let n = norm(a);
    if n < 1e-12 {
        a
    } else {
        scale(a, 1.0 / n)
    }
}
fn any_orthogonal(z: P3) -> P3 {
    let t = if z[0].abs() < 0.9 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    unit(sub(t, scale(z, dot(t, z))))
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
