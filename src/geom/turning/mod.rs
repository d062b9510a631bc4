//! Turning profiles and LinuxCNC 2.9's lathe cycles on them: G70
//! finishing, G71 roughing along Z and G72 facing (with .1: no pockets,
//! .2: pockets only). A profile is a chain of lines and arcs in the Z/X
//! half-plane (complex numbers on nalgebra, `re` = Z, `im` = X).
//!
//! The cycles bring the profile into one normal position first, where it
//! runs towards -Z and its X falls: G72 turns it a quarter (X and Z swap
//! roles), then it is mirrored in X and/or Z as needed. The moves made
//! there are mapped back ([`Placement`]). The roughing steps down by the
//! depth of cut I from the start X, cuts towards the profile, retracts by
//! R at 45 degrees, and goes down into pockets as it meets them
//! ([`pocket`]). D is the finishing allowance, applied as an offset of
//! the profile in small steps so that short elements vanish cleanly
//! ([`Profile::offset`]); U and W shift the profile.
//!
//! The moves come out through [`Motion`]; the interpreter turns them into
//! canonical calls ([`crate::interp::lathe_cycles`]).

mod offset;
mod pocket;
pub mod segment;
#[cfg(test)]
mod tests;

pub use segment::{Corner, Seg, Shape};

use nalgebra::Complex;

/// A point: `re` = Z, `im` = X.
pub type Pt = Complex<f64>;

/// LinuxCNC's "on the line" tolerance for these cycles.
pub const TOL: f64 = 1e-6;

/// Why a cycle could not be made.
#[derive(Clone, Debug, PartialEq)]
pub enum TurnError {
    /// The profile's geometry (LinuxCNC's `G7X error: ...` text).
    Geometry(&'static str),
    /// A corner that could not be rounded, at the given point.
    Corner(Pt),
    /// The roughing does not come to an end (LinuxCNC loops for ever).
    Endless,
    /// The move sink refused a move (its own error, already made).
    Sink,
}

/// Where the moves go (in the program's own Z/X).
pub trait Motion {
    fn rapid(&mut self, to: Pt) -> Result<(), TurnError>;
    fn feed(&mut self, to: Pt) -> Result<(), TurnError>;
    fn arc(&mut self, ccw: bool, center: Pt, to: Pt) -> Result<(), TurnError>;
}

/// How the profile was placed into normal position: a quarter turn, then
/// mirrors in X (`im`) and Z (`re`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Placement {
    pub turned: bool,
    pub mirror_x: bool,
    pub mirror_z: bool,
}

impl Placement {
    /// A point of the normal position back in program Z/X.
    pub fn back(&self, p: Pt) -> Pt {
        let mut q = p;
        if self.mirror_x {
            q = q.conj();
        }
        if self.mirror_z {
            q = -q.conj();
        }
        if self.turned {
            q *= Pt::i();
        }
        q
    }

    /// Whether arcs change direction on the way back.
    pub fn reverses(&self) -> bool {
        self.mirror_x ^ self.mirror_z
    }
}

/// Maps moves made in normal position back to the program's.
struct Placed<'a> {
    place: Placement,
    out: &'a mut dyn Motion,
}

impl Motion for Placed<'_> {
    fn rapid(&mut self, to: Pt) -> Result<(), TurnError> {
        self.out.rapid(self.place.back(to))
    }
    fn feed(&mut self, to: Pt) -> Result<(), TurnError> {
        self.out.feed(self.place.back(to))
    }
    fn arc(&mut self, ccw: bool, center: Pt, to: Pt) -> Result<(), TurnError> {
        let ccw = ccw ^ self.place.reverses();
        self.out
            .arc(ccw, self.place.back(center), self.place.back(to))
    }
}

/// A profile: the first element is the approach from the cycle's start.
#[derive(Clone, Debug, Default)]
pub struct Profile {
    pub segs: Vec<Seg>,
    pub place: Placement,
}

/// Which part of the roughing G71/G72 makes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Pockets {
    /// Everything (G71, G72).
    All,
    /// The first pass and the profile, no pockets (G71.1, G72.1).
    None,
    /// Only the pockets (G71.2, G72.2).
    Only,
}

/// The roughing cycle's numbers.
#[derive(Clone, Copy, Debug)]
pub struct Rough {
    pub start: Pt,
    /// Shift of the profile (U on X, W on Z).
    pub shift: Pt,
    /// Finishing allowance.
    pub allowance: f64,
    /// Depth of cut.
    pub depth: f64,
    /// Retract.
    pub retract: f64,
    pub pockets: Pockets,
    /// G72: facing (the profile is turned a quarter first).
    pub facing: bool,
}

/// The finishing cycle's numbers.
#[derive(Clone, Copy, Debug)]
pub struct Finish {
    pub start: Pt,
    /// Allowance of the first pass, of the last one, number of passes.
    pub first: f64,
    pub last: f64,
    pub passes: f64,
}

impl Profile {
    fn map(&mut self, f: impl Fn(Pt) -> Pt + Copy, mirror: bool) {
        for s in &mut self.segs {
            s.map(f, mirror);
        }
    }

    /// A quarter turn (G72: facing becomes turning).
    fn turn(&mut self) {
        self.map(|p| -p * Pt::i(), false);
        self.place.turned = !self.place.turned;
    }

