//! A readable listing of a project's features with their operations and
//! the workplan's order (for reviews and snapshot tests).

use crate::stepnc::model::*;
use std::fmt::Write;

fn n(x: f64) -> String {
    crate::ir::num::short_text(x, 4)
}

fn p3(p: P3) -> String {
    format!("({}, {}, {})", n(p[0]), n(p[1]), n(p[2]))
}

/// Each feature with its operations, then the workplan's order.
pub fn listing(project: &Project) -> String {
    let mut out = String::new();
    for f in &project.features {
        feature(&mut out, f);
        for op in &f.operations {
            operation(&mut out, project.operation(*op));
        }
    }
    out.push_str("workplan:\n");
    for e in &project.main_workplan.elements {
        let line = match e {
            Executable::Workingstep(ws) => ws.id.clone(),
            other => format!("{other:?}"),
        };
        let _ = writeln!(out, "  {line}");
    }
    out
}

fn feature(out: &mut String, f: &Feature) {
    let at = p3(f.placement.location.xyz);
    let x = f
        .placement
        .ref_direction
        .as_ref()
        .map_or([1.0, 0.0, 0.0], |d| d.ratios);
    let depth = -f.depth_z();
    let _ = writeln!(
        out,
        "{}: {} at {at} x {} depth {}",
        f.id,
        kind(&f.kind),
        p3(x),
        n(depth)
    );
}

/// A hole bottom in a word or two (`through`, `conical 118°`).
pub fn hole_bottom(b: &HoleBottom) -> String {
    match b {
        HoleBottom::Through => "through".into(),
        HoleBottom::Flat => "flat".into(),
        HoleBottom::Conical { tip_angle, .. } => format!("conical {}°", n(*tip_angle)),
        other => format!("{other:?}"),
    }
}

fn tl(t: &Toleranced) -> String {
    n(t.nominal)
}

fn closed(p: &ClosedProfile) -> String {
    match p {
        ClosedProfile::Rectangular { width, length, .. } => {
            format!("rectangle {} x {}", tl(length), tl(width))
        }
        ClosedProfile::Circular { diameter, .. } => format!("circle D{}", tl(diameter)),
        ClosedProfile::General { shape, .. } => format!("general {}", curve(shape)),
        ClosedProfile::Other(r) => format!("other {}", r.entity),
    }
}

fn curve(c: &Curve) -> String {
    match c {
        Curve::Polyline { points, .. } => {
            let pts: Vec<String> = points.iter().map(|p| p3(p.xyz)).collect();
            format!("polyline [{}]", pts.join(" "))
        }
        other => format!("{other:?}"),
    }
}

fn path(t: &TravelPath) -> String {
    match t {
        TravelPath::Linear {
            distance,
            direction,
            ..
        } => format!("linear {} along {}", tl(distance), p3(direction.ratios)),
        TravelPath::General { path, .. } => format!("general {}", curve(path)),
        TravelPath::Other(r) => format!("other {}", r.entity),
    }
}

/// A feature kind in a few words (`closed pocket rectangle 40 x 30 ...`).
pub fn kind(k: &FeatureKind) -> String {
    match k {
        FeatureKind::PlanarFace {
            course_of_travel,
            removal_boundary,
            ..
        } => {
            let w = match removal_boundary {
                OpenProfile::Linear { length, .. } => n(length.value),
                other => format!("{other:?}"),
            };
            format!("PLANAR_FACE course {} width {w}", path(course_of_travel))
        }
        FeatureKind::RoundHole {
            diameter, bottom, ..
        } => {
            format!(
                "ROUND_HOLE D{} bottom {}",
                tl(diameter),
                hole_bottom(bottom)
            )
        }
        FeatureKind::ClosedPocket { pocket, boundary } => {
            let r = pocket.orthogonal_radius.as_ref().map_or("-".into(), tl);
            format!(
                "CLOSED_POCKET {} corner R{r} bottom {:?}",
                closed(boundary),
                pocket.bottom
            )
        }
        FeatureKind::Slot {
            course_of_travel,
            swept_shape,
            end_conditions,
        } => {
            let w = match swept_shape {
                OpenProfile::SquareU {
                    width,
                    first_radius,
                    ..
                } => format!(
                    "square U width {} radius {}",
                    tl(width),
                    first_radius.as_ref().map_or("unset".into(), tl)
                ),
                other => format!("{other:?}"),
            };
            format!(
                "SLOT course {} {w} ends {end_conditions:?}",
                path(course_of_travel)
            )
        }
        FeatureKind::GeneralOutsideProfile {
            boundary,
            swept_shape,
        } => {
            let b = match boundary {
                Profile::Closed(c) => closed(c),
                Profile::Open(o) => format!("{o:?}"),
            };
            format!("GENERAL_OUTSIDE_PROFILE {b} swept {}", path(swept_shape))
        }
        other => format!("{other:?}")
            .split([' ', '{'])
            .next()
            .unwrap_or("")
            .to_string(),
    }
}

fn operation(out: &mut String, o: &Operation) {
    let t = &o.technology;
    let f = t.feed.map_or("-".into(), n);
    let s = t.spindle.map_or("-".into(), n);
    let cool = if o.machine_functions.coolant {
        "coolant"
    } else {
        "dry"
    };
    let rp = o.retract_plane.map_or("-".into(), n);
    let _ = writeln!(
        out,
        "  {}: tool #{} F{f} S{s} {cool} retract {rp}",
        o.id, o.tool.0
    );
    let _ = writeln!(out, "    {}", op_kind(&o.kind));
}

