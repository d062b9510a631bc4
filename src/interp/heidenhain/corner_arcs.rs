//! The rounding (`RND`) between two arcs: a circle of radius r tangent to
//! both. Its centre F lies R1 ± r from the first arc's centre and R2 ± r
//! from the second's (the four pairs of offset circles are intersected);
//! the solution kept touches the first arc between its start and the
//! corner, the second between the corner and its end, continues both
//! arcs' directions, and is the nearest to the corner.

type P2 = (f64, f64);

fn sub(a: P2, b: P2) -> P2 {
    (a.0 - b.0, a.1 - b.1)
}

fn len(a: P2) -> f64 {
    a.0.hypot(a.1)
}

/// Where the circles (c1, r1) and (c2, r2) meet.
fn intersections(c1: P2, r1: f64, c2: P2, r2: f64) -> Vec<P2> {
    let d = len(sub(c2, c1));
    if d < 1e-12 || d > r1 + r2 + 1e-12 || d < (r1 - r2).abs() - 1e-12 {
        return Vec::new();
    }
    let a = (r1 * r1 - r2 * r2 + d * d) / (2.0 * d);
    let h = (r1 * r1 - a * a).max(0.0).sqrt();
    let u = ((c2.0 - c1.0) / d, (c2.1 - c1.1) / d);
    let m = (c1.0 + a * u.0, c1.1 + a * u.1);
    vec![
        (m.0 - h * u.1, m.1 + h * u.0),
        (m.0 + h * u.1, m.1 - h * u.0),
    ]
}

/// The direction of travel at `p` on a circle round `c`.
fn tangent(c: P2, p: P2, ccw: bool) -> P2 {
    let r = sub(p, c);
    let l = len(r);
    if ccw {
        (-r.1 / l, r.0 / l)
    } else {
        (r.1 / l, -r.0 / l)
    }
}

/// The angle swept from `from` to `to` round `c` turning `ccw` (0..2π).
fn sweep(c: P2, from: P2, to: P2, ccw: bool) -> f64 {
    let a0 = (from.1 - c.1).atan2(from.0 - c.0);
    let a1 = (to.1 - c.1).atan2(to.0 - c.0);
    let d = if ccw { a1 - a0 } else { a0 - a1 };
    d.rem_euclid(std::f64::consts::TAU)
}

/// The rounding's centre, where it leaves the first arc and meets the
/// second, and whether it turns counterclockwise; or why there is none.
/// The first arc runs from `s1` to the corner `p` round `c1`, the second
/// from `p` to `e2` round `c2`.
#[allow(clippy::too_many_arguments)]
pub fn fillet(
    s1: P2,
    p: P2,
    (c1, ccw1): (P2, bool),
    (c2, ccw2): (P2, bool),
    e2: P2,
    r: f64,
) -> Result<(P2, P2, P2, bool), &'static str> {
    let (r1, r2) = (len(sub(p, c1)), len(sub(p, c2)));
    if r1 < 1e-9 || r2 < 1e-9 || r < 1e-9 {
        return Err("the arcs beside RND, or the rounding, have no radius");
    }
    let (d1, d2) = (tangent(c1, p, ccw1), tangent(c2, p, ccw2));
    if (d1.0 * d2.1 - d1.1 * d2.0).abs() < 1e-9 && d1.0 * d2.0 + d1.1 * d2.1 > 0.0 {
        return Err("the arcs meet tangentially: there is no corner to round");
    }
    let (span1, span2) = (sweep(c1, s1, p, ccw1), sweep(c2, p, e2, ccw2));
    let mut best: Option<(f64, (P2, P2, P2, bool))> = None;
    for rho1 in [r1 + r, (r1 - r).abs()] {
        for rho2 in [r2 + r, (r2 - r).abs()] {
            for f in intersections(c1, rho1, c2, rho2) {
                let (f1, f2) = (len(sub(f, c1)), len(sub(f, c2)));
                if f1 < 1e-9 || f2 < 1e-9 {
                    continue;
                }
                let t1 = (c1.0 + r1 * (f.0 - c1.0) / f1, c1.1 + r1 * (f.1 - c1.1) / f1);
                let t2 = (c2.0 + r2 * (f.0 - c2.0) / f2, c2.1 + r2 * (f.1 - c2.1) / f2);
                if (len(sub(t1, f)) - r).abs() > 1e-7 || (len(sub(t2, f)) - r).abs() > 1e-7 {
                    continue;
                }
                // On the first arc before the corner, on the second after it.
                let back = sweep(c1, t1, p, ccw1);
                let ahead = sweep(c2, p, t2, ccw2);
                if back > span1 + 1e-9 && span1 > 1e-9 || ahead > span2 + 1e-9 && span2 > 1e-9 {
                    continue;
                }
                // The rounding continues both arcs' directions.
                let a = tangent(c1, t1, ccw1);
                let ccw = (t1.0 - f.0) * a.1 - (t1.1 - f.1) * a.0 > 0.0;
                let b = tangent(f, t2, ccw);
                let want = tangent(c2, t2, ccw2);
                if b.0 * want.0 + b.1 * want.1 < 1.0 - 1e-6 {
                    continue;
                }
                let near = back * r1 + ahead * r2;
                if best.as_ref().is_none_or(|(n, _)| near < *n) {
                    best = Some((near, (f, t1, t2, ccw)));
                }
            }
        }
    }
    best.map(|(_, x)| x)
        .ok_or("the rounding does not fit between the two arcs")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_half_circles_meeting_at_a_cusp() {
        // Clockwise round (5, 0) from (0, 0) to (10, 0) (over the top,
        // arriving downwards), then counterclockwise round (15, 0) to
        // (20, 0) (leaving downwards, under): an S. They meet tangentially.
        assert!(fillet(
            (0.0, 0.0),
            (10.0, 0.0),
            ((5.0, 0.0), false),
            ((15.0, 0.0), true),
            (20.0, 0.0),
            1.0
        )
        .is_err());
    }

    #[test]
    fn two_arcs_meeting_at_a_corner() {
        // Clockwise round (5, 0) over the top to (10, 0), arriving
        // downwards; then clockwise round (15, 0), leaving upwards: a cusp.
        // The rounding lies above it, outside both circles (5 + 1 from
        // each centre), and turns counterclockwise.
        let (f, t1, t2, ccw) = fillet(
            (0.0, 0.0),
            (10.0, 0.0),
            ((5.0, 0.0), false),
            ((15.0, 0.0), false),
            (20.0, 0.0),
            1.0,
        )
        .unwrap();
        assert!((len(sub(f, (5.0, 0.0))) - 6.0).abs() < 1e-9, "{f:?}");
        assert!((len(sub(f, (15.0, 0.0))) - 6.0).abs() < 1e-9, "{f:?}");
        assert!(
            (f.0 - 10.0).abs() < 1e-9 && (f.1 - 11f64.sqrt()).abs() < 1e-9,
            "{f:?}"
        );
        assert!((len(sub(t1, f)) - 1.0).abs() < 1e-9 && (len(sub(t2, f)) - 1.0).abs() < 1e-9);
        assert!(ccw);
    }
}
