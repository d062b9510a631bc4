//! A round hole milled with helical moves, for targets without a circular
//! pocket cycle: per layer, the tool descends on a helix (G2/G3 with Z,
//! each piece at most half a turn) about the hole's axis from the R plane
//! or the layer above, levels out with a full circle, then steps out to
//! rings of the stepover up to the wall circle (the finishing circle: the
//! hole's radius less the tool radius and the side allowance). The helix
//! radius is the innermost ring's, at most the tool radius, so that the
//! helix also clears the centre. A tool as wide as the hole plunges.

use super::pocket::{circle_loop, loop_offsets, PocketCut, Shape};
use super::{reversed, MoveSink, P2};

/// How the hole is cut: the pocket's parameters and the helix's pitch
/// (mm of descent per turn).
#[derive(Clone, Debug)]
pub struct HoleCut {
    pub cut: PocketCut,
    pub pitch: f64,
}

/// Radii (mm) below this are a plunge, not a helix.
const PLUNGE: f64 = 1e-3;

/// Why the hole cannot be cut as asked.
pub fn check(diameter: f64, c: &HoleCut) -> Result<(), String> {
    let p = &c.cut;
    let wall = diameter / 2.0 - p.tool_radius - p.allowance_side;
    if wall < -1e-9 {
        return Err(format!(
            "the tool (radius {}) with side allowance {} is wider than the hole (diameter {})",
            p.tool_radius, p.allowance_side, diameter
        ));
    }
    if wall > PLUNGE && (p.stepover <= 1e-9 || p.stepover > 2.0 * p.tool_radius + 1e-9) {
        return Err(format!(
            "the stepover {} must be more than 0 and at most the tool diameter {}",
            p.stepover,
            2.0 * p.tool_radius
        ));
    }
    if c.pitch <= 1e-6 {
        return Err(format!("the helix's pitch {} is not positive", c.pitch));
    }
    Ok(())
}

/// The tool-centre ring radii of a cleared layer, innermost first (the
/// last is the wall circle); empty when the tool is as wide as the hole.
pub fn rings(diameter: f64, c: &PocketCut) -> Vec<f64> {
    let wall = diameter / 2.0 - c.tool_radius - c.allowance_side;
    if wall <= PLUNGE {
        return Vec::new();
    }
    loop_offsets(&Shape::Circle { diameter }, c)
        .into_iter()
        .map(|d| diameter / 2.0 - d)
        .collect()
}

/// The helix radius: the innermost ring's, at most the tool radius.
pub fn helix_radius(diameter: f64, c: &PocketCut) -> f64 {
    rings(diameter, c)
        .first()
        .map_or(0.0, |r| r.min(c.tool_radius))
}

/// All the moves, from above the hole back to the clearance plane.
pub fn moves(diameter: f64, c: &HoleCut, sink: &mut MoveSink<'_>) {
    let p = &c.cut;
    let all = rings(diameter, p);
    let hr = helix_radius(diameter, p);
    let start: P2 = [hr, 0.0];
    sink.rapid(start, p.clear);
    sink.rapid(start, p.r_plane);
    let mut z0 = p.r_plane;
    for (i, &z) in p.levels.iter().enumerate() {
        let bottom = i + 1 == p.levels.len();
        if hr <= PLUNGE {
            sink.line(start, z);
        } else {
            descend(sink, hr, z0, z, c.pitch, p.ccw);
            circle(sink, hr, z, p.ccw);
        }
        let rings: Vec<f64> = if p.walls_only_above_bottom && !bottom {
            all.last().copied().into_iter().collect()
        } else {
            all.clone()
        };
        for r in rings.into_iter().filter(|r| *r > hr + 1e-9) {
            sink.line([r, 0.0], z);
            circle(sink, r, z, p.ccw);
        }
        sink.line(start, z);
        z0 = z;
    }
    sink.line([0.0, 0.0], z0);
    sink.rapid([0.0, 0.0], p.clear);
}

/// A helix of radius `r` from `(r, 0)` at `z0` down to `z1`, in whole
/// turns of at most `pitch`, each turn as two half-turn pieces.
fn descend(sink: &mut MoveSink<'_>, r: f64, z0: f64, z1: f64, pitch: f64, ccw: bool) {
    let depth = z0 - z1;
    if depth <= 1e-9 {
        return;
    }
    let turns = ((depth / pitch) - 1e-9).ceil().max(1.0) as usize;
    let halves = 2 * turns;
    let mut l = circle_loop(r);
    if !ccw {
        l = reversed(&l);
    }
    for k in 1..=halves {
        let z = z0 - depth * k as f64 / halves as f64;
        sink.seg(&l[(k - 1) % 2], z);
    }
}