    /// Mirrors so that, first end to last end, X and Z both fall.
    fn normalise(&mut self) {
        let (Some(f), Some(l)) = (self.segs.first(), self.segs.last()) else {
            return;
        };
        let d = f.end - l.end;
        if d.im > 0.0 {
            self.map(|p| p.conj(), true);
            self.place.mirror_x = !self.place.mirror_x;
        }
        if d.re < 0.0 {
            self.map(|p| -p.conj(), true);
            self.place.mirror_z = !self.place.mirror_z;
        }
    }

    /// Shapes the requested corners between their neighbours and drops
    /// what became too short.
    fn finish_corners(&mut self) -> Result<(), TurnError> {
        let n = self.segs.len();
        for h in 1..n.saturating_sub(1) {
            if self.segs[h].corner == Corner::Plain {
                continue;
            }
            let (a, rest) = self.segs.split_at_mut(h);
            let (mid, b) = rest.split_at_mut(1);
            corner(&mut a[h - 1], &mut mid[0], &mut b[0])?;
        }
        self.segs.retain(|s| s.size() >= 1e-3);
        Ok(())
    }

    /// Every element must run towards -Z; a first element going the
    /// wrong way is made vertical.
    fn check_monotonic(&mut self) -> Result<(), TurnError> {
        if let Some(f) = self.segs.first_mut() {
            if (f.end - f.start).re > 0.0 {
                f.start.re = f.end.re;
            }
        }
        if self.segs.iter().all(Seg::monotonic) {
            Ok(())
        } else {
            Err(TurnError::Geometry("Not monotonic"))
        }
    }

    fn front(&self) -> Result<&Seg, TurnError> {
        self.segs
            .first()
            .ok_or(TurnError::Geometry("empty profile"))
    }

    /// G71/G72.
    pub fn rough(mut self, c: &Rough, out: &mut dyn Motion) -> Result<(), TurnError> {
        if self.segs.is_empty() {
            return Ok(());
        }
        self.segs[0].start = c.start;
        if c.facing {
            self.turn();
        }
        self.normalise();
        self.finish_corners()?;
        self.check_monotonic()?;
        self.offset(c.allowance)?;
        for s in &mut self.segs {
            s.map(|p| p + c.shift, false);
        }
        let mut out = Placed {
            place: self.place,
            out,
        };
        let from = self.front()?.start;
        out.rapid(from)?;
        let last = self.segs.last().map(|s| s.end).unwrap_or(from);
        if last.im < from.im {
            self.segs.push(Seg::line(last, Pt::new(last.re, from.im)));
        }
        let mut r = pocket::Roughing {
            segs: &self.segs,
            delta: c.depth.max(2.0 * TOL),
            escape: Pt::new(1.0, 1.0) * c.retract,
            starts: vec![from],
            steps: 0,
        };
        r.pocket(c.pockets, from, 0, &mut out)
    }

    /// G70: passes along the profile, from allowance `first` to `last`.
    pub fn finish(mut self, c: &Finish, out: &mut dyn Motion) -> Result<(), TurnError> {
        if self.segs.is_empty() {
            return Ok(());
        }
        self.segs[0].start = c.start;
        let mut probe = self.clone();
        probe.segs.remove(0);
        probe.normalise();
        if !probe.segs.iter().all(Seg::monotonic) {
            probe.turn();
            probe.normalise();
        }
        probe.check_monotonic()?;
        if probe.place.turned {
            self.turn();
        }
        self.normalise();
        self.finish_corners()?;
        self.check_monotonic()?;
        let place = self.place;
        let mut out = Placed { place, out };
        let passes = c.passes as i64;
        for pass in (1..=passes).rev() {
            let allowance = (pass - 1) as f64 * (c.first - c.last) / c.passes + c.last;
            let mut path = self.clone();
            path.offset(allowance)?;
            let first = *path.front()?;
            out.rapid(first.start)?;
            out.rapid(first.end)?;
            for s in &path.segs[1..] {
                s.draw(&mut out)?;
            }
        }
        Ok(())
    }
}

/// Gives a fillet or chamfer (`mid`) its geometry between `prev` and
/// `next`, trimming them.
fn corner(prev: &mut Seg, mid: &mut Seg, next: &mut Seg) -> Result<(), TurnError> {
    let mut f = mid.finish;
    let shifted = |f: f64| {
        let (mut p, mut n) = (*prev, *next);
        p.offset(f);
        n.offset(f);
        (p, n)
    };
    let (mut p, mut n) = shifted(f);
    if (p.end - n.start).re > 1e-2 {
        f = -f;
        (p, n) = shifted(f);
    }
    if (p.end - n.start).re > 1e-2 {
        return Err(TurnError::Corner(prev.end));
    }
    segment::join(&mut p, &mut n)?;
    let center = (p.end + n.start) / 2.0;
    p.offset(-f);
    n.offset(-f);
    mid.start = p.end;
    prev.end = p.end;
    mid.end = n.start;
    next.start = n.start;
    match mid.corner {
        Corner::Fillet => {
            let ccw = (mid.start - center).im > 0.0 || (mid.end - center).im > 0.0;
            mid.shape = Shape::Arc { center, ccw };
            mid.finish = 0.0;
        }
        _ => mid.finish = f,
    }
    Ok(())
}
