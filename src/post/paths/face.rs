//! A planar face milled zigzag: passes parallel to the strategy's feed
//! direction, stepping across by the stepover, each pass run out past the
//! face by the tool radius plus the clearance, layer by layer down to the
//! face's depth.

use super::{MoveSink, P2};

/// The face in its own plane: the rectangle `[0, across] x [0, along]` of
/// a frame whose second axis is the pass direction.
#[derive(Clone, Copy, Debug)]
pub struct FaceArea {
    pub across: f64,
    pub along: f64,
}

#[derive(Clone, Debug)]
pub struct FaceCut {
    pub tool_radius: f64,
    pub stepover: f64,
    /// How far the tool hangs over each side edge (overlap x diameter).
    pub overhang: f64,
    /// Step from the high `across` side towards 0 (stepover to the left of
    /// the feed direction).
    pub from_high_side: bool,
    pub levels: Vec<f64>,
    pub clear: f64,
    pub r_plane: f64,
    /// Run-out beyond each end of a pass.
    pub run_out: f64,
}

/// The pass positions across the face, in cutting order.
pub fn pass_positions(a: &FaceArea, c: &FaceCut) -> Vec<f64> {
    let inset = (c.tool_radius - c.overhang).max(0.0);
    let span = a.across - 2.0 * inset;
    let mut out = if span <= 1e-9 {
        vec![a.across / 2.0]
    } else {
        let n = ((span / c.stepover) - 1e-9).ceil().max(1.0) as usize;
        (0..=n)
            .map(|i| inset + span * i as f64 / n as f64)
            .collect()
    };
    if c.from_high_side {
        out.reverse();
    }
    out
}

/// All the moves, from the clearance plane back to it.
pub fn moves(a: &FaceArea, c: &FaceCut, sink: &mut MoveSink<'_>) {
    let xs = pass_positions(a, c);
    let (y0, y1) = (-c.run_out, a.along + c.run_out);
    let start: P2 = [xs[0], y0];
    sink.rapid(start, c.clear);
    for &z in &c.levels {
        sink.rapid(start, c.r_plane);
        sink.line(start, z);
        let mut forward = true;
        for (i, &x) in xs.iter().enumerate() {
            let (from, to) = if forward { (y0, y1) } else { (y1, y0) };
            if i > 0 {
                sink.line([x, from], z);
            }
            sink.line([x, to], z);
            forward = !forward;
        }
        let end_y = if forward { y0 } else { y1 };
        let last = *xs.last().unwrap_or(&0.0);
        sink.rapid([last, end_y], c.r_plane);
    }
    let end = match sink.moves.last() {
        Some(super::Move::Rapid(p)) => *p,
        _ => return,
    };
    sink.moves
        .push(super::Move::Rapid([end[0], end[1], c.clear]));
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::post::frame::Frame;
    use crate::post::paths::Move;

    fn cut() -> FaceCut {
        FaceCut {
            tool_radius: 9.0,
            stepover: 17.1,
            overhang: 0.9,
            from_high_side: true,
            levels: vec![2.5, 0.0],
            clear: 30.0,
            r_plane: 15.0,
            run_out: 11.0,
        }
    }

    #[test]
    fn passes_cover_the_face_edge_to_edge() {
        let a = FaceArea {
            across: 100.0,
            along: 120.0,
        };
        let xs = pass_positions(&a, &cut());
        assert_eq!(xs.len(), 6);
        assert!((xs[0] - 91.9).abs() < 1e-9 && (xs[5] - 8.1).abs() < 1e-9);
        for w in xs.windows(2) {
            assert!((w[0] - w[1]) <= 17.1 + 1e-9);
        }
    }

    #[test]
    fn zigzag_alternates_and_ends_at_the_clearance_plane() {
        let a = FaceArea {
            across: 100.0,
            along: 120.0,
        };
        let f = Frame::identity();
        let mut sink = MoveSink::new(&f);
        moves(&a, &cut(), &mut sink);
        let feeds: Vec<[f64; 3]> = sink
            .moves
            .iter()
            .filter_map(|m| match m {
                Move::Line(p) => Some(*p),
                _ => None,
            })
            .collect();
        // Layer 1: plunge, pass up, step, pass down, ...
        assert_eq!(feeds[1][1], 131.0);
        assert_eq!(feeds[3][1], -11.0);
        assert!(matches!(sink.moves.last(), Some(Move::Rapid(p)) if p[2] == 30.0));
    }
}
