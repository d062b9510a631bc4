//! From chunks to cuts: a chunk of vertical moves is a hole; milling
//! chunks that continue one another (layers, strokes) are merged into one
//! milling cut; anything else is kept as it is.

use super::hole::{as_hole, HoleCut};
use super::level::{bbox, grow, Box2, MillCut};
use super::segment::{chunks, Chunk};
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
pub fn cuts(events: &[Event], radius: &dyn Fn(i64) -> Option<f64>) -> Vec<Cut> {
    let mut b = CutBuilder::default();
    for c in chunks(events) {
        b.push(c, radius);
    }
    b.finish()
}

/// The cuts of a run made chunk by chunk ([`super::segment::Chunker`]):
/// only the cuts are kept, each chunk is moved into its cut.
#[derive(Debug, Default)]
pub struct CutBuilder {
    out: Vec<Cut>,
}

impl CutBuilder {
    /// Takes the next chunk: a hole, a milling cut (merged into the one
    /// before when it continues it) or another cut.
    pub fn push(&mut self, c: Chunk, radius: &dyn Fn(i64) -> Option<f64>) {
        if let Some(hole) = as_hole(&c) {
            self.out.push(Cut::Hole {
                hole,
                tool: c.tool,
                moves: c.moves,
            });
            return;
        }
        let Some(m) = MillCut::of_chunk(&c) else {
            self.out.push(Cut::Other(c));
            return;
        };
        let r = radius(m.tool).unwrap_or(0.0);
        match self.out.last_mut() {
            Some(Cut::Mill(prev)) if prev.continued_by(&m, r) => prev.absorb(m),
            _ => self.out.push(Cut::Mill(m)),
        }
    }

    /// The cuts, in program order.
    pub fn finish(self) -> Vec<Cut> {
        self.out
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
