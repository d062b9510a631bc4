//! Prismatic features: a cross-section swept along a straight line (a V
//! slot, a U slot with sloped walls, a step whose wall is sloped). The
//! section is the target surface `z = s(u)` across the feature (`u` to
//! the left of the course of travel, mm; absolute z), a polyline with the
//! material's top (or air) beyond its ends.
//!
//! Passes are made in the section as a drop cutter does on a 1-D
//! profile: the lowest tool tip at `u` is the highest `s(u') - h(|u-u'|)`
//! under the tool (`h` the tool's height above its tip at a radius, for
//! flat, ball, bull-nose and V tools), so no pass goes below the surface.
//! The depth is taken in levels from the top; each level clears, across
//! the width the tool can reach at that level, passes at most a stepover
//! apart, the first and last touching the walls. A flat tool so leaves a
//! staircase on a sloped wall, a ball or bull-nose tool scallops: the
//! material left over what the tool could reach at all is computed on the
//! section (a 0.01 mm grid) and the level spacing is halved until it is
//! within the tolerance ([`plan`]). What the tool cannot reach at all (a
//! radius smaller than the tool's corner, a V's point) is measured too,
//! for the caller to refuse where the cut must finish the feature.

/// The target surface across the feature.
#[derive(Clone, Debug)]
pub struct Section {
    /// `(u, z)` points with increasing u.
    pub points: Vec<[f64; 2]>,
    /// The surface's height beyond the first point (`None`: air).
    pub below_first: Option<f64>,
    /// The surface's height beyond the last point (`None`: air).
    pub beyond_last: Option<f64>,
    /// The top of the material, where the levels start.
    pub top: f64,
}

/// The tool as seen in the section (its profile through its axis).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ToolShape {
    Flat {
        r: f64,
    },
    Ball {
        r: f64,
    },
    /// Corner radius `rc` on a tool of radius `r`.
    Bull {
        r: f64,
        rc: f64,
    },
    /// A pointed tool: the cone's half angle from the axis (degrees).
    Vee {
        r: f64,
        half_angle: f64,
    },
}

impl ToolShape {
    pub fn radius(&self) -> f64 {
        match *self {
            ToolShape::Flat { r }
            | ToolShape::Ball { r }
            | ToolShape::Bull { r, .. }
            | ToolShape::Vee { r, .. } => r,
        }
    }

    /// Height of the tool's surface above its tip at radius `rho`
    /// (`None` beyond the tool).
    pub fn height(&self, rho: f64) -> Option<f64> {
        let r = self.radius();
        if rho > r + 1e-12 {
            return None;
        }
        let rho = rho.min(r);
        Some(match *self {
            ToolShape::Flat { .. } => 0.0,
            ToolShape::Ball { r } => r - (r * r - rho * rho).max(0.0).sqrt(),
            ToolShape::Bull { r, rc } => {
                let q = rho - (r - rc);
                if q <= 0.0 {
                    0.0
                } else {
                    rc - (rc * rc - q * q).max(0.0).sqrt()
                }
            }
            ToolShape::Vee { half_angle, .. } => rho / half_angle.to_radians().tan(),
        })
    }

    pub fn describe(&self) -> String {
        let d = |v: f64| (v * 2000.0).round() / 1000.0;
        match *self {
            ToolShape::Flat { r } => format!("flat, diameter {}", d(r)),
            ToolShape::Ball { r } => format!("ball, diameter {}", d(r)),
            ToolShape::Bull { r, rc } => {
                format!("corner radius {}, diameter {}", d(rc / 2.0), d(r))
            }
            ToolShape::Vee { r, half_angle } => {
                format!("pointed {}°, diameter {}", d(half_angle), d(r))
            }
        }
    }
}

/// Grid spacing of the section (mm).
pub const DU: f64 = 0.01;