fn opt(x: Option<f64>) -> String {
    x.map_or("-".into(), n)
}

fn op_kind(k: &OperationKind) -> String {
    match k {
        OperationKind::PlaneMilling {
            finish,
            milling,
            axial_cutting_depth,
            allowance_bottom,
        } => format!(
            "PLANE_{}_MILLING ap {} allowance bottom {}; {}",
            rf(*finish),
            opt(*axial_cutting_depth),
            opt(*allowance_bottom),
            milling_text(milling)
        ),
        OperationKind::SideMilling {
            finish,
            milling,
            axial_cutting_depth,
            radial_cutting_depth,
            allowance_side,
        } => format!(
            "SIDE_{}_MILLING ap {} ae {} allowance side {}; {}",
            rf(*finish),
            opt(*axial_cutting_depth),
            opt(*radial_cutting_depth),
            opt(*allowance_side),
            milling_text(milling)
        ),
        OperationKind::BottomAndSideMilling {
            finish,
            milling,
            axial_cutting_depth,
            radial_cutting_depth,
            allowance_side,
            allowance_bottom,
        } => format!(
            "BOTTOM_AND_SIDE_{}_MILLING ap {} ae {} allowance side {} bottom {}; {}",
            rf(*finish),
            opt(*axial_cutting_depth),
            opt(*radial_cutting_depth),
            opt(*allowance_side),
            opt(*allowance_bottom),
            milling_text(milling)
        ),
        OperationKind::MultistepDrilling {
            retract_distance,
            first_depth,
            depth_of_step,
            ..
        } => format!(
            "MULTISTEP_DRILLING first {} step {} retract {}",
            n(*first_depth),
            n(*depth_of_step),
            n(*retract_distance)
        ),
        OperationKind::Boring {
            reaming,
            spindle_stop_at_bottom,
            drill,
            ..
        } => format!(
            "{} spindle stop {spindle_stop_at_bottom} dwell {}",
            if *reaming { "REAMING" } else { "BORING" },
            opt(drill.dwell_time_bottom)
        ),
        OperationKind::Drilling(d) => format!("DRILLING dwell {}", opt(d.dwell_time_bottom)),
        OperationKind::CenterDrilling(_) => "CENTER_DRILLING".into(),
        OperationKind::Tapping {
            compensation_chuck, ..
        } => format!("TAPPING compensation chuck {compensation_chuck}"),
        OperationKind::ThreadDrilling {
            helical_movement_on_forward,
            ..
        } => format!("THREAD_DRILLING helical {helical_movement_on_forward}"),
        OperationKind::CounterSinking(_) => "COUNTER_SINKING".into(),
        OperationKind::Freeform { .. } => "FREEFORM_OPERATION (explicit toolpath)".into(),
        OperationKind::Other(r) => r.entity.clone(),
    }
}

fn rf(finish: bool) -> &'static str {
    if finish {
        "FINISH"
    } else {
        "ROUGH"
    }
}

fn milling_text(m: &MillingCommon) -> String {
    let a = match &m.approach {
        Some(ApproachRetract::PlungeToolaxis { .. }) => "PLUNGE_TOOLAXIS".into(),
        Some(ApproachRetract::PlungeRamp { angle, .. }) => format!("PLUNGE_RAMP {}°", n(*angle)),
        Some(ApproachRetract::PlungeHelix { radius, angle, .. }) => {
            format!("PLUNGE_HELIX R{} {}°", n(*radius), n(*angle))
        }
        Some(other) => format!("{other:?}"),
        None => "-".into(),
    };
    let s = match &m.strategy {
        Some(s) => strategy(s),
        None => "-".into(),
    };
    format!("approach {a}; strategy {s}")
}

fn strategy(s: &Strategy) -> String {
    let dir = |d: &Option<Direction>| d.as_ref().map_or("-".into(), |d| p3(d.ratios));
    match s {
        Strategy::Bidirectional {
            base,
            feed_direction,
            stepover_direction,
            ..
        } => format!(
            "BIDIRECTIONAL feed {} stepover {stepover_direction:?} overlap {}",
            dir(feed_direction),
            opt(base.overlap)
        ),
        Strategy::Unidirectional {
            feed_direction,
            cutmode,
            ..
        } => format!("UNIDIRECTIONAL feed {} {cutmode:?}", dir(feed_direction)),
        Strategy::ContourParallel {
            rotation, cutmode, ..
        } => format!("CONTOUR_PARALLEL {rotation:?} {cutmode:?}"),
        Strategy::ContourSpiral {
            rotation, cutmode, ..
        } => format!("CONTOUR_SPIRAL {rotation:?} {cutmode:?}"),
        Strategy::BidirectionalContour {
            contour_first,
            rotation,
            cutmode,
            ..
        } => format!(
            "{} {rotation:?} {cutmode:?}",
            if *contour_first {
                "CONTOUR_BIDIRECTIONAL"
            } else {
                "BIDIRECTIONAL_CONTOUR"
            }
        ),
        Strategy::CenterMilling { .. } => "CENTER_MILLING".into(),
        other => format!("{other:?}"),
    }
}
