//! Does a generated path clear what it claims? The floor is rasterised
//! (a square grid) and every cell within the tool radius of a cutting
//! move at the floor's height is marked swept; cells the tool can reach
//! (the caller says which) that stay unswept form islands, and each
//! island's width (the smaller side of its bounding box) is measured. A
//! pocket, face or slot path is right when no island is wider than the
//! tolerance. Used by the tests of the path generators.

use super::{Move, P2};

/// One island of material left standing on the floor.
#[derive(Clone, Debug, PartialEq)]
pub struct Island {
    /// Bounding box, min and max corner.
    pub min: P2,
    pub max: P2,
    pub cells: usize,
}

impl Island {
    /// The smaller side of the bounding box.
    pub fn width(&self) -> f64 {
        (self.max[0] - self.min[0]).min(self.max[1] - self.min[1])
    }
}

/// The raster: `lo`..`hi` in steps of `cell`.
pub struct Floor {
    pub lo: P2,
    pub hi: P2,
    pub cell: f64,
}

impl Floor {
    fn dims(&self) -> (usize, usize) {
        let n = |k: usize| (((self.hi[k] - self.lo[k]) / self.cell).ceil() as usize).max(1);
        (n(0), n(1))
    }

    fn centre(&self, i: usize, j: usize) -> P2 {
        [
            self.lo[0] + (i as f64 + 0.5) * self.cell,
            self.lo[1] + (j as f64 + 0.5) * self.cell,
        ]
    }
}

/// Islands left on the floor at height `z` by `moves` (tool-centre moves,
/// absolute) of a tool of radius `r`; `reachable` says which points the
/// feature asks to be cleared.
pub fn islands(
    moves: &[Move],
    z: f64,
    r: f64,
    floor: &Floor,
    reachable: impl Fn(P2) -> bool,
) -> Vec<Island> {
    let (nx, ny) = floor.dims();
    let mut swept = vec![false; nx * ny];
    let mut cur: Option<[f64; 3]> = None;
    for m in moves {
        let (to, pieces) = match m {
            Move::Rapid(p) => (*p, Vec::new()),
            Move::Line(p) => (*p, vec![(cur, *p)]),
            Move::Arc { to, centre, ccw } => (*to, arc_chords(cur, *to, *centre, *ccw)),
        };
        for (from, end) in pieces {
            let Some(from) = from else { continue };
            if (from[2] - z).abs() < 1e-6 && (end[2] - z).abs() < 1e-6 {
                sweep(&mut swept, floor, [from[0], from[1]], [end[0], end[1]], r);
            }
        }
        cur = Some(to);
    }
    collect(&swept, floor, reachable)
}

/// An arc as short chords (each piece a line from the last point).
fn arc_chords(
    from: Option<[f64; 3]>,
    to: [f64; 3],
    c: P2,
    ccw: bool,
) -> Vec<(Option<[f64; 3]>, [f64; 3])> {
    let Some(f) = from else { return Vec::new() };
    let a0 = (f[1] - c[1]).atan2(f[0] - c[0]);
    let a1 = (to[1] - c[1]).atan2(to[0] - c[0]);
    let rad = ((f[0] - c[0]).powi(2) + (f[1] - c[1]).powi(2)).sqrt();
    let tau = std::f64::consts::TAU;
    let mut sweep = if ccw { a1 - a0 } else { a0 - a1 };
    if sweep <= 1e-12 {
        sweep += tau;
    }
    let n = ((sweep * rad / 0.05).ceil() as usize).clamp(2, 10_000);
    let mut out = Vec::with_capacity(n);
    let mut last = f;
    for k in 1..=n {
        let t = sweep * k as f64 / n as f64;
        let a = if ccw { a0 + t } else { a0 - t };
        let p = [c[0] + rad * a.cos(), c[1] + rad * a.sin(), to[2]];
        out.push((Some(last), p));
        last = p;
    }
    out
}

fn sweep(swept: &mut [bool], floor: &Floor, a: P2, b: P2, r: f64) {
    let (nx, ny) = floor.dims();
    let cell = |v: f64, k: usize, n: usize| {
        (((v - floor.lo[k]) / floor.cell).floor().max(0.0) as usize).min(n - 1)
    };
    let (i0, i1) = (
        cell(a[0].min(b[0]) - r, 0, nx),
        cell(a[0].max(b[0]) + r, 0, nx),
    );
    let (j0, j1) = (
        cell(a[1].min(b[1]) - r, 1, ny),
        cell(a[1].max(b[1]) + r, 1, ny),
    );
    for j in j0..=j1 {
        for i in i0..=i1 {
            if segment_distance(floor.centre(i, j), a, b) <= r + 1e-9 {
                swept[j * nx + i] = true;
            }
        }
    }
}

fn segment_distance(p: P2, a: P2, b: P2) -> f64 {
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let len2 = dx * dx + dy * dy;
    let t = if len2 < 1e-18 {
        0.0
    } else {
        (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2).clamp(0.0, 1.0)
    };
    let (qx, qy) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
    (qx * qx + qy * qy).sqrt()
}

/// Connected unswept reachable cells, as islands.
fn collect(swept: &[bool], floor: &Floor, reachable: impl Fn(P2) -> bool) -> Vec<Island> {
    let (nx, ny) = floor.dims();
    let mut seen = vec![false; nx * ny];
    let mut out = Vec::new();
    for start in 0..nx * ny {
        let open = |k: usize| !swept[k] && reachable(floor.centre(k % nx, k / nx));
        if seen[start] || !open(start) {
            continue;
        }
        let mut stack = vec![start];
        seen[start] = true;
        let c = floor.centre(start % nx, start / nx);
        let mut isl = Island {
            min: c,
            max: c,
            cells: 0,
        };
        while let Some(k) = stack.pop() {
            let (i, j) = (k % nx, k / nx);
            let p = floor.centre(i, j);
            isl.cells += 1;
            isl.min = [isl.min[0].min(p[0]), isl.min[1].min(p[1])];
            isl.max = [isl.max[0].max(p[0]), isl.max[1].max(p[1])];
            let near = [
                (i > 0).then(|| k - 1),
                (i + 1 < nx).then(|| k + 1),
                (j > 0).then(|| k - nx),
                (j + 1 < ny).then(|| k + nx),
            ];
            for n in near.into_iter().flatten() {
                if !seen[n] && open(n) {
                    seen[n] = true;
                    stack.push(n);
                }
            }
        }
        out.push(isl);
    }
    out
}

/// Whether `p` lies in the rounded rectangle of half sizes `a`, `b` and
/// corner radius `rho` about the origin, grown by `grow`.
pub fn in_rounded_rect(p: P2, a: f64, b: f64, rho: f64, grow: f64) -> bool {
    let rho = rho.min(a).min(b).max(0.0);
    let q = [p[0].abs() - (a - rho), p[1].abs() - (b - rho)];
    let outside = (q[0].max(0.0).powi(2) + q[1].max(0.0).powi(2)).sqrt();
    let inside = q[0].max(q[1]).min(0.0);
    outside + inside - rho <= grow + 1e-9
}
