//! Look-ahead across moves, as a controller's trajectory planner does:
//! each corner between consecutive moves gets a **junction speed** from
//! the angle between the tangents, and a window of the next moves is
//! planned backwards (each move's entry is the most from which the moves
//! after it in the window can still stop by the window's end) so that the
//! move run now ends at a speed the following moves can take.
//!
//! - **Junction deviation model** (as Grbl's planner): the tool passes a
//!   corner at `v_j = √(a·δ·sin(θ/2) / (1 − sin(θ/2)))`, `a` the path
//!   acceleration, `δ` the corner tolerance (`--corner-tolerance`, mm)
//!   and `θ` the angle between the reversed incoming tangent and the
//!   outgoing one (the corner's opening: 180° on a straight continuation,
//!   90° at a square corner, 0° on a reversal). It is the speed at which
//!   a circle of deviation δ from the corner, tangent to both moves, would
//!   be taken at centripetal acceleration `a`. **The path is not
//!   rounded**: the tool goes through the corner point itself (every
//!   set-point stays on the programmed path); δ only sets the speed, and
//!   the axes see a velocity step of `2·v_j·cos(θ/2)` at the corner.
//!   A straight continuation (a direction change below about 1.4 µrad,
//!   `1 − cos < 1e-12`) has no limit but the feeds; a reversal stops; δ = 0
//!   stops at every other corner. Arcs join by their end tangents. The
//!   junction speed is also at most the feed of each of the two moves.
//! - **Window**: at most `ahead` moves after the one run are held (the
//!   memory is bounded by the window, not the program); the plan assumes
//!   the machine stops at the end of the last one held, so a short window
//!   of short moves caps the speed (about `√(2·a·ahead·L)` for moves of
//!   length L). A dwell, a tool change, a program stop and the end of the
//!   run empty the window and stop.
//! - The backward pass stops early where an entry speed comes out as it
//!   was (the moves before it are then unchanged), so the cost per move
//!   is small on average; the move run takes its entry from the last
//!   one's exit and exits at the lesser of the next move's planned entry
//!   and what it can reach over its length (the forward pass).
//!
//! Works with both profiles ([`super::profile::Limits::reach`] gives the
//! speed reachable over a length under each): the jerk-limited moves start
//! and end with zero acceleration, so the acceleration never steps.

use super::path::Path;
use super::profile::Limits;
use nalgebra::Vector3;
use std::collections::VecDeque;

/// `1 − cos` of a direction change below which two moves run as one.
const STRAIGHT: f64 = 1e-12;

/// The junction speed (mm/s) between a move leaving along `t_in` and the
/// next entering along `t_out` (unit tangents), by the junction deviation
/// model; infinite with no acceleration limit or on a straight
/// continuation.
pub fn junction_speed(
    t_in: &Vector3<f64>,
    t_out: &Vector3<f64>,
    accel: f64,
    tolerance: f64,
) -> f64 {
    if !(accel > 0.0 && accel.is_finite()) {
        return f64::INFINITY;
    }
    let cos_turn = t_in.dot(t_out).clamp(-1.0, 1.0);
    if cos_turn >= 1.0 - STRAIGHT {
        return f64::INFINITY;
    }
    if tolerance <= 0.0 {
        return 0.0;
    }
    // θ = π − turn: sin(θ/2) = cos(turn/2) = √((1 + cos turn)/2).
    let s = ((1.0 + cos_turn) / 2.0).sqrt();
    (accel * tolerance * s / (1.0 - s)).sqrt()
}

/// A move waiting in the window.
#[derive(Clone, Copy, Debug)]
pub struct Planned {
    pub path: Path,
    pub length: f64,
    /// Its feed, mm/s.
    pub speed: f64,
    /// The most it may enter at (the junction with the move before), mm/s.
    pub junction: f64,
    /// The most it may enter at so that the window can still stop (the
    /// backward pass), mm/s.
    entry: f64,
}

impl Planned {
    pub fn new(path: Path, length: f64, speed: f64, junction: f64) -> Self {
        Planned {
            path,
            length,
            speed,
            junction: junction.min(speed),
            entry: 0.0,
        }
    }
}

/// The moves planned together.
pub struct Window {
    moves: VecDeque<Planned>,
    lim: Limits,
}

impl Window {
    pub fn new(lim: Limits) -> Self {
        Window {
            moves: VecDeque::new(),
            lim,
        }
    }

    pub fn len(&self) -> usize {
        self.moves.len()
    }

    pub fn is_empty(&self) -> bool {
        self.moves.is_empty()
    }

    /// Adds a move at the end (where the plan stops) and re-plans
    /// backwards.
    pub fn push(&mut self, m: Planned) {
        self.moves.push_back(m);
        let n = self.moves.len();
        let mut exit = 0.0;
        for i in (0..n).rev() {
            let m = &mut self.moves[i];
            let e = m.junction.min(self.lim.reach(exit, m.length));
            if i + 1 < n && e == m.entry {
                break;
            }
            m.entry = e;
            exit = e;
        }
    }

    /// Takes the first move to run, entered at `v0`: the move and its exit
    /// speed (0 when it is the last held).
    pub fn pop(&mut self, v0: f64) -> Option<(Planned, f64)> {
        let m = self.moves.pop_front()?;
        let next = self.moves.front().map_or(0.0, |n| n.entry);
        let v1 = next.min(self.lim.reach(v0, m.length)).min(m.speed);
        Some((m, v1))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn junction_speeds_by_angle() {
        let x = Vector3::new(1.0, 0.0, 0.0);
        let y = Vector3::new(0.0, 1.0, 0.0);
        assert!(junction_speed(&x, &x, 500.0, 0.0).is_infinite());
        assert_eq!(junction_speed(&x, &-x, 500.0, 1.0), 0.0);
        assert_eq!(junction_speed(&x, &y, 500.0, 0.0), 0.0);
        // 90°: sin 45° / (1 − sin 45°) = 1 + √2.
        let v = junction_speed(&x, &y, 500.0, 0.02);
        assert!((v * v - 500.0 * 0.02 * (1.0 + 2f64.sqrt())).abs() < 1e-9);
    }
}
