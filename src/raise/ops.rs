//! Pieces of the model the raiser makes: technology and machine
//! functions from a move's state, toolpaths, and the feature and
//! operation of a recognised hole.
//!
//! Hole geometry: the feature is placed at the hole's axis on the top
//! surface, which is the stock's top when `--stock` is given and the R
//! plane (where the feed starts) otherwise. Its depth plane is at the
//! depth of the cylindrical part: for drills the conical tip (118°, the
//! usual twist-drill point; the program does not say) is taken off the
//! depth the tip reached; a hole whose tip reaches the stock's bottom is
//! THROUGH. Boring and reaming leave a flat bottom. The diameter is the
//! tool's (from the tool table). No tolerance is known: ±0.
//! Explicit toolpaths of a hole are in the hole's own frame (ISO 14649
//! §4.2: toolpaths of a workingstep tied to a feature are feature-local),
//! as NIST's `ex1E.stp` writes them.

use super::holes::{HoleCycle, HoleKind};
use super::project::{placement, plane_at};
use crate::stepnc::model::*;
use crate::toolpath::{FeedMode, Move};

/// The point angle assumed for drills, degrees.
pub const DRILL_TIP_ANGLE: f64 = 118.0;

/// The feed in mm/min of a move (a per-revolution feed times the speed).
pub fn feed_per_minute(m: &Move) -> f64 {
    match m.feed_mode {
        FeedMode::PerMinute => m.feed,
        FeedMode::PerRev => m.feed * m.spindle.abs(),
    }
}

pub fn technology(m: &Move) -> Technology {
    Technology {
        feed: Some(feed_per_minute(m)),
        feed_at_tcp: true,
        spindle: Some(m.spindle),
        ..Technology::default()
    }
}

pub fn machine_functions(m: &Move) -> MachineFunctions {
    MachineFunctions {
        coolant: m.coolant.flood,
        mist: m.coolant.mist.then_some(true),
        ..MachineFunctions::default()
    }
}

/// A cutter-location trajectory along `curve`.
pub fn trajectory(curve: Curve, technology: Option<Technology>, kind: ToolpathType) -> Toolpath {
    let speed = match kind {
        ToolpathType::Connect => Some(ToolpathSpeed::Named("RAPID".into())),
        _ => None,
    };
    Toolpath::CutterLocation {
        base: ToolpathBase {
            priority: true,
            kind,
            speed,
            technology,
            machine_functions: None,
        },
        direction: None,
        basic_curve: curve,
        tool_axis: None,
        surface_normal: None,
    }
}

pub fn feedstop(seconds: f64) -> Toolpath {
    Toolpath::Feedstop {
        base: ToolpathBase {
            priority: true,
            kind: ToolpathType::TrajectoryPath,
            speed: None,
            technology: None,
            machine_functions: None,
        },
        dwell: seconds,
    }
}

/// Tolerance-free length.
fn exact(v: f64) -> Toleranced {
    Toleranced {
        nominal: v,
        tolerance: Tolerance::PlusMinus {
            upper: 0.0,
            lower: 0.0,
            significant_digits: 3,
        },
    }
}

/// The geometry of a hole: (top z, cylindrical depth, bottom condition).
pub fn hole_geometry(
    h: &HoleCycle,
    diameter: f64,
    stock: Option<(f64, f64)>,
) -> (f64, f64, HoleBottom) {
    let top = stock.map(|(_, top)| top).unwrap_or(h.r_z);
    let tip_depth = (top - h.bottom).max(0.0);
    if let Some((bottom, _)) = stock {
        if h.bottom <= bottom + 1e-9 {
            return (top, top - bottom, HoleBottom::Through);
        }
    }
    match h.kind {
        HoleKind::Drilling { .. } | HoleKind::Multistep { .. } => {
            let cone = diameter / 2.0 / (DRILL_TIP_ANGLE / 2.0).to_radians().tan();
            let bottom = HoleBottom::Conical {
                tip_angle: DRILL_TIP_ANGLE,
                tip_radius: None,
            };
            (top, (tip_depth - cone).max(0.0), bottom)
        }
        HoleKind::Boring { .. } | HoleKind::Tapping { .. } => (top, tip_depth, HoleBottom::Flat),
    }
}

