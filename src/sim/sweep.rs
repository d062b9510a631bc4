//! The tool swept along a straight segment of its tip, cell by cell.
//!
//! For a cell centre `p`, the lowest point of the tool's surface over `p`
//! while the tip moves from `a` to `b` is the minimum over `t` in [0, 1]
//! of `z(t) + profile(rho(t))`, `rho(t)` being the distance in XY from `p`
//! to the tool axis at `t`. `rho(t)` is convex in `t` (the distance to a
//! line), the profile is convex and rising, `z(t)` is linear: the sum is
//! convex, so its minimum is found exactly in closed form for horizontal
//! and vertical moves and for flat tools, and by bisection on the slope
//! (to 1e-12 of the move) for a ramp with a shaped tool. The result is
//! exact at each cell centre: a slot, a drilled hole or a helix is cut
//! exactly at the grid's sampling.
//!
//! Arcs and helices are swept as chords within a tolerance (see
//! [`super::Simulation`]).

use super::cutter::{Cutter, Shape};
use super::grid::HeightField;
use nalgebra::{Vector2, Vector3};

/// Longest piece a segment is swept in (in tool radii), so that the box
/// of cells visited stays close to the tool's path.
const PIECE_RADII: f64 = 2.0;
/// Bisection steps for a ramp with a shaped tool.
const STEPS: usize = 48;

/// The deepest point where a probe found material above the tool.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Hit {
    /// How far the material stands above the tool's surface, mm.
    pub depth: f64,
    /// The cell centre, and the material's height there.
    pub at: [f64; 3],
}

/// One move of the tip, from `a` to `b`, swept with `cutter` over `field`.
pub struct Sweep<'a> {
    pub cutter: &'a Cutter,
    pub a: Vector3<f64>,
    pub b: Vector3<f64>,
    /// How far from the axis the tool reaches (its radius, at least half
    /// a cell so that a tool of unknown size still marks its path;
    /// smaller for a probe that gives the tool's side some play).
    pub reach: f64,
}

impl Sweep<'_> {
    /// Cuts: lowers every cell the tool passes below; the volume removed (mm³).
    pub fn cut(&self, field: &mut HeightField) -> f64 {
        let bottom = field.bottom;
        let mut removed = 0.0;
        self.visit(field, |h, s| {
            let s = s.max(bottom);
            if s < *h as f64 {
                removed += *h as f64 - s;
                *h = s as f32;
            }
        });
        removed * field.cell_area()
    }

    /// Looks without cutting: the deepest material above the tool.
    pub fn probe(&self, field: &mut HeightField) -> Option<Hit> {
        let mut best: Option<(f64, usize, f64)> = None;
        // Below the stock's bottom there is no material (the way out of
        // a through hole).
        let bottom = field.bottom;
        self.visit_indexed(field, |idx, h, s| {
            let depth = *h as f64 - s.max(bottom);
            if depth > best.map_or(0.0, |b| b.0) {
                best = Some((depth, idx, *h as f64));
            }
        });
        best.map(|(depth, k, h)| {
            let (x, y) = field.centre(k % field.nx, k / field.nx);
            Hit {
                depth,
                at: [x, y, h],
            }
        })
    }

    fn visit(&self, field: &mut HeightField, mut f: impl FnMut(&mut f32, f64)) {
        self.visit_indexed(field, |_, h, s| f(h, s))
    }

    /// Calls `f(index, height, surface)` for every cell in reach whose
    /// height is above the tool's lowest tip.
    fn visit_indexed(&self, field: &mut HeightField, mut f: impl FnMut(usize, &mut f32, f64)) {
        let len = (self.b.xy() - self.a.xy()).norm();
        let piece = (PIECE_RADII * self.reach).max(8.0 * field.dx.max(field.dy));
        let n = ((len / piece).ceil() as usize).clamp(1, 1 << 20);
        for k in 0..n {
            let a = self.a + (self.b - self.a) * (k as f64 / n as f64);
            let b = self.a + (self.b - self.a) * ((k + 1) as f64 / n as f64);
            self.visit_piece(field, a, b, &mut f);
        }
    }

    fn visit_piece(
        &self,
        field: &mut HeightField,
        a: Vector3<f64>,
        b: Vector3<f64>,
        f: &mut impl FnMut(usize, &mut f32, f64),
    ) {
        let r = self.reach;
        let cols = field.columns(a.x.min(b.x) - r, a.x.max(b.x) + r);
        let rows = field.rows(a.y.min(b.y) - r, a.y.max(b.y) + r);
        let tip = a.z.min(b.z);
        let seg = Segment::new(a, b);
        for j in rows {
            for i in cols.clone() {
                let idx = j * field.nx + i;
                if field.z[idx] as f64 <= tip {
                    continue;
                }
                let (x, y) = field.centre(i, j);
                if let Some(s) = seg.surface(self.cutter, r, Vector2::new(x, y)) {
                    f(idx, &mut field.z[idx], s);
                }
            }
        }
    }
}

