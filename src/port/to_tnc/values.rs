//! The Q values of the Heidenhain cycle a word-address canned cycle
//! becomes (see [`super`] for the mapping and its reasons): which cycle
//! kind of the target's table, its name, and the values by Q number.

use crate::ir::CycleKind;

/// The levels and feed every mapped cycle shares.
pub(super) struct Levels {
    /// The R plane (Q203 surface).
    pub r: f64,
    /// The bottom Z.
    pub z: f64,
    /// The level the cycle retracts to (G98 initial level or R).
    pub rtp: f64,
    /// The feed in force.
    pub feed: f64,
}

/// The cycle kind in the target's table and the name written after the
/// number, or None when `kind` has no mapping.
pub(super) fn target(kind: CycleKind) -> Option<(&'static str, &'static str)> {
    Some(match kind {
        CycleKind::Drill | CycleKind::DrillDwell => ("drill", "DRILLING"),
        CycleKind::Peck | CycleKind::ChipBreak => ("peck", "UNIVERSAL DRILLING"),
        CycleKind::Tap | CycleKind::TapLeft => ("tap", "TAPPING NEW"),
        CycleKind::BoreFeedOut | CycleKind::BoreDwellFeedOut => ("bore-feed-out", "REAMING"),
        CycleKind::BoreStopRapidOut => ("fine-bore", "BORING"),
        CycleKind::BackBore | CycleKind::BoreManual | CycleKind::FineBore => return None,
    })
}

/// The values shared by the drilling, tapping and boring cycles.
pub(super) fn common(l: &Levels) -> Vec<(&'static str, f64)> {
    vec![
        ("Q200", 0.0),
        ("Q201", l.z - l.r),
        ("Q206", l.feed),
        ("Q210", 0.0),
        ("Q203", l.r),
        ("Q204", l.rtp - l.r),
        ("Q211", 0.0),
    ]
}

/// Sets (or adds) `q` to `v`.
pub(super) fn set(vals: &mut Vec<(&'static str, f64)>, q: &'static str, v: f64) {
    match vals.iter_mut().find(|(n, _)| *n == q) {
        Some(slot) => slot.1 = v,
        None => vals.push((q, v)),
    }
}

/// The label after a Q value: the shared table's, or the few this
/// mapping adds.
pub(super) fn label(q: &str) -> &'static str {
    match super::label(q) {
        "" => match q {
            "Q239" => "THREAD PITCH",
            "Q214" => "DISENGAGING DIRECTN",
            "Q336" => "ANGLE OF SPINDLE",
            _ => "",
        },
        l => l,
    }
}
