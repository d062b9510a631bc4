//! Round holes: drilling (G81/G82, CYCLE81/82), multistep drilling (G83,
//! CYCLE83), reaming (G85, CYCLE85), boring (G86, CYCLE86) and tapping
//! (G84/G74, CYCLE84, CYCL DEF 207; see [`super::tapping`]), at the hole's
//! position. What a cycle cannot carry is named in a comment.

use super::group::{self, Pattern};
use super::names::operation_kind;
use super::plan::Step;
use super::step::{feed, spindle_rpm};
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::*;

pub fn write(w: &mut Writer<'_>, steps: &[&Step<'_>]) -> Result<(), PostError> {
    let s = steps[0];
    let cycle = cycle(w, s)?;
    positions(w, cycle, steps)?;
    w.emit("cycle_end.j2", Vals::new())
}

/// The hole positions after the cycle: the ones the cycle's template does
/// not take, one by one or as the target's pattern cycle.
fn positions(w: &mut Writer<'_>, cycle: &str, steps: &[&Step<'_>]) -> Result<(), PostError> {
    let pts: Vec<[f64; 2]> = steps.iter().map(|s| group::xy(s)).collect();
    let first_in_cycle = !w.post.ignores(cycle, "x");
    if !first_in_cycle {
        if let Some(p) = group::pattern(&pts) {
            if let Some((name, v)) = pattern_vals(w, &p) {
                if w.post.has(name) {
                    let v = v.set_derived("top", w.fmt.len(steps[0].top));
                    return w.emit(name, v);
                }
            }
        }
    }
    let rest = if first_in_cycle { &pts[1..] } else { &pts[..] };
    for p in rest {
        w.emit(
            "hole_at.j2",
            Vals::new()
                .set("x", w.fmt.len(p[0]))
                .set("y", w.fmt.len(p[1])),
        )?;
    }
    Ok(())
}

fn pattern_vals(w: &Writer<'_>, p: &Pattern) -> Option<(&'static str, Vals)> {
    let f = &w.fmt;
    Some(match p {
        Pattern::Row {
            start,
            angle,
            spacing,
            num,
        } => (
            "holes_row.j2",
            Vals::new()
                .set("x", f.len(start[0]))
                .set("y", f.len(start[1]))
                .set("angle", f.angle(*angle))
                .set("spacing", f.len(*spacing))
                .set("num", num.to_string()),
        ),
        Pattern::Circle {
            centre,
            radius,
            start,
            index,
            num,
        } => (
            "holes_circle.j2",
            Vals::new()
                .set("cx", f.len(centre[0]))
                .set("cy", f.len(centre[1]))
                .set("radius", f.len(*radius))
                .set_derived("diameter", f.len(2.0 * radius))
                .set("start", f.angle(*start))
                .set("index", f.angle(*index))
                .set("num", num.to_string()),
        ),
        Pattern::Grid {
            origin,
            dx,
            dy,
            nx,
            ny,
        } => (
            "holes_grid.j2",
            Vals::new()
                .set("x", f.len(origin[0]))
                .set("y", f.len(origin[1]))
                .set("dx", f.len(*dx))
                .set("dy", f.len(*dy))
                .set("nx", nx.to_string())
                .set("ny", ny.to_string()),
        ),
    })
}

