//! The Siemens programmable frame as an affine map from programmed
//! coordinates to the settable work offset's frame (the "base" in which
//! canonical calls are printed).
//!
//! Sources: SINUMERIK 840D programming manual (fundamentals), "Frames"
//! chapter, as summarised in `reference/dialects.md` §1.5 [K]:
//!
//! * The frame chain is machine → basic frame → settable frame (G54..) →
//!   programmable frame. Canon positions are printed in the settable
//!   frame's coordinates (as rs274 prints positions relative to G5x), so
//!   only the programmable frame is applied here.
//! * Within one programmable frame the components act in the order
//!   TRANS, ROT, SCALE, MIRROR. Every additive instruction (ATRANS, AROT,
//!   ASCALE, AMIRROR) acts in the coordinate system the frame built so far
//!   defines, so a later ATRANS is rotated, scaled and mirrored by what was
//!   programmed before it. The map is kept as `base = m · p + t`; an
//!   additive step `g` gives `m' = m · g.m`, `t' = m · g.t + t`.
//! * An absolute instruction (TRANS, ROT, SCALE, MIRROR) replaces the whole
//!   programmable frame; written without axes it clears it.
//! * `ROT X.. Y.. Z..` turns about Z, then the new Y, then the newest X
//!   (roll-pitch-yaw order of MD 10600 FRAME_ANGLE_ORDER's default) [?];
//!   `ROT RPL=` turns about the active plane's normal (G17 Z, G18 Y,
//!   G19 X), positive counter-clockwise looking down the normal.
//! * `MIRROR X0` inverts the X direction; the value written is ignored [K].
//! * Lengths are millimetres, like the interpreter's state.

/// One programmable frame: `base = m · p + t` (mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProgFrame {
    /// Linear part, row-major: `base[i] = Σ m[i][j] p[j] + t[i]`.
    pub m: [[f64; 3]; 3],
    pub t: [f64; 3],
}

const IDENTITY: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

impl Default for ProgFrame {
    fn default() -> Self {
        ProgFrame::identity()
    }
}