/// A straight move of the tip, set up for many cells.
struct Segment {
    a: Vector3<f64>,
    d2: Vector2<f64>,
    l2: f64,
    dz: f64,
}

impl Segment {
    fn new(a: Vector3<f64>, b: Vector3<f64>) -> Segment {
        let d2 = b.xy() - a.xy();
        Segment {
            a,
            d2,
            l2: d2.norm_squared(),
            dz: b.z - a.z,
        }
    }

    /// The lowest point of the tool's surface over `p`, if the tool
    /// comes within `reach` of it.
    fn surface(&self, c: &Cutter, reach: f64, p: Vector2<f64>) -> Option<f64> {
        let w = p - self.a.xy();
        let r2 = reach * reach;
        if self.l2 < 1e-18 {
            let rho2 = w.norm_squared();
            return (rho2 <= r2).then(|| self.a.z + self.dz.min(0.0) + c.profile(rho2.sqrt()));
        }
        let t0 = w.dot(&self.d2) / self.l2;
        let e2 = (w - self.d2 * t0).norm_squared().max(0.0);
        if e2 > r2 {
            return None;
        }
        if self.dz.abs() < 1e-12 {
            let t = t0.clamp(0.0, 1.0);
            let rho2 = (w - self.d2 * t).norm_squared();
            return (rho2 <= r2).then(|| self.a.z + c.profile(rho2.sqrt()));
        }
        let half = ((r2 - e2) / self.l2).sqrt();
        let (lo, hi) = ((t0 - half).max(0.0), (t0 + half).min(1.0));
        if lo > hi {
            return None;
        }
        let t = if c.is_flat() {
            if self.dz > 0.0 {
                lo
            } else {
                hi
            }
        } else if matches!(c.shape, Shape::Ball) {
            self.ball_lowest(c.radius, w)
                .map_or_else(|| self.lowest(c, e2, t0, lo, hi), |t| t.clamp(lo, hi))
        } else {
            self.lowest(c, e2, t0, lo, hi)
        };
        let rho = (e2 + self.l2 * (t - t0).powi(2)).sqrt();
        Some(self.a.z + t * self.dz + c.profile(rho))
    }

    /// For a ball of radius `r`, where along the whole line the ball's
    /// lowest point over `p` (`w` = p - a, in XY) is lowest, in closed
    /// form: the point (p, z) lowest at distance `r` from the line of the
    /// ball's centre, `z - (a.z + r) = s` the smaller root of
    /// `l2 s² - 2 k dz s + (L3 |w|² - k² - r² L3) = 0` (`k = w . d`,
    /// `L3 = l2 + dz²`); its foot on the line is the parameter. The
    /// height is convex in the parameter, so clamped to the cells' range
    /// it is the lowest there. None when the line passes further than `r`.
    fn ball_lowest(&self, r: f64, w: Vector2<f64>) -> Option<f64> {
        let k = w.dot(&self.d2);
        let l3 = self.l2 + self.dz * self.dz;
        let c = l3 * w.norm_squared() - k * k - r * r * l3;
        let b = k * self.dz;
        let disc = b * b - self.l2 * c;
        if disc < 0.0 || !disc.is_finite() {
            return None;
        }
        let s = (b - disc.sqrt()) / self.l2;
        Some((k + s * self.dz) / l3)
    }

    /// Where in `[lo, hi]` the convex height is lowest: bisection on its slope.
    fn lowest(&self, c: &Cutter, e2: f64, t0: f64, lo: f64, hi: f64) -> f64 {
        let slope = |t: f64| {
            let rho = (e2 + self.l2 * (t - t0).powi(2)).sqrt();
            if rho < 1e-15 {
                return self.dz;
            }
            self.dz + c.slope(rho) * self.l2 * (t - t0) / rho
        };
        if slope(lo) >= 0.0 {
            return lo;
        }
        if slope(hi) <= 0.0 {
            return hi;
        }
        let (mut l, mut h) = (lo, hi);
        for _ in 0..STEPS {
            let m = 0.5 * (l + h);
            if slope(m) < 0.0 {
                l = m;
            } else {
                h = m;
            }
        }
        0.5 * (l + h)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::toolpath::Stock;

    fn field() -> HeightField {
        let s: Stock = "100x50x20".parse().unwrap();
        HeightField::new(&s, 0.1).unwrap()
    }

    fn sweep(c: &Cutter, a: [f64; 3], b: [f64; 3]) -> Sweep<'_> {
        Sweep {
            cutter: c,
            a: Vector3::from(a),
            b: Vector3::from(b),
            reach: c.radius,
        }
    }

