//! The one geometry kernel: an affine map `base = M · p + t` on nalgebra,
//! used by every interpreter and by the STEP-NC post for the frames that
//! place a program's coordinates in another frame:
//!
//! * LinuxCNC: the XY rotation of a work offset (`G10 L2 R`), with G92
//!   inside the rotated frame ([`crate::interp::state::Placement`]);
//! * Fanuc/Haas: `G68` rotation, `G51` scaling, `G51.1` mirror about a
//!   centre ([`crate::interp::fanuc_xform`]);
//! * Siemens: the programmable frame (`TRANS`/`ROT`/`SCALE`/`MIRROR` and
//!   their additive forms, [`crate::interp::siemens`]);
//! * Heidenhain: datum shift, rotation and mirror (`CYCL DEF 7/10/8`);
//! * STEP-NC: the placement chain setup → workpiece → feature → profile
//!   ([`crate::post::frame::Frame`], a rigid [`Transform`]).
//!
//! Each controller builds its transform from its own words in its own
//! order; applying, composing and inverting is done here, the same way
//! for all of them.

pub mod turning;

use nalgebra::{Matrix3, Vector3};

/// A point or a direction, mm.
pub type V3 = Vector3<f64>;

/// An affine map `base = m · p + t` (lengths in mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Transform {
    /// The linear part (rotation, scale, mirror).
    pub m: Matrix3<f64>,
    /// The translation, in the base frame.
    pub t: V3,
}

impl Default for Transform {
    fn default() -> Self {
        Transform::identity()
    }
}

/// Sine and cosine values within 1e-15 of -1, 0 or 1 made exact, so that
/// quarter turns keep printed coordinates free of 1e-17 noise.
pub fn snap(v: f64) -> f64 {
    for r in [-1.0, 0.0, 1.0] {
        if (v - r).abs() < 1e-15 {
            return r;
        }
    }
    v
}

/// The right-handed rotation matrix by `deg` about axis 0 (X), 1 (Y) or
/// 2 (Z), from sine and cosine as given.
fn turn(axis: usize, s: f64, c: f64) -> Matrix3<f64> {
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut m = Matrix3::identity();
    m[(i, i)] = c;
    m[(i, j)] = -s;
    m[(j, i)] = s;
    m[(j, j)] = c;
    m
}

impl Transform {
    pub fn identity() -> Self {
        Transform {
            m: Matrix3::identity(),
            t: V3::zeros(),
        }
    }

    pub fn is_identity(&self) -> bool {
        *self == Transform::identity()
    }

    /// A translation.
    pub fn trans(t: [f64; 3]) -> Self {
        Transform {
            m: Matrix3::identity(),
            t: V3::from(t),
        }
    }

    /// A linear map alone.
    pub fn linear(m: Matrix3<f64>) -> Self {
        Transform { m, t: V3::zeros() }
    }

    /// A rotation by `deg` about one axis (0 X, 1 Y, 2 Z), quarter turns
    /// exact ([`snap`]).
    pub fn rot_about(axis: usize, deg: f64) -> Self {
        let (s, c) = deg.to_radians().sin_cos();
        Transform::linear(turn(axis.min(2), snap(s), snap(c)))
    }

    /// A rotation by `deg` about Z with the sine and cosine as computed,
    /// not snapped: LinuxCNC's rs274 turns a rotated work offset so, and
    /// its printed coordinates keep the noise.
    pub fn rot_z_unsnapped(deg: f64) -> Self {
        let (s, c) = deg.to_radians().sin_cos();
        Transform::linear(turn(2, s, c))
    }

    /// Rotations about Z, then Y', then X'' (`angles` = [x, y, z] degrees).
    pub fn rot_xyz(angles: [f64; 3]) -> Self {
        Transform::rot_about(2, angles[2])
            .then(&Transform::rot_about(1, angles[1]))
            .then(&Transform::rot_about(0, angles[0]))
    }

    /// Rotations about X, then Y', then Z'' (each about the axes the
    /// previous ones turned; `angles` = [x, y, z] degrees): the reverse
    /// order of [`Self::rot_xyz`].
    pub fn rot_xyz_intrinsic(angles: [f64; 3]) -> Self {
        Transform::rot_about(0, angles[0])
            .then(&Transform::rot_about(1, angles[1]))
            .then(&Transform::rot_about(2, angles[2]))
    }

    /// The angles [x, y, z] (degrees) that [`Self::rot_xyz`] turns by to
    /// give this map's rotation (about Z, then Y', then X''; the same as
    /// about the fixed X, then Y, then Z). `None` when the linear part is
    /// not a rotation. At a quarter turn about Y (gimbal lock) the
    /// rotation about X is 0 [nalgebra's choice].
    pub fn angles_zyx(&self) -> Option<[f64; 3]> {
        let r = self.rotation()?;
        let (x, y, z) = r.euler_angles();
        Some([x, y, z].map(|a| clean_deg(a.to_degrees())))
    }

