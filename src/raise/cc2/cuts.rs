//! From chunks to cuts: a chunk of vertical moves is a hole; milling
//! chunks that continue one another (layers, strokes) are merged into one
//! milling cut; anything else is kept as it is. Finished cuts are
//! stored packed ([`Stored`]) until the run has ended.

use super::hole::{as_hole, HoleCut};
use super::level::{bbox, grow, Box2, MillCut, PackedMillCut};
use super::packed::PackedMoves;
use super::segment::{chunks, Chunk, DwellAt};
use crate::toolpath::{Event, Move};

#[derive(Clone, Debug, PartialEq)]
pub enum Cut {
    Hole {
        hole: HoleCut,
        tool: i64,
        moves: Vec<Move>,
    },
    Mill(MillCut),
    Other(Chunk),
}

/// The cuts of a run, in program order; `radius` gives a tool's radius.
#[cfg(test)]
pub fn cuts(events: &[Event], radius: &dyn Fn(i64) -> Option<f64>) -> Vec<Cut> {
    stored(events, radius).iter().map(Stored::unpack).collect()
}

/// [`cuts`], kept as [`Stored`] cuts.
pub fn stored(events: &[Event], radius: &dyn Fn(i64) -> Option<f64>) -> Vec<Stored> {
    let mut b = CutBuilder::default();
    for c in chunks(events) {
        b.push(c, radius);
    }
    b.finish(radius)
}

/// The cuts of a run made chunk by chunk ([`super::segment::Chunker`]):
/// each chunk is moved into its cut, and a cut is stored as soon as the
/// next one shows it is finished.
#[derive(Debug, Default)]
pub struct CutBuilder {
    done: Vec<Stored>,
    /// The last cut: a milling cut the next chunk may continue.
    last: Option<Cut>,
}

impl CutBuilder {
    /// Takes the next chunk: a hole, a milling cut (merged into the one
    /// before when it continues it) or another cut.
    pub fn push(&mut self, c: Chunk, radius: &dyn Fn(i64) -> Option<f64>) {
        let cut = if let Some(hole) = as_hole(&c) {
            Cut::Hole {
                hole,
                tool: c.tool,
                moves: c.moves,
            }
        } else if let Some(m) = MillCut::of_chunk(&c) {
            let r = radius(m.tool).unwrap_or(0.0);
            if let Some(Cut::Mill(prev)) = self.last.as_mut() {
                if prev.continued_by(&m, r) {
                    prev.absorb(m);
                    return;
                }
            }
            Cut::Mill(m)
        } else {
            Cut::Other(c)
        };
        if let Some(done) = self.last.replace(cut) {
            self.done.push(Stored::new(done, radius));
        }
    }

    /// The cuts, in program order.
    pub fn finish(mut self, radius: &dyn Fn(i64) -> Option<f64>) -> Vec<Stored> {
        if let Some(done) = self.last.take() {
            self.done.push(Stored::new(done, radius));
        }
        self.done
    }
}

/// A finished cut kept until the run has ended: its moves packed
/// ([`PackedMoves`]), with what recognising the other cuts asks of it
/// (its envelope and top).
#[derive(Debug)]
pub struct Stored {
    cut: Packed,
    /// The XY box the tool sweeps ([`Cut::envelope`]).
    pub envelope: Box2,
    /// [`Cut::top`].
    pub top: f64,
}

#[derive(Debug)]
enum Packed {
    Hole {
        hole: HoleCut,
        tool: i64,
        moves: PackedMoves,
    },
    Mill(PackedMillCut),
    Other {
        tool: i64,
        moves: PackedMoves,
        dwells: Vec<DwellAt>,
    },
}

impl Stored {
    fn new(cut: Cut, radius: &dyn Fn(i64) -> Option<f64>) -> Stored {
        let (envelope, top) = (cut.envelope(radius), cut.top());
        let cut = match cut {
            Cut::Hole { hole, tool, moves } => Packed::Hole {
                hole,
                tool,
                moves: PackedMoves::pack(moves),
            },
            Cut::Mill(m) => Packed::Mill(m.pack()),
            Cut::Other(c) => Packed::Other {
                tool: c.tool,
                moves: PackedMoves::pack(c.moves),
                dwells: c.dwells,
            },
        };
        Stored { cut, envelope, top }
    }

    /// The cut as it was made.
    pub fn unpack(&self) -> Cut {
        match &self.cut {
            Packed::Hole { hole, tool, moves } => Cut::Hole {
                hole: hole.clone(),
                tool: *tool,
                moves: moves.unpack(),
            },
            Packed::Mill(m) => Cut::Mill(m.unpack()),
            Packed::Other {
                tool,
                moves,
                dwells,
            } => Cut::Other(Chunk {
                tool: *tool,
                moves: moves.unpack(),
                dwells: dwells.clone(),
            }),
        }
    }
}

impl Cut {
    /// The XY box the tool sweeps.
    pub fn envelope(&self, radius: &dyn Fn(i64) -> Option<f64>) -> Box2 {
        match self {
            Cut::Hole { hole, tool, .. } => {
                let r = radius(*tool).unwrap_or(0.0);
                grow([hole.xy[0], hole.xy[1], hole.xy[0], hole.xy[1]], r)
            }
            Cut::Mill(m) => grow(m.footprint(), radius(m.tool).unwrap_or(0.0)),
            Cut::Other(c) => grow(bbox(&c.moves), radius(c.tool).unwrap_or(0.0)),
        }
    }

    /// The highest cutting level of a milling cut (-∞ for others).
    pub fn top(&self) -> f64 {
        match self {
            Cut::Mill(m) => m
                .levels
                .iter()
                .map(|l| l.z)
                .fold(f64::NEG_INFINITY, f64::max),
            Cut::Hole { .. } | Cut::Other(_) => f64::NEG_INFINITY,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::segment::tests::path;
    use super::*;

    /// A square loop at `z` of half-size `h` about (10, 10), entered from
    /// above at its corner.
    fn layer(z: f64, h: f64) -> Vec<Event> {
        let (a, b) = (10.0 - h, 10.0 + h);
        path(
            &[
                [a, a, 2.0],
                [a, a, z],
                [b, a, z],
                [b, b, z],
                [a, b, z],
                [a, a, z],
                [a, a, 2.0],
                [0.0, 0.0, 2.0],
            ],
            &[false, false, false, false, false, true, true],
            3,
        )
    }

    #[test]
    fn layers_merge_a_different_footprint_does_not() {
        let mut ev = layer(-2.0, 5.0);
        ev.extend(layer(-4.0, 5.0));
        ev.extend(layer(-4.1, 5.2));
        let c = cuts(&ev, &|_| Some(5.0));
        assert_eq!(c.len(), 2);
        let Cut::Mill(m) = &c[0] else { panic!() };
        assert_eq!(m.levels.len(), 2);
    }
}
