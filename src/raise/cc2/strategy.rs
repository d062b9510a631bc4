//! Milling strategies and approaches read from the moves: parallel
//! strokes (bidirectional or unidirectional), contour-parallel loops,
//! a spiral, a contour with strokes inside; climb or conventional from
//! the loop's direction and the spindle's; the approach from the first
//! feed move (plunge along the axis, ramp, helix).

use super::build::{direction, r6};
use super::level::{horizontal, split, Level};
use super::shape::{is_ccw, loop_shape, vertices};
use crate::stepnc::model::{
    ApproachRetract, CutMode, LeftOrRight, RotDirection, Strategy, StrategyBase,
};
use crate::toolpath::{Move, MoveKind};

/// The long straight moves of a level (at least half the longest line).
pub fn strokes(moves: &[Move]) -> Vec<&Move> {
    let lines = || moves.iter().filter(|m| matches!(m.kind, MoveKind::Line));
    let longest = lines().map(|m| m.length()).fold(0.0, f64::max);
    lines().filter(|m| m.length() >= 0.5 * longest).collect()
}

/// The long straight moves along the longest one's direction (a
/// zig-zag's strokes among its links and lead moves).
pub fn strokes_along(moves: &[Move]) -> Vec<&Move> {
    let all = strokes(moves);
    let Some(longest) = all
        .iter()
        .copied()
        .max_by(|a, b| a.length().total_cmp(&b.length()))
    else {
        return all;
    };
    all.into_iter()
        .filter(|m| parallel(&[longest, m]))
        .collect()
}

pub fn unit(m: &Move) -> [f64; 2] {
    let (dx, dy) = (m.to[0] - m.from[0], m.to[1] - m.from[1]);
    let l = dx.hypot(dy).max(1e-12);
    [dx / l, dy / l]
}

/// Are all strokes parallel (either way)?
pub fn parallel(strokes: &[&Move]) -> bool {
    let Some(first) = strokes.first() else {
        return false;
    };
    let d = unit(first);
    strokes.iter().all(|m| {
        let e = unit(m);
        (d[0] * e[1] - d[1] * e[0]).abs() < 1e-3
    })
}

/// Zig-zag or one-way strokes, with the stepover's side and the overlap.
pub fn stroke_strategy(strokes: &[&Move], radius: f64) -> Strategy {
    let d = unit(strokes[0]);
    let feed_direction = Some(direction("FEED DIRECTION", [d[0], d[1], 0.0]));
    let (side, overlap) = match strokes.get(1) {
        Some(next) => {
            let s = [
                next.from[0] - strokes[0].from[0],
                next.from[1] - strokes[0].from[1],
            ];
            let across = d[0] * s[1] - d[1] * s[0];
            let side = if across > 0.0 {
                LeftOrRight::Left
            } else {
                LeftOrRight::Right
            };
            let ov = (2.0 * radius - across.abs()) / (2.0 * radius);
            (Some(side), (ov > 0.0 && ov < 1.0).then(|| r6(ov)))
        }
        None => (None, None),
    };
    let base = StrategyBase {
        overlap,
        allow_multiple_passes: None,
    };
    let zigzag = strokes.windows(2).any(|w| {
        let (a, b) = (unit(w[0]), unit(w[1]));
        a[0] * b[0] + a[1] * b[1] < 0.0
    });
    if zigzag {
        Strategy::Bidirectional {
            base,
            feed_direction,
            stepover_direction: side,
            stroke_connection: None,
        }
    } else {
        Strategy::Unidirectional {
            base,
            feed_direction,
            cutmode: None,
        }
    }
}

/// Climb or conventional for a loop with the material outside it
/// (`walls_outside`, a pocket) or inside it (an outside profile): with
/// the spindle turning clockwise (M3), climb milling keeps the material
/// on the tool's right.
pub fn cutmode(ccw: bool, spindle: f64, walls_outside: bool) -> CutMode {
    let material_right = ccw == walls_outside;
    if material_right == (spindle >= 0.0) {
        CutMode::Climb
    } else {
        CutMode::Conventional
    }
}

fn rot(ccw: bool) -> RotDirection {
    if ccw {
        RotDirection::Ccw
    } else {
        RotDirection::Cw
    }
}