    /// The angles [x, y, z] (degrees) that [`Self::rot_xyz_intrinsic`]
    /// turns by to give this map's rotation (about X, then Y', then Z'').
    pub fn angles_xyz_intrinsic(&self) -> Option<[f64; 3]> {
        // m = Rx(a) Ry(b) Rz(c) exactly when mᵀ = Rz(-c) Ry(-b) Rx(-a).
        let r = self.rotation()?.inverse();
        let (x, y, z) = r.euler_angles();
        Some([-x, -y, -z].map(|a| clean_deg(a.to_degrees())))
    }

    /// The linear part as a rotation, when it is one (orthonormal, no
    /// mirror).
    fn rotation(&self) -> Option<nalgebra::Rotation3<f64>> {
        let m = self.m;
        let ortho = (m.transpose() * m - Matrix3::identity()).norm() < 1e-9;
        (ortho && m.determinant() > 0.0).then(|| nalgebra::Rotation3::from_matrix_unchecked(m))
    }

    /// Scale factors per axis.
    pub fn scale(f: [f64; 3]) -> Self {
        Transform::linear(Matrix3::from_diagonal(&V3::from(f)))
    }

    /// Mirror the axes marked true.
    pub fn mirror(axes: [bool; 3]) -> Self {
        Transform::scale(axes.map(|m| if m { -1.0 } else { 1.0 }))
    }

    /// A rigid frame from its origin and axes (the columns of `m`).
    pub fn from_axes(origin: V3, x: V3, y: V3, z: V3) -> Self {
        Transform {
            m: Matrix3::from_columns(&[x, y, z]),
            t: origin,
        }
    }

    /// This map followed by `g` acting in this map's coordinates (`g` is
    /// applied first to a point): `m' = m · g.m`, `t' = m · g.t + t`.
    pub fn then(&self, g: &Transform) -> Self {
        Transform {
            m: self.m * g.m,
            t: self.m * g.t + self.t,
        }
    }

    /// A point of this frame in the base frame.
    pub fn apply(&self, p: V3) -> V3 {
        self.m * p + self.t
    }

    /// A direction of this frame in the base frame (no translation).
    pub fn apply_dir(&self, d: V3) -> V3 {
        self.m * d
    }

    /// The inverse map; `None` when it is singular (a scale of 0).
    pub fn inverse(&self) -> Option<Transform> {
        let inv = if self.m == Matrix3::identity() {
            // Bit for bit, so that no zero changes sign.
            Matrix3::identity()
        } else {
            let d = self.m.determinant();
            if d.abs() < 1e-12 || !d.is_finite() {
                return None;
            }
            self.m.try_inverse()?
        };
        Some(Transform {
            m: inv,
            t: -(inv * self.t),
        })
    }

    /// A base point in this frame's coordinates (`None` when singular).
    pub fn unapply(&self, b: V3) -> Option<V3> {
        let inv = self.inverse()?;
        Some(inv.m * (b - self.t))
    }

    /// [`Self::apply`] on an array (mm).
    pub fn to_base(&self, p: [f64; 3]) -> [f64; 3] {
        self.apply(V3::from(p)).into()
    }

    /// [`Self::apply_dir`] on an array.
    pub fn dir_to_base(&self, d: [f64; 3]) -> [f64; 3] {
        self.apply_dir(V3::from(d)).into()
    }

    /// [`Self::unapply`] on an array.
    pub fn from_base(&self, b: [f64; 3]) -> Option<[f64; 3]> {
        self.unapply(V3::from(b)).map(Into::into)
    }

    /// Does the map mirror the plane with axes `a`, `b` (a negative
    /// determinant of that 2 x 2 part)?
    pub fn mirrors(&self, a: usize, b: usize) -> bool {
        let m = &self.m;
        m[(a, a)] * m[(b, b)] - m[(a, b)] * m[(b, a)] < 0.0
    }

    /// How an arc in the plane with axes (`a`, `b`, normal `n`) maps: Ok
    /// (reverses its direction) when the map keeps the plane and is a
    /// similarity in it (uniform scale, rotation about the normal,
    /// mirror); Err with the reason otherwise.
    pub fn arc_map(&self, a: usize, b: usize, n: usize) -> Result<bool, &'static str> {
        let m = &self.m;
        let eps = 1e-9;
        let stays = m[(n, a)].abs() < eps
            && m[(n, b)].abs() < eps
            && m[(a, n)].abs() < eps
            && m[(b, n)].abs() < eps;
        if !stays {
            return Err("the frame turns the arc out of the active plane");
        }
        let (u, v) = (
            nalgebra::Vector2::new(m[(a, a)], m[(b, a)]),
            nalgebra::Vector2::new(m[(a, b)], m[(b, b)]),
        );
        let (lu, lv, dot) = (u.norm_squared(), v.norm_squared(), u.dot(&v));
        if (lu - lv).abs() > eps * lu.max(1.0) || dot.abs() > eps * lu.max(1.0) || lu < eps {
            return Err(
                "the frame scales the plane's axes differently: an arc would become an ellipse",
            );
        }
        Ok(u.perp(&v) < 0.0)
    }
}

