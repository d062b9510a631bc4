//! The queue of held-back calls. Compensation cannot know where a move ends
//! until it sees the next one, so moves wait here, together with the
//! non-motion calls that came after them (so their order is kept).

use super::angle::find_turn;
use super::error::{BlockTag, CompErrorKind};
use super::MoveKind;
use crate::canon::{Canon, Pose};

/// One held-back call.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Queued {
    /// A straight move to `to`; `dir` is the direction checked when its end
    /// is moved (LinuxCNC's, not always the move's own).
    Line {
        kind: MoveKind,
        dir: (f64, f64),
        to: Pose,
        block: BlockTag,
    },
    /// An arc; `sweep` is the programmed sweep (0: never checked).
    Arc {
        sweep: f64,
        end: (f64, f64),
        centre: (f64, f64),
        turn: i64,
        z: f64,
        abc: [f64; 3],
        block: BlockTag,
    },
    Other(Canon),
}

/// The queue and the start point of its first move.
#[derive(Clone, Debug, Default)]
pub(super) struct Queue {
    pub items: Vec<Queued>,
    /// Where the held-back path starts, when known (LinuxCNC's endpoint).
    pub start: Option<(f64, f64)>,
    /// Compensation in the XZ plane: held moves are in Z X Y order.
    pub xz: bool,
    /// Added to every compensated point (plane order): a lathe tool's
    /// imaginary tip seen from its nose centre ([`super::RadiusComp::set_tip`]).
    pub tip: (f64, f64),
}

impl Queue {
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }

    /// The first held-back item.
    pub fn front(&self) -> Option<&Queued> {
        self.items.first()
    }

    pub fn push(&mut self, q: Queued) {
        self.items.push(q);
    }

    /// Emits everything held back, in order, and forgets the start point.
    pub fn flush(&mut self, out: &mut dyn FnMut(Canon)) {
        self.start = None;
        for q in self.items.drain(..) {
            out(to_canon(q, self.xz, self.tip));
        }
    }

    /// Moves the end of every held-back move to `p`, checking that no
    /// move turns back, then flushes and makes `p` the new start point.
    /// Does nothing at all when the queue is empty.
    pub fn move_end_and_flush(
        &mut self,
        p: (f64, f64),
        out: &mut dyn FnMut(Canon),
    ) -> Result<(), (CompErrorKind, BlockTag)> {
        if self.items.is_empty() {
            return Ok(());
        }
        let start = self.start;
        for q in self.items.iter_mut() {
            move_end(q, start, p)?;
        }
        self.flush(out);
        self.start = Some(p);
        Ok(())
    }
}

fn move_end(
    q: &mut Queued,
    start: Option<(f64, f64)>,
    p: (f64, f64),
) -> Result<(), (CompErrorKind, BlockTag)> {
    match q {
        Queued::Arc {
            sweep,
            end,
            centre,
            turn,
            block,
            ..
        } => {
            let r1 = (end.0 - centre.0).hypot(end.1 - centre.1);
            let r2 = (p.0 - centre.0).hypot(p.1 - centre.1);
            if (r1 - r2).abs() > 0.01 {
                return Err((CompErrorKind::Bug, *block));
            }
            if let Some(s) = start {
                let l2 = find_turn(s, *centre, *turn, p);
                if *sweep != 0.0 && l2.abs() > sweep.abs() + 0.001 {
                    return Err((CompErrorKind::ArcGouge, *block));
                }
            }
            *end = p;
        }
        Queued::Line {
            kind,
            dir,
            to,
            block,
        } => {
            if let Some(s) = start {
                let dot = dir.0 * (p.0 - s.0) + dir.1 * (p.1 - s.1);
                if dot < 0.0 {
                    return Err((gouge_kind(*kind), *block));
                }
            }
            to[0] = p.0;
            to[1] = p.1;
        }
        Queued::Other(_) => {}
    }
    Ok(())
}

fn gouge_kind(kind: MoveKind) -> CompErrorKind {
    match kind {
        MoveKind::Rapid => CompErrorKind::StraightTraverseGouge,
        MoveKind::Feed => CompErrorKind::StraightFeedGouge,
    }
}

/// A held-back call as it goes out; `xz`: straight moves are held in
/// Z X Y order (arcs are already in `ARC_FEED`'s plane order).
fn to_canon(q: Queued, xz: bool, tip: (f64, f64)) -> Canon {
    let real = |p: Pose| {
        let (a, b) = (p[0] + tip.0, p[1] + tip.1);
        if xz {
            [b, p[2], a, p[3], p[4], p[5]]
        } else {
            [a, b, p[2], p[3], p[4], p[5]]
        }
    };
    let shift = |p: (f64, f64)| (p.0 + tip.0, p.1 + tip.1);
    match q {
        Queued::Line {
            kind: MoveKind::Rapid,
            to,
            ..
        } => Canon::StraightTraverse(real(to)),
        Queued::Line {
            kind: MoveKind::Feed,
            to,
            ..
        } => Canon::StraightFeed(real(to)),
        Queued::Arc {
            end,
            centre,
            turn,
            z,
            abc,
            ..
        } => Canon::ArcFeed {
            first_end: shift(end).0,
            second_end: shift(end).1,
            first_axis: shift(centre).0,
            second_axis: shift(centre).1,
            rotation: turn,
            axis_end: z,
            abc,
        },
        Queued::Other(c) => c,
    }
}

/// Whether LinuxCNC holds this call back behind a queued move (it does for
/// feed, dwell, coolant, spindle and comments).
pub(super) fn is_queueable(c: &Canon) -> bool {
    use Canon::*;
    matches!(
        c,
        SetFeedRate(_)
            | Dwell(_)
            | SetFeedMode(_)
            | MistOn
            | MistOff
            | FloodOn
            | FloodOff
            | SpindleCw
            | SpindleCcw
            | StopSpindle
            | SetSpindleMode(_)
            | SetSpindleSpeed(_)
            | Comment(_)
    )
}

/// Whether LinuxCNC prints this call at once, ahead of queued moves,
/// without flushing them (messages).
pub(super) fn jumps_queue(c: &Canon) -> bool {
    matches!(c, Canon::Message(_))
}