/// The section sampled on a grid, with the lowest tool tip at each u.
pub struct Grid {
    pub u0: f64,
    pub s: Vec<f64>,
    pub tip: Vec<f64>,
    pub tool: ToolShape,
    /// Tool centres allowed: grid indexes `lo..=hi`.
    pub lo: usize,
    pub hi: usize,
}

impl Section {
    /// The surface at `u` (NEG_INFINITY in air).
    pub fn at(&self, u: f64) -> f64 {
        let p = &self.points;
        let air = f64::NEG_INFINITY;
        if u < p[0][0] {
            return self.below_first.unwrap_or(air);
        }
        if u > p[p.len() - 1][0] {
            return self.beyond_last.unwrap_or(air);
        }
        let k = p.partition_point(|q| q[0] < u).clamp(1, p.len() - 1);
        let (a, b) = (p[k - 1], p[k]);
        if (b[0] - a[0]).abs() < 1e-12 {
            return a[1].max(b[1]);
        }
        a[1] + (b[1] - a[1]) * (u - a[0]) / (b[0] - a[0])
    }

    /// The section's lowest point.
    pub fn bottom(&self) -> f64 {
        self.points
            .iter()
            .map(|p| p[1])
            .fold(f64::INFINITY, f64::min)
    }

    /// The section sampled, offset by `allowance` (normal to the
    /// surface), and the drop cutter's lowest tip for `tool`; tool
    /// centres limited to `centres` (u range).
    pub fn grid(&self, tool: ToolShape, allowance: f64, centres: (f64, f64)) -> Grid {
        let r = tool.radius();
        let (first, last) = (self.points[0][0], self.points[self.points.len() - 1][0]);
        let u0 = first.min(centres.0) - r - allowance - 1.0;
        let u1 = last.max(centres.1) + r + allowance + 1.0;
        let n = ((u1 - u0) / DU).ceil() as usize + 1;
        let raw: Vec<f64> = (0..n).map(|i| self.at(u0 + i as f64 * DU)).collect();
        // Every point's own vertex too, so that a sharp point is not lost
        // between grid points.
        let mut s = raw.clone();
        for p in &self.points {
            let i = ((p[0] - u0) / DU).round() as usize;
            if i < n {
                s[i] = s[i].max(p[1]);
            }
        }
        if allowance > 0.0 {
            let k = (allowance / DU).ceil() as isize;
            let base = s.clone();
            for (i, v) in s.iter_mut().enumerate() {
                for d in -k..=k {
                    let j = i as isize + d;
                    if j < 0 || j >= n as isize {
                        continue;
                    }
                    let du = d as f64 * DU;
                    if du.abs() <= allowance {
                        let up = (allowance * allowance - du * du).sqrt();
                        *v = v.max(base[j as usize] + up);
                    }
                }
            }
        }
        let kr = (r / DU).ceil() as isize;
        let heights: Vec<Option<f64>> = (-kr..=kr)
            .map(|d| tool.height((d as f64 * DU).abs()))
            .collect();
        let tip = (0..n)
            .map(|i| {
                let mut z = f64::NEG_INFINITY;
                for (m, h) in heights.iter().enumerate() {
                    let j = i as isize + m as isize - kr;
                    if j < 0 || j >= n as isize {
                        continue;
                    }
                    if let Some(h) = h {
                        z = z.max(s[j as usize] - h);
                    }
                }
                z
            })
            .collect();
        let idx = |u: f64| (((u - u0) / DU).round().max(0.0) as usize).min(n - 1);
        Grid {
            u0,
            s,
            tip,
            tool,
            lo: idx(centres.0),
            hi: idx(centres.1),
        }
    }
}

/// One pass along the travel: across position and height.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pass {
    pub u: f64,
    pub z: f64,
    /// Index of the level, and of the reachable interval in it.
    pub level: usize,
    pub interval: usize,
}

impl Grid {
    pub fn u(&self, i: usize) -> f64 {
        self.u0 + i as f64 * DU
    }

