//! Milling chunks seen as layers: the horizontal feed moves grouped by
//! their Z level, each level split into closed loops and the other moves
//! (strokes, links); consecutive chunks of one tool that are layers of
//! one cut (same footprint, deeper, same feed and spindle) or open
//! strokes of one face (same Z, touching, no loops) are merged into one
//! [`MillCut`].

use super::packed::PackedMoves;
use super::segment::{Chunk, EPS};
use crate::toolpath::{Move, MoveKind};
use std::collections::HashMap;

/// A 2D box: min x, min y, max x, max y.
pub type Box2 = [f64; 4];

/// The moves at one Z level, in program order.
#[derive(Clone, Debug, PartialEq)]
pub struct Level {
    pub z: f64,
    pub moves: Vec<Move>,
}

/// One milling operation's moves.
#[derive(Clone, Debug, PartialEq)]
pub struct MillCut {
    pub tool: i64,
    /// Every move, in order (approach, plunges, cuts, retracts).
    pub moves: Vec<Move>,
    /// Levels in the order they are first cut.
    pub levels: Vec<Level>,
    /// The XY box of the horizontal cutting moves.
    footprint: Box2,
    /// The highest cutting feed and the first cutting move's spindle.
    speeds: (f64, f64),
    /// Does any level hold a closed loop?
    has_loops: bool,
}

/// Is it a feed move in the XY plane at one Z?
pub fn horizontal(m: &Move) -> bool {
    let flat = (m.to[2] - m.from[2]).abs() < EPS;
    match &m.kind {
        MoveKind::Line => flat && super::segment::moves_in_xy(m),
        MoveKind::Arc(a) => flat && a.axes == [0, 1, 2],
        MoveKind::Rapid | MoveKind::Probe => false,
    }
}

/// The points of a move's path after its start, XY plane arcs flattened
/// within 1 µm.
pub fn points(m: &Move) -> Vec<[f64; 3]> {
    match &m.kind {
        MoveKind::Arc(a) => a.points(m.from, m.to, 1e-3),
        MoveKind::Rapid | MoveKind::Line | MoveKind::Probe => vec![m.to],
    }
}

/// The XY box of moves' paths.
pub fn bbox(moves: &[Move]) -> Box2 {
    let mut b = [
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    ];
    for m in moves {
        for p in std::iter::once(m.from).chain(points(m)) {
            b = [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ];
        }
    }
    b
}

pub fn grow(b: Box2, d: f64) -> Box2 {
    [b[0] - d, b[1] - d, b[2] + d, b[3] + d]
}

pub fn same_box(a: Box2, b: Box2, tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol)
}

pub fn overlap(a: Box2, b: Box2) -> bool {
    a[0] <= b[2] + EPS && b[0] <= a[2] + EPS && a[1] <= b[3] + EPS && b[1] <= a[3] + EPS
}

/// Does `outer` contain `inner`?
pub fn contains(outer: Box2, inner: Box2, tol: f64) -> bool {
    outer[0] <= inner[0] + tol
        && outer[1] <= inner[1] + tol
        && outer[2] >= inner[2] - tol
        && outer[3] >= inner[3] - tol
}

/// A [`MillCut`] with its moves packed ([`MillCut::pack`]).
#[derive(Clone, Debug)]
pub struct PackedMillCut {
    tool: i64,
    moves: PackedMoves,
    levels: Vec<(f64, PackedMoves)>,
    footprint: Box2,
    speeds: (f64, f64),
    has_loops: bool,
}

impl MillCut {
    pub fn pack(self) -> PackedMillCut {
        PackedMillCut {
            tool: self.tool,
            moves: PackedMoves::pack(self.moves),
            levels: self
                .levels
                .into_iter()
                .map(|l| (l.z, PackedMoves::pack(l.moves)))
                .collect(),
            footprint: self.footprint,
            speeds: self.speeds,
            has_loops: self.has_loops,
        }
    }
}

impl PackedMillCut {
    pub fn unpack(&self) -> MillCut {
        MillCut {
            tool: self.tool,
            moves: self.moves.unpack(),
            levels: self
                .levels
                .iter()
                .map(|(z, m)| Level {
                    z: *z,
                    moves: m.unpack(),
                })
                .collect(),
            footprint: self.footprint,
            speeds: self.speeds,
            has_loops: self.has_loops,
        }
    }
}

impl MillCut {
    pub fn of_chunk(c: &Chunk) -> Option<MillCut> {
        let mut levels: Vec<Level> = Vec::new();
        // Level index by Z on the EPS grid (programs hold thousands).
        let mut by_z: HashMap<i64, usize> = HashMap::new();
        for m in c.moves.iter().filter(|m| horizontal(m)) {
            let key = (m.from[2] / EPS).round() as i64;
            match by_z.get(&key) {
                Some(i) => levels[*i].moves.push(m.clone()),
                None => {
                    by_z.insert(key, levels.len());
                    levels.push(Level {
                        z: m.from[2],
                        moves: vec![m.clone()],
                    });
                }
            }
        }
        if levels.is_empty() {
            return None;
        }
        let cuts: Vec<Move> = levels
            .iter()
            .flat_map(|l| l.moves.iter().cloned())
            .collect();
        let feed = cuts.iter().map(|m| m.feed).fold(0.0, f64::max);
        Some(MillCut {
            tool: c.tool,
            moves: c.moves.clone(),
            footprint: bbox(&cuts),
            speeds: (feed, cuts[0].spindle),
            has_loops: levels.iter().any(|l| !split(&l.moves).loops.is_empty()),
            levels,
        })
    }

