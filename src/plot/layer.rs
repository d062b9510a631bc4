//! One layer of a plot's paths and the simplifier that builds it:
//! points closer than half a pixel to the last one kept are merged, and a
//! point is left out when the straight line past it stays within a
//! quarter pixel of every point left out since the last one kept (a
//! sleeve of directions, in constant time per point). Tolerances are
//! given in millimetres by the [`super::scene::Scene`].

/// A view-plane point, mm.
pub type Pt = (f64, f64);

/// One piece of a path, view-plane millimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Seg {
    /// Start a new subpath here.
    Move(Pt),
    Line(Pt),
    /// A circular arc to `to` around `centre`, from angle `start` through
    /// the signed `sweep` (radians, counter-clockwise positive, v up).
    Arc {
        to: Pt,
        centre: Pt,
        r: f64,
        start: f64,
        sweep: f64,
    },
    /// A drilled hole seen from above: a circle of the tool's radius
    /// (drawn at least a few pixels wide).
    Hole {
        centre: Pt,
        r: f64,
    },
}

/// The straight run being extended: its start, first direction, and the
/// cone of directions (relative to the first) that keep every point left
/// out within tolerance.
#[derive(Clone, Copy, Debug)]
struct Sleeve {
    anchor: Pt,
    dir: f64,
    lo: f64,
    hi: f64,
    reach: f64,
}

/// One layer's paths, with the state of the simplifier.
#[derive(Clone, Debug, Default)]
pub struct Layer {
    pub segs: Vec<Seg>,
    last: Option<Pt>,
    sleeve: Option<Sleeve>,
    pending: Option<Pt>,
    /// Where the last hole was drawn (pecks draw it once).
    last_hole: Option<Pt>,
}

pub(super) fn dist(a: Pt, b: Pt) -> f64 {
    (a.0 - b.0).hypot(a.1 - b.1)
}

/// An angle difference in (-pi, pi].
fn wrap(a: f64) -> f64 {
    use std::f64::consts::{PI, TAU};
    let a = a.rem_euclid(TAU);
    if a > PI {
        a - TAU
    } else {
        a
    }
}

impl Layer {
    fn pen(&self) -> Option<Pt> {
        self.pending.or(self.last)
    }

    pub(super) fn begin(&mut self, p: Pt, merge: f64) {
        if self.pen().is_some_and(|q| dist(p, q) < merge) {
            return;
        }
        self.flush();
        self.segs.push(Seg::Move(p));
        self.last = Some(p);
        self.sleeve = None;
    }

    /// `merge` and `chord` are the tolerances in mm.
    pub(super) fn line_to(&mut self, p: Pt, merge: f64, chord: f64) {
        let Some(last) = self.last else {
            self.begin(p, merge);
            return;
        };
        if dist(p, last) < merge {
            self.pending = Some(p);
            return;
        }
        self.pending = None;
        if let (Some(s), Some(Seg::Line(end))) = (self.sleeve.as_mut(), self.segs.last_mut()) {
            let d = dist(p, s.anchor);
            let rel = wrap((p.1 - s.anchor.1).atan2(p.0 - s.anchor.0) - s.dir);
            if d >= s.reach && rel >= s.lo && rel <= s.hi {
                // `last` is left out: the line now ends at `p`.
                let half = (chord / d).min(1.0).asin();
                s.lo = s.lo.max(rel - half);
                s.hi = s.hi.min(rel + half);
                s.reach = d;
                *end = p;
                self.last = Some(p);
                return;
            }
        }
        self.segs.push(Seg::Line(p));
        let d = dist(p, last);
        let half = (chord / d).min(1.0).asin();
        self.sleeve = Some(Sleeve {
            anchor: last,
            dir: (p.1 - last.1).atan2(p.0 - last.0),
            lo: -half,
            hi: half,
            reach: d,
        });
        self.last = Some(p);
    }

    pub(super) fn arc_to(&mut self, seg: Seg, to: Pt) {
        self.flush();
        self.segs.push(seg);
        self.last = Some(to);
        self.sleeve = None;
    }

    pub(super) fn hole(&mut self, centre: Pt, r: f64, merge: f64) {
        if self.last_hole.is_some_and(|h| dist(h, centre) < merge) {
            return;
        }
        self.last_hole = Some(centre);
        self.flush();
        self.segs.push(Seg::Hole { centre, r });
        self.last = None;
        self.sleeve = None;
    }

    /// Draws a merged last point, if any.
    pub(super) fn flush(&mut self) {
        if let Some(p) = self.pending.take() {
            self.segs.push(Seg::Line(p));
            self.sleeve = None;
            self.last = Some(p);
        }
    }
}
