//! Drilling cycles recognised from their motion pattern.
//!
//! Every move a canned cycle makes carries the span of the cycle's
//! statement (Fanuc `G81`..`G89` and each repeat position, Siemens
//! `CYCLE81`..`CYCLE89` and each `MCALL` position), so the moves of one
//! hole are a run of consecutive moves sharing one span; an ordinary
//! statement makes one move. This module reads such a run; it does not
//! look at the program's statements, so every dialect whose cycles the
//! interpreter runs is covered alike, and a cycle written out as plain
//! moves is not mistaken for one.
//!
//! The run: rapids positioning over the hole (kept apart, as a rapid
//! movement), then only vertical moves at the hole's X Y, starting with a
//! feed downwards. The R plane is where the first feed starts; the bottom
//! is the lowest point. The rule, after the pattern of the Fanuc/LinuxCNC
//! cycles:
//! - several feeds downwards (pecks, G83/G73/CYCLE83) → MULTISTEP_DRILLING;
//! - one feed down, then a feed out: with a dwell at the bottom (G89) →
//!   BORING with that dwell, without (G85) → REAMING;
//! - one feed down, the spindle stopped before a rapid out (G86) → BORING
//!   with `spindle_stop_at_bottom`;
//! - one feed down, rapid out (G81; G82 with its dwell) → DRILLING;
//! - one feed down, then a feed out with the spindle turning the other
//!   way (G84/G74, and the rigid taps CYCLE84 / CYCLE DEF 207 / G33.1,
//!   whose way out the toolpath gives reversed) → TAPPING; the spindle's
//!   direction on the way down gives the hand (M4: left hand);
//! - anything else (back boring G87, G88's stop) → not a hole:
//!   [`Pattern::Other`].

use crate::toolpath::{Move, MoveKind, P3};

/// One thing a cycle does: a move or a dwell (seconds).
#[derive(Clone, Debug)]
pub enum Item {
    Move(Move),
    Dwell(f64),
}

/// A recognised hole cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct HoleCycle {
    /// How many leading items position the tool (rapids) before the hole.
    pub lead: usize,
    /// The hole's axis.
    pub x: f64,
    pub y: f64,
    /// Where the first feed starts (the R plane).
    pub r_z: f64,
    /// The lowest point reached.
    pub bottom: f64,
    /// The feed downwards, mm/min as the move gives it.
    pub feed: f64,
    pub kind: HoleKind,
}

#[derive(Clone, Debug, PartialEq)]
pub enum HoleKind {
    Drilling {
        dwell: Option<f64>,
    },
    Multistep {
        /// Below where the first feed starts (the R plane).
        first_depth: f64,
        depth_of_step: f64,
        retract_distance: f64,
        dwell: Option<f64>,
    },
    Boring {
        reaming: bool,
        spindle_stop: bool,
        dwell: Option<f64>,
        /// The feed out as a ratio of the feed in.
        feed_on_retract: Option<f64>,
    },
    /// Fed in, spindle reversed, fed out.
    Tapping {
        /// The spindle turned counter-clockwise (M4) on the way in.
        left_hand: bool,
        dwell: Option<f64>,
    },
}

/// What a run of moves sharing one span is.
#[derive(Clone, Debug, PartialEq)]
pub enum Pattern {
    /// One ordinary statement's move(s).
    Plain,
    Hole(HoleCycle),
    /// A cycle-like vertical run that is none of the holes above.
    Other,
}

const EPS: f64 = 1e-6;

fn vertical_at(m: &Move, x: f64, y: f64) -> bool {
    let at = |p: P3| (p[0] - x).abs() < EPS && (p[1] - y).abs() < EPS;
    at(m.from) && at(m.to) && !matches!(m.kind, MoveKind::Arc(_) | MoveKind::Probe)
}

fn is_feed_down(m: &Move) -> bool {
    m.kind == MoveKind::Line && m.to[2] < m.from[2] - EPS
}