/// Writes the cycle call; returns its template's name.
fn cycle(w: &mut Writer<'_>, s: &Step<'_>) -> Result<&'static str, PostError> {
    if matches!(s.op.kind, OperationKind::MultistepDrilling { .. })
        && w.post.has("peck_universal.j2")
    {
        return super::pecking::write(w, s);
    }
    let name = match &s.op.kind {
        OperationKind::Drilling(d)
        | OperationKind::CenterDrilling(d)
        | OperationKind::CounterSinking(d) => {
            strategy_notes(w, d)?;
            match d.dwell_time_bottom.filter(|t| *t > 0.0) {
                None => {
                    w.emit("drill.j2", base(w, s, d)?)?;
                    "drill.j2"
                }
                Some(t) => {
                    w.emit("drill_dwell.j2", dwell(w, base(w, s, d)?, t))?;
                    "drill_dwell.j2"
                }
            }
        }
        OperationKind::MultistepDrilling {
            drill,
            retract_distance,
            first_depth,
            depth_of_step,
            dwell_time_step,
        } => {
            strategy_notes(w, drill)?;
            if *depth_of_step <= 0.0 {
                return Err(PostError::broken(
                    &s.op.id,
                    "its depth of step is not positive",
                ));
            }
            w.not_carried(&format!(
                "retract distance {} mm between steps (the cycle retracts to the R plane)",
                w.fmt.plain(*retract_distance, 3)
            ))?;
            if dwell_time_step.is_some_and(|t| t > 0.0) {
                w.not_carried("dwell time between steps")?;
            }
            // A peck.j2 without `first` pecks evenly from the R plane
            // (G83's Q): its first step ends Q below R. `first_depth` is
            // measured from the hole's top.
            let first_from_r = first_depth + s.sdis;
            if w.post.ignores("peck.j2", "first") && (first_from_r - depth_of_step).abs() > 1e-6 {
                w.not_carried(&format!(
                    "first depth {} mm below the top (the target's cycle pecks evenly from the R plane, {} mm above the top)",
                    w.fmt.plain(*first_depth, 3),
                    w.fmt.plain(s.sdis, 3)
                ))?;
            }
            let v = base(w, s, drill)?
                .set("first", w.fmt.len(s.top - first_depth))
                .set("step", w.fmt.len(*depth_of_step));
            w.emit("peck.j2", v)?;
            "peck.j2"
        }
        OperationKind::Boring {
            reaming,
            drill,
            spindle_stop_at_bottom,
            depth_of_testcut,
            waiting_position,
        } => {
            strategy_notes(w, drill)?;
            let stop = *spindle_stop_at_bottom && !reaming;
            if !stop && drill.dwell_time_bottom.is_some_and(|t| t > 0.0) {
                w.not_carried("dwell at the bottom of a reaming pass")?;
            }
            if depth_of_testcut.is_some() || waiting_position.is_some() {
                w.not_carried("test cut depth / waiting position")?;
            }
            if *spindle_stop_at_bottom && *reaming {
                w.not_carried("spindle stop at the bottom of the reaming pass (the reaming cycle feeds out turning)")?;
            }
            if stop {
                // The spindle direction to restore after the oriented stop.
                let sdir = if spindle_rpm(s)? >= 0.0 { "3" } else { "4" };
                let t = drill.dwell_time_bottom.unwrap_or(0.0).max(0.0);
                let v = dwell(w, base(w, s, drill)?.set("sdir", sdir), t);
                w.emit("bore.j2", v)?;
                "bore.j2"
            } else {
                w.emit("ream.j2", base(w, s, drill)?)?;
                "ream.j2"
            }
        }
        OperationKind::Tapping {
            drill,
            compensation_chuck,
        } => {
            strategy_notes(w, drill)?;
            let v = super::tapping::values(w, s, base(w, s, drill)?, drill, *compensation_chuck)?;
            let name = super::tapping::template(w, *compensation_chuck);
            w.emit(name, v)?;
            name
        }
        OperationKind::PlaneMilling { .. }
        | OperationKind::SideMilling { .. }
        | OperationKind::BottomAndSideMilling { .. }
        | OperationKind::Freeform { .. }
        | OperationKind::ThreadDrilling { .. }
        | OperationKind::Other(_) => {
            return Err(PostError::unsupported(
                &s.op.id,
                &format!("a {} on a round hole", operation_kind(&s.op.kind)),
            ))
        }
    };
    Ok(name)
}

/// The values every hole cycle has.
pub(super) fn base(w: &Writer<'_>, s: &Step<'_>, d: &DrillCommon) -> Result<Vals, PostError> {
    let bottom = match d.cutting_depth {
        Some(depth) => s.top - depth,
        None => s.bottom - cone_below_depth(s),
    };
    let at = s.frame.origin;
    Ok(Vals::new()
        .set("x", w.fmt.len(at[0]))
        .set("y", w.fmt.len(at[1]))
        .set("clear", w.fmt.len(s.clear))
        .set("top", w.fmt.len(s.top))
        .set("sdis", w.fmt.len(s.sdis))
        .set("rplane", w.fmt.len(s.top + s.sdis))
        .set("bottom", w.fmt.len(bottom))
        .set("feed", w.fmt.feed(feed(s)?))
        .set_derived("depth", w.fmt.len(bottom - s.top))
        .set_derived("depth_abs", w.fmt.len(s.top - bottom))
        .set_derived("clear_inc", w.fmt.len(s.clear - s.top)))
}

