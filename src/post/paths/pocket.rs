//! A closed pocket, rectangular (with corner radius) or circular, cleared
//! contour-parallel from the inside out: per layer, a pass along the
//! centre line, then offset loops of the boundary growing outwards by the
//! stepover up to the finishing offset (tool radius + side allowance).
//! A layer that an earlier roughing operation already cleared gets only
//! its wall pass (the finishing pass); the bottom layer of a finishing
//! operation is cleared whole (the floor).

use super::{reversed, MoveSink, Seg, P2};

/// The pocket in its own plane: centred at the origin, length along x.
#[derive(Clone, Copy, Debug)]
pub struct RectPocket {
    pub length: f64,
    pub width: f64,
    pub corner_radius: f64,
}

/// A pocket's outline, centred at the origin of its plane.
#[derive(Clone, Copy, Debug)]
pub enum Shape {
    Rect(RectPocket),
    Circle { diameter: f64 },
}

impl Shape {
    /// Half the smaller size: the offset at which nothing is left.
    fn half(&self) -> f64 {
        match self {
            Shape::Rect(p) => p.width.min(p.length) / 2.0,
            Shape::Circle { diameter } => diameter / 2.0,
        }
    }

    /// The ends of the centre line, along the longer side (one point for
    /// a circle or a square): what is left once every loop is cut.
    fn centre_line(&self) -> (P2, P2) {
        match self {
            Shape::Rect(p) => {
                let along_x = (p.length / 2.0 - self.half()).max(0.0);
                let along_y = (p.width / 2.0 - self.half()).max(0.0);
                if along_x >= along_y {
                    ([-along_x, 0.0], [along_x, 0.0])
                } else {
                    ([0.0, -along_y], [0.0, along_y])
                }
            }
            Shape::Circle { .. } => ([0.0, 0.0], [0.0, 0.0]),
        }
    }

    fn offset_loop(&self, d: f64) -> Vec<Seg> {
        match self {
            Shape::Rect(p) => offset_loop(p, d),
            Shape::Circle { diameter } => circle_loop(diameter / 2.0 - d),
        }
    }
}

/// A full circle of radius `r` about the origin from `(r, 0)`, as two
/// half arcs, counter-clockwise.
pub fn circle_loop(r: f64) -> Vec<Seg> {
    vec![
        Seg {
            from: [r, 0.0],
            to: [-r, 0.0],
            arc: Some(([0.0, 0.0], true)),
        },
        Seg {
            from: [-r, 0.0],
            to: [r, 0.0],
            arc: Some(([0.0, 0.0], true)),
        },
    ]
}

/// How the pocket is cut.
#[derive(Clone, Debug)]
pub struct PocketCut {
    pub tool_radius: f64,
    pub stepover: f64,
    pub allowance_side: f64,
    /// Layer depths (absolute z), top to bottom.
    pub levels: Vec<f64>,
    /// Only the last layer is cleared; the others get their wall pass.
    pub walls_only_above_bottom: bool,
    /// Loops run counter-clockwise (seen from above).
    pub ccw: bool,
    /// Absolute z of the clearance plane and the R plane.
    pub clear: f64,
    pub r_plane: f64,
}

/// Why a pocket cannot be cut as asked.
pub fn check(shape: &Shape, c: &PocketCut) -> Result<(), String> {
    let d = c.tool_radius + c.allowance_side;
    if d > shape.half() + 1e-9 {
        return Err(format!(
            "the tool (radius {}) with side allowance {} does not fit the pocket (half width {})",
            c.tool_radius,
            c.allowance_side,
            shape.half()
        ));
    }
    let Shape::Rect(p) = shape else {
        return check_stepover(c);
    };
    if c.tool_radius > p.corner_radius + 1e-9 && p.corner_radius > 0.0 {
        return Err(format!(
            "the tool radius {} is larger than the pocket's corner radius {}",
            c.tool_radius, p.corner_radius
        ));
    }
    check_stepover(c)
}

fn check_stepover(c: &PocketCut) -> Result<(), String> {
    if c.stepover <= 1e-9 || c.stepover > 2.0 * c.tool_radius + 1e-9 {
        return Err(format!(
            "the stepover {} must be more than 0 and at most the tool diameter {}",
            c.stepover,
            2.0 * c.tool_radius
        ));
    }
    Ok(())
}

/// The tool-centre loop at `d` inside the boundary, starting and ending
/// on the +x axis, counter-clockwise.
pub fn offset_loop(p: &RectPocket, d: f64) -> Vec<Seg> {
    let (a, b) = (p.length / 2.0 - d, p.width / 2.0 - d);
    let r = (p.corner_radius - d).max(0.0).min(a).min(b);
    let mut segs = Vec::new();
    let mut cur: P2 = [a, 0.0];
    let corners = [
        ([a, b], [a - r, b - r], [a, b - r], [a - r, b]),
        ([-a, b], [-a + r, b - r], [-a + r, b], [-a, b - r]),
        ([-a, -b], [-a + r, -b + r], [-a, -b + r], [-a + r, -b]),
        ([a, -b], [a - r, -b + r], [a - r, -b], [a, -b + r]),
    ];
    for (corner, centre, enter, leave) in corners {
        if r > 1e-9 {
            push_line(&mut segs, &mut cur, enter);
            segs.push(Seg {
                from: cur,
                to: leave,
                arc: Some((centre, true)),
            });
            cur = leave;
        } else {
            push_line(&mut segs, &mut cur, corner);
        }
    }
    push_line(&mut segs, &mut cur, [a, 0.0]);
    segs
}

