//! A closed pocket whose boundary is a general polygon (a `POLYLINE`, or
//! a composite curve of lines): its tool-centre paths.
//!
//! - A convex boundary is cleared contour-parallel: the inset polygons
//!   (half-plane intersections, exact) from the inside out, each a loop,
//!   the last the finishing contour at the tool radius plus the side
//!   allowance; loops closer to the wall than the pocket's corner radius
//!   have arcs at their corners (the inset at the corner radius grown
//!   back). Between loops the step is the stepover, less at sharp corners
//!   so that no corner island stays: at most `r (1 + sin(a/2))` for the
//!   smallest angle `a` of the next loop.
//! - A concave (simple) boundary is cleared zigzag inside its finishing
//!   contour (the exact offset: mitred convex corners, arcs about the
//!   reflex ones), then that contour. The zigzag lines are the points at
//!   least the offset from every edge (each edge's capsule removed from
//!   the scanline); moves between them that would come closer to a wall
//!   lift to the R plane. A contour whose offset collapses an edge or
//!   crosses itself (a neck narrower than the tool) is refused, and so is
//!   a corner radius larger than the offset (no generator for both).

use super::{reversed, MoveSink, Seg, P2};

const EPS: f64 = 1e-9;

/// A simple polygon, counter-clockwise, without repeated or collinear
/// points.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    pub pts: Vec<P2>,
}

fn sub(a: P2, b: P2) -> P2 {
    [a[0] - b[0], a[1] - b[1]]
}
fn add(a: P2, b: P2) -> P2 {
    [a[0] + b[0], a[1] + b[1]]
}
fn mul(a: P2, k: f64) -> P2 {
    [a[0] * k, a[1] * k]
}
fn dot(a: P2, b: P2) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}
fn cross(a: P2, b: P2) -> f64 {
    a[0] * b[1] - a[1] * b[0]
}
fn len(a: P2) -> f64 {
    dot(a, a).sqrt()
}
fn dist(a: P2, b: P2) -> f64 {
    len(sub(a, b))
}
/// The unit left normal of `a -> b` (inwards on a counter-clockwise loop).
fn left(a: P2, b: P2) -> P2 {
    let d = sub(b, a);
    let l = len(d);
    [-d[1] / l, d[0] / l]
}

/// Signed area (positive counter-clockwise).
pub fn area(pts: &[P2]) -> f64 {
    let n = pts.len();
    (0..n).map(|i| cross(pts[i], pts[(i + 1) % n])).sum::<f64>() / 2.0
}