/// Reads a run of items sharing one span.
pub fn classify(items: &[Item]) -> Pattern {
    let moves = items.iter().filter(|i| matches!(i, Item::Move(_))).count();
    if moves < 2 {
        return Pattern::Plain;
    }
    let Some(k) = items
        .iter()
        .position(|i| matches!(i, Item::Move(m) if m.kind != MoveKind::Rapid))
    else {
        return Pattern::Plain;
    };
    let Item::Move(first) = &items[k] else {
        return Pattern::Plain;
    };
    let (x, y) = (first.from[0], first.from[1]);
    let lead_ok = items[..k].iter().all(|i| matches!(i, Item::Move(_)));
    let body_vertical = items[k..].iter().all(|i| match i {
        Item::Move(m) => vertical_at(m, x, y),
        Item::Dwell(_) => true,
    });
    if !is_feed_down(first) || !lead_ok || !body_vertical {
        return Pattern::Plain;
    }
    match hole_kind(&items[k..], first.spindle) {
        Some(kind) => Pattern::Hole(HoleCycle {
            lead: k,
            x,
            y,
            r_z: first.from[2],
            bottom: lowest(&items[k..]),
            feed: first.feed,
            kind,
        }),
        None => Pattern::Other,
    }
}

fn lowest(items: &[Item]) -> f64 {
    items
        .iter()
        .filter_map(|i| match i {
            Item::Move(m) => Some(m.to[2].min(m.from[2])),
            Item::Dwell(_) => None,
        })
        .fold(f64::INFINITY, f64::min)
}

/// The body of the cycle, from its first feed down.
fn hole_kind(body: &[Item], spindle: f64) -> Option<HoleKind> {
    let moves: Vec<&Move> = body
        .iter()
        .filter_map(|i| match i {
            Item::Move(m) => Some(m),
            Item::Dwell(_) => None,
        })
        .collect();
    let dwell = body.iter().find_map(|i| match i {
        Item::Dwell(s) if *s > 0.0 => Some(*s),
        _ => None,
    });
    if moves.iter().any(|m| m.spindle * spindle < 0.0) {
        return tapping(&moves, spindle, dwell);
    }
    let downs: Vec<&&Move> = moves.iter().filter(|m| is_feed_down(m)).collect();
    if downs.len() >= 2 {
        let first_bottom = downs[0].to[2];
        let top_after = moves
            .iter()
            .skip_while(|m| !std::ptr::eq(**m, *downs[0]))
            .take_while(|m| !std::ptr::eq(**m, *downs[1]))
            .map(|m| m.to[2])
            .fold(f64::NEG_INFINITY, f64::max);
        return Some(HoleKind::Multistep {
            first_depth: downs[0].from[2] - first_bottom,
            depth_of_step: first_bottom - downs[1].to[2],
            retract_distance: top_after - first_bottom,
            dwell,
        });
    }
    let out = moves.get(1)?;
    if out.to[2] <= out.from[2] + EPS {
        return None;
    }
    let stopped = out.spindle == 0.0;
    match out.kind {
        MoveKind::Line if !stopped => Some(HoleKind::Boring {
            reaming: dwell.is_none(),
            spindle_stop: false,
            dwell,
            feed_on_retract: (moves[0].feed > 0.0).then(|| out.feed / moves[0].feed),
        }),
        MoveKind::Rapid if stopped => Some(HoleKind::Boring {
            reaming: false,
            spindle_stop: true,
            dwell,
            feed_on_retract: None,
        }),
        MoveKind::Rapid => Some(HoleKind::Drilling { dwell }),
        MoveKind::Line | MoveKind::Arc(_) | MoveKind::Probe => None,
    }
}

