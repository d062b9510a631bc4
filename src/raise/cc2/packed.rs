//! Moves packed for keeping: a cut's moves are held from the moment the
//! cut is made until the run has ended and it is raised, so they are kept
//! in less than half the room of [`Move`]s. Each move keeps its ends and
//! span; its arc (when it is one) and its feed, tool, spindle and coolant
//! (which change seldom) are indices into side tables. Unpacking gives
//! back the very same moves, bit for bit.

use crate::span::Span;
use crate::toolpath::{ArcGeom, CoolantState, FeedMode, Move, MoveKind, P3};

/// Moves, packed ([`PackedMoves::pack`], [`PackedMoves::unpack`]).
#[derive(Clone, Debug, Default)]
pub struct PackedMoves {
    moves: Vec<Packed>,
    arcs: Vec<ArcGeom>,
    states: Vec<State>,
}

/// One move: its ends, its span, its kind (`RAPID`, `LINE`, `PROBE` or
/// `ARC` + the arc's index) and its state's index.
#[derive(Clone, Copy, Debug)]
struct Packed {
    from: P3,
    to: P3,
    span: Span,
    kind: u32,
    state: u32,
}

const RAPID: u32 = 0;
const LINE: u32 = 1;
const PROBE: u32 = 2;
const ARC: u32 = 3;

/// What a move shares with the moves around it.
#[derive(Clone, Copy, Debug, PartialEq)]
struct State {
    feed: f64,
    feed_mode: FeedMode,
    tool: i64,
    spindle: f64,
    coolant: CoolantState,
}

impl PackedMoves {
    pub fn pack(moves: Vec<Move>) -> PackedMoves {
        let mut p = PackedMoves::default();
        for m in moves {
            p.push(m);
        }
        p.moves.shrink_to_fit();
        p.arcs.shrink_to_fit();
        p.states.shrink_to_fit();
        p
    }

    fn push(&mut self, m: Move) {
        let kind = match m.kind {
            MoveKind::Rapid => RAPID,
            MoveKind::Line => LINE,
            MoveKind::Probe => PROBE,
            MoveKind::Arc(a) => {
                self.arcs.push(a);
                ARC + (self.arcs.len() - 1) as u32
            }
        };
        let state = State {
            feed: m.feed,
            feed_mode: m.feed_mode,
            tool: m.tool,
            spindle: m.spindle,
            coolant: m.coolant,
        };
        // Compared bit for bit: a NaN feed is a state like any other.
        if self.states.last().is_none_or(|s| !same_state(s, &state)) {
            self.states.push(state);
        }
        self.moves.push(Packed {
            from: m.from,
            to: m.to,
            span: m.span,
            kind,
            state: (self.states.len() - 1) as u32,
        });
    }

    pub fn unpack(&self) -> Vec<Move> {
        self.moves.iter().map(|p| self.unpack_one(p)).collect()
    }

    fn unpack_one(&self, p: &Packed) -> Move {
        let s = self.states[p.state as usize];
        let kind = match p.kind {
            RAPID => MoveKind::Rapid,
            LINE => MoveKind::Line,
            PROBE => MoveKind::Probe,
            k => MoveKind::Arc(self.arcs[(k - ARC) as usize]),
        };
        Move {
            kind,
            from: p.from,
            to: p.to,
            feed: s.feed,
            feed_mode: s.feed_mode,
            tool: s.tool,
            spindle: s.spindle,
            coolant: s.coolant,
            span: p.span,
        }
    }
}

fn same_state(a: &State, b: &State) -> bool {
    a.feed.to_bits() == b.feed.to_bits()
        && a.feed_mode == b.feed_mode
        && a.tool == b.tool
        && a.spindle.to_bits() == b.spindle.to_bits()
        && a.coolant == b.coolant
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raise::cc2::segment::tests::{circle, path};
    use crate::toolpath::Event;

    #[test]
    fn unpacking_gives_back_the_same_moves() {
        let mut ev = path(
            &[[0.0, 0.0, 5.0], [1.0, 2.0, -0.0], [3.5, 2.0, -1.0]],
            &[true, false],
            4,
        );
        ev.push(circle([1.0, 1.0], [0.0, 1.0, -1.0], true, 4));
        let mut moves: Vec<Move> = ev
            .into_iter()
            .filter_map(|e| match e {
                Event::Move(m) => Some(m),
                _ => None,
            })
            .collect();
        let mut probe = moves[0].clone();
        probe.kind = MoveKind::Probe;
        moves.push(probe);
        moves[1].feed = 120.0;
        moves[1].feed_mode = FeedMode::PerRev;
        moves[1].coolant.mist = true;
        let packed = PackedMoves::pack(moves.clone());
        let back = packed.unpack();
        assert_eq!(back, moves);
        // Rapid, line, arc, probe: one arc; the arc and the probe share
        // the first move's state, the line has its own.
        assert_eq!((packed.arcs.len(), packed.states.len()), (1, 3));
        assert_eq!(back[0].to[2].to_bits(), (-0.0f64).to_bits());
    }
}
