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
use super::grid::{HeightField, TILE};
use nalgebra::{Vector2, Vector3};
use std::cell::Cell;

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
        let mut plateaus = 0.0;
        self.visit_indexed(
            field,
            |_, h, s| {
                let s = s.max(bottom);
                if s < *h as f64 {
                    removed += *h as f64 - s;
                    *h = s as f32;
                }
            },
            |_, cells, z, zmin| {
                // The same test and height as `f` cell by cell, without
                // branches, the sum in four parts (no chain of dependent
                // additions): the compiler can take cells in pairs.
                let s = z.max(bottom);
                let low = s as f32;
                let (mut sum, mut lowered) = ([0.0f64; 4], false);
                let mut quads = cells.chunks_exact_mut(4);
                for q in &mut quads {
                    for k in 0..4 {
                        let old = q[k] as f64;
                        let cut = old > zmin && s < old;
                        sum[k] += if cut { old - s } else { 0.0 };
                        q[k] = if cut { low } else { q[k] };
                        lowered |= cut;
                    }
                }
                for (k, h) in quads.into_remainder().iter_mut().enumerate() {
                    let old = *h as f64;
                    let cut = old > zmin && s < old;
                    sum[k] += if cut { old - s } else { 0.0 };
                    *h = if cut { low } else { *h };
                    lowered |= cut;
                }
                plateaus += (sum[0] + sum[1]) + (sum[2] + sum[3]);
                lowered
            },
        );
        (removed + plateaus) * field.cell_area()
    }

    /// Looks without cutting: the deepest material above the tool.
    pub fn probe(&self, field: &mut HeightField) -> Option<Hit> {
        let best: Cell<Option<(f64, usize, f64)>> = Cell::new(None);
        // Below the stock's bottom there is no material (the way out of
        // a through hole).
        let bottom = field.bottom;
        let look = |idx: usize, h: f32, s: f64| {
            let depth = h as f64 - s.max(bottom);
            if depth > best.get().map_or(0.0, |b| b.0) {
                best.set(Some((depth, idx, h as f64)));
            }
        };
        self.visit_indexed(
            field,
            |idx, h, s| look(idx, *h, s),
            |idx, cells, z, zmin| {
                for (k, h) in cells.iter().enumerate() {
                    if *h as f64 > zmin {
                        look(idx + k, *h, z);
                    }
                }
                false
            },
        );
        best.get().map(|(depth, k, h)| {
            let (x, y) = field.centre(k % field.nx, k / field.nx);
            Hit {
                depth,
                at: [x, y, h],
            }
        })
    }

    /// Calls `f(index, height, surface)` for every cell in reach that the
    /// tool's surface may go below (see the module doc: whole tiles and
    /// cells the bound rules out are passed over; `f` decides). A run of
    /// cells of one row in a flat tool's [`Plateau`] goes to `run(index
    /// of the first, cells, the plateau's height, lowest tip)`, which
    /// must do what `f` does to each cell standing above the lowest tip
    /// and say whether it lowered any. The cells are visited in the same
    /// order, with the same heights, as when every cell is solved.
    fn visit_indexed(
        &self,
        field: &mut HeightField,
        mut f: impl FnMut(usize, &mut f32, f64),
        mut run: impl FnMut(usize, &mut [f32], f64, f64) -> bool,
    ) {
        let r = self.reach;
        let (a, b) = (self.a, self.b);
        let bound = Bound::new(self.cutter, a.z.min(b.z));
        // No cell stands above the stock's top (as the cells hold it): a
        // move whose lowest tip is at or above it (a rapid in air)
        // touches nothing.
        if bound.zmin >= field.top as f32 as f64 {
            return;
        }
        let rows = field.rows(a.y.min(b.y) - r, a.y.max(b.y) + r);
        let cols = field.columns(a.x.min(b.x) - r, a.x.max(b.x) + r);
        if rows.is_empty() || cols.is_empty() {
            return;
        }
        let tile_cols = cols.start / TILE..cols.end.div_ceil(TILE);
        let seg = Segment::new(a, b);
        let plateau = Plateau::new(self.cutter, &seg, r);
        let plateau_z = plateau.as_ref().map_or(0.0, |p| p.z);
        // A flat tool's surface is within reach or nowhere: the cell's
        // own bound (the lowest tip) is the tile's, tested first.
        let flat = matches!(self.cutter.shape, Shape::Flat);
        // Half the diagonal of a tile's cell centres.
        let half = (TILE - 1) as f64 / 2.0;
        let tile_half = (half * field.dx).hypot(half * field.dy);
        let mut spans = [(0, 0); TILE];
        let mut flats = [(0, 0); TILE];
        for tj in rows.start / TILE..rows.end.div_ceil(TILE) {
            // A row of tiles none of whose material stands above the
            // lowest tip is passed over before its rows are clipped.
            let peaks = &field.peaks[tj * field.tiles_x..];
            if peaks[tile_cols.clone()]
                .iter()
                .all(|p| *p as f64 <= bound.zmin)
            {
                continue;
            }
            let j0 = tj * TILE;
            let (mut lo, mut hi) = (usize::MAX, 0);
            for (k, span) in spans.iter_mut().enumerate() {
                let j = j0 + k;
                *span = (0, 0);
                flats[k] = (0, 0);
                if !rows.contains(&j) {
                    continue;
                }
                let y = field.origin[1] + (j as f64 + 0.5) * field.dy;
                if let Some((x0, x1)) = seg.row(y, r) {
                    let c = field.columns(x0, x1);
                    if c.start < c.end {
                        *span = (c.start, c.end);
                        lo = lo.min(c.start);
                        hi = hi.max(c.end);
                        if let Some((x0, x1)) = plateau.as_ref().and_then(|p| p.row(&seg, y)) {
                            let c = field.columns(x0, x1);
                            flats[k] = (c.start.max(span.0), c.end.min(span.1));
                        }
                    }
                }
            }
            if lo >= hi {
                continue;
            }
            // The cells of a whole tile (fewer at the field's far edges).
            let tile_rows = (j0 + TILE).min(field.ny) - j0;
            for ti in lo / TILE..hi.div_ceil(TILE) {
                let peak = field.peaks[tj * field.tiles_x + ti] as f64;
                if peak <= bound.zmin {
                    continue;
                }
                let (cx, cy) = field.centre(ti * TILE, j0);
                let centre = Vector2::new(cx + half * field.dx, cy + half * field.dy);
                let e = seg.distance2(centre).sqrt() - tile_half;
                if e > r + SLACK || (e > 0.0 && !bound.may_reach(peak, e * e)) {
                    continue;
                }
                let cols = ti * TILE..((ti + 1) * TILE).min(field.nx);
                let mut lowered = false;
                // The highest cell seen, and how many: when the sweep saw
                // the whole tile, its highest cell is its new peak.
                let (mut top, mut seen) = (f32::NEG_INFINITY, 0);
                for (k, span) in spans.iter().enumerate() {
                    let j = j0 + k;
                    let y = field.origin[1] + (j as f64 + 0.5) * field.dy;
                    let (start, end) = (span.0.max(cols.start), span.1.min(cols.end));
                    if start >= end {
                        continue;
                    }
                    seen += end - start;
                    // The plateau's cells of this row in this tile, if any.
                    let (f0, f1) = (flats[k].0.max(start), flats[k].1.min(end));
                    let (f0, f1) = if f0 < f1 { (f0, f1) } else { (end, end) };
                    let mut i = start;
                    while i < end {
                        if i == f0 {
                            let row = j * field.nx;
                            let cells = &mut field.z[row + f0..row + f1];
                            lowered |= run(row + f0, cells, plateau_z, bound.zmin);
                            top = cells.iter().fold(top, |m, h| m.max(*h));
                            i = f1;
                            continue;
                        }
                        let idx = j * field.nx + i;
                        let x = field.origin[0] + (i as f64 + 0.5) * field.dx;
                        i += 1;
                        let h = field.z[idx];
                        if h as f64 > bound.zmin {
                            let p = Vector2::new(x, y);
                            let near = flat || {
                                let e2 = seg.distance2(p);
                                e2 <= r * r && bound.may_reach(h as f64, e2)
                            };
                            if let Some(s) = near.then(|| seg.surface(self.cutter, r, p)).flatten()
                            {
                                f(idx, &mut field.z[idx], s);
                                lowered |= field.z[idx] < h;
                            }
                        }
                        top = top.max(field.z[idx]);
                    }
                }
                if lowered {
                    if seen == tile_rows * cols.len() {
                        // Every cell seen, after the cut: the highest.
                        field.peaks[tj * field.tiles_x + ti] = top;
                    } else {
                        field.refresh_peak(ti, tj);
                    }
                }
            }
        }
    }
}