fn push_line(segs: &mut Vec<Seg>, cur: &mut P2, to: P2) {
    if (to[0] - cur[0]).abs() > 1e-9 || (to[1] - cur[1]).abs() > 1e-9 {
        segs.push(Seg {
            from: *cur,
            to,
            arc: None,
        });
        *cur = to;
    }
}

/// Between loops with sharp corners the tool must reach the corner of
/// the outer loop's inside from the inner loop's corner, a diagonal
/// `step * sqrt 2` away: no island is left while `step <= r (1 + 1/sqrt 2)`.
const SHARP_STEP: f64 = 1.0 + std::f64::consts::FRAC_1_SQRT_2;

/// The stepover from the loop at offset `d` to the next one inwards: the
/// strategy's, or less where the next loop's corners are sharp.
fn step_after(shape: &Shape, c: &PocketCut, d: f64) -> f64 {
    match shape {
        Shape::Rect(p) if p.corner_radius - (d + c.stepover) <= 1e-9 => {
            c.stepover.min(SHARP_STEP * c.tool_radius)
        }
        Shape::Rect(_) | Shape::Circle { .. } => c.stepover,
    }
}

/// The offsets of the loops of a cleared layer, innermost first.
pub fn loop_offsets(shape: &Shape, c: &PocketCut) -> Vec<f64> {
    let half = shape.half();
    let last = c.tool_radius + c.allowance_side;
    let mut out = Vec::new();
    let mut d = last;
    while d < half - 1e-9 {
        out.push(d);
        d += step_after(shape, c, d);
    }
    out.reverse();
    out
}

