//! One element of a turning profile: a line or an arc in the lathe's
//! Z/X half-plane, held as complex numbers (`re` = Z, `im` = X), with the
//! operations the roughing and finishing cycles need: where a level line
//! X = x crosses it, offsetting, trimming two neighbours to meet, and the
//! moves that follow it down (a dive) or up (a climb). Tolerances are
//! LinuxCNC 2.9's (1e-6 for "on", 1e-3 for "long enough").

use super::{Motion, Pt, TurnError, TOL};

/// Line or arc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    Line,
    Arc { center: Pt, ccw: bool },
}

/// A corner the program asked to round (`A`) or break (`C`) between its
/// two neighbours; it gets its geometry in [`super::Profile::finish_corners`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Corner {
    Plain,
    Fillet,
    Chamfer,
}

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    pub start: Pt,
    pub end: Pt,
    pub shape: Shape,
    /// The corner size still to be made (fillet radius, chamfer length).
    pub finish: f64,
    pub corner: Corner,
}

/// Crossings of a level line, in the order LinuxCNC lists them.
pub type Hits = Vec<f64>;

impl Seg {
    pub fn line(start: Pt, end: Pt) -> Self {
        Seg {
            start,
            end,
            shape: Shape::Line,
            finish: 0.0,
            corner: Corner::Plain,
        }
    }

    pub fn arc(ccw: bool, start: Pt, center: Pt, end: Pt) -> Self {
        Seg {
            start,
            end,
            shape: Shape::Arc { center, ccw },
            finish: 0.0,
            corner: Corner::Plain,
        }
    }

    /// A corner of size `size` at `at`, to be shaped between its neighbours.
    pub fn corner(kind: Corner, size: f64, at: Pt) -> Self {
        let shape = match kind {
            Corner::Fillet => Shape::Arc {
                center: at,
                ccw: false,
            },
            _ => Shape::Line,
        };
        Seg {
            start: at,
            end: at,
            shape,
            finish: size,
            corner: kind,
        }
    }

    /// The length of a line; the smaller of chord and radius of an arc.
    pub fn size(&self) -> f64 {
        match self.shape {
            Shape::Line => (self.start - self.end).norm(),
            Shape::Arc { center, .. } => (self.start - self.end)
                .norm()
                .min((self.start - center).norm()),
        }
    }

    /// Moves only towards -Z (and an arc stays on one side of its centre).
    pub fn monotonic(&self) -> bool {
        match self.shape {
            Shape::Line => (self.end - self.start).re <= 1e-3,
            Shape::Arc { center, ccw } => {
                if self.finish != 0.0 {
                    return true;
                }
                let entry = (self.start - center).im;
                let exit = (self.end - center).im;
                let dz = (self.end - self.start).re;
                if ccw {
                    entry >= -1e-3 && exit >= -1e-3 && dz <= -1e-3
                } else {
                    entry <= 1e-3 && exit <= 1e-3 && dz <= -1e-3
                }
            }
        }
    }

    /// Applies a point map to every point; `mirror` reverses arcs.
    pub fn map(&mut self, f: impl Fn(Pt) -> Pt, mirror: bool) {
        self.start = f(self.start);
        self.end = f(self.end);
        if let Shape::Arc { center, ccw } = self.shape {
            self.shape = Shape::Arc {
                center: f(center),
                ccw: ccw ^ mirror,
            };
        }
    }

    /// Shifts the element sideways by `d` (to the right of its direction
    /// for a line, so up in X for one running to -Z; away from the centre
    /// of a counter-clockwise arc).
    pub fn offset(&mut self, d: f64) {
        match self.shape {
            Shape::Line => {
                let dir = self.start - self.end;
                let shift = Pt::i() * d * dir / dir.norm();
                self.start += shift;
                self.end += shift;
            }
            Shape::Arc { center, ccw } => {
                let r = (self.start - center).norm();
                let factor = (r + if ccw { d } else { -d }) / r;
                self.start = (self.start - center) * factor + center;
                self.end = (self.end - center) * factor + center;
            }
        }
    }

    fn on_arc(&self, center: Pt, ccw: bool, p: Pt) -> bool {
        let a = ((self.start - center).conj() * (p - center)).im;
        let b = ((self.end - center).conj() * (p - center)).im;
        if ccw {
            a >= -TOL && b <= TOL
        } else {
            a <= TOL && b >= -TOL
        }
    }