/// A full circle of radius `r` from `(r, 0)` at height `z`.
fn circle(sink: &mut MoveSink<'_>, r: f64, z: f64, ccw: bool) {
    let mut l = circle_loop(r);
    if !ccw {
        l = reversed(&l);
    }
    for s in &l {
        sink.seg(s, z);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::post::frame::Frame;
    use crate::post::paths::coverage::{in_rounded_rect, islands, Floor};
    use crate::post::paths::Move;

    fn cut(r: f64, step: f64, levels: Vec<f64>) -> HoleCut {
        HoleCut {
            cut: PocketCut {
                tool_radius: r,
                stepover: step,
                allowance_side: 0.0,
                levels,
                walls_only_above_bottom: false,
                ccw: true,
                clear: 20.0,
                r_plane: 2.0,
            },
            pitch: 2.0,
        }
    }

    fn run(diameter: f64, c: &HoleCut) -> Vec<Move> {
        let frame = Frame::identity();
        let mut sink = MoveSink::new(&frame);
        moves(diameter, c, &mut sink);
        sink.moves
    }

    /// Islands wider than 0.1 mm left on the floor at `z`.
    fn left(diameter: f64, c: &HoleCut, z: f64) -> Vec<crate::post::paths::coverage::Island> {
        let m = run(diameter, c);
        let big = diameter / 2.0;
        let floor = Floor {
            lo: [-big, -big],
            hi: [big, big],
            cell: 0.05,
        };
        let r = c.cut.tool_radius;
        let a = big - r;
        let reach = |p: P2| in_rounded_rect(p, a, a, a, r);
        islands(&m, z, r, &floor, reach)
            .into_iter()
            .filter(|i| i.width() > 0.1)
            .collect()
    }

    #[test]
    fn a_small_hole_is_one_helix_and_a_circle() {
        // A 10 mm hole with a 6 mm tool: helix radius 2 (< tool radius).
        let c = cut(3.0, 4.5, vec![-18.25]);
        assert_eq!(rings(10.0, &c.cut), vec![2.0]);
        assert_eq!(helix_radius(10.0, &c.cut), 2.0);
        let m = run(10.0, &c);
        let arcs = m.iter().filter(|m| matches!(m, Move::Arc { .. })).count();
        // 20.25 mm at 2 mm a turn: 11 turns, 22 half-turn pieces; then
        // the circle at the bottom, two halves.
        assert_eq!(arcs, 24);
        assert!(left(10.0, &c, -18.25).is_empty());
    }

    #[test]
    fn helical_holes_leave_no_island_on_the_floor() {
        let cases = [
            (10.0, 3.0, 4.5),
            (39.0, 3.0, 4.5),
            (39.0, 3.0, 6.0),
            (22.0, 5.0, 7.0),
            (50.0, 4.0, 7.9),
            (13.0, 6.0, 12.0),
        ];
        for (d, r, step) in cases {
            let c = cut(r, step, vec![-3.0, -6.0]);
            assert!(check(d, &c).is_ok());
            assert!(left(d, &c, -3.0).is_empty(), "{d} {r} {step} at -3");
            assert!(left(d, &c, -6.0).is_empty(), "{d} {r} {step} at -6");
        }
    }

    #[test]
    fn moves_stay_in_the_hole_and_pieces_are_at_most_half_a_turn() {
        let c = cut(3.0, 4.5, vec![-6.0]);
        let m = run(39.0, &c);
        let mut at = [2.0, 0.0, 20.0];
        for mv in &m {
            let to = match mv {
                Move::Rapid(p) | Move::Line(p) => *p,
                Move::Arc { to, centre, .. } => {
                    assert_eq!(*centre, [0.0, 0.0]);
                    // Half a turn ends opposite its start.
                    let dot = at[0] * to[0] + at[1] * to[1];
                    assert!(dot <= 1e-9, "{at:?} -> {to:?}");
                    *to
                }
            };
            assert!((to[0].powi(2) + to[1].powi(2)).sqrt() <= 16.5 + 1e-9);
            at = to;
        }
        assert!(matches!(m.last(), Some(Move::Rapid(p)) if p[2] == 20.0));
    }

    #[test]
    fn a_tool_as_wide_as_the_hole_plunges_and_a_wider_one_is_refused() {
        let c = cut(5.0, 5.0, vec![-12.0]);
        assert!(check(10.0, &c).is_ok());
        let m = run(10.0, &c);
        assert!(!m.iter().any(|m| matches!(m, Move::Arc { .. })));
        assert!(check(9.0, &c).unwrap_err().contains("wider than the hole"));
    }
}
