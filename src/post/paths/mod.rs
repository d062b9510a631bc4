//! Explicit toolpaths for features the target has no cycle for: pockets
//! cleared contour-parallel from the inside out ([`pocket`], general
//! polygon boundaries in [`polygon`]), holes milled on a helix
//! ([`helix`]) and faces milled zigzag ([`face`]). Geometry is made in the feature's plane
//! (2-D, mm) and placed with the feature's frame.

pub mod coverage;
pub mod face;
pub mod helix;
pub mod pocket;
pub mod polygon;
pub mod section;

use super::frame::Frame;

/// A 2-D point in the feature's plane.
pub type P2 = [f64; 2];

/// One tool-centre move, absolute workpiece coordinates (mm).
#[derive(Clone, Debug, PartialEq)]
pub enum Move {
    Rapid([f64; 3]),
    Line([f64; 3]),
    /// An arc about an axis parallel to Z: in the XY plane when `to` is
    /// at the current z, else one piece (at most half a turn) of a helix.
    Arc {
        to: [f64; 3],
        centre: P2,
        ccw: bool,
    },
}

/// One segment of a closed loop in the plane: to `to`, straight or about
/// `centre`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Seg {
    pub from: P2,
    pub to: P2,
    pub arc: Option<(P2, bool)>,
}

/// The same loop run the other way round.
pub fn reversed(segs: &[Seg]) -> Vec<Seg> {
    segs.iter()
        .rev()
        .map(|s| Seg {
            from: s.to,
            to: s.from,
            arc: s.arc.map(|(c, ccw)| (c, !ccw)),
        })
        .collect()
}

/// The depths of the layers from `top` down to `bottom`, each at most
/// `step` deep, evenly shared out.
pub fn levels(top: f64, bottom: f64, step: Option<f64>) -> Vec<f64> {
    let depth = top - bottom;
    if depth <= 1e-9 {
        return vec![bottom];
    }
    let n = match step {
        Some(s) if s > 1e-9 => ((depth / s) - 1e-9).ceil().max(1.0) as usize,
        _ => 1,
    };
    (1..=n).map(|i| top - depth * i as f64 / n as f64).collect()
}

/// Builds moves in the plane, placed by a frame.
pub struct MoveSink<'f> {
    pub frame: &'f Frame,
    pub moves: Vec<Move>,
}

impl<'f> MoveSink<'f> {
    pub fn new(frame: &'f Frame) -> Self {
        MoveSink {
            frame,
            moves: Vec::new(),
        }
    }

    fn at(&self, p: P2, z: f64) -> [f64; 3] {
        let q = self.frame.apply([p[0], p[1], 0.0]);
        [q[0], q[1], z]
    }

    /// The plane point (in the feature's plane) of the last move: its
    /// offset from the frame's origin projected on the frame's x and y
    /// axes (the inverse of [`Self::at`] for the frame's orthonormal axes).
    pub fn last_xy(&self) -> P2 {
        let last = match self.moves.last() {
            Some(Move::Rapid(p)) | Some(Move::Line(p)) => *p,
            Some(Move::Arc { to, .. }) => *to,
            None => return [0.0, 0.0],
        };
        let f = self.frame;
        let v = [last[0] - f.origin[0], last[1] - f.origin[1]];
        [v[0] * f.x[0] + v[1] * f.x[1], v[0] * f.y[0] + v[1] * f.y[1]]
    }

    pub fn rapid(&mut self, p: P2, z: f64) {
        let to = self.at(p, z);
        self.moves.push(Move::Rapid(to));
    }

    pub fn line(&mut self, p: P2, z: f64) {
        let to = self.at(p, z);
        self.moves.push(Move::Line(to));
    }

    pub fn seg(&mut self, s: &Seg, z: f64) {
        match s.arc {
            None => self.line(s.to, z),
            Some((c, ccw)) => {
                let to = self.at(s.to, z);
                let cc = self.at(c, z);
                // The frame is a rotation about Z: senses are kept.
                self.moves.push(Move::Arc {
                    to,
                    centre: [cc[0], cc[1]],
                    ccw,
                });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn levels_share_the_depth_evenly() {
        assert_eq!(levels(0.0, -29.5, Some(6.5)).len(), 5);
        let l = levels(5.0, 0.0, Some(2.5));
        assert_eq!(l, vec![2.5, 0.0]);
        assert_eq!(levels(0.0, -3.0, None), vec![-3.0]);
    }
}