    /// Where the level line X = `x` meets the element (Z values).
    pub fn crossings(&self, x: f64) -> Hits {
        let (s, e) = (self.start, self.end);
        match self.shape {
            Shape::Line => {
                if s.im.min(e.im) > x + TOL || s.im.max(e.im) < x - TOL {
                    return vec![];
                }
                if (s - e).im.abs() < TOL {
                    vec![s.re, e.re]
                } else {
                    vec![(x - s.im) / (e.im - s.im) * (e.re - s.re) + s.re]
                }
            }
            Shape::Arc { center, ccw } => {
                let r = (s - center).norm();
                let mut q = -(x - r - center.im) * (x + r - center.im);
                if q < -TOL {
                    return vec![];
                }
                if q < 0.0 {
                    q = 0.0;
                }
                let q = q.sqrt();
                let mut hits = Vec::new();
                for z in [center.re + q, center.re - q] {
                    if self.on_arc(center, ccw, Pt::new(z, x)) {
                        hits.push(z);
                    }
                }
                hits
            }
        }
    }

    /// The element's own move, from its start.
    pub fn draw(&self, out: &mut dyn Motion) -> Result<(), TurnError> {
        match self.shape {
            Shape::Line => out.feed(self.end),
            Shape::Arc { center, ccw } => out.arc(ccw, center, self.end),
        }
    }

    /// Follows the element down to level `x` (or its end). `Ok(true)`:
    /// the element does not go down from here.
    pub fn dive(
        &self,
        at: &mut Pt,
        x: f64,
        out: &mut dyn Motion,
        fast: bool,
    ) -> Result<bool, TurnError> {
        let (s, e) = (self.start, self.end);
        match self.shape {
            Shape::Line => {
                if s.im <= e.im + TOL {
                    return Ok(true);
                }
                let to = if x < e.im {
                    e
                } else {
                    let hits = self.crossings(x);
                    let Some(&z) = hits.first() else {
                        return Err(TurnError::Geometry("x too large in straight dive"));
                    };
                    Pt::new(z, x)
                };
                if fast {
                    out.rapid(to)?;
                } else {
                    out.feed(to)?;
                }
                *at = to;
                Ok(false)
            }
            Shape::Arc { center, ccw } => {
                if (*at - e).norm() < TOL || (*at - e).re <= TOL {
                    *at = e;
                    return Ok(false);
                }
                let mut hits = self.crossings(x);
                if hits.is_empty() {
                    hits = self.crossings(x - TOL);
                }
                if ccw {
                    if at.re - TOL > center.re {
                        return Ok(true);
                    }
                    let to = match hits.last() {
                        Some(&z) if z <= center.re => Pt::new(z, x),
                        _ => e,
                    };
                    out.arc(true, center, to)?;
                    *at = to;
                    return Ok(false);
                }
                if at.re <= center.re {
                    return Ok(true);
                }
                let to = match hits.first() {
                    None => e,
                    // hit on the far side only: the pocket steps down
                    Some(&z) if z < center.re => return Ok(false),
                    Some(&z) => Pt::new(z, x),
                };
                out.arc(false, center, to)?;
                *at = to;
                Ok(false)
            }
        }
    }

    /// Follows the element up from `at`. `Ok(true)`: it goes down again
    /// (a pocket starts here); an arc stops at its top.
    pub fn climb(&self, at: &mut Pt, out: &mut dyn Motion) -> Result<bool, TurnError> {
        match self.shape {
            Shape::Line => {
                if self.end.im + TOL < self.start.im {
                    return Ok(true);
                }
                if (*at - self.start).norm() > TOL {
                    return Err(TurnError::Geometry("How did we get here?"));
                }
                out.feed(self.end)?;
                *at = self.end;
                Ok(false)
            }
            Shape::Arc { center, ccw: false } => {
                if at.re > center.re {
                    return Ok(true);
                }
                if (*at - self.end).norm() > 1e-3 {
                    out.arc(false, center, self.end)?;
                }
                *at = self.end;
                Ok(false)
            }
            Shape::Arc { center, ccw: true } => {
                if at.re < center.re {
                    return Ok(true);
                }
                let top = self.arc_top(center);
                if (*at - top).norm() > 1e-3 {
                    out.arc(true, center, top)?;
                }
                *at = top;
                Ok(true)
            }
        }
    }

