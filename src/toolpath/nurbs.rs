//! Points along a G5.2/G5.3 NURBS curve (`Canon::NurbsFeed`): a rational
//! B-spline of the given order over the control points, with the clamped
//! uniform knot vector LinuxCNC builds (the curve starts at the first
//! control point and ends at the last).

use crate::canon::NurbsPoint;

/// The clamped uniform knots for `n` control points of order `k`.
fn knots(n: usize, k: usize) -> Vec<f64> {
    let inner = n.saturating_sub(k);
    let mut t = vec![0.0; k];
    t.extend((1..=inner).map(|i| i as f64));
    t.extend(std::iter::repeat_n((inner + 1) as f64, k));
    t
}

/// The B-spline basis values of order `k` at `u` (Cox–de Boor).
fn basis(t: &[f64], n: usize, k: usize, u: f64) -> Vec<f64> {
    let last = t[n];
    let mut b: Vec<f64> = (0..t.len() - 1)
        .map(|i| {
            let inside = t[i] <= u && u < t[i + 1];
            // The curve's end belongs to the last non-empty span.
            let at_end = u >= last && t[i] < t[i + 1] && t[i + 1] >= last;
            f64::from(u8::from(inside || at_end))
        })
        .collect();
    for d in 2..=k {
        for i in 0..t.len() - d {
            let l = t[i + d - 1] - t[i];
            let r = t[i + d] - t[i + 1];
            let a = if l > 0.0 { (u - t[i]) / l * b[i] } else { 0.0 };
            let c = if r > 0.0 {
                (t[i + d] - u) / r * b[i + 1]
            } else {
                0.0
            };
            b[i] = a + c;
        }
    }
    b.truncate(n);
    b
}

/// `samples` points along the curve (the first control point excluded,
/// the last included), in the units of the control points.
pub fn sample(points: &[NurbsPoint], order: u32, samples: usize) -> Vec<[f64; 2]> {
    let (n, k) = (points.len(), order as usize);
    if n == 0 || k < 2 || n < k {
        return points.iter().skip(1).map(|p| [p.x, p.y]).collect();
    }
    let t = knots(n, k);
    let end = t[n];
    (1..=samples)
        .map(|s| {
            let u = end * s as f64 / samples as f64;
            let b = basis(&t, n, k, u);
            let (mut x, mut y, mut w) = (0.0, 0.0, 0.0);
            for (p, bi) in points.iter().zip(&b) {
                x += bi * p.w * p.x;
                y += bi * p.w * p.y;
                w += bi * p.w;
            }
            if w.abs() < 1e-12 {
                [points[n - 1].x, points[n - 1].y]
            } else {
                [x / w, y / w]
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> NurbsPoint {
        NurbsPoint { x, y, w: 1.0 }
    }

    #[test]
    fn clamped_curve_ends_on_its_end_points_and_order_two_is_the_polygon() {
        let pts = [p(0.0, 0.0), p(10.0, 0.0), p(10.0, 10.0)];
        let s = sample(&pts, 3, 10);
        let last = s.last().unwrap();
        assert!((last[0] - 10.0).abs() < 1e-9 && (last[1] - 10.0).abs() < 1e-9);
        let s2 = sample(&pts, 2, 2);
        assert!((s2[0][0] - 10.0).abs() < 1e-9 && s2[0][1].abs() < 1e-9);
    }
}