/// A conical hole bottom lies below the feature's depth plane (which ends
/// the cylinder): the drill's point goes down to the cone's tip. A
/// through hole drilled with a pointed drill is drilled until the drill's
/// full diameter breaks out of the bottom: its point goes below by the
/// point's length (the tool's tip angle, else 118° for twist and tapered
/// drills [?]: what the raisers assume) and [`BREAKTHROUGH`] more, so
/// that the depth written (rounded) still breaks out. 0 for any other
/// bottom.
fn cone_below_depth(s: &Step<'_>) -> f64 {
    match &s.feature.kind {
        FeatureKind::RoundHole {
            diameter,
            bottom: HoleBottom::Conical { tip_angle, .. },
            ..
        } if *tip_angle > 0.0 && *tip_angle < 180.0 => {
            diameter.nominal / 2.0 / (tip_angle / 2.0).to_radians().tan()
        }
        FeatureKind::RoundHole {
            bottom: HoleBottom::Through,
            ..
        } if drills(s) => point_length(s.tool) + BREAKTHROUGH,
        _ => 0.0,
    }
}

/// How far (mm) a through hole's drill goes past its full diameter's
/// break-out [?]: enough to survive the rounding of the depth written;
/// shops often allow more (0.5 to 1 mm), which the STEP-NC plan does not
/// say.
const BREAKTHROUGH: f64 = 0.1;

/// A drilling operation (single or pecked) with a pointed drill.
fn drills(s: &Step<'_>) -> bool {
    matches!(
        s.op.kind,
        OperationKind::Drilling(_) | OperationKind::MultistepDrilling { .. }
    ) && point_length(s.tool) > 0.0
}

/// How far a drill's point reaches below its full diameter (0 for tools
/// without a point). The point is taken as 118° for every twist and
/// tapered drill, as the raisers take it: the plans' `tool_tip_half_angle`
/// is read both ways [?] (NIST's ex1 gives 31° for a drill, the angle to
/// the horizontal; AP238 files give half the point angle).
fn point_length(t: &crate::stepnc::model::Tool) -> f64 {
    use crate::stepnc::model::ToolBodyKind as K;
    if !matches!(t.body.kind, K::TwistDrill | K::TaperedDrill) {
        return 0.0;
    }
    let half = crate::raise::ops::DRILL_TIP_ANGLE / 2.0;
    t.body.dimension.diameter / 2.0 / half.to_radians().tan()
}

pub(super) fn dwell(w: &Writer<'_>, v: Vals, seconds: f64) -> Vals {
    v.set("dwell_s", w.fmt.plain(seconds, 3))
        .set("dwell_ms", w.fmt.plain((seconds * 1000.0).round(), 0))
}

pub(super) fn strategy_notes(w: &mut Writer<'_>, d: &DrillCommon) -> Result<(), PostError> {
    if let Some(st) = &d.strategy {
        let parts: Vec<String> = [
            ("reduced cut at start", st.reduced_cut_at_start),
            ("reduced feed at start", st.reduced_feed_at_start),
            ("depth of start", st.depth_of_start),
            ("reduced cut at end", st.reduced_cut_at_end),
            ("reduced feed at end", st.reduced_feed_at_end),
            ("depth of end", st.depth_of_end),
        ]
        .iter()
        .filter_map(|(n, v)| v.map(|v| format!("{n} {}", w.fmt.plain(v, 3))))
        .collect();
        if !parts.is_empty() {
            w.not_carried(&format!("drilling strategy: {}", parts.join(", ")))?;
        }
    }
    if d.feed_on_retract.is_some_and(|r| (r - 1.0).abs() > 1e-9) {
        w.not_carried("feed on retract (the cycle's own retract)")?;
    }
    Ok(())
}