    #[test]
    fn a_flat_slot_is_exact() {
        let mut f = field();
        let c = Cutter::flat(5.0);
        let v = sweep(&c, [10.0, 20.0, -3.0], [60.0, 20.0, -3.0]).cut(&mut f);
        let exact = 3.0 * (50.0 * 10.0 + std::f64::consts::PI * 25.0);
        assert!((v - exact).abs() / exact < 0.005, "{v} vs {exact}");
        assert!((f.removed() - v).abs() < 1e-6 * exact);
    }

    #[test]
    fn a_ball_ramp_cuts_a_round_groove() {
        let mut f = field();
        let c = Cutter {
            radius: 3.0,
            shape: Shape::Ball,
        };
        sweep(&c, [10.0, 20.0, 0.0], [60.0, 20.0, -5.0]).cut(&mut f);
        // Halfway along, 2 mm beside the path: the ball's surface.
        let z = f.at(35.05, 22.05).unwrap();
        // The lowest of the ball over that point, by brute force.
        let expect = (0..=200_000)
            .map(|k| {
                let x = 10.0 + 50.0 * k as f64 / 200_000.0;
                let rho2 = (x - 35.05).powi(2) + 2.05f64.powi(2);
                (rho2 <= 9.0).then(|| -(x - 10.0) / 10.0 + 3.0 - (9.0 - rho2).sqrt())
            })
            .flatten()
            .fold(f64::MAX, f64::min);
        assert!((z - expect).abs() < 0.01, "{z} vs {expect}");
    }

    #[test]
    fn a_probe_finds_material_and_does_not_cut() {
        let mut f = field();
        let c = Cutter::flat(5.0);
        let hit = sweep(&c, [10.0, 20.0, 5.0], [60.0, 20.0, -1.0])
            .probe(&mut f)
            .unwrap();
        assert!((hit.depth - 1.0).abs() < 0.01, "{hit:?}");
        assert_eq!(f.removed(), 0.0);
        assert!(sweep(&c, [10.0, 20.0, 5.0], [60.0, 20.0, 1.0])
            .probe(&mut f)
            .is_none());
    }

    #[test]
    fn the_ball_closed_form_agrees_with_the_bisection() {
        let ball = Cutter {
            radius: 3.0,
            shape: Shape::Ball,
        };
        let moves = [
            ([0.0, 0.0, 0.0], [10.0, 4.0, -5.0]),
            ([0.0, 0.0, -2.0], [1.0, -0.5, 3.0]),
            ([5.0, 5.0, 0.0], [5.5, 5.0, -20.0]),
            ([0.0, 0.0, 0.0], [0.3, 0.1, -0.01]),
        ];
        for (a, b) in moves {
            let seg = Segment::new(Vector3::from(a), Vector3::from(b));
            for k in 0..400 {
                let p = Vector2::new(-4.0 + 0.037 * k as f64, -3.0 + 0.029 * k as f64);
                let w = p - seg.a.xy();
                let t0 = w.dot(&seg.d2) / seg.l2;
                let e2 = (w - seg.d2 * t0).norm_squared();
                if e2 >= 9.0 {
                    continue;
                }
                let half = ((9.0 - e2) / seg.l2).sqrt();
                let (lo, hi) = ((t0 - half).max(0.0), (t0 + half).min(1.0));
                if lo > hi {
                    continue;
                }
                let z = |t: f64| {
                    let rho = (e2 + seg.l2 * (t - t0).powi(2)).sqrt();
                    seg.a.z + t * seg.dz + ball.profile(rho)
                };
                let closed = z(seg.ball_lowest(3.0, w).unwrap().clamp(lo, hi));
                let bisected = z(seg.lowest(&ball, e2, t0, lo, hi));
                assert!(
                    (closed - bisected).abs() < 1e-7,
                    "{a:?} {b:?} {p:?}: {closed} {bisected}"
                );
            }
        }
    }
}