/// All the moves, from above the pocket back to the clearance plane.
pub fn moves(shape: &Shape, c: &PocketCut, sink: &mut MoveSink<'_>) {
    let (start, centre_end) = shape.centre_line();
    let centre_line = start != centre_end;
    let offsets = loop_offsets(shape, c);
    let last = c.tool_radius + c.allowance_side;
    sink.rapid(start, c.clear);
    for (i, &z) in c.levels.iter().enumerate() {
        let bottom = i + 1 == c.levels.len();
        sink.rapid(start, c.r_plane);
        sink.line(start, z);
        let loops: Vec<f64> = if c.walls_only_above_bottom && !bottom {
            vec![last]
        } else {
            if centre_line {
                sink.line(centre_end, z);
            }
            offsets.clone()
        };
        for d in loops {
            let mut l = shape.offset_loop(d);
            if !c.ccw {
                l = reversed(&l);
            }
            sink.line(l[0].from, z);
            for s in &l {
                sink.seg(s, z);
            }
        }
        sink.rapid(sink.last_xy(), c.r_plane);
    }
    sink.rapid(sink.last_xy(), c.clear);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::post::frame::Frame;
    use crate::post::paths::Move;

    fn rect() -> RectPocket {
        RectPocket {
            length: 80.0,
            width: 50.0,
            corner_radius: 10.0,
        }
    }

    fn ex1() -> Shape {
        Shape::Rect(rect())
    }

    fn cut(allow: f64, step: f64) -> PocketCut {
        PocketCut {
            tool_radius: 9.0,
            stepover: step,
            allowance_side: allow,
            levels: vec![-15.0, -30.0],
            walls_only_above_bottom: false,
            ccw: true,
            clear: 30.0,
            r_plane: 15.0,
        }
    }

    #[test]
    fn the_last_loop_leaves_the_allowance_at_the_wall() {
        let l = offset_loop(&rect(), 10.0);
        // Corner radius 10 - 10 = 0: a sharp rectangle 60 x 30 about the centre.
        let xs: Vec<f64> = l.iter().map(|s| s.to[0]).collect();
        let max = xs.iter().cloned().fold(f64::MIN, f64::max);
        assert!((max - 30.0).abs() < 1e-9);
        assert!(l.iter().all(|s| s.arc.is_none()));
        assert_eq!(l.last().unwrap().to, [30.0, 0.0]);
        // At offset 9 (the finishing pass) the corners are arcs of radius 1.
        let f = offset_loop(&rect(), 9.0);
        let arcs: Vec<_> = f.iter().filter_map(|s| s.arc).collect();
        assert_eq!(arcs.len(), 4);
        assert_eq!(arcs[0].0, [30.0, 15.0]);
        assert!(arcs.iter().all(|a| a.1));
    }

    #[test]
    fn loops_grow_from_the_inside_by_at_most_the_stepover() {
        let o = loop_offsets(&ex1(), &cut(1.0, 5.0));
        assert_eq!(o, vec![20.0, 15.0, 10.0]);
        // The centre line (offset 25) to the innermost loop: 5 <= stepover.
        assert!(25.0 - o[0] <= 5.0 + 1e-9);
    }

    #[test]
    fn a_tool_too_big_for_the_corner_is_an_error() {
        let mut c = cut(0.0, 5.0);
        c.tool_radius = 12.0;
        assert!(check(&ex1(), &c).unwrap_err().contains("corner radius"));
        assert!(check(&ex1(), &cut(1.0, 5.0)).is_ok());
    }

    #[test]
    fn moves_stay_inside_the_pocket_and_reach_the_bottom() {
        let frame = Frame::identity();
        let mut sink = MoveSink::new(&frame);
        moves(&ex1(), &cut(0.0, 5.0), &mut sink);
        let mut lowest = f64::MAX;
        for m in &sink.moves {
            let p = match m {
                Move::Rapid(p) | Move::Line(p) => *p,
                Move::Arc { to, .. } => *to,
            };
            lowest = lowest.min(p[2]);
            assert!(
                p[0].abs() <= 31.0 + 1e-9 && p[1].abs() <= 16.0 + 1e-9,
                "{p:?}"
            );
        }
        assert_eq!(lowest, -30.0);
        assert!(matches!(sink.moves.last(), Some(Move::Rapid(p)) if p[2] == 30.0));
    }

    #[test]
    fn a_circular_pocket_is_cleared_in_rings_from_the_centre() {
        let shape = Shape::Circle { diameter: 60.0 };
        let c = cut(0.5, 8.0);
        assert_eq!(loop_offsets(&shape, &c), vec![25.5, 17.5, 9.5]);
        let frame = Frame::identity();
        let mut sink = MoveSink::new(&frame);
        moves(&shape, &c, &mut sink);
        let arcs = sink
            .moves
            .iter()
            .filter(|m| matches!(m, Move::Arc { .. }))
            .count();
        assert_eq!(arcs, 2 * 3 * 2); // two halves, three rings, two layers
        for m in &sink.moves {
            let p = match m {
                Move::Rapid(p) | Move::Line(p) => *p,
                Move::Arc { to, .. } => *to,
            };
            assert!((p[0] * p[0] + p[1] * p[1]).sqrt() <= 20.5 + 1e-9, "{p:?}");
        }
        assert!(check(&Shape::Circle { diameter: 17.0 }, &c).is_err());
    }

    /// The floor a rectangular or circular pocket path leaves: islands
    /// wider than `tol` (mm) where the tool could reach.
    fn floor_islands(shape: &Shape, r: f64, step: f64) -> Vec<super::super::coverage::Island> {
        use super::super::coverage::{in_rounded_rect, islands, Floor};
        let c = PocketCut {
            tool_radius: r,
            stepover: step,
            allowance_side: 0.0,
            levels: vec![-5.0],
            walls_only_above_bottom: false,
            ccw: true,
            clear: 10.0,
            r_plane: 2.0,
        };
        let frame = Frame::identity();
        let mut sink = MoveSink::new(&frame);
        moves(shape, &c, &mut sink);
        let (a, b, rho) = match shape {
            Shape::Rect(p) => (p.length / 2.0, p.width / 2.0, p.corner_radius),
            Shape::Circle { diameter } => (diameter / 2.0, diameter / 2.0, diameter / 2.0),
        };
        let floor = Floor {
            lo: [-a, -b],
            hi: [a, b],
            cell: 0.05,
        };
        // Reachable: within r of the region the tool centre may visit.
        let reach = |p: P2| in_rounded_rect(p, a - r, b - r, (rho - r).max(0.0), r);
        islands(&sink.moves, -5.0, r, &floor, reach)
    }

    #[test]
    fn pocket_paths_leave_no_rib_on_the_floor() {
        let tol = 0.1;
        let rect = |length, width, corner_radius| {
            Shape::Rect(RectPocket {
                length,
                width,
                corner_radius,
            })
        };
        let cases = [
            (rect(40.0, 50.0, 0.0), 3.0, 4.5),
            (rect(50.0, 40.0, 0.0), 3.0, 4.5),
            (rect(40.0, 50.0, 5.0), 3.0, 4.5),
            (rect(80.0, 50.0, 10.0), 9.0, 5.0),
            (rect(30.0, 30.0, 0.0), 3.0, 6.0),
            (rect(23.0, 61.0, 4.0), 4.0, 7.9),
            (Shape::Circle { diameter: 60.0 }, 9.0, 8.0),
            (Shape::Circle { diameter: 41.0 }, 3.0, 5.9),
        ];
        for (shape, r, step) in cases {
            let left: Vec<_> = floor_islands(&shape, r, step)
                .into_iter()
                .filter(|i| i.width() > tol)
                .collect();
            assert!(left.is_empty(), "{shape:?} r {r} step {step}: {left:?}");
        }
    }
}