/// The strategy of a pocket's level.
pub fn pocket_strategy(level: &Level, spindle: f64, radius: f64) -> Strategy {
    let s = split(&level.moves);
    let long = strokes_along(&s.others);
    let base = StrategyBase::default();
    let Some(outer) = s.loops.iter().max_by(|a, b| area(a).total_cmp(&area(b))) else {
        if long.len() >= 2 && parallel(&long) {
            return stroke_strategy(&long, radius);
        }
        let ccw = winding(&level.moves) > 0.0;
        return Strategy::ContourSpiral {
            base,
            rotation: Some(rot(ccw)),
            cutmode: Some(cutmode(ccw, spindle, true)),
        };
    };
    let ccw = is_ccw(outer);
    let mode = Some(cutmode(ccw, spindle, true));
    let spiral = s.others.len() > 1 && winding(&s.others).abs() >= std::f64::consts::TAU - 1e-3;
    if spiral && long.is_empty() {
        return Strategy::ContourSpiral {
            base,
            rotation: Some(rot(ccw)),
            cutmode: mode,
        };
    }
    if long.len() >= 2 && parallel(&long) {
        let pos = |m: &Move| level.moves.iter().position(|x| x == m).unwrap_or(0);
        let Strategy::Bidirectional {
            feed_direction,
            stepover_direction,
            ..
        } = stroke_strategy(&long, radius)
        else {
            return Strategy::ContourParallel {
                base,
                rotation: Some(rot(ccw)),
                cutmode: mode,
            };
        };
        return Strategy::BidirectionalContour {
            contour_first: pos(&outer[0]) < pos(long[0]),
            base,
            feed_direction,
            stepover_direction,
            rotation: Some(rot(ccw)),
            cutmode: mode,
        };
    }
    Strategy::ContourParallel {
        base,
        rotation: Some(rot(ccw)),
        cutmode: mode,
    }
}

fn area(lp: &[Move]) -> f64 {
    let b = super::level::bbox(lp);
    (b[2] - b[0]) * (b[3] - b[1])
}

/// The total angle (radians) the path turns about its box centre.
pub fn winding(moves: &[Move]) -> f64 {
    let b = super::level::bbox(moves);
    let c = [(b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0];
    let v = vertices(moves);
    let ang = |p: [f64; 2]| (p[1] - c[1]).atan2(p[0] - c[0]);
    v.windows(2)
        .map(|w| {
            let mut d = ang(w[1]) - ang(w[0]);
            while d > std::f64::consts::PI {
                d -= std::f64::consts::TAU;
            }
            while d < -std::f64::consts::PI {
                d += std::f64::consts::TAU;
            }
            d
        })
        .sum()
}

/// The stepover between the two outermost concentric loops, if the level
/// has them.
pub fn loop_stepover(level: &Level) -> Option<f64> {
    let mut loops = split(&level.moves).loops;
    loops.sort_by(|a, b| area(b).total_cmp(&area(a)));
    let (outer, inner) = (loops.first()?, loops.get(1)?);
    loop_shape(inner).even_growth_to(&loop_shape(outer)).map(r6)
}

/// The retract plane: where the first feed move starts, above `top`
/// (the feature's placement).
pub fn retract_plane(moves: &[Move], top: f64) -> Option<f64> {
    moves
        .iter()
        .find(|m| m.is_feed())
        .map(|m| r6(m.from[2] - top))
}

/// The stepover between a level's first two strokes, if it has them.
pub fn stroke_stepover(level: &Level) -> Option<f64> {
    let others = split(&level.moves).others;
    let st = strokes_along(&others);
    let (a, b) = (st.first()?, st.get(1)?);
    let d = unit(a);
    let across = (b.from[0] - a.from[0]) * d[1] - (b.from[1] - a.from[1]) * d[0];
    (across.abs() > 1e-6).then(|| r6(across.abs()))
}

/// How the tool first enters the material: the first feed move that is
/// not horizontal, if it comes before the first horizontal cut.
pub fn approach(moves: &[Move]) -> Option<ApproachRetract> {
    let first = moves.iter().find(|m| m.is_feed())?;
    if horizontal(first) || first.to[2] >= first.from[2] {
        return None;
    }
    let dz = first.from[2] - first.to[2];
    let dxy = (first.to[0] - first.from[0]).hypot(first.to[1] - first.from[1]);
    Some(match &first.kind {
        MoveKind::Arc(a) if a.axes == [0, 1, 2] => {
            let len = a.radius(first.from) * a.sweep(first.from, first.to).abs();
            ApproachRetract::PlungeHelix {
                orientation: None,
                radius: r6(a.radius(first.from)),
                angle: r6(dz.atan2(len).to_degrees()),
            }
        }
        _ if dxy > 1e-4 => ApproachRetract::PlungeRamp {
            orientation: None,
            angle: r6(dz.atan2(dxy).to_degrees()),
        },
        _ => ApproachRetract::PlungeToolaxis { orientation: None },
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cutmode_follows_direction_side_and_spindle() {
        assert_eq!(cutmode(true, 3000.0, true), CutMode::Climb);
        assert_eq!(cutmode(false, 3000.0, true), CutMode::Conventional);
        assert_eq!(cutmode(true, -3000.0, true), CutMode::Conventional);
        assert_eq!(cutmode(false, 3000.0, false), CutMode::Climb);
    }
}
