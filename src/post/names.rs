//! Names of STEP-NC entities as the posted comments write them
//! (`closed_pocket`, `bottom_and_side_rough_milling`, `twist_drill`), and
//! the 840D's `$TC_DP1` tool type of each tool body.

use crate::stepnc::model::*;

/// `$TC_DP1` tool type (dialects.md §1.6).
pub fn siemens_tool_type(k: &ToolBodyKind) -> Option<u32> {
    Some(match k {
        // A tapered end mill is posted as an end mill (type 120): the
        // 840D's taper types (155/156) need angles the model may not give.
        ToolBodyKind::Endmill | ToolBodyKind::TaperedEndmill => 120,
        ToolBodyKind::BullnoseEndmill => 121,
        ToolBodyKind::BallEndmill => 110,
        ToolBodyKind::Facemill => 140,
        ToolBodyKind::ThreadMill => 145,
        ToolBodyKind::TwistDrill | ToolBodyKind::TaperedDrill => 200,
        ToolBodyKind::CenterDrill | ToolBodyKind::Spotdrill => 220,
        ToolBodyKind::Countersink => 230,
        ToolBodyKind::Counterbore => 231,
        ToolBodyKind::Tap => 240,
        ToolBodyKind::Reamer | ToolBodyKind::TaperedReamer => 250,
        // ISO 14649-111 boring_tool: the 840D's boring bar (type 210
        // [K: tool types 200-299 drills; 210 boring bar]).
        ToolBodyKind::Other(e) if e.eq_ignore_ascii_case("BORING_TOOL") => 210,
        ToolBodyKind::Other(_) => return None,
    })
}

pub fn body_kind(k: &ToolBodyKind) -> String {
    match k {
        ToolBodyKind::Endmill => "endmill".into(),
        ToolBodyKind::TaperedEndmill => "tapered_endmill".into(),
        ToolBodyKind::BallEndmill => "ball_endmill".into(),
        ToolBodyKind::BullnoseEndmill => "bullnose_endmill".into(),
        ToolBodyKind::Facemill => "facemill".into(),
        ToolBodyKind::TwistDrill => "twist_drill".into(),
        ToolBodyKind::TaperedDrill => "tapered_drill".into(),
        ToolBodyKind::CenterDrill => "center_drill".into(),
        ToolBodyKind::Spotdrill => "spotdrill".into(),
        ToolBodyKind::Countersink => "countersink".into(),
        ToolBodyKind::Counterbore => "counterbore".into(),
        ToolBodyKind::Reamer => "reamer".into(),
        ToolBodyKind::TaperedReamer => "tapered_reamer".into(),
        ToolBodyKind::Tap => "tap".into(),
        ToolBodyKind::ThreadMill => "thread_mill".into(),
        ToolBodyKind::Other(s) => s.to_ascii_lowercase(),
    }
}

pub fn feature_kind(k: &FeatureKind) -> String {
    match k {
        FeatureKind::PlanarFace { .. } => "planar_face".into(),
        FeatureKind::RoundHole { .. } => "round_hole".into(),
        FeatureKind::ClosedPocket { .. } => "closed_pocket".into(),
        FeatureKind::OpenPocket { .. } => "open_pocket".into(),
        FeatureKind::Slot { .. } => "slot".into(),
        FeatureKind::Step { .. } => "step".into(),
        FeatureKind::GeneralOutsideProfile { .. } => "general_outside_profile".into(),
        FeatureKind::ToolpathFeature => "toolpath_feature".into(),
        FeatureKind::Other(r) => r.entity.to_ascii_lowercase(),
    }
}

pub fn operation_kind(k: &OperationKind) -> String {
    let fin = |f: &bool| if *f { "finish" } else { "rough" };
    match k {
        OperationKind::PlaneMilling { finish, .. } => format!("plane_{}_milling", fin(finish)),
        OperationKind::SideMilling { finish, .. } => format!("side_{}_milling", fin(finish)),
        OperationKind::BottomAndSideMilling { finish, .. } => {
            format!("bottom_and_side_{}_milling", fin(finish))
        }
        OperationKind::Freeform { .. } => "freeform_operation".into(),
        OperationKind::Drilling(_) => "drilling".into(),
        OperationKind::CenterDrilling(_) => "center_drilling".into(),
        OperationKind::CounterSinking(_) => "counter_sinking".into(),
        OperationKind::MultistepDrilling { .. } => "multistep_drilling".into(),
        OperationKind::Boring { reaming: true, .. } => "reaming".into(),
        OperationKind::Boring { reaming: false, .. } => "boring".into(),
        OperationKind::Tapping { .. } => "tapping".into(),
        OperationKind::ThreadDrilling { .. } => "thread_drilling".into(),
        OperationKind::Other(r) => r.entity.to_ascii_lowercase(),
    }
}