    /// The end of a counter-clockwise arc, or its highest point when the
    /// end lies past the top.
    fn arc_top(&self, center: Pt) -> Pt {
        if self.end.re < center.re {
            Pt::new(center.re, center.im + (self.start - center).norm())
        } else {
            self.end
        }
    }

    /// Climbs along the element from the level of `at`, if it rises there
    /// (G7x.1: the final pass along the profile).
    pub fn climb_only(&self, at: &mut Pt, out: &mut dyn Motion) -> Result<(), TurnError> {
        if self.shape == Shape::Line && self.end.im < self.start.im {
            return Ok(());
        }
        let hits = self.crossings(at.im);
        let (Some(&first), Some(&last)) = (hits.first(), hits.last()) else {
            return Ok(());
        };
        match self.shape {
            Shape::Line => {
                at.re = first;
                out.feed(*at)?;
                out.feed(self.end)?;
                *at = self.end;
            }
            Shape::Arc { center, ccw: false } => {
                if last > center.re {
                    return Ok(());
                }
                at.re = last;
                out.feed(*at)?;
                if (*at - self.end).norm() > 1e-3 {
                    out.arc(false, center, self.end)?;
                }
                *at = self.end;
            }
            Shape::Arc { center, ccw: true } => {
                if first < center.re {
                    return Ok(());
                }
                at.re = first;
                out.feed(*at)?;
                let top = self.arc_top(center);
                if (*at - top).norm() > 1e-3 {
                    out.arc(true, center, top)?;
                }
                *at = top;
            }
        }
        Ok(())
    }
}

/// Trims `prev`'s end and `next`'s start to where the two meet.
pub fn join(prev: &mut Seg, next: &mut Seg) -> Result<(), TurnError> {
    let meet = match (prev.shape, next.shape) {
        (Shape::Line, Shape::Line) => {
            let rot = (next.start - next.end).conj() / (next.start - next.end).norm();
            let ps = (prev.start - next.end) * rot;
            let pe = (prev.end - next.end) * rot;
            if (ps - pe).im == 0.0 {
                return Err(TurnError::Geometry("Cannot intersect parallel lines"));
            }
            let f = ps.im / (ps - pe).im;
            (ps + (pe - ps) * f) / rot + next.end
        }
        (Shape::Arc { center, .. }, Shape::Line) => {
            if (next.start - prev.end).norm() < TOL {
                return Ok(());
            }
            line_meets_circle(next.start, next.end, center, prev.end, next.start)
        }
        (Shape::Line, Shape::Arc { center, .. }) => {
            if (next.start - prev.end).norm() < TOL {
                return Ok(());
            }
            line_meets_circle(prev.start, prev.end, center, next.end, next.start)
        }
        (Shape::Arc { center: pc, .. }, Shape::Arc { center: nc, .. }) => {
            let a = (next.start - nc).norm();
            let b = (prev.start - pc).norm();
            let c = (nc - pc).norm();
            let cos = (c * c + a * a - b * b) / 2.0 / a / c;
            let sin = (1.0 - (cos * cos).min(1.0)).sqrt();
            Pt::new(cos, sin) * (pc - nc) / c * a + nc
        }
    };
    prev.end = meet;
    next.start = meet;
    Ok(())
}

/// The point where the line through `a`→`b` meets the circle round
/// `center` through `on`, the one of the two nearer `near`.
fn line_meets_circle(a: Pt, b: Pt, center: Pt, on: Pt, near: Pt) -> Pt {
    let rot = (a - b).conj() / (a - b).norm();
    let pe = (on - b) * rot;
    let pc = (center - b) * rot;
    let q = (pc - pe).norm_sqr() - pc.im * pc.im;
    let q = if q < 0.0 { 0.0 } else { q.sqrt() };
    let s1 = Pt::new(pc.re + q, 0.0) / rot + b;
    let s2 = Pt::new(pc.re - q, 0.0) / rot + b;
    if (near - s1).norm() < (near - s2).norm() {
        s1
    } else {
        s2
    }
}
