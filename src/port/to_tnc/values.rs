//! The Q values of the Heidenhain cycle a word-address canned cycle
//! becomes (see [`super`] for the mapping and its reasons): which cycle
//! kind of the target's table, its name, and the values by Q number.

use super::Pass;
use crate::diag::Code;
use crate::dialect::Meaning;
use crate::ir::{CycleKind, DwellUnit};
use crate::span::Span;

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
            "Q389" => "STRATEGY",
            "Q225" => "STARTNG PNT 1ST AXIS",
            "Q226" => "STARTNG PNT 2ND AXIS",
            "Q227" => "STARTNG PNT 3RD AXIS",
            "Q386" => "END POINT 3RD AXIS",
            "Q253" => "F PRE-POSITIONING",
            "Q357" => "CLEARANCE TO SIDE",
            _ => "",
        },
        l => l,
    }
}

impl Pass<'_> {
    /// The thread pitch of a tapping cycle: F under feed per revolution,
    /// F / S under feed per minute.
    pub(super) fn pitch(&mut self, feed: f64, span: Span) -> Option<f64> {
        if self.per_rev {
            return Some(feed.abs());
        }
        let s = self.num(self.modal.speed.clone().as_ref(), span, "spindle speed S")?;
        if s == 0.0 {
            self.refuse(Code::PortRunTimeValue, span, "tapping with spindle speed 0");
            return None;
        }
        Some((feed / s).abs())
    }

    /// Seconds per unit of the source's dwell word P.
    pub(super) fn dwell_scale(&self) -> f64 {
        let ms = self.from.code_for(Meaning::Dwell).is_some_and(|c| {
            c.dwell_units
                .iter()
                .any(|(l, u)| *l == 'P' && *u == DwellUnit::Milliseconds)
        });
        if ms {
            0.001
        } else {
            1.0
        }
    }
}
