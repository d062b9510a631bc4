//! Small builders of model values: points, placements, planes, toleranced
//! lengths, technology and machine functions from moves.
//!
//! A part program gives no tolerances, so every toleranced length is
//! written with a ±0 plus-minus value (3 significant digits): the size is
//! the size the program cuts, nothing more is claimed.

use crate::stepnc::model::*;
use crate::toolpath::{FeedMode, Move};

/// Rounds to 1e-6 mm, so float noise from arcs and offsets does not show.
pub fn r6(x: f64) -> f64 {
    let v = (x * 1e6).round() / 1e6;
    if v == 0.0 {
        0.0
    } else {
        v
    }
}

pub fn point(name: &str, xyz: P3) -> Point {
    Point {
        name: name.to_string(),
        xyz: [r6(xyz[0]), r6(xyz[1]), r6(xyz[2])],
    }
}

pub fn direction(name: &str, ratios: P3) -> Direction {
    Direction {
        name: name.to_string(),
        ratios: [r6(ratios[0]), r6(ratios[1]), r6(ratios[2])],
    }
}

/// A placement at `at` with +Z axis and local X along `x_dir`.
pub fn placement(name: &str, at: P3, x_dir: [f64; 2]) -> Axis2Placement {
    Axis2Placement {
        name: name.to_string(),
        location: point(name, at),
        axis: Some(direction("AXIS", [0.0, 0.0, 1.0])),
        ref_direction: Some(direction("REF_DIRECTION", [x_dir[0], x_dir[1], 0.0])),
    }
}

/// A horizontal plane through `at`.
pub fn plane(name: &str, at: P3) -> Plane {
    Plane {
        name: name.to_string(),
        position: placement(name, at, [1.0, 0.0]),
    }
}

pub fn tol(v: f64) -> Toleranced {
    Toleranced {
        nominal: r6(v),
        tolerance: Tolerance::PlusMinus {
            upper: 0.0,
            lower: 0.0,
            significant_digits: 3,
        },
    }
}

/// A move's feed in mm/min (a feed per revolution times the spindle
/// speed).
pub fn feed_per_minute(m: &Move) -> f64 {
    match m.feed_mode {
        FeedMode::PerMinute => m.feed,
        FeedMode::PerRev => m.feed * m.spindle.abs(),
    }
}

/// Feed and spindle of an operation, from its cutting moves: the feed is
/// the highest feed among them (plunges are often slower), in mm/min, the
/// spindle that of the first.
pub fn technology(cuts: &[&Move]) -> Technology {
    Technology {
        feed: cuts
            .iter()
            .map(|m| feed_per_minute(m))
            .reduce(f64::max)
            .map(r6),
        feed_at_tcp: true,
        spindle: cuts.first().map(|m| r6(m.spindle)),
        ..Technology::default()
    }
}

/// Coolant on when any cutting move has it.
pub fn machine_functions(cuts: &[&Move]) -> MachineFunctions {
    let flood = cuts.iter().any(|m| m.coolant.flood);
    let mist = cuts.iter().any(|m| m.coolant.mist);
    MachineFunctions {
        coolant: flood || mist,
        mist: mist.then_some(true),
        ..MachineFunctions::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::raise::cc2::segment::tests::mv;
    use crate::toolpath::MoveKind;

    #[test]
    fn feed_per_revolution_becomes_per_minute() {
        let mut m = mv(MoveKind::Line, [0.0; 3], [1.0, 0.0, 0.0], 1);
        m.feed_mode = FeedMode::PerRev;
        m.feed = 0.1;
        m.spindle = -2000.0;
        let t = technology(&[&m]);
        assert_eq!((t.feed, t.spindle), (Some(200.0), Some(-2000.0)));
    }
}

/// A milling operation on cut `m`, with the fields every milled feature
/// fills the same way: the retract plane from the cut's moves above
/// `top`, the tool, and the technology and machine functions of its
/// cutting moves. `kind` says the rest.
pub fn milled_operation(
    r: &super::state::Raiser,
    m: &super::level::MillCut,
    id: String,
    top: f64,
    cuts: &[&Move],
    kind: OperationKind,
) -> Operation {
    Operation {
        id,
        toolpath: None,
        tool_direction: None,
        retract_plane: super::strategy::retract_plane(&m.moves, top),
        start_point: None,
        tool: (r.tool)(m.tool),
        technology: technology(cuts),
        machine_functions: machine_functions(cuts),
        overcut_length: None,
        kind,
    }
}