    /// The lowest tip the tool reaches.
    pub fn lowest(&self) -> f64 {
        self.tip[self.lo..=self.hi]
            .iter()
            .copied()
            .fold(f64::INFINITY, f64::min)
    }

    /// Passes at the levels `levels` (top down), at most `stepover`
    /// apart across each reachable interval (only its two ends on the
    /// first level when `ends_first`).
    pub fn passes(&self, levels: &[f64], stepover: f64, ends_first: bool) -> Vec<Pass> {
        let mut out = Vec::new();
        for (li, &z) in levels.iter().enumerate() {
            let ends_only = ends_first && li == 0;
            // At the top itself only where the tool goes below it.
            let lim = if ends_only { z - 1e-6 } else { z + 1e-9 };
            let mut interval = 0;
            let mut i = self.lo;
            while i <= self.hi {
                if self.tip[i] > lim {
                    i += 1;
                    continue;
                }
                let a = i;
                while i < self.hi && self.tip[i + 1] <= lim {
                    i += 1;
                }
                let b = i;
                let (ua, ub) = (self.u(a), self.u(b));
                let n = if ends_only {
                    usize::from(ub - ua > 1e-9)
                } else {
                    (((ub - ua) / stepover) - 1e-9).ceil().max(0.0) as usize
                };
                for k in 0..=n {
                    let u = if n == 0 {
                        ua
                    } else {
                        ua + (ub - ua) * k as f64 / n as f64
                    };
                    out.push(Pass {
                        u,
                        z,
                        level: li,
                        interval,
                    });
                }
                interval += 1;
                i += 1;
            }
        }
        out
    }

    /// The material left at each grid point by `passes` (the top where
    /// no pass reaches; NEG_INFINITY where the surface is air).
    pub fn left(&self, passes: &[Pass], top: f64) -> Vec<f64> {
        let mut left = vec![top; self.s.len()];
        let r = self.tool.radius();
        let kr = (r / DU).ceil() as isize;
        for p in passes {
            let c = ((p.u - self.u0) / DU).round() as isize;
            for d in -kr..=kr {
                let j = c + d;
                if j < 0 || j >= left.len() as isize {
                    continue;
                }
                let rho = (self.u(j as usize) - p.u).abs();
                if let Some(h) = self.tool.height(rho) {
                    let v = &mut left[j as usize];
                    *v = v.min(p.z + h);
                }
            }
        }
        left
    }

    /// What dense passes (one at every grid point, at its lowest tip)
    /// leave: the form the tool can make at best.
    pub fn best(&self, top: f64) -> Vec<f64> {
        let all: Vec<Pass> = (self.lo..=self.hi)
            .filter(|&i| self.tip[i] < top)
            .map(|i| Pass {
                u: self.u(i),
                z: self.tip[i],
                level: 0,
                interval: 0,
            })
            .collect();
        self.left(&all, top)
    }
}

/// The largest of `a[i] - b[i]` where the surface is material below the
/// top, measured normal to the surface (the vertical difference times the
/// cosine of the surface's slope there), with where it is (u).
pub fn worst(g: &Grid, a: &[f64], b: &[f64], top: f64) -> (f64, f64) {
    let mut out = (0.0, g.u0);
    let n = g.s.len();
    for i in 0..n {
        if !(g.s[i].is_finite() && g.s[i] < top - 1e-9) {
            continue;
        }
        let (l, r) = (i.saturating_sub(1), (i + 1).min(n - 1));
        let slope = if g.s[l].is_finite() && g.s[r].is_finite() && r > l {
            (g.s[r] - g.s[l]) / ((r - l) as f64 * DU)
        } else {
            0.0
        };
        let e = (a[i] - b[i]) / (1.0 + slope * slope).sqrt();
        if e > out.0 {
            out = (e, g.u(i));
        }
    }
    out
}