/// One feed down, then the feed out with the spindle reversed (and
/// nothing else reversed after it).
fn tapping(moves: &[&Move], spindle: f64, dwell: Option<f64>) -> Option<HoleKind> {
    let out = moves.get(1)?;
    let out_reversed =
        out.kind == MoveKind::Line && out.to[2] > out.from[2] + EPS && out.spindle * spindle < 0.0;
    let downs = moves.iter().filter(|m| is_feed_down(m)).count();
    let later_reversed = moves[2..]
        .iter()
        .any(|m| m.is_feed() && m.spindle * spindle < 0.0);
    (out_reversed && downs == 1 && !later_reversed).then_some(HoleKind::Tapping {
        left_hand: spindle < 0.0,
        dwell,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::span::Span;
    use crate::toolpath::{CoolantState, FeedMode};

    fn mv(kind: MoveKind, from: P3, to: P3, spindle: f64) -> Item {
        Item::Move(Move {
            kind,
            from,
            to,
            feed: 100.0,
            feed_mode: FeedMode::PerMinute,
            tool: 2,
            spindle,
            coolant: CoolantState::default(),
            span: Span::default(),
        })
    }

    const R: MoveKind = MoveKind::Rapid;
    const L: MoveKind = MoveKind::Line;

    #[test]
    fn drilling_reaming_and_boring() {
        let lead = mv(R, [0.0, 0.0, 30.0], [5.0, 5.0, 30.0], 1000.0);
        let to_r = mv(R, [5.0, 5.0, 30.0], [5.0, 5.0, 2.0], 1000.0);
        let down = mv(L, [5.0, 5.0, 2.0], [5.0, 5.0, -10.0], 1000.0);
        let g81 = [
            lead.clone(),
            to_r.clone(),
            down.clone(),
            mv(R, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], 1000.0),
        ];
        let Pattern::Hole(h) = classify(&g81) else {
            panic!()
        };
        assert_eq!((h.lead, h.r_z, h.bottom), (2, 2.0, -10.0));
        assert_eq!(h.kind, HoleKind::Drilling { dwell: None });
        let g85 = [
            to_r.clone(),
            down.clone(),
            mv(L, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], 1000.0),
        ];
        let Pattern::Hole(h) = classify(&g85) else {
            panic!()
        };
        assert!(matches!(h.kind, HoleKind::Boring { reaming: true, .. }));
        let g86 = [
            down.clone(),
            Item::Dwell(0.0),
            mv(R, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], 0.0),
        ];
        let Pattern::Hole(h) = classify(&g86) else {
            panic!()
        };
        assert!(matches!(
            h.kind,
            HoleKind::Boring {
                spindle_stop: true,
                reaming: false,
                ..
            }
        ));
        let tap = [
            down.clone(),
            mv(L, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], -1000.0),
        ];
        let Pattern::Hole(h) = classify(&tap) else {
            panic!()
        };
        let right = HoleKind::Tapping {
            left_hand: false,
            dwell: None,
        };
        assert_eq!(h.kind, right);
        let g74 = [
            mv(L, [5.0, 5.0, 2.0], [5.0, 5.0, -10.0], -1000.0),
            mv(L, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], 1000.0),
        ];
        let Pattern::Hole(h) = classify(&g74) else {
            panic!()
        };
        assert!(matches!(
            h.kind,
            HoleKind::Tapping {
                left_hand: true,
                ..
            }
        ));
        // Reversed on a rapid out is no tapping.
        let odd = [
            mv(L, [5.0, 5.0, 2.0], [5.0, 5.0, -10.0], 1000.0),
            mv(R, [5.0, 5.0, -10.0], [5.0, 5.0, 2.0], -1000.0),
        ];
        assert_eq!(classify(&odd), Pattern::Other);
    }

    #[test]
    fn pecks_and_plain_moves() {
        let p = |a: f64, b: f64, k| mv(k, [1.0, 1.0, a], [1.0, 1.0, b], 500.0);
        let g83 = [
            p(2.0, -4.0, L),
            p(-4.0, 2.0, R),
            p(2.0, -3.5, R),
            p(-3.5, -10.0, L),
            p(-10.0, 2.0, R),
        ];
        let Pattern::Hole(h) = classify(&g83) else {
            panic!()
        };
        assert_eq!(
            h.kind,
            HoleKind::Multistep {
                first_depth: 6.0,
                depth_of_step: 6.0,
                retract_distance: 6.0,
                dwell: None
            }
        );
        let slot = [
            mv(L, [0.0; 3], [0.0, 0.0, -1.0], 1.0),
            mv(L, [0.0, 0.0, -1.0], [9.0, 0.0, -1.0], 1.0),
        ];
        assert_eq!(classify(&slot), Pattern::Plain);
        assert_eq!(classify(&slot[..1]), Pattern::Plain);
    }
}