/// The ROUND_HOLE feature of a hole (operations filled in by the caller).
pub fn hole_feature(
    name: String,
    h: &HoleCycle,
    diameter: f64,
    stock: Option<(f64, f64)>,
) -> Feature {
    let (top, depth, bottom) = hole_geometry(h, diameter, stock);
    Feature {
        id: name.clone(),
        workpiece: WorkpieceId(0),
        operations: Vec::new(),
        placement: placement(&name, [h.x, h.y, top]),
        depth: Some(plane_at(&format!("{name} DEPTH"), -depth)),
        kind: FeatureKind::RoundHole {
            diameter: exact(diameter),
            change_in_diameter: None,
            bottom,
        },
    }
}

/// The drilling-type operation kind of a hole; `top` is the feature's.
pub fn hole_operation_kind(h: &HoleCycle, top: f64) -> OperationKind {
    let depth = top - h.bottom;
    let common = |dwell: Option<f64>, feed_on_retract| DrillCommon {
        cutting_depth: Some(depth),
        previous_diameter: None,
        dwell_time_bottom: dwell,
        feed_on_retract,
        strategy: None,
    };
    match h.kind {
        HoleKind::Drilling { dwell } => OperationKind::Drilling(common(dwell, None)),
        HoleKind::Multistep {
            first_depth,
            depth_of_step,
            retract_distance,
            dwell,
        } => OperationKind::MultistepDrilling {
            drill: common(None, None),
            retract_distance,
            // Measured from the feature's top, as the posts read it
            // (the recogniser measures from where the first feed starts).
            first_depth: first_depth + (top - h.r_z),
            depth_of_step,
            dwell_time_step: dwell,
        },
        HoleKind::Boring {
            reaming,
            spindle_stop,
            dwell,
            feed_on_retract,
        } => OperationKind::Boring {
            reaming,
            drill: common(dwell, feed_on_retract),
            spindle_stop_at_bottom: spindle_stop,
            depth_of_testcut: None,
            waiting_position: None,
        },
        // Fed by the canon's rigid tap or G84: no compensating chuck.
        HoleKind::Tapping { dwell, .. } => OperationKind::Tapping {
            drill: common(dwell, None),
            compensation_chuck: false,
        },
    }
}

/// The entity name of an operation kind, for ids and summaries.
pub fn operation_name(k: &OperationKind) -> &'static str {
    match k {
        OperationKind::PlaneMilling { finish: false, .. } => "PLANE_ROUGH_MILLING",
        OperationKind::PlaneMilling { finish: true, .. } => "PLANE_FINISH_MILLING",
        OperationKind::SideMilling { finish: false, .. } => "SIDE_ROUGH_MILLING",
        OperationKind::SideMilling { finish: true, .. } => "SIDE_FINISH_MILLING",
        OperationKind::BottomAndSideMilling { finish: false, .. } => {
            "BOTTOM_AND_SIDE_ROUGH_MILLING"
        }
        OperationKind::BottomAndSideMilling { finish: true, .. } => {
            "BOTTOM_AND_SIDE_FINISH_MILLING"
        }
        OperationKind::Freeform { .. } => "FREEFORM_OPERATION",
        OperationKind::Drilling(_) => "DRILLING",
        OperationKind::CenterDrilling(_) => "CENTER_DRILLING",
        OperationKind::CounterSinking(_) => "COUNTER_SINKING",
        OperationKind::MultistepDrilling { .. } => "MULTISTEP_DRILLING",
        OperationKind::Boring { reaming: true, .. } => "REAMING",
        OperationKind::Boring { reaming: false, .. } => "BORING",
        OperationKind::Tapping { .. } => "TAPPING",
        OperationKind::ThreadDrilling { .. } => "THREAD_DRILLING",
        OperationKind::Other(_) => "OTHER",
    }
}