fn mul(a: &[[f64; 3]; 3], b: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let mut r = [[0.0; 3]; 3];
    for (i, row) in r.iter_mut().enumerate() {
        for (j, v) in row.iter_mut().enumerate() {
            *v = (0..3).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    r
}

fn apply(m: &[[f64; 3]; 3], p: [f64; 3]) -> [f64; 3] {
    [0, 1, 2].map(|i| m[i][0] * p[0] + m[i][1] * p[1] + m[i][2] * p[2])
}

/// A right-handed rotation by `deg` about axis 0 (X), 1 (Y) or 2 (Z).
fn rotation(axis: usize, deg: f64) -> [[f64; 3]; 3] {
    let (s, c) = deg.to_radians().sin_cos();
    // Exact quarter turns keep printed coordinates free of 1e-17 noise.
    let (s, c) = (snap(s), snap(c));
    let (i, j) = ((axis + 1) % 3, (axis + 2) % 3);
    let mut m = IDENTITY;
    m[i][i] = c;
    m[i][j] = -s;
    m[j][i] = s;
    m[j][j] = c;
    m
}

/// Sine and cosine values within 1e-15 of -1, 0 or 1 made exact.
pub fn snap(v: f64) -> f64 {
    for r in [-1.0, 0.0, 1.0] {
        if (v - r).abs() < 1e-15 {
            return r;
        }
    }
    v
}

impl ProgFrame {
    pub fn identity() -> Self {
        ProgFrame {
            m: IDENTITY,
            t: [0.0; 3],
        }
    }

    pub fn is_identity(&self) -> bool {
        *self == ProgFrame::identity()
    }

    /// A translation.
    pub fn trans(t: [f64; 3]) -> Self {
        ProgFrame { m: IDENTITY, t }
    }

    /// Rotations about Z, then Y', then X'' (`angles` = [x, y, z] degrees).
    pub fn rot_xyz(angles: [f64; 3]) -> Self {
        let m = mul(
            &mul(&rotation(2, angles[2]), &rotation(1, angles[1])),
            &rotation(0, angles[0]),
        );
        ProgFrame { m, t: [0.0; 3] }
    }

    /// A rotation about one axis (0 X, 1 Y, 2 Z).
    pub fn rot_about(axis: usize, deg: f64) -> Self {
        ProgFrame {
            m: rotation(axis.min(2), deg),
            t: [0.0; 3],
        }
    }

    /// Scale factors per axis.
    pub fn scale(f: [f64; 3]) -> Self {
        ProgFrame {
            m: [[f[0], 0.0, 0.0], [0.0, f[1], 0.0], [0.0, 0.0, f[2]]],
            t: [0.0; 3],
        }
    }

    /// Mirror the axes marked true.
    pub fn mirror(axes: [bool; 3]) -> Self {
        ProgFrame::scale(axes.map(|m| if m { -1.0 } else { 1.0 }))
    }

    /// This frame followed by `g` acting in this frame's coordinates.
    pub fn then(&self, g: &ProgFrame) -> Self {
        let gt = apply(&self.m, g.t);
        ProgFrame {
            m: mul(&self.m, &g.m),
            t: [0, 1, 2].map(|i| gt[i] + self.t[i]),
        }
    }

    /// A programmed point (mm) in the base frame (mm).
    pub fn to_base(&self, p: [f64; 3]) -> [f64; 3] {
        let q = apply(&self.m, p);
        [0, 1, 2].map(|i| q[i] + self.t[i])
    }

    /// A programmed direction (no translation).
    pub fn dir_to_base(&self, d: [f64; 3]) -> [f64; 3] {
        apply(&self.m, d)
    }

    /// The inverse map: a base point in programmed coordinates; `None`
    /// when the frame is singular (a scale factor of 0).
    pub fn from_base(&self, b: [f64; 3]) -> Option<[f64; 3]> {
        let inv = self.inverse()?;
        let d = [0, 1, 2].map(|i| b[i] - self.t[i]);
        Some(apply(&inv, d))
    }

    fn det(&self) -> f64 {
        let m = &self.m;
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    }

    fn inverse(&self) -> Option<[[f64; 3]; 3]> {
        // The identity (bit for bit, so no zero changes sign) is its own
        // inverse, as the cofactors below would compute it.
        const ID: [[f64; 3]; 3] = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
        let mut identity = true;
        for (row, id_row) in self.m.iter().zip(&ID) {
            for (v, id) in row.iter().zip(id_row) {
                identity &= v.to_bits() == id.to_bits();
            }
        }
        if identity {
            return Some(ID);
        }
        let d = self.det();
        if d.abs() < 1e-12 || !d.is_finite() {
            return None;
        }
        let m = &self.m;
        let c = |r: usize, k: usize| {
            let (r1, r2, k1, k2) = ((r + 1) % 3, (r + 2) % 3, (k + 1) % 3, (k + 2) % 3);
            m[r1][k1] * m[r2][k2] - m[r1][k2] * m[r2][k1]
        };
        let mut inv = [[0.0; 3]; 3];
        for (i, row) in inv.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v = c(j, i) / d;
            }
        }
        Some(inv)
    }

    /// How an arc in the plane with axes (`a`, `b`, normal `n`) maps: Ok
    /// (reverses its direction) when the frame keeps the plane and is a
    /// similarity in it (uniform scale, rotation about the normal, mirror);
    /// Err with the reason otherwise.
    pub fn arc_map(&self, a: usize, b: usize, n: usize) -> Result<bool, &'static str> {
        let m = &self.m;
        let eps = 1e-9;
        let stays = m[n][a].abs() < eps
            && m[n][b].abs() < eps
            && m[a][n].abs() < eps
            && m[b][n].abs() < eps;
        if !stays {
            return Err("the programmable frame turns the arc out of the active plane");
        }
        let (ua, ub, va, vb) = (m[a][a], m[b][a], m[a][b], m[b][b]);
        let (lu, lv, dot) = (ua * ua + ub * ub, va * va + vb * vb, ua * va + ub * vb);
        if (lu - lv).abs() > eps * lu.max(1.0) || dot.abs() > eps * lu.max(1.0) || lu < eps {
            return Err("the programmable frame scales the plane's axes differently: an arc would become an ellipse");
        }
        Ok(ua * vb - ub * va < 0.0)
    }
}
