//! Generated moves (faces, pockets, slots from [`super::paths`]) written
//! through the same rapid, line and arc templates as explicit toolpaths
//! ([`super::toolpaths::write`]), every cutting move at one feed.

use super::paths::Move;
use super::toolpaths::PathMove;
use super::{PostError, Writer};

pub fn write(w: &mut Writer<'_>, moves: &[Move], feed: f64) -> Result<(), PostError> {
    let path: Vec<PathMove> = moves
        .iter()
        .map(|m| match m {
            Move::Rapid(p) => PathMove::Straight { to: *p, feed: None },
            Move::Line(p) => PathMove::Straight {
                to: *p,
                feed: Some(feed),
            },
            Move::Arc { to, centre, ccw } => PathMove::Arc {
                to: *to,
                centre: *centre,
                ccw: *ccw,
                feed,
            },
        })
        .collect();
    // Where the tool is before the first move is not known here: the first
    // move is always written (an arc first is taken to start at its end).
    let start = match moves.first() {
        Some(Move::Arc { to, .. }) => *to,
        _ => [f64::NAN; 3],
    };
    super::toolpaths::write(w, &path, start).map(|_| ())
}
