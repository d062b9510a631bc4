//! Readable text for operations and points, as comparison reports say
//! them: `line to X75 Y15 Z-2`, `hole at X10 Y10 to Z-10`.

use super::ops::{Op, OpKind};
use crate::toolpath::P3;

/// A number with at most four decimals, trailing zeros dropped.
pub fn num(v: f64) -> String {
    crate::ir::num::short_text(v, 4)
}

/// `X.. Y.. Z..`
pub fn point(p: P3) -> String {
    format!("X{} Y{} Z{}", num(p[0]), num(p[1]), num(p[2]))
}

/// What an operation does, in a few words.
pub fn op(o: &Op) -> String {
    match &o.kind {
        OpKind::Line { to } => format!("line to {}", point(*to)),
        OpKind::Arc {
            to,
            centre,
            axes,
            rotation,
        } => {
            let names = ["X", "Y", "Z"];
            let (u, v) = (axes[0] as usize % 3, axes[1] as usize % 3);
            let turns = rotation.unsigned_abs();
            let extra = if turns > 1 {
                format!(", {turns} turns")
            } else {
                String::new()
            };
            format!(
                "{} arc to {} about {}{} {}{}{extra}",
                if *rotation > 0 { "ccw" } else { "cw" },
                point(*to),
                names[u],
                num(centre[0]),
                names[v],
                num(centre[1]),
            )
        }
        OpKind::Plunge { at, .. } => {
            format!("hole at X{} Y{} to Z{}", num(at[0]), num(at[1]), num(at[2]))
        }
        OpKind::Probe { to } => format!("probe to {}", point(*to)),
        OpKind::Tool(t) => format!("tool change to T{t}"),
    }
}

/// The point an operation ends at (a plunge's bottom); none for a tool change.
pub fn end_of(o: &Op) -> Option<P3> {
    match &o.kind {
        OpKind::Line { to } | OpKind::Arc { to, .. } | OpKind::Probe { to } => Some(*to),
        OpKind::Plunge { at, .. } => Some(*at),
        OpKind::Tool(_) => None,
    }
}

/// Feed in words: `F300 mm/min` (with the per-revolution form when so).
pub fn feed(o: &Op) -> String {
    match o.feed_mode {
        crate::toolpath::FeedMode::PerMinute => format!("F{} mm/min", num(o.feed)),
        crate::toolpath::FeedMode::PerRev => {
            format!(
                "F{} mm/min (per revolution at S{})",
                num(o.feed),
                num(o.spindle.abs())
            )
        }
    }
}
