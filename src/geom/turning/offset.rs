//! The finishing allowance: a turning profile offset sideways by a
//! distance, as LinuxCNC 2.9 does it: in steps no larger than half the
//! shortest element, so that elements shrinking below 1e-3 drop out
//! before they turn over; gaps that open at convex corners are closed
//! with arcs round the old corner, and neighbours are trimmed to meet.

use super::segment::{join, Seg};
use super::{Profile, TurnError};

/// Most offset steps before the offset is taken as endless.
const MAX_STEPS: u32 = 100_000;

impl Profile {
    /// Offsets every element after the approach by `distance` (to the
    /// outside of the profile as it winds from its start), and moves the
    /// approach's end onto the new first element.
    pub fn offset(&mut self, distance: f64) -> Result<(), TurnError> {
        let (first, last) = match (self.segs.first(), self.segs.last()) {
            (Some(f), Some(l)) => (*f, *l),
            _ => return Err(TurnError::Geometry("empty profile")),
        };
        let turn = (first.end - first.start) / (last.start - first.start);
        let distance = if turn.im < 0.0 { -distance } else { distance };
        let mut approach = self.segs.remove(0);
        let segs = &mut self.segs;
        let mut done = 0.0;
        let mut steps = 0;
        while done != distance {
            steps += 1;
            if steps > MAX_STEPS {
                return Err(TurnError::Endless);
            }
            let mut step = segs.iter().map(|s| s.size() / 2.0).fold(1e9, f64::min);
            step = step.min((distance - done).abs());
            if distance < 0.0 {
                step = -step;
            }
            for s in segs.iter_mut() {
                s.offset(step);
            }
            segs.retain(|s| s.size() >= 1e-3);
            close_gaps(segs, step, distance > 0.0);
            trim(segs)?;
            done += step;
        }
        for i in 1..segs.len() {
            let mid = (segs[i - 1].end + segs[i].start) / 2.0;
            segs[i - 1].end = mid;
            segs[i].start = mid;
        }
        let Some(head) = segs.first() else {
            return Err(TurnError::Geometry("empty profile"));
        };
        approach.end = head.start;
        segs.insert(0, approach);
        Ok(())
    }
}

/// Where two neighbours moved apart (a convex corner), an arc round the
/// corner they had before the step.
fn close_gaps(segs: &mut Vec<Seg>, step: f64, ccw: bool) {
    let mut i = 0;
    while i + 1 < segs.len() {
        if (segs[i].end - segs[i + 1].start).re > 1e-2 {
            let (mut s, mut e) = (segs[i], segs[i + 1]);
            s.offset(-step);
            e.offset(-step);
            let center = (s.end + e.start) / 2.0;
            let arc = Seg::arc(ccw, segs[i].end, center, segs[i + 1].start);
            segs.insert(i + 1, arc);
            i += 1;
        }
        i += 1;
    }
}

/// Drops elements that turned over or vanished, trims the rest to meet.
fn trim(segs: &mut Vec<Seg>) -> Result<(), TurnError> {
    let mut i = 0;
    while i + 1 < segs.len() {
        if !segs[i].monotonic() {
            let drop = if i == 0 || segs[i].size() < segs[i - 1].size() {
                i
            } else {
                i - 1
            };
            segs.remove(drop);
            i = 0;
            if segs.len() < 2 {
                break;
            }
        }
        if segs[i].size() < 1e-3 {
            segs.remove(i);
            i = 0;
        } else {
            let (a, b) = segs.split_at_mut(i + 1);
            join(&mut a[i], &mut b[0])?;
        }
        i += 1;
    }
    Ok(())
}