    /// The XY box of the horizontal cutting moves.
    pub fn footprint(&self) -> Box2 {
        self.footprint
    }

    pub fn deepest(&self) -> &Level {
        let mut best = &self.levels[0];
        for l in &self.levels {
            if l.z < best.z {
                best = l;
            }
        }
        best
    }

    /// Does `next` continue this cut: deeper layers over the same
    /// footprint, or more strokes at the same single level that touch it?
    pub fn continued_by(&self, next: &MillCut, radius: f64) -> bool {
        if next.tool != self.tool {
            return false;
        }
        let (a, b) = (self.footprint(), next.footprint());
        let below = next.levels.iter().all(|l| l.z < self.deepest().z - EPS);
        // A pass cut with other speeds is another operation (a finishing
        // pass), not a layer.
        let layers = below && same_box(a, b, 1e-3) && self.speeds == next.speeds;
        let one_level = |c: &MillCut| c.levels.len() == 1;
        let strokes = one_level(self)
            && one_level(next)
            && !self.has_loops
            && !next.has_loops
            && (self.levels[0].z - next.levels[0].z).abs() < EPS
            && overlap(grow(a, radius), grow(b, radius));
        layers || strokes
    }

    pub fn absorb(&mut self, next: MillCut) {
        let (a, b) = (self.footprint, next.footprint);
        self.footprint = [
            a[0].min(b[0]),
            a[1].min(b[1]),
            a[2].max(b[2]),
            a[3].max(b[3]),
        ];
        self.speeds.0 = self.speeds.0.max(next.speeds.0);
        self.has_loops |= next.has_loops;
        self.moves.extend(next.moves);
        for l in next.levels {
            match self.levels.iter_mut().find(|m| (m.z - l.z).abs() < EPS) {
                Some(m) => m.moves.extend(l.moves),
                None => self.levels.push(l),
            }
        }
    }
}

/// A level split into closed loops and everything else.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Split {
    pub loops: Vec<Vec<Move>>,
    pub others: Vec<Move>,
}

fn same_xy(a: [f64; 3], b: [f64; 3]) -> bool {
    (a[0] - b[0]).abs() < EPS && (a[1] - b[1]).abs() < EPS
}

/// Splits a level's moves into closed loops (a run of contiguous moves
/// coming back to where it started) and the rest.
pub fn split(moves: &[Move]) -> Split {
    let mut out = Split::default();
    let mut cur: Vec<Move> = Vec::new();
    // Where each start point of `cur` first occurs (on a 0.1 µm grid).
    let mut starts: HashMap<(i64, i64), usize> = HashMap::new();
    let key = |p: [f64; 3]| ((p[0] * 1e7).round() as i64, (p[1] * 1e7).round() as i64);
    for m in moves {
        if let Some(last) = cur.last() {
            if !same_xy(last.to, m.from) {
                out.others.append(&mut cur);
                starts.clear();
            }
        }
        starts.entry(key(m.from)).or_insert(cur.len());
        cur.push(m.clone());
        let closes = starts.get(&key(m.to)).copied();
        if let Some(i) = closes {
            let is_circle = i + 1 == cur.len() && matches!(m.kind, MoveKind::Arc(_));
            if i + 1 < cur.len() || is_circle {
                let lp = cur.split_off(i);
                out.others.append(&mut cur);
                out.loops.push(lp);
                starts.clear();
            }
        }
    }
    out.others.append(&mut cur);
    out
}

#[cfg(test)]
mod tests {
    use super::super::segment::{chunks, tests::path};
    use super::*;

    #[test]
    fn loops_and_links_are_told_apart() {
        let z = -2.0;
        let pts = [
            [5.0, 5.0, 2.0],
            [5.0, 5.0, z],
            [4.0, 4.0, z],
            [6.0, 4.0, z],
            [6.0, 6.0, z],
            [4.0, 6.0, z],
            [4.0, 4.0, z],
            [2.0, 2.0, z],
            [8.0, 2.0, z],
            [8.0, 8.0, z],
            [2.0, 8.0, z],
            [2.0, 2.0, z],
        ];
        let c = chunks(&path(&pts, &[false; 11], 3));
        let cut = MillCut::of_chunk(&c[0]).unwrap();
        assert_eq!(cut.levels.len(), 1);
        let s = split(&cut.levels[0].moves);
        assert_eq!(s.loops.len(), 2);
        assert_eq!(s.loops[1].len(), 4);
        assert_eq!(s.others.len(), 2);
        assert_eq!(cut.footprint(), [2.0, 2.0, 8.0, 8.0]);
    }
}