/// Turns the plane point (x, y) by `deg` degrees counter-clockwise about
/// `centre`, quarter turns exact.
pub fn turn_about(p: [f64; 2], centre: [f64; 2], deg: f64) -> [f64; 2] {
    let q =
        Transform::rot_about(2, deg).apply_dir(V3::new(p[0] - centre[0], p[1] - centre[1], 0.0));
    [q.x + centre[0], q.y + centre[1]]
}

/// An angle in degrees with rounding noise removed (nine places, and no
/// negative zero).
fn clean_deg(a: f64) -> f64 {
    let r = (a * 1e9).round() / 1e9;
    if r == 0.0 {
        0.0
    } else {
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: V3, b: [f64; 3]) -> bool {
        (a - V3::from(b)).norm() < 1e-12
    }

    #[test]
    fn a_later_step_acts_in_the_frame_built_so_far() {
        // TRANS X10, then AROT Z90, then ATRANS X5: the shift is turned.
        let f = Transform::trans([10.0, 0.0, 0.0])
            .then(&Transform::rot_about(2, 90.0))
            .then(&Transform::trans([5.0, 0.0, 0.0]));
        assert!(close(f.apply(V3::zeros()), [10.0, 5.0, 0.0]));
        assert!(close(f.apply(V3::new(1.0, 0.0, 0.0)), [10.0, 6.0, 0.0]));
        let back = f.unapply(V3::new(10.0, 6.0, 0.0)).unwrap();
        assert!(close(back, [1.0, 0.0, 0.0]));
    }

    /// The frames of a box's faces (axis, x axis), as STEP-NC feature
    /// placements give them, and a skew one: both angle sets rebuild the
    /// rotation.
    #[test]
    fn tilt_angles_rebuild_the_rotation_of_every_face_frame() {
        let frames: [([f64; 3], [f64; 3]); 7] = [
            ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
            ([-1.0, 0.0, 0.0], [0.0, -1.0, 0.0]),
            ([0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]),
            ([0.0, -1.0, 0.0], [1.0, 0.0, 0.0]),
            ([0.0, 0.0, -1.0], [1.0, 0.0, 0.0]),
            ([0.0, 0.0, 1.0], [0.0, 1.0, 0.0]),
            ([0.6, 0.0, 0.8], [0.8, 0.0, -0.6]),
        ];
        for (z, x) in frames {
            let (z, x) = (V3::from(z), V3::from(x));
            let f = Transform::from_axes(V3::zeros(), x, z.cross(&x), z);
            let a = f.angles_zyx().unwrap();
            let g = Transform::rot_xyz(a);
            assert!((g.m - f.m).norm() < 1e-9, "zyx {a:?} for z {z:?}");
            let b = f.angles_xyz_intrinsic().unwrap();
            let h = Transform::rot_xyz_intrinsic(b);
            assert!((h.m - f.m).norm() < 1e-9, "xyz {b:?} for z {z:?}");
        }
        // A hole drilled along -X from the right-hand face: a quarter turn.
        let right = Transform::from_axes(V3::zeros(), V3::y(), V3::z(), V3::x());
        assert_eq!(right.angles_xyz_intrinsic().unwrap(), [90.0, 90.0, 0.0]);
        assert!(Transform::mirror([true, false, false])
            .angles_zyx()
            .is_none());
    }

    #[test]
    fn quarter_turns_are_exact_and_scale_zero_has_no_inverse() {
        let p = Transform::rot_about(2, 90.0).apply(V3::new(1.0, 0.0, 0.0));
        assert_eq!((p.x, p.y), (0.0, 1.0));
        assert!(Transform::scale([0.0, 1.0, 1.0]).inverse().is_none());
        let raw = Transform::rot_z_unsnapped(90.0).apply(V3::new(1.0, 0.0, 0.0));
        assert!(raw.x != 0.0 && raw.x.abs() < 1e-15);
    }

    #[test]
    fn arcs_map_under_similarities_only() {
        assert_eq!(
            Transform::mirror([true, false, false]).arc_map(0, 1, 2),
            Ok(true)
        );
        assert_eq!(Transform::rot_about(2, 30.0).arc_map(0, 1, 2), Ok(false));
        assert!(Transform::scale([2.0, 1.0, 1.0]).arc_map(0, 1, 2).is_err());
        assert!(Transform::rot_about(0, 30.0).arc_map(0, 1, 2).is_err());
        assert!(Transform::mirror([true, false, false]).mirrors(0, 1));
    }

    #[test]
    fn turn_about_a_centre() {
        let p = turn_about([2.0, 1.0], [1.0, 1.0], 90.0);
        assert_eq!(p, [1.0, 2.0]);
    }
}