impl Polygon {
    /// The polygon through `points` (a closing point repeating the first
    /// is dropped), or why it is not one.
    pub fn new(points: &[P2]) -> Result<Polygon, String> {
        let mut pts: Vec<P2> = Vec::new();
        for p in points {
            if pts.last().is_none_or(|q| dist(*q, *p) > 1e-7) {
                pts.push(*p);
            }
        }
        while pts.len() > 1 && dist(pts[0], pts[pts.len() - 1]) <= 1e-7 {
            pts.pop();
        }
        // Drop points on a straight line with their neighbours.
        let mut changed = true;
        while changed && pts.len() >= 3 {
            changed = false;
            let n = pts.len();
            for i in 0..n {
                let (a, b, c) = (pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]);
                let turn = cross(sub(b, a), sub(c, b)) / (dist(a, b) * dist(b, c));
                if turn.abs() < 1e-9 && dot(sub(b, a), sub(c, b)) > 0.0 {
                    pts.remove(i);
                    changed = true;
                    break;
                }
            }
        }
        if pts.len() < 3 || area(&pts).abs() < 1e-9 {
            return Err("the boundary encloses no area (fewer than three corners)".into());
        }
        if area(&pts) < 0.0 {
            pts.reverse();
        }
        let p = Polygon { pts };
        if let Some((i, j)) = p.crossing() {
            return Err(format!(
                "the boundary crosses itself (its edges {} and {})",
                i + 1,
                j + 1
            ));
        }
        Ok(p)
    }

    fn edge(&self, i: usize) -> (P2, P2) {
        let n = self.pts.len();
        (self.pts[i], self.pts[(i + 1) % n])
    }

    /// Two edges that are not neighbours and meet.
    fn crossing(&self) -> Option<(usize, usize)> {
        let n = self.pts.len();
        for i in 0..n {
            for j in i + 2..n {
                if i == 0 && j == n - 1 {
                    continue;
                }
                let (a, b) = self.edge(i);
                let (c, d) = self.edge(j);
                if segments_meet(a, b, c, d) {
                    return Some((i, j));
                }
            }
        }
        None
    }

    /// Every corner turns left (seen going round counter-clockwise).
    pub fn is_convex(&self) -> bool {
        let n = self.pts.len();
        (0..n).all(|i| {
            let (a, b, c) = (
                self.pts[(i + n - 1) % n],
                self.pts[i],
                self.pts[(i + 1) % n],
            );
            cross(sub(b, a), sub(c, b)) > 0.0
        })
    }

    /// `p` lies inside (crossing rule).
    pub fn contains(&self, p: P2) -> bool {
        let n = self.pts.len();
        let mut inside = false;
        for i in 0..n {
            let (a, b) = self.edge(i);
            if (a[1] > p[1]) != (b[1] > p[1]) {
                let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if p[0] < x {
                    inside = !inside;
                }
            }
        }
        inside
    }

    /// The distance from `p` to the nearest edge.
    pub fn boundary_distance(&self, p: P2) -> f64 {
        (0..self.pts.len())
            .map(|i| {
                let (a, b) = self.edge(i);
                point_segment(p, a, b)
            })
            .fold(f64::MAX, f64::min)
    }

    /// A convex polygon inset by `d`: the intersection of its edges'
    /// half-planes moved in by `d` (empty when nothing is left).
    pub fn inset_convex(&self, d: f64) -> Vec<P2> {
        let mut poly = self.pts.clone();
        for i in 0..self.pts.len() {
            let (a, b) = self.edge(i);
            let n = left(a, b);
            poly = clip(&poly, |q| dot(sub(q, a), n) - d);
            if poly.is_empty() {
                break;
            }
        }
        let mut out: Vec<P2> = Vec::new();
        for p in poly {
            if out.last().is_none_or(|q| dist(*q, p) > 1e-7) {
                out.push(p);
            }
        }
        while out.len() > 1 && dist(out[0], out[out.len() - 1]) <= 1e-7 {
            out.pop();
        }
        out
    }

    /// The largest inset of a convex polygon that leaves anything (the
    /// inscribed circle's radius), to 1e-6 mm.
    pub fn inradius_convex(&self) -> f64 {
        let (mut lo, mut hi) = (0.0, self.extent());
        while hi - lo > 1e-6 {
            let mid = (lo + hi) / 2.0;
            if self.inset_convex(mid).is_empty() {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        lo
    }

    fn extent(&self) -> f64 {
        let (lo, hi) = bbox(&self.pts);
        (hi[0] - lo[0]).max(hi[1] - lo[1])
    }
}

/// Keeps the part of a convex polygon where `f >= 0` (Sutherland-Hodgman).
fn clip(poly: &[P2], f: impl Fn(P2) -> f64) -> Vec<P2> {
    let n = poly.len();
    let mut out = Vec::new();
    for i in 0..n {
        let (a, b) = (poly[i], poly[(i + 1) % n]);
        let (fa, fb) = (f(a), f(b));
        if fa >= 0.0 {
            out.push(a);
        }
        if (fa >= 0.0) != (fb >= 0.0) {
            let t = fa / (fa - fb);
            out.push(add(a, mul(sub(b, a), t)));
        }
    }
    out
}

pub fn bbox(pts: &[P2]) -> (P2, P2) {
    let mut lo = [f64::MAX, f64::MAX];
    let mut hi = [f64::MIN, f64::MIN];
    for p in pts {
        lo = [lo[0].min(p[0]), lo[1].min(p[1])];
        hi = [hi[0].max(p[0]), hi[1].max(p[1])];
    }
    (lo, hi)
}

fn point_segment(p: P2, a: P2, b: P2) -> f64 {
    let ab = sub(b, a);
    let l2 = dot(ab, ab);
    let t = if l2 < 1e-18 {
        0.0
    } else {
        (dot(sub(p, a), ab) / l2).clamp(0.0, 1.0)
    };
    dist(p, add(a, mul(ab, t)))
}

fn segments_meet(a: P2, b: P2, c: P2, d: P2) -> bool {
    let o = |p: P2, q: P2, r: P2| cross(sub(q, p), sub(r, p));
    let (d1, d2, d3, d4) = (o(c, d, a), o(c, d, b), o(a, b, c), o(a, b, d));
    if ((d1 > EPS && d2 < -EPS) || (d1 < -EPS && d2 > EPS))
        && ((d3 > EPS && d4 < -EPS) || (d3 < -EPS && d4 > EPS))
    {
        return true;
    }
    point_segment(a, c, d) < 1e-9
        || point_segment(b, c, d) < 1e-9
        || point_segment(c, a, b) < 1e-9
        || point_segment(d, a, b) < 1e-9
}

fn segment_segment(a: P2, b: P2, c: P2, d: P2) -> f64 {
    if segments_meet(a, b, c, d) {
        return 0.0;
    }
    point_segment(a, c, d)
        .min(point_segment(b, c, d))
        .min(point_segment(c, a, b))
        .min(point_segment(d, a, b))
}

/// A closed loop through the points of a convex polygon, counter-
/// clockwise; two points make a there-and-back, one point no move.
fn sharp_loop(pts: &[P2]) -> Vec<Seg> {
    let n = pts.len();
    if n < 2 {
        return Vec::new();
    }
    (0..n)
        .map(|i| Seg {
            from: pts[i],
            to: pts[(i + 1) % n],
            arc: None,
        })
        .collect()
}

/// A convex polygon grown by `g`: its edges moved out, arcs about its
/// corners.
fn grown_loop(pts: &[P2], g: f64) -> Vec<Seg> {
    let n = pts.len();
    if n == 1 {
        let c = pts[0];
        let l = super::pocket::circle_loop(g);
        return l
            .iter()
            .map(|s| Seg {
                from: add(s.from, c),
                to: add(s.to, c),
                arc: Some((c, true)),
            })
            .collect();
    }
    let out_n = |i: usize| mul(left(pts[i], pts[(i + 1) % n]), -g);
    let mut segs = Vec::new();
    for i in 0..n {
        let prev = out_n((i + n - 1) % n);
        let next = out_n(i);
        let (enter, leave) = (add(pts[i], prev), add(pts[i], next));
        if dist(enter, leave) > 1e-9 {
            segs.push(Seg {
                from: enter,
                to: leave,
                arc: Some((pts[i], true)),
            });
        }
        segs.push(Seg {
            from: leave,
            to: add(pts[(i + 1) % n], next),
            arc: None,
        });
    }
    segs
}

/// The smallest corner angle (radians) of a convex polygon (pi for
/// fewer than three corners).
fn min_angle(pts: &[P2]) -> f64 {
    let n = pts.len();
    if n < 3 {
        return std::f64::consts::PI;
    }
    (0..n)
        .map(|i| {
            let u = sub(pts[(i + n - 1) % n], pts[i]);
            let v = sub(pts[(i + 1) % n], pts[i]);
            (dot(u, v) / (len(u) * len(v))).clamp(-1.0, 1.0).acos()
        })
        .fold(std::f64::consts::PI, f64::min)
}

/// How a general pocket is cut (the same as a rectangular one's).
pub use super::pocket::PocketCut;

/// What the pocket needs: a corner radius (0 for sharp corners).
#[derive(Clone, Debug)]
pub struct GeneralPocket {
    pub boundary: Polygon,
    pub corner_radius: f64,
}

/// The finishing offset.
fn wall(c: &PocketCut) -> f64 {
    c.tool_radius + c.allowance_side
}

/// Why the pocket cannot be cut as asked.
pub fn check(p: &GeneralPocket, c: &PocketCut) -> Result<(), String> {
    if c.stepover <= 1e-9 || c.stepover > 2.0 * c.tool_radius + 1e-9 {
        return Err(format!(
            "the stepover {} must be more than 0 and at most the tool diameter {}",
            c.stepover,
            2.0 * c.tool_radius
        ));
    }
    if p.corner_radius > 0.0 && c.tool_radius > p.corner_radius + 1e-9 {
        return Err(format!(
            "the tool radius {} is larger than the pocket's corner radius {}",
            c.tool_radius, p.corner_radius
        ));
    }
    let d = wall(c);
    if p.boundary.is_convex() {
        if p.boundary.inset_convex(d).is_empty() {
            return Err(format!(
                "the tool (radius {}) with side allowance {} does not fit the pocket",
                c.tool_radius, c.allowance_side
            ));
        }
        return Ok(());
    }
    if p.corner_radius > d + 1e-9 {
        return Err(format!(
            "a concave boundary with a corner radius {} larger than the tool radius and allowance {} (no generator)",
            p.corner_radius, d
        ));
    }
    contour(&p.boundary, d).map(|_| ())
}

/// The loops of a cleared layer of a convex pocket, innermost first,
/// each with its offset.
pub fn convex_loops(p: &GeneralPocket, c: &PocketCut) -> Vec<(f64, Vec<Seg>)> {
    let poly = &p.boundary;
    let last = wall(c);
    let inr = poly.inradius_convex();
    let r = c.tool_radius;
    let mut offsets = vec![last];
    let mut d = last;
    while !poly.inset_convex(d + r).is_empty() && d < inr - 2e-3 {
        let mut step = c.stepover;
        for _ in 0..2 {
            let a = min_angle(&poly.inset_convex((d + step).min(inr - 1e-3)));
            step = c.stepover.min(r * (1.0 + (a / 2.0).sin()));
        }
        d = (d + step).min(inr - 1e-3);
        offsets.push(d);
    }
    offsets.reverse();
    offsets
        .into_iter()
        .map(|d| (d, convex_loop(p, d)))
        .collect()
}

/// The loop of a convex pocket at offset `d`.
fn convex_loop(p: &GeneralPocket, d: f64) -> Vec<Seg> {
    let rho = p.corner_radius;
    if d >= rho - 1e-9 {
        return sharp_loop(&p.boundary.inset_convex(d));
    }
    let core = p.boundary.inset_convex(rho);
    if core.is_empty() {
        return sharp_loop(&p.boundary.inset_convex(d));
    }
    grown_loop(&core, rho - d)
}

/// The exact inward offset of a simple polygon by `d`: mitred convex
/// corners, clockwise arcs about the reflex ones; or why there is none.
pub fn contour(poly: &Polygon, d: f64) -> Result<Vec<Seg>, String> {
    let pts = &poly.pts;
    let n = pts.len();
    let normal = |i: usize| left(pts[i], pts[(i + 1) % n]);
    let mut enter = Vec::with_capacity(n);
    let mut leave = Vec::with_capacity(n);
    for i in 0..n {
        let (ip, np, ni) = ((i + n - 1) % n, normal((i + n - 1) % n), normal(i));
        let e0 = sub(pts[i], pts[ip]);
        let e1 = sub(pts[(i + 1) % n], pts[i]);
        if cross(e0, e1) > 0.0 {
            // Convex: where the two moved edges meet.
            let a = add(pts[ip], mul(np, d));
            let b = add(pts[i], mul(ni, d));
            let t = cross(sub(b, a), e1) / cross(e0, e1);
            let c = add(a, mul(e0, t));
            enter.push(c);
            leave.push(c);
        } else {
            enter.push(add(pts[i], mul(np, d)));
            leave.push(add(pts[i], mul(ni, d)));
        }
    }
    let mut segs = Vec::new();
    for i in 0..n {
        let e = sub(pts[(i + 1) % n], pts[i]);
        let (a, b) = (leave[i], enter[(i + 1) % n]);
        if dot(sub(b, a), e) < -1e-9 {
            return Err(format!(
                "the tool-centre contour at {} mm from the wall collapses the edge from ({}, {}) (the pocket is too narrow there for the tool)",
                round3(d),
                round3(pts[i][0]),
                round3(pts[i][1])
            ));
        }
        if dist(a, b) > 1e-9 {
            segs.push(Seg {
                from: a,
                to: b,
                arc: None,
            });
        }
        let j = (i + 1) % n;
        if dist(enter[j], leave[j]) > 1e-9 {
            segs.push(Seg {
                from: enter[j],
                to: leave[j],
                arc: Some((pts[j], false)),
            });
        }
    }
    // The contour keeps its distance from every wall and does not cross
    // itself.
    let chords = chords(&segs);
    for (k, &(a, b, line)) in chords.iter().enumerate() {
        let m = if line { mul(add(a, b), 0.5) } else { b };
        if !poly.contains(m) || poly.boundary_distance(m) < d - 1e-6 {
            return Err(format!(
                "the tool-centre contour at {} mm from the wall comes closer to another wall near ({}, {}) (a neck narrower than the tool)",
                round3(d),
                round3(m[0]),
                round3(m[1])
            ));
        }
        for &(c, e, _) in chords.iter().skip(k + 2) {
            if segments_meet(a, b, c, e) && dist(a, e) > 1e-9 {
                return Err(format!(
                    "the tool-centre contour at {} mm from the wall crosses itself near ({}, {})",
                    round3(d),
                    round3(a[0]),
                    round3(a[1])
                ));
            }
        }
    }
    Ok(segs)
}

fn round3(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}

/// A loop as straight pieces (arcs in pieces of at most 10 degrees),
/// each marked whether it is a straight segment of the loop.
fn chords(segs: &[Seg]) -> Vec<(P2, P2, bool)> {
    let mut out = Vec::new();
    for s in segs {
        match s.arc {
            None => out.push((s.from, s.to, true)),
            Some((c, ccw)) => {
                let a0 = (s.from[1] - c[1]).atan2(s.from[0] - c[0]);
                let a1 = (s.to[1] - c[1]).atan2(s.to[0] - c[0]);
                let tau = std::f64::consts::TAU;
                let sweep = if ccw { a1 - a0 } else { a0 - a1 }.rem_euclid(tau);
                let k = (sweep / 10f64.to_radians()).ceil().max(1.0) as usize;
                let rad = dist(s.from, c);
                let mut last = s.from;
                for i in 1..=k {
                    let t = sweep * i as f64 / k as f64;
                    let a = if ccw { a0 + t } else { a0 - t };
                    let p = if i == k {
                        s.to
                    } else {
                        [c[0] + rad * a.cos(), c[1] + rad * a.sin()]
                    };
                    out.push((last, p, false));
                    last = p;
                }
            }
        }
    }
    out
}

/// The scanline at height `y`: the x intervals where the tool centre may
/// be (inside the polygon, at least `d` from every edge).
pub fn scan(poly: &Polygon, d: f64, y: f64) -> Vec<(f64, f64)> {
    let n = poly.pts.len();
    let mut xs = Vec::new();
    for i in 0..n {
        let (a, b) = poly.edge(i);
        if (a[1] > y) != (b[1] > y) {
            xs.push(a[0] + (y - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
        }
    }
    xs.sort_by(f64::total_cmp);
    let mut inside: Vec<(f64, f64)> = xs
        .chunks(2)
        .filter(|c| c.len() == 2)
        .map(|c| (c[0], c[1]))
        .collect();
    for i in 0..n {
        let (a, b) = poly.edge(i);
        if let Some(f) = capsule(a, b, d, y) {
            inside = inside
                .into_iter()
                .flat_map(|(lo, hi)| {
                    let mut v = Vec::new();
                    if f.0 > lo {
                        v.push((lo, hi.min(f.0)));
                    }
                    if f.1 < hi {
                        v.push((lo.max(f.1), hi));
                    }
                    v
                })
                .filter(|(lo, hi)| hi - lo > 1e-6)
                .collect();
        }
    }
    inside
}

/// The x interval of the line at `y` within `d` of the segment `a b`.
fn capsule(a: P2, b: P2, d: f64, y: f64) -> Option<(f64, f64)> {
    let mut lo = f64::MAX;
    let mut hi = f64::MIN;
    for p in [a, b] {
        let dy = y - p[1];
        if dy.abs() <= d {
            let w = (d * d - dy * dy).sqrt();
            lo = lo.min(p[0] - w);
            hi = hi.max(p[0] + w);
        }
    }
    // The band: 0 <= (x - a) . u <= L and |(x - a) x u| <= d.
    let e = sub(b, a);
    let l = len(e);
    let u = mul(e, 1.0 / l);
    let mut band = (f64::MIN, f64::MAX);
    let mut ok = true;
    let mut within = |k: f64, c0: f64, min: f64, max: f64| {
        // k (x - a.x) + c0 in [min, max]
        if k.abs() < 1e-12 {
            ok &= c0 >= min - 1e-12 && c0 <= max + 1e-12;
        } else {
            let (x0, x1) = ((min - c0) / k + a[0], (max - c0) / k + a[0]);
            band = (band.0.max(x0.min(x1)), band.1.min(x0.max(x1)));
        }
    };
    within(u[0], (y - a[1]) * u[1], 0.0, l);
    within(u[1], -(y - a[1]) * u[0], -d, d);
    if ok && band.0 <= band.1 {
        lo = lo.min(band.0);
        hi = hi.max(band.1);
    }
    (lo <= hi).then_some((lo, hi))
}

/// A straight move from `a` to `b` keeps the tool centre at least `d`
/// from every wall.
pub fn safe(poly: &Polygon, d: f64, a: P2, b: P2) -> bool {
    poly.contains(mul(add(a, b), 0.5))
        && (0..poly.pts.len()).all(|i| {
            let (c, e) = poly.edge(i);
            segment_segment(a, b, c, e) >= d - 1e-7
        })
}

/// All the moves, from above the pocket back to the clearance plane.
pub fn moves(p: &GeneralPocket, c: &PocketCut, sink: &mut MoveSink<'_>) {
    if p.boundary.is_convex() {
        convex_moves(p, c, sink)
    } else {
        concave_moves(p, c, sink)
    }
}

fn oriented(l: Vec<Seg>, ccw: bool) -> Vec<Seg> {
    if ccw {
        l
    } else {
        reversed(&l)
    }
}

/// The loop turned to start at its point nearest `to`.
fn starting_near(l: &[Seg], to: P2) -> Vec<Seg> {
    let k = (0..l.len())
        .min_by(|&i, &j| dist(l[i].from, to).total_cmp(&dist(l[j].from, to)))
        .unwrap_or(0);
    l[k..].iter().chain(l[..k].iter()).copied().collect()
}

fn run_loop(sink: &mut MoveSink<'_>, l: &[Seg], z: f64) {
    if let Some(first) = l.first() {
        sink.line(first.from, z);
    }
    for s in l {
        sink.seg(s, z);
    }
}

fn convex_moves(p: &GeneralPocket, c: &PocketCut, sink: &mut MoveSink<'_>) {
    let all = convex_loops(p, c);
    let start = match all.first() {
        Some((_, l)) if !l.is_empty() => l[0].from,
        Some((d, _)) => p
            .boundary
            .inset_convex(*d)
            .first()
            .copied()
            .unwrap_or([0.0, 0.0]),
        None => [0.0, 0.0],
    };
    let loops: Vec<Vec<Seg>> = all.into_iter().map(|(_, l)| oriented(l, c.ccw)).collect();
    sink.rapid(start, c.clear);
    for (i, &z) in c.levels.iter().enumerate() {
        let bottom = i + 1 == c.levels.len();
        sink.rapid(start, c.r_plane);
        sink.line(start, z);
        let chosen: Vec<&Vec<Seg>> = if c.walls_only_above_bottom && !bottom {
            loops.last().into_iter().collect()
        } else {
            loops.iter().collect()
        };
        let mut at = start;
        for l in chosen {
            let l = starting_near(l, at);
            run_loop(sink, &l, z);
            at = l.first().map_or(at, |s| s.from);
        }
        sink.rapid(at, c.r_plane);
    }
    let end = sink.last_xy();
    sink.rapid(end, c.clear);
}

/// The zigzag lines of a concave pocket at the offset `d`, in cutting
/// order: pieces `(from, to)`.
pub fn zigzag(poly: &Polygon, d: f64, step: f64) -> Vec<(P2, P2)> {
    let (lo, hi) = bbox(&poly.pts);
    let (y0, y1) = (lo[1] + d, hi[1] - d);
    if y1 <= y0 {
        return Vec::new();
    }
    let n = ((y1 - y0) / step).ceil().max(1.0) as usize;
    let mut out = Vec::new();
    for k in 0..=n {
        let y = y0 + (y1 - y0) * k as f64 / n as f64;
        let mut iv = scan(poly, d, y);
        if k % 2 == 1 {
            iv.reverse();
            out.extend(iv.into_iter().map(|(a, b)| ([b, y], [a, y])));
        } else {
            out.extend(iv.into_iter().map(|(a, b)| ([a, y], [b, y])));
        }
    }
    out
}

fn concave_moves(p: &GeneralPocket, c: &PocketCut, sink: &mut MoveSink<'_>) {
    let d = wall(c);
    let poly = &p.boundary;
    let Ok(contour) = contour(poly, d) else {
        return;
    };
    let contour = oriented(contour, c.ccw);
    let lines = zigzag(poly, d, c.stepover);
    let start = lines.first().map_or(contour[0].from, |l| l.0);
    sink.rapid(start, c.clear);
    for (i, &z) in c.levels.iter().enumerate() {
        let bottom = i + 1 == c.levels.len();
        sink.rapid(start, c.r_plane);
        sink.line(start, z);
        let mut at = start;
        if !c.walls_only_above_bottom || bottom {
            for &(a, b) in &lines {
                go(sink, poly, d, c, &mut at, a, z);
                sink.line(b, z);
                at = b;
            }
        }
        let first = contour[0].from;
        go(sink, poly, d, c, &mut at, first, z);
        run_loop(sink, &contour, z);
        at = first;
        sink.rapid(at, c.r_plane);
    }
    let end = sink.last_xy();
    sink.rapid(end, c.clear);
}

/// To `to` at `z`: straight where that keeps off the walls, else over
/// the R plane and down again.
fn go(sink: &mut MoveSink<'_>, poly: &Polygon, d: f64, c: &PocketCut, at: &mut P2, to: P2, z: f64) {
    if dist(*at, to) < 1e-9 {
        return;
    }
    if safe(poly, d, *at, to) {
        sink.line(to, z);
    } else {
        sink.rapid(*at, c.r_plane);
        sink.rapid(to, c.r_plane);
        sink.line(to, z);
    }
    *at = to;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::post::frame::Frame;
    use crate::post::paths::coverage::{islands, Floor, Island};
    use crate::post::paths::Move;

    fn cut(r: f64, step: f64, allow: f64) -> PocketCut {
        PocketCut {
            tool_radius: r,
            stepover: step,
            allowance_side: allow,
            levels: vec![-5.0, -10.0],
            walls_only_above_bottom: false,
            ccw: true,
            clear: 20.0,
            r_plane: 2.0,
        }
    }

    fn pocket(pts: &[P2], rho: f64) -> GeneralPocket {
        GeneralPocket {
            boundary: Polygon::new(pts).unwrap(),
            corner_radius: rho,
        }
    }

    fn run(p: &GeneralPocket, c: &PocketCut) -> Vec<Move> {
        let frame = Frame::identity();
        let mut sink = MoveSink::new(&frame);
        moves(p, c, &mut sink);
        sink.moves
    }

    /// Islands wider than 0.1 mm left at the floor (z -10) where the
    /// tool could reach: inside the finishing contour or within the tool
    /// radius of it.
    fn left(p: &GeneralPocket, c: &PocketCut) -> Vec<Island> {
        let d = c.tool_radius + c.allowance_side;
        let fin = if p.boundary.is_convex() {
            convex_loop(p, d)
        } else {
            contour(&p.boundary, d).unwrap()
        };
        let ch = chords(&fin);
        let ring: Vec<P2> = ch.iter().map(|c| c.0).collect();
        let inner = Polygon { pts: ring };
        let r = c.tool_radius;
        let reach = |q: P2| {
            inner.contains(q)
                || ch
                    .iter()
                    .any(|&(a, b, _)| point_segment(q, a, b) <= r + 1e-9)
        };
        let (lo, hi) = bbox(&p.boundary.pts);
        let floor = Floor { lo, hi, cell: 0.1 };
        let m = run(p, c);
        islands(&m, -10.0, r, &floor, reach)
            .into_iter()
            .filter(|i| i.width() > 0.15)
            .collect()
    }

    /// Every cutting move keeps the tool centre at least the offset from
    /// every wall (no gouge).
    fn no_gouge(p: &GeneralPocket, c: &PocketCut) {
        let d = c.tool_radius + c.allowance_side;
        let m = run(p, c);
        let mut at: Option<[f64; 3]> = None;
        for mv in &m {
            match mv {
                Move::Line(to) => {
                    if let Some(f) = at {
                        if f[2] <= 0.0 || to[2] <= 0.0 {
                            let (a, b) = ([f[0], f[1]], [to[0], to[1]]);
                            assert!(
                                safe(&p.boundary, d - 1e-5, a, b) || dist(a, b) < 1e-9,
                                "{a:?} -> {b:?}"
                            );
                        }
                    }
                    at = Some(*to);
                }
                Move::Rapid(to) | Move::Arc { to, .. } => {
                    let q = [to[0], to[1]];
                    if to[2] <= 0.0 {
                        assert!(p.boundary.boundary_distance(q) >= d - 1e-5, "{q:?}");
                    }
                    at = Some(*to);
                }
            }
        }
    }

    const TRIANGLE: [P2; 3] = [[0.0, 0.0], [-84.0, -49.0], [-66.0, -114.0]];
    const L_SHAPE: [P2; 6] = [
        [0.0, 0.0],
        [60.0, 0.0],
        [60.0, 20.0],
        [20.0, 20.0],
        [20.0, 50.0],
        [0.0, 50.0],
    ];

    #[test]
    fn a_polygon_is_read_counter_clockwise_without_repeats() {
        let p = Polygon::new(&[
            [0.0, 0.0],
            [0.0, 10.0],
            [5.0, 10.0],
            [10.0, 10.0],
            [10.0, 0.0],
            [0.0, 0.0],
        ])
        .unwrap();
        assert_eq!(p.pts.len(), 4);
        assert!(area(&p.pts) > 0.0);
        assert!(p.is_convex());
        assert!(Polygon::new(&[[0.0, 0.0], [10.0, 0.0]]).is_err());
        let bow = Polygon::new(&[[0.0, 0.0], [10.0, 10.0], [10.0, 0.0], [0.0, 4.0]]);
        assert!(bow.unwrap_err().contains("crosses itself"));
        assert!(!Polygon::new(&L_SHAPE).unwrap().is_convex());
    }

    #[test]
    fn convex_insets_are_exact() {
        let sq = Polygon::new(&[[0.0, 0.0], [20.0, 0.0], [20.0, 10.0], [0.0, 10.0]]).unwrap();
        let i = sq.inset_convex(2.0);
        assert_eq!(bbox(&i), ([2.0, 2.0], [18.0, 8.0]));
        assert!(sq.inset_convex(5.0 + 1e-6).is_empty());
        assert!((sq.inradius_convex() - 5.0).abs() < 1e-5);
    }

    #[test]
    fn convex_pockets_leave_no_island_and_do_not_gouge() {
        let hexagon: Vec<P2> = (0..6)
            .map(|k| {
                let a = (k as f64) * std::f64::consts::PI / 3.0;
                [30.0 * a.cos(), 30.0 * a.sin()]
            })
            .collect();
        let chamfered = [
            [0.0, 0.0],
            [40.0, 0.0],
            [40.0, 25.0],
            [37.0, 30.0],
            [0.0, 30.0],
        ];
        // A half disc of radius 14 (its arc as 93 chords).
        let half_disc: Vec<P2> = (0..=93)
            .map(|k| {
                let a = k as f64 * std::f64::consts::PI / 93.0;
                [14.0 * a.cos(), 14.0 * a.sin()]
            })
            .collect();
        let cases: Vec<(GeneralPocket, PocketCut)> = vec![
            (pocket(&TRIANGLE, 12.0), cut(10.0, 15.0, 0.5)),
            (pocket(&TRIANGLE, 12.0), cut(5.0, 7.5, 0.5)),
            (pocket(&TRIANGLE, 12.0), cut(6.0, 9.0, 0.0)),
            (pocket(&TRIANGLE, 0.0), cut(3.0, 6.0, 0.0)),
            (pocket(&hexagon, 0.0), cut(3.0, 4.5, 0.0)),
            (pocket(&hexagon, 6.0), cut(4.0, 7.9, 0.2)),
            (pocket(&chamfered, 0.0), cut(3.0, 6.0, 0.0)),
            (pocket(&half_disc, 0.0), cut(4.0, 5.0, 0.0)),
            (pocket(&half_disc, 0.0), cut(2.0, 3.9, 0.2)),
        ];
        for (p, c) in cases {
            check(&p, &c).unwrap();
            let l = left(&p, &c);
            assert!(
                l.is_empty(),
                "{:?} r {}: {l:?}",
                p.boundary.pts,
                c.tool_radius
            );
            no_gouge(&p, &c);
        }
    }

    #[test]
    fn concave_pockets_are_cleared_zigzag_inside_their_contour() {
        for c in [cut(4.0, 6.0, 0.0), cut(3.0, 5.9, 0.3), cut(5.0, 10.0, 0.0)] {
            let p = pocket(&L_SHAPE, 0.0);
            check(&p, &c).unwrap();
            let l = left(&p, &c);
            assert!(l.is_empty(), "r {}: {l:?}", c.tool_radius);
            no_gouge(&p, &c);
        }
        // The contour arcs about the reflex corner (20, 20).
        let k = contour(&Polygon::new(&L_SHAPE).unwrap(), 4.0).unwrap();
        let arcs: Vec<_> = k.iter().filter_map(|s| s.arc).collect();
        assert_eq!(arcs, vec![([20.0, 20.0], false)]);
    }

    #[test]
    fn a_neck_narrower_than_the_tool_is_refused() {
        let dumbbell = [
            [0.0, 0.0],
            [30.0, 0.0],
            [30.0, 12.0],
            [50.0, 12.0],
            [50.0, 0.0],
            [80.0, 0.0],
            [80.0, 30.0],
            [50.0, 30.0],
            [50.0, 18.0],
            [30.0, 18.0],
            [30.0, 30.0],
            [0.0, 30.0],
        ];
        let p = pocket(&dumbbell, 0.0);
        assert!(check(&p, &cut(5.0, 7.0, 0.0)).is_err());
        // A tool that fits the neck is fine.
        let c = cut(2.5, 4.0, 0.0);
        check(&p, &c).unwrap();
        assert!(left(&p, &c).is_empty());
        no_gouge(&p, &c);
        // A concave pocket with a corner radius above the tool's: no generator.
        let e = check(&pocket(&L_SHAPE, 8.0), &cut(4.0, 6.0, 0.0)).unwrap_err();
        assert!(e.contains("corner radius"), "{e}");
    }
}
