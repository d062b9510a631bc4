//! Cutting the event stream into chunks: the moves one tool makes at one
//! place. A chunk ends at a tool change, a program stop, or a rapid that
//! moves in X or Y (the tool leaves for another place); vertical rapids
//! (peck retracts, the approach down to the R plane) stay in the chunk.
//! Chunks without any feed move are only positioning and are not kept
//! (the workplan's security plane stands for them). [`Chunker`] cuts a
//! run as it comes.

use crate::toolpath::{Event, Move, MoveKind};

/// The moves one tool makes at one place, with the dwells among them.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Chunk {
    pub tool: i64,
    pub moves: Vec<Move>,
    pub dwells: Vec<DwellAt>,
}

/// A dwell made after `moves[after - 1]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DwellAt {
    pub after: usize,
    pub seconds: f64,
}

/// Same place within this distance, mm.
pub const EPS: f64 = 1e-4;

/// Does the move change X or Y?
pub fn moves_in_xy(m: &Move) -> bool {
    (m.to[0] - m.from[0]).abs() > EPS || (m.to[1] - m.from[1]).abs() > EPS
}

/// The chunks of a run, in program order.
pub fn chunks(events: &[Event]) -> Vec<Chunk> {
    let mut c = Chunker::default();
    let mut out: Vec<Chunk> = events.iter().filter_map(|e| c.push(e.clone())).collect();
    out.extend(c.finish());
    out
}

/// The chunks of a run made event by event: each is given back as soon
/// as the event that ends it comes, so a run is never held whole.
#[derive(Debug, Default)]
pub struct Chunker {
    cur: Chunk,
}

impl Chunker {
    /// Takes the next event; gives back the chunk it ends, if any.
    pub fn push(&mut self, e: Event) -> Option<Chunk> {
        let cur = &mut self.cur;
        match e {
            Event::Move(m) => {
                if matches!(m.kind, MoveKind::Rapid) && moves_in_xy(&m) {
                    let done = take(cur);
                    cur.tool = m.tool;
                    return done;
                }
                if cur.moves.is_empty() {
                    cur.tool = m.tool;
                }
                cur.moves.push(m);
                None
            }
            Event::ToolChange { tool, .. } => {
                let done = take(cur);
                cur.tool = tool;
                done
            }
            Event::Dwell { seconds, .. } => {
                cur.dwells.push(DwellAt {
                    after: cur.moves.len(),
                    seconds,
                });
                None
            }
            Event::Stop { .. } => take(cur),
            Event::Comment { .. } => None,
        }
    }

    /// The last chunk, once the run has ended.
    pub fn finish(mut self) -> Option<Chunk> {
        take(&mut self.cur)
    }
}

/// The chunk so far, when it cuts (has a feed move); `cur` is emptied and
/// keeps its tool.
fn take(cur: &mut Chunk) -> Option<Chunk> {
    let chunk = Chunk {
        tool: cur.tool,
        moves: std::mem::take(&mut cur.moves),
        dwells: std::mem::take(&mut cur.dwells),
    };
    chunk.moves.iter().any(|m| m.is_feed()).then_some(chunk)
}

#[cfg(test)]
pub mod tests {
    use super::*;
    use crate::span::Span;
    use crate::toolpath::{ArcGeom, CoolantState, FeedMode};

    /// A move for synthetic tests.
    pub fn mv(kind: MoveKind, from: [f64; 3], to: [f64; 3], tool: i64) -> Move {
        Move {
            kind,
            from,
            to,
            feed: 500.0,
            feed_mode: FeedMode::PerMinute,
            tool,
            spindle: 3000.0,
            coolant: CoolantState::default(),
            span: Span::default(),
        }
    }

    /// A polyline of events from points; `rapid[i]` says whether the move
    /// to point i+1 is a rapid.
    pub fn path(points: &[[f64; 3]], rapid: &[bool], tool: i64) -> Vec<Event> {
        points
            .windows(2)
            .zip(rapid)
            .map(|(w, r)| {
                let kind = if *r { MoveKind::Rapid } else { MoveKind::Line };
                Event::Move(mv(kind, w[0], w[1], tool))
            })
            .collect()
    }

    /// A full circle in XY about `c` starting at `start`.
    pub fn circle(c: [f64; 2], start: [f64; 3], ccw: bool, tool: i64) -> Event {
        let geom = ArcGeom {
            axes: [0, 1, 2],
            centre: [c[0], c[1], start[2]],
            rotation: if ccw { 1 } else { -1 },
        };
        Event::Move(mv(MoveKind::Arc(geom), start, start, tool))
    }

    #[test]
    fn xy_rapids_and_tool_changes_split_vertical_rapids_do_not() {
        let mut ev = path(
            &[
                [0.0, 0.0, 5.0],
                [0.0, 0.0, 2.0],
                [0.0, 0.0, -3.0],
                [0.0, 0.0, 2.0],
                [0.0, 0.0, -6.0],
                [0.0, 0.0, 5.0],
                [10.0, 0.0, 5.0],
                [10.0, 0.0, -6.0],
            ],
            &[true, false, true, false, true, true, false],
            2,
        );
        ev.push(Event::ToolChange {
            tool: 3,
            span: Span::default(),
        });
        ev.extend(path(&[[0.0; 3], [5.0, 0.0, 0.0]], &[false], 3));
        let c = chunks(&ev);
        assert_eq!(c.len(), 3);
        assert_eq!(c[0].moves.len(), 5);
        assert_eq!(c[1].moves.len(), 1);
        assert_eq!(c[2].tool, 3);
    }
}