/// Levels from `top` down to `bottom`, at most `step` apart.
pub fn levels(top: f64, bottom: f64, step: f64) -> Vec<f64> {
    super::levels(top, bottom, Some(step))
}

/// The passes of a cut and what they leave.
pub struct Planned {
    pub passes: Vec<Pass>,
    /// The level spacing used.
    pub step: f64,
    /// Most material left over the tool's best form (mm) and where.
    pub stepping: (f64, f64),
    /// Most material the tool cannot remove at all (mm) and where.
    pub form: (f64, f64),
}

/// Plans the passes: levels `first_step` apart (the axial depth of cut,
/// or the whole depth), halved while the stepping leaves more than `tol`
/// over the tool's best form (`tol` None: roughing, no halving).
pub fn plan(g: &Grid, top: f64, first_step: f64, stepover: f64, tol: Option<f64>) -> Planned {
    let bottom = g.lowest();
    let best = g.best(top);
    let surface: Vec<f64> = g.s.iter().map(|v| v.max(f64::MIN)).collect();
    let form = worst(g, &best, &surface, top);
    let mut step = first_step.max(1e-3);
    // A tool with a rounded or pointed end touches a wall's top edge only
    // from a level at the top: without it, the wall between that edge and
    // the first level's contact is left as half a scallop.
    let rounded = !matches!(g.tool, ToolShape::Flat { .. }) && tol.is_some();
    loop {
        let mut zs = levels(top, bottom, step);
        if rounded {
            zs.insert(0, top);
        }
        let passes = g.passes(&zs, stepover, rounded);
        let left = g.left(&passes, top);
        let stepping = worst(g, &left, &best, top);
        let done = match tol {
            None => true,
            Some(t) => stepping.0 <= t || step < 0.005,
        };
        if done {
            return Planned {
                passes,
                step,
                stepping,
                form,
            };
        }
        step /= 2.0;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 90° V, 10 deep, sharp point at u 0, top at z 0.
    fn vee() -> Section {
        Section {
            points: vec![[-10.0, 0.0], [0.0, -10.0], [10.0, 0.0]],
            below_first: Some(0.0),
            beyond_last: Some(0.0),
            top: 0.0,
        }
    }

    #[test]
    fn a_flat_tool_stops_where_its_edge_meets_the_walls() {
        let g = vee().grid(ToolShape::Flat { r: 3.0 }, 0.0, (-20.0, 20.0));
        // The centre can go down to z -7 (edges on the 45° walls).
        assert!((g.lowest() + 7.0).abs() < 0.02, "{}", g.lowest());
    }

    #[test]
    fn a_vee_tool_of_the_same_angle_reaches_the_point() {
        let tool = ToolShape::Vee {
            r: 5.0,
            half_angle: 45.0,
        };
        let g = vee().grid(tool, 0.0, (-20.0, 20.0));
        assert!((g.lowest() + 10.0).abs() < 0.02);
        let p = plan(&g, 0.0, 2.0, 1.0, Some(0.02));
        assert!(p.form.0 < 0.02, "{:?}", p.form);
        assert!(p.stepping.0 <= 0.02);
    }

    #[test]
    fn stepping_a_flat_tool_down_a_wall_meets_the_tolerance() {
        let g = vee().grid(ToolShape::Flat { r: 2.0 }, 0.0, (-20.0, 20.0));
        let p = plan(&g, 0.0, 2.0, 1.8, Some(0.05));
        assert!(p.stepping.0 <= 0.05, "{:?}", p.stepping);
        // The point the flat tool cannot reach: about its radius deep.
        assert!(p.form.0 > 1.5, "{:?}", p.form);
        // Never below the surface.
        let left = g.left(&p.passes, 0.0);
        for (i, v) in left.iter().enumerate() {
            assert!(*v >= g.s[i] - 1e-6, "gouge at {}", g.u(i));
        }
    }
}
