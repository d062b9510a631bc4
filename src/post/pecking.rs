//! Multistep drilling on a target that has a universal pecking cycle
//! (`peck_universal.j2`, Heidenhain CYCL DEF 205) besides its pecking
//! cycle with even infeeds (`peck.j2`, CYCL DEF 203). The universal
//! cycle is chosen where the operation's pecks need it:
//! * decreasing pecks (a first depth deeper than the later steps): the
//!   first infeed Q202, each next one Q212 less, never below Q205 (the
//!   step), with a full retract after each;
//! * chip breaking (a retract distance shorter than a step, so the drill
//!   backs off rather than leaving the hole): one infeed to the depth with
//!   a chip break after every step (Q257), backing off the retract
//!   distance (Q256); a decreasing first depth is then not carried.
//!
//! Otherwise the even cycle, whose retract to the set-up clearance does
//! not carry the retract distance. A comment says which was chosen.

use super::holes::{base, strategy_notes};
use super::plan::Step;
use super::values::Vals;
use super::{PostError, Writer};
use crate::stepnc::model::OperationKind;

const EPS: f64 = 1e-9;

/// Writes the cycle definition; returns its template's name.
pub fn write(w: &mut Writer<'_>, s: &Step<'_>) -> Result<&'static str, PostError> {
    let OperationKind::MultistepDrilling {
        drill,
        retract_distance,
        first_depth,
        depth_of_step,
        dwell_time_step,
    } = &s.op.kind
    else {
        return Err(PostError::unsupported(
            &s.op.id,
            "this operation as pecking",
        ));
    };
    let (retract, first, step) = (*retract_distance, *first_depth, *depth_of_step);
    strategy_notes(w, drill)?;
    if step <= 0.0 {
        return Err(PostError::broken(
            &s.op.id,
            "its depth of step is not positive",
        ));
    }
    if dwell_time_step.is_some_and(|t| t > 0.0) {
        w.not_carried("dwell time between steps")?;
    }
    let decreasing = first > step + EPS;
    let chip = retract > EPS && retract < step - EPS;
    let v = base(w, s, drill)?;
    if !decreasing && !chip {
        return even(w, s, v, retract, first, step);
    }
    let f = &w.fmt;
    let (v, why) = if chip {
        let depth = v.get("depth_abs").unwrap_or("0").to_string();
        let v = v
            .set("first_inc", depth)
            .set("decrement", f.len(0.0))
            .set("min_step", f.len(step))
            .set("break_depth", f.len(step))
            .set("break_retract", f.len(retract));
        (v, "chip breaking")
    } else {
        let v = v
            .set("first_inc", f.len(first))
            .set("decrement", f.len(first - step))
            .set("min_step", f.len(step))
            .set("break_depth", f.len(0.0))
            .set("break_retract", f.len(0.2));
        (v, "decreasing infeeds")
    };
    w.comment(&format!(
        "multistep drilling with {why}: the universal pecking cycle"
    ))?;
    if chip && decreasing {
        w.not_carried(&format!(
            "first depth {} mm (chip breaking at even steps)",
            w.fmt.plain(first, 3)
        ))?;
    }
    if !chip && retract > EPS {
        w.not_carried(&format!(
            "retract distance {} mm between steps (the cycle retracts to the set-up clearance)",
            w.fmt.plain(retract, 3)
        ))?;
    }
    w.emit("peck_universal.j2", v)?;
    Ok("peck_universal.j2")
}

/// Even infeeds with a full retract after each.
fn even(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    v: Vals,
    retract: f64,
    first: f64,
    step: f64,
) -> Result<&'static str, PostError> {
    w.comment("multistep drilling with even infeeds: the pecking cycle")?;
    if retract > EPS {
        w.not_carried(&format!(
            "retract distance {} mm between steps (the cycle retracts to the set-up clearance)",
            w.fmt.plain(retract, 3)
        ))?;
    }
    if (first - step).abs() > EPS {
        w.not_carried(&format!(
            "first depth {} mm (the cycle pecks evenly)",
            w.fmt.plain(first, 3)
        ))?;
    }
    let v = v
        .set("first", w.fmt.len(s.top - first))
        .set("step", w.fmt.len(step));
    w.emit("peck.j2", v)?;
    Ok("peck.j2")
}