/// Where a flat tool's swept surface is one height, known without a
/// root: [`Segment::surface`] gives every cell centre there exactly
/// `z` (the same float). For a horizontal move that is the whole band
/// round the path, for a move along Z the disc round the axis, for a
/// ramp the disc round its lower end (the tool passes there last going
/// down, first going up: the parameter clamps to that end). The region
/// is taken `margin` inside the reach, far more than the rounding of
/// [`Segment::surface`]'s tests, so that its every cell passes them.
struct Plateau {
    z: f64,
    /// The disc's centre and radius; `None`: the band round the path.
    disc: Option<(Vector2<f64>, f64)>,
    radius: f64,
}

impl Plateau {
    fn new(c: &Cutter, seg: &Segment, reach: f64) -> Option<Plateau> {
        if !matches!(c.shape, Shape::Flat) {
            return None;
        }
        let margin = 1e-6 * (1.0 + reach + seg.l2.sqrt());
        let radius = reach - margin;
        if !(radius > 0.0) {
            return None;
        }
        // The same sums as `Segment::surface` makes (the profile is 0).
        let (z, centre) = if seg.l2 < 1e-18 {
            (seg.a.z + seg.dz.min(0.0) + 0.0, Some(seg.a.xy()))
        } else if seg.dz.abs() < 1e-12 {
            (seg.a.z + 0.0, None)
        } else if seg.dz > 0.0 {
            (seg.a.z + 0.0 * seg.dz + 0.0, Some(seg.a.xy()))
        } else {
            (seg.a.z + 1.0 * seg.dz + 0.0, Some(seg.a.xy() + seg.d2))
        };
        Some(Plateau {
            z,
            disc: centre.map(|c| (c, radius)),
            radius,
        })
    }

