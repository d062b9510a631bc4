//! The roughing passes of G71/G72 in normal position (the profile runs
//! towards -Z with X falling): level cuts every `delta` below the start,
//! each fed in -Z until it meets the profile, then a 45° retract by
//! `escape` and a rapid back; when a level no longer meets the profile
//! the tool follows the profile up until it dips again, and the pocket
//! found there is roughed the same way.

use super::segment::Seg;
use super::{Motion, Pockets, Pt, TurnError, TOL};

/// Most passes before the roughing is taken as endless (rs274 loops).
const MAX_STEPS: u64 = 2_000_000;

pub struct Roughing<'a> {
    pub segs: &'a [Seg],
    pub delta: f64,
    pub escape: Pt,
    /// Where the pockets started (the level their passes count from).
    pub starts: Vec<Pt>,
    pub steps: u64,
}

/// What is left to cut.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    All,
    NoPockets,
    /// G7x.2, after its silent first pass.
    Resumed,
}

impl Roughing<'_> {
    fn tick(&mut self) -> Result<(), TurnError> {
        self.steps += 1;
        if self.steps > MAX_STEPS {
            return Err(TurnError::Endless);
        }
        Ok(())
    }

    /// Roughs from `at` on element `p` to the end of the profile.
    pub fn pocket(
        &mut self,
        pockets: Pockets,
        mut at: Pt,
        mut p: usize,
        out: &mut dyn Motion,
    ) -> Result<(), TurnError> {
        let n = self.segs.len();
        let mode = match pockets {
            Pockets::All => Mode::All,
            Pockets::None => Mode::NoPockets,
            Pockets::Only => {
                while p < n && !self.segs[p].dive(&mut at, -1e9, out, p == 0)? {
                    p += 1;
                }
                Mode::Resumed
            }
        };
        'pocket: loop {
            let mut x = self.starts.last().map_or(at.im, |s| s.im);
            while p < n {
                self.tick()?;
                while x - TOL > at.im {
                    self.tick()?;
                    x -= self.delta;
                }
                if self.segs[p].dive(&mut at, x, out, p == 0)? {
                    if mode == Mode::NoPockets {
                        for s in &self.segs[p..] {
                            s.climb_only(&mut at, out)?;
                        }
                        return Ok(());
                    }
                    for q in p..n {
                        if self.segs[q].climb(&mut at, out)? {
                            if mode == Mode::Resumed {
                                self.note_pocket(at);
                            }
                            p = q;
                            continue 'pocket;
                        }
                    }
                    return Ok(());
                }
                if (at.im - x).abs() > TOL {
                    p += 1;
                    continue;
                }
                self.level(&mut p, &mut x, at, out)?;
            }
            return Ok(());
        }
    }

    /// G7x.2: which pocket's start the levels count from.
    fn note_pocket(&mut self, at: Pt) {
        let top = self.starts.last().map_or(f64::MIN, |s| s.im);
        if at.im > top && self.starts.len() > 1 {
            self.starts.pop();
        }
        if self.starts.len() == 1 {
            self.starts.push(at);
        }
    }

    /// One level cut from `at` (on element `p`) to the profile ahead.
    fn level(
        &mut self,
        p: &mut usize,
        x: &mut f64,
        at: Pt,
        out: &mut dyn Motion,
    ) -> Result<(), TurnError> {
        for ip in *p..self.segs.len() {
            let hits = self.segs[ip].crossings(at.im);
            let (Some(&first), Some(&last)) = (hits.first(), hits.last()) else {
                continue;
            };
            let dz = if ip != *p { first } else { last };
            let distance = (dz - at.re).abs();
            if dz - TOL > at.re {
                continue;
            }
            if distance < TOL {
                if *p == ip {
                    continue;
                }
                if (at - self.segs[ip].start).norm() < TOL {
                    *p = ip;
                } else {
                    *x -= self.delta;
                }
                return Ok(());
            }
            let mut dest = Pt::new(dz, at.im);
            out.feed(dest)?;
            let scale = (distance / 2.0 / self.escape.re).min(1.0);
            dest += self.escape * scale;
            out.rapid(dest)?;
            out.rapid(at - (self.escape * scale).conj())?;
            if *p == 0 {
                out.rapid(at)?;
            } else {
                out.feed(at)?;
            }
            *x -= self.delta;
            return Ok(());
        }
        Ok(())
    }
}
