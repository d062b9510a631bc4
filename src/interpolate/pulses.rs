//! Set-points on the BLU grid (basic length unit: the smallest step an
//! axis makes), from which the reference pulses are the differences.
//!
//! - A line is quantised as a 3D digital differential analyser does: on
//!   the grid line between its rounded end points, its major axis (the
//!   one that moves most) is rounded and the other axes are rounded at
//!   that major coordinate. Each point is then off that line only across
//!   the major axis, at most half a BLU in each of the two others: within
//!   √2/2 ≈ 0.707 BLU of the line (the bound of Ibrahim et al. 2015). Per
//!   axis rounding alone would allow √3/2 ≈ 0.866 BLU on a diagonal.
//! - An arc's point is rounded axis by axis: a planar arc's normal axis
//!   does not move, so its points are within 0.707 BLU of the circle; a
//!   helix's within √3/2 ≈ 0.866 BLU.
//!
//! Pulses are differences of successive grid points, so they sum exactly
//! to the grid displacement of each axis (the end points' rounding: the
//! programmed displacement itself when the end points are on the grid).

use nalgebra::Vector3;

/// A grid point, BLU.
pub type Q3 = [i64; 3];

/// The grid point nearest `p` (mm) for a BLU of `blu` mm.
pub fn round_point(p: &Vector3<f64>, blu: f64) -> Q3 {
    [
        (p[0] / blu).round() as i64,
        (p[1] / blu).round() as i64,
        (p[2] / blu).round() as i64,
    ]
}

/// The grid point at fraction `f` of the grid line from `qs` to `qe`,
/// quantised along its major axis (see the module note).
pub fn line_point(qs: Q3, qe: Q3, f: f64) -> Q3 {
    let d = [qe[0] - qs[0], qe[1] - qs[1], qe[2] - qs[2]];
    let major = (0..3).max_by_key(|&i| d[i].abs()).unwrap_or(0);
    if d[major] == 0 {
        return qs;
    }
    let f = f.clamp(0.0, 1.0);
    let m = (qs[major] as f64 + f * d[major] as f64).round() as i64;
    let fm = (m - qs[major]) as f64 / d[major] as f64;
    let mut q = [0; 3];
    for i in 0..3 {
        q[i] = if i == major {
            m
        } else {
            (qs[i] as f64 + fm * d[i] as f64).round() as i64
        };
    }
    q
}

/// Pulses from `a` to `b`.
pub fn pulses(a: Q3, b: Q3) -> Q3 {
    [b[0] - a[0], b[1] - a[1], b[2] - a[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_diagonal_stays_within_0_707_blu() {
        let (qs, qe) = ([0, 0, 0], [1000, 617, -389]);
        let d = Vector3::new(1000.0, 617.0, -389.0);
        let u = d.normalize();
        for k in 0..=10_000 {
            let q = line_point(qs, qe, k as f64 / 10_000.0);
            let p = Vector3::new(q[0] as f64, q[1] as f64, q[2] as f64);
            let off = (p - u * p.dot(&u)).norm();
            assert!(off <= 0.5f64.sqrt() + 1e-12, "{q:?}: {off}");
        }
        assert_eq!(line_point(qs, qe, 1.0), qe);
        assert_eq!(line_point(qs, qe, 0.0), qs);
    }
}