    /// The X range of row `y` in the plateau.
    fn row(&self, seg: &Segment, y: f64) -> Option<(f64, f64)> {
        match self.disc {
            None => seg
                .row(y, self.radius)
                .map(|(lo, hi)| (lo + SLACK, hi - SLACK)),
            Some((c, r)) => {
                let dy = y - c.y;
                (dy.abs() < r).then(|| {
                    let w = (r * r - dy * dy).sqrt();
                    (c.x - w, c.x + w)
                })
            }
        }
    }
}

/// How far (mm) beyond the reach a row's span and a tile's distance are
/// taken, so that rounding never leaves out a cell the exact test takes.
const SLACK: f64 = 1e-9;

/// The lower bound of a move's swept surface: over a point at distance
/// `e` from the path (in XY) the tool's surface is no lower than
/// `zmin + profile(e)`, `zmin` the lowest tip (the profile rises).
struct Bound {
    zmin: f64,
    radius: f64,
    shape: Shape,
}

impl Bound {
    fn new(c: &Cutter, zmin: f64) -> Bound {
        Bound {
            zmin,
            radius: c.radius,
            shape: c.shape,
        }
    }

    /// May the tool's surface at distance `sqrt(e2)` from the path go
    /// below material standing at `h`? False when `zmin + profile(e) >=
    /// h`, decided without a root for a ball: `profile(e) >= g` is `e >=`
    /// the profile's inverse at `g` (the profile clamps at the radius).
    fn may_reach(&self, h: f64, e2: f64) -> bool {
        let g = h - self.zmin;
        if g <= 0.0 {
            return false;
        }
        let r = self.radius;
        match self.shape {
            Shape::Flat => true,
            Shape::Ball => g > r || e2 < g * (2.0 * r - g),
            Shape::Bull { corner: c } => {
                g > c || {
                    let rho = (r - c) + (g * (2.0 * c - g)).max(0.0).sqrt();
                    e2 < rho * rho
                }
            }
            Shape::Cone { angle } => {
                let rho = g * (angle.to_radians() / 2.0).tan();
                rho > r || e2 < rho * rho
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
    /// `1 / l2` (0 for a move along Z) and `1 / (l2 + dz²)`.
    inv_l2: f64,
    inv_l3: f64,
}

impl Segment {
    fn new(a: Vector3<f64>, b: Vector3<f64>) -> Segment {
        let d2 = b.xy() - a.xy();
        let l2 = d2.norm_squared();
        let dz = b.z - a.z;
        let l3 = l2 + dz * dz;
        Segment {
            a,
            d2,
            l2,
            dz,
            inv_l2: if l2 < 1e-18 { 0.0 } else { 1.0 / l2 },
            inv_l3: if l3 < 1e-18 { 0.0 } else { 1.0 / l3 },
        }
    }

    /// The squared distance in XY from `p` to the segment.
    fn distance2(&self, p: Vector2<f64>) -> f64 {
        let w = p - self.a.xy();
        let t = (w.dot(&self.d2) * self.inv_l2).clamp(0.0, 1.0);
        (w - self.d2 * t).norm_squared()
    }

    /// The X range (widened by [`SLACK`]) of the points of row `y` within
    /// `r` of the segment: the hull of the two end discs' chords and the
    /// band between them. None when the row passes further away.
    fn row(&self, y: f64, r: f64) -> Option<(f64, f64)> {
        let (a, b) = (self.a.xy(), self.a.xy() + self.d2);
        let mut span: Option<(f64, f64)> = None;
        let mut add = |lo: f64, hi: f64| {
            if lo <= hi {
                let s = span.get_or_insert((lo, hi));
                *s = (s.0.min(lo), s.1.max(hi));
            }
        };
        for c in [a, b] {
            let dy = y - c.y;
            if dy.abs() <= r {
                let w = (r * r - dy * dy).max(0.0).sqrt();
                add(c.x - w, c.x + w);
            }
        }
        if self.l2 >= 1e-18 {
            let len = self.l2.sqrt();
            let u = self.d2 / len;
            let n = Vector2::new(-u.y, u.x);
            // Across the path within r, along it within the segment.
            let across = slab(n.x, n.y * (y - a.y) - n.x * a.x, -r, r);
            let along = slab(u.x, u.y * (y - a.y) - u.x * a.x, 0.0, len);
            if let (Some(p), Some(q)) = (across, along) {
                add(p.0.max(q.0), p.1.min(q.1));
            }
        }
        span.map(|(lo, hi)| (lo - SLACK, hi + SLACK))
    }

    /// The lowest point of the tool's surface over `p`, if the tool
    /// comes within `reach` of it.
    #[inline]
    fn surface(&self, c: &Cutter, reach: f64, p: Vector2<f64>) -> Option<f64> {
        let w = p - self.a.xy();
        let r2 = reach * reach;
        if self.l2 < 1e-18 {
            let rho2 = w.norm_squared();
            return (rho2 <= r2).then(|| self.a.z + self.dz.min(0.0) + c.profile(rho2.sqrt()));
        }
        let t0 = w.dot(&self.d2) * self.inv_l2;
        let e2 = (w - self.d2 * t0).norm_squared().max(0.0);
        if e2 > r2 {
            return None;
        }
        if self.dz.abs() < 1e-12 {
            let t = t0.clamp(0.0, 1.0);
            let rho2 = (w - self.d2 * t).norm_squared();
            return (rho2 <= r2).then(|| self.a.z + c.profile(rho2.sqrt()));
        }
        if matches!(c.shape, Shape::Ball) && reach >= c.radius {
            if let Some(z) = self.ball_surface(c.radius, w) {
                return Some(z);
            }
        }
        let half = ((r2 - e2) * self.inv_l2).sqrt();
        let (lo, hi) = ((t0 - half).max(0.0), (t0 + half).min(1.0));
        if lo > hi {
            return None;
        }
        if matches!(c.shape, Shape::Flat) {
            // The profile is 0: the height where the tool is lowest.
            let t = if self.dz > 0.0 { lo } else { hi };
            return Some(self.a.z + t * self.dz + 0.0);
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

    /// A ball of radius `r` (reaching at least `r`) over `p` (`w` = p -
    /// a, in XY), in closed form: the lowest point of the cylinder round
    /// the line of the ball's centre (see [`Segment::ball_lowest`], the
    /// root taken in its stable form) when its foot lies on the segment,
    /// else the ball at the nearer end when `p` is under it. None leaves
    /// it to the general path (the line passes further than `r`, or `p`
    /// is beyond the end ball).
    #[inline]
    fn ball_surface(&self, r: f64, w: Vector2<f64>) -> Option<f64> {
        let k = w.dot(&self.d2);
        let l3 = self.l2 + self.dz * self.dz;
        let c = l3 * w.norm_squared() - k * k - r * r * l3;
        let b = k * self.dz;
        let disc = b * b - self.l2 * c;
        if !(disc >= 0.0 && disc.is_finite()) {
            return None;
        }
        let root = disc.sqrt();
        // s = (b - root) / l2, without the cancellation when b > 0.
        let s = if b > 0.0 {
            c / (b + root)
        } else {
            (b - root) * self.inv_l2
        };
        let t = (k + s * self.dz) * self.inv_l3;
        if (0.0..=1.0).contains(&t) {
            return Some(self.a.z + r + s);
        }
        let end = t.clamp(0.0, 1.0);
        let q2 = (w - self.d2 * end).norm_squared();
        (q2 <= r * r).then(|| self.a.z + end * self.dz + r - (r * r - q2).sqrt())
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

/// The `x` with `lo <= k x + off <= hi` (all of them when `k` is 0 and
/// `off` is in range: an unbounded interval).
fn slab(k: f64, off: f64, lo: f64, hi: f64) -> Option<(f64, f64)> {
    if k.abs() < 1e-12 {
        return (lo - SLACK <= off && off <= hi + SLACK).then_some((f64::MIN, f64::MAX));
    }
    let (p, q) = ((lo - off) / k, (hi - off) / k);
    Some((p.min(q), p.max(q)))
}

#[cfg(test)]
mod tests;
