//! Holes: a chunk whose moves all go straight up and down at one X Y.
//!
//! What the moves tell (the cycle semantics of G81..G89 / CYCLE81..89):
//! * one feed down, rapid out: DRILLING (G81, CYCLE81); a dwell at the
//!   bottom is kept as `dwell_time_bottom` (G82, CYCLE82);
//! * several feeds down, each deeper than the last, with retracts
//!   between: MULTISTEP_DRILLING (G83, G73, CYCLE83); `first_depth` and
//!   `depth_of_step` are measured from the level the first feed starts
//!   at (the R plane), `retract_distance` is how far the first retract
//!   goes back up;
//! * feed out of the hole: REAMING without a dwell at the bottom (G85,
//!   CYCLE85), BORING with one (G89, CYCLE89);
//! * spindle stopped at the bottom then rapid out: BORING with
//!   `spindle_stop_at_bottom` (G86, CYCLE86).
//!
//! * fed out with the spindle reversed: TAPPING (G84, G74, CYCLE84,
//!   CYCL DEF 207, G33.1), the tool a TAP of the spindle's hand.
//!
//! The tool's kind, when the project knows it, wins: a reamer reams, a
//! centre or spot drill centre-drills, a countersink countersinks.

use super::segment::{moves_in_xy, Chunk, EPS};
use crate::toolpath::{CoolantState, MoveKind};

/// What a hole chunk did.
#[derive(Clone, Debug, PartialEq)]
pub struct HoleCut {
    pub xy: [f64; 2],
    /// Where the first feed down starts (the R plane).
    pub start_z: f64,
    /// The deepest point reached.
    pub bottom: f64,
    /// The depth reached by each feed that went deeper than before.
    pub pecks: Vec<f64>,
    /// How high the first retract after the first peck went.
    pub first_retract_to: Option<f64>,
    pub dwell_bottom: Option<f64>,
    pub feed_out: bool,
    /// Fed out with the spindle turned the other way (G84, G74, CYCLE84).
    pub tapping: bool,
    pub spindle_stop: bool,
    pub feed: f64,
    pub spindle: f64,
    pub coolant: CoolantState,
}

/// The hole a chunk drills, if all its moves are vertical lines.
pub fn as_hole(chunk: &Chunk) -> Option<HoleCut> {
    let ms = &chunk.moves;
    let vertical = ms
        .iter()
        .all(|m| matches!(m.kind, MoveKind::Rapid | MoveKind::Line) && !moves_in_xy(m));
    if !vertical {
        return None;
    }
    let first = ms.iter().find(|m| m.is_feed() && m.to[2] < m.from[2])?;
    let mut low = f64::INFINITY;
    let mut pecks = Vec::new();
    let mut bottom_at = 0;
    let mut first_retract_to = None;
    for (i, m) in ms.iter().enumerate() {
        if m.is_feed() && m.to[2] < low - EPS && m.to[2] < m.from[2] {
            low = m.to[2];
            pecks.push(m.to[2]);
            bottom_at = i;
        } else if pecks.len() == 1 && m.to[2] > m.from[2] {
            first_retract_to = Some(first_retract_to.unwrap_or(f64::MIN).max(m.to[2]));
        }
    }
    let after = ms.get(bottom_at + 1);
    let dwell_bottom = chunk
        .dwells
        .iter()
        .find(|d| d.after == bottom_at + 1 && d.seconds > 0.0)
        .map(|d| d.seconds);
    Some(HoleCut {
        xy: [first.from[0], first.from[1]],
        start_z: first.from[2],
        bottom: low,
        first_retract_to: if pecks.len() > 1 {
            first_retract_to
        } else {
            None
        },
        pecks,
        dwell_bottom,
        feed_out: after.is_some_and(|m| m.is_feed() && m.to[2] > m.from[2]),
        tapping: after.is_some_and(|m| m.is_feed() && m.spindle * first.spindle < 0.0),
        spindle_stop: after.is_some_and(|m| m.spindle == 0.0),
        feed: first.feed,
        spindle: first.spindle,
        coolant: first.coolant,
    })
}

/// The drilling operation the moves describe (before the tool's kind is
/// considered).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HoleOp {
    Drilling,
    Multistep,
    Reaming,
    Boring,
}

pub fn hole_op(h: &HoleCut) -> HoleOp {
    if h.spindle_stop || (h.feed_out && h.dwell_bottom.is_some()) {
        HoleOp::Boring
    } else if h.feed_out {
        HoleOp::Reaming
    } else if h.pecks.len() > 1 {
        HoleOp::Multistep
    } else {
        HoleOp::Drilling
    }
}

#[cfg(test)]
mod tests {
    use super::super::segment::{chunks, tests::path};
    use super::*;
    use crate::toolpath::Event;

    fn hole(points: &[[f64; 3]], rapid: &[bool]) -> HoleCut {
        let c = chunks(&path(points, rapid, 2));
        assert_eq!(c.len(), 1);
        as_hole(&c[0]).expect("a hole")
    }

    #[test]
    fn single_plunge_is_drilling() {
        let h = hole(
            &[
                [5.0, 5.0, 25.0],
                [5.0, 5.0, 2.0],
                [5.0, 5.0, -13.0],
                [5.0, 5.0, 25.0],
            ],
            &[true, false, true],
        );
        assert_eq!(h.bottom, -13.0);
        assert_eq!(h.start_z, 2.0);
        assert_eq!(hole_op(&h), HoleOp::Drilling);
    }

    #[test]
    fn pecks_are_multistep_with_first_retract() {
        let z = |z| [1.0, 1.0, z];
        let h = hole(
            &[
                z(2.0),
                z(-2.0),
                z(2.0),
                z(-1.4),
                z(-6.0),
                z(2.0),
                z(-5.4),
                z(-9.0),
                z(2.0),
            ],
            &[false, true, true, false, true, true, false, true],
        );
        assert_eq!(h.pecks, vec![-2.0, -6.0, -9.0]);
        assert_eq!(h.first_retract_to, Some(2.0));
        assert_eq!(hole_op(&h), HoleOp::Multistep);
    }

    #[test]
    fn feed_out_reams_and_dwell_with_feed_out_bores() {
        let z = |z| [0.0, 0.0, z];
        let pts = [z(2.0), z(-10.0), z(2.0)];
        assert_eq!(hole_op(&hole(&pts, &[false, false])), HoleOp::Reaming);
        let mut ev = path(&pts[..2], &[false], 2);
        ev.push(Event::Dwell {
            seconds: 0.5,
            span: Default::default(),
        });
        ev.extend(path(&pts[1..], &[false], 2));
        let h = as_hole(&chunks(&ev)[0]).unwrap();
        assert_eq!(h.dwell_bottom, Some(0.5));
        assert_eq!(hole_op(&h), HoleOp::Boring);
    }

    #[test]
    fn sideways_feed_is_not_a_hole() {
        let c = chunks(&path(
            &[[0.0; 3], [0.0, 0.0, -2.0], [5.0, 0.0, -2.0]],
            &[false, false],
            3,
        ));
        assert!(as_hole(&c[0]).is_none());
    }
}
