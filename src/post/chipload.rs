//! Feeds plausible for the tool: the chip load a workingstep's feed and
//! spindle speed imply (feed per revolution for drilling-type tools, per
//! tooth for cutters), warned about (W0901) when far above what such a
//! tool takes; and the cutting speed the spindle speed implies at the
//! tool's diameter (W0901 above [`MAX_CUTTING_SPEED`]). The limits are deliberately loose [?]: they catch unit
//! mistakes (a feed in mm/s read as m/s gives 60 times too much), not
//! tuning.

use super::plan::Step;
use super::step::{feed, spindle_rpm};
use crate::diag::{Code, Diagnostic};
use crate::stepnc::model::*;

/// Most feed per revolution for a drilling-type operation, as a share of
/// the tool diameter (handbooks give 0.01 to 0.05 D for twist drills) [?].
const DRILL_FEED_PER_REV: f64 = 0.1;
/// Most chip load per tooth for a cutter, as a share of its diameter, and
/// in mm whatever the size [?].
const TOOTH_SHARE: f64 = 0.1;
const TOOTH_MAX_MM: f64 = 1.0;

/// A warning when the step's feed implies an implausible chip load.
pub fn check(s: &Step<'_>) -> Option<Diagnostic> {
    let rpm = spindle_rpm(s).ok()?.abs();
    let f = feed(s).ok()?;
    let d = s.tool.body.dimension.diameter;
    if !(rpm > 0.0 && f > 0.0 && d > 0.0) {
        return None;
    }
    let per_rev = f / rpm;
    if matches!(
        s.op.kind,
        OperationKind::Tapping { .. } | OperationKind::ThreadDrilling { .. }
    ) {
        // The feed per revolution is the thread's pitch.
        return None;
    }
    let msg = if is_drilling(&s.op.kind) {
        (per_rev > DRILL_FEED_PER_REV * d).then(|| {
            format!(
                "`{}`: feed {} mm/min at {} rpm is {} mm per revolution for a {} mm tool",
                s.op.id,
                r3(f),
                r3(rpm),
                r3(per_rev),
                r3(d)
            )
        })
    } else {
        let teeth = s.tool.body.number_of_teeth.filter(|z| *z > 0).unwrap_or(1) as f64;
        let fz = per_rev / teeth;
        (fz > (TOOTH_SHARE * d).min(TOOTH_MAX_MM)).then(|| {
            format!(
                "`{}`: feed {} mm/min at {} rpm with {} teeth is a chip load of {} mm per tooth for a {} mm cutter",
                s.op.id,
                r3(f),
                r3(rpm),
                teeth,
                r3(fz),
                r3(d)
            )
        })
    }?;
    Some(
        Diagnostic::new(Code::ImplausibleFeed, msg).help(
            "ISO 14649 gives feeds in m/s and spindle speeds in rev/s; check the MILLING_TECHNOLOGY of the operation",
        ),
    )
}

/// Most cutting speed (m/min) the spindle speed may imply at the tool's
/// circumference [?]: above what carbide takes even in aluminium; a plan
/// that writes rpm where ISO 14649 wants rev/s gives 60 times more.
const MAX_CUTTING_SPEED: f64 = 3000.0;

/// A warning when the step's spindle speed implies an implausible
/// cutting speed for the tool's diameter.
pub fn check_speed(s: &Step<'_>) -> Option<Diagnostic> {
    let rpm = spindle_rpm(s).ok()?.abs();
    let d = s.tool.body.dimension.diameter;
    let vc = rpm * std::f64::consts::PI * d / 1000.0;
    (vc > MAX_CUTTING_SPEED).then(|| {
        Diagnostic::new(
            Code::ImplausibleFeed,
            format!(
                "`{}`: {} rpm on a {} mm tool is a cutting speed of {} m/min",
                s.op.id,
                r3(rpm),
                r3(d),
                r3(vc)
            ),
        )
        .help("ISO 14649 gives spindle speeds in rev/s and cutting speeds in m/s; check the MILLING_TECHNOLOGY of the operation (rpm or m/min written instead?)")
    })
}

fn is_drilling(k: &OperationKind) -> bool {
    match k {
        OperationKind::Drilling(_)
        | OperationKind::CenterDrilling(_)
        | OperationKind::CounterSinking(_)
        | OperationKind::MultistepDrilling { .. }
        | OperationKind::Boring { .. }
        | OperationKind::Tapping { .. }
        | OperationKind::ThreadDrilling { .. } => true,
        OperationKind::PlaneMilling { .. }
        | OperationKind::SideMilling { .. }
        | OperationKind::BottomAndSideMilling { .. }
        | OperationKind::Freeform { .. }
        | OperationKind::Other(_) => false,
    }
}

fn r3(v: f64) -> f64 {
    (v * 1000.0).round() / 1000.0
}
