//! A straight slot with radiused ends posted as one of the target's slot
//! cycles (840D `SLOT1`, `LONGHOLE`: templates `slot1.j2`,
//! `slot_longhole.j2`), when the slot fits what the cycle cuts:
//!
//! * `LONGHOLE` when the slot is exactly as wide as the tool (the cycle
//!   cuts the hole with the tool's width; it has no width parameter);
//! * `SLOT1` when it is wider and the tool cuts across its centre (the
//!   cycle plunges inside the slot as POCKET1 does).
//!
//! Both cycles place their slots radially on a circle: element k lies at
//! STA1 + k·INDA about (CPA, CPO), RAD out from the centre to the
//! element's inner end, LENG long including the round ends ([?]: our
//! reading of the classic cycle pictures, the same the interpreter uses,
//! `interp/siemens/milling/slots.rs`). One slot is posted as NUM=1 with
//! RAD=0: the circle's centre is the slot's inner end (the outline's end
//! behind the course of travel's origin) and STA1 the direction of travel
//! [?: whether a control accepts RAD 0 is not confirmed].
//!
//! When the slot does not fit (a tilted slot, an open or flat end, a tool
//! wider than the slot, a side allowance on a tool-wide slot...), the
//! caller cuts it with explicit moves and the reason is written in the
//! workingstep's comment.

use super::frame::Frame;
use super::milling::{spindle_cw, Cut};
use super::plan::Step;
use super::slot_circle::SlotCircle;
use super::step::{feed, spindle_rpm};
use super::values::Vals;
use super::{PostError, Writer};

/// The slot as the cycles see it: centre, direction of travel (unit,
/// outer frame), travel between the end centres, width.
pub struct SlotGeom {
    pub frame: Frame,
    pub travel: f64,
    pub width: f64,
}

/// Posts the slot as a cycle when the target has one that fits:
/// `Ok(None)` when done, `Ok(Some(why))` when the slot must be cut with
/// explicit moves instead (`why` says which condition failed).
pub fn try_cycle(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    g: &SlotGeom,
    radiused: bool,
    circle: Option<&SlotCircle>,
) -> Result<Option<String>, PostError> {
    let has_slot1 = w.post.has("slot1.j2");
    let has_longhole = w.post.has("slot_longhole.j2");
    if !has_slot1 && !has_longhole {
        if w.post.has("slot.j2") {
            let why = super::slot_cycle::why_not(s);
            return Ok(Some(why.unwrap_or("the slot cycle was not used").into()));
        }
        return Ok(Some("the target has no slot cycle".into()));
    }
    if !radiused {
        return Ok(Some(
            "SLOT1/LONGHOLE cut round ends; this slot's ends are not both radiused".into(),
        ));
    }
    if !g.frame.is_vertical() {
        return Ok(Some(
            "the slot's floor is not square to the tool axis".into(),
        ));
    }
    let d = s.tool.body.dimension.diameter;
    let tool_wide = (g.width - d).abs() < 1e-6;
    if tool_wide {
        if !has_longhole {
            return Ok(Some("the target has no LONGHOLE cycle".into()));
        }
        if c.allow_side > 0.0 && !c.finish {
            return Ok(Some(
                "a side allowance on a slot as wide as the tool (LONGHOLE cuts the full width)"
                    .into(),
            ));
        }
        return longhole(w, s, c, g, circle).map(|()| None);
    }
    if g.width < d {
        return Ok(Some("the tool is wider than the slot".into()));
    }
    if !has_slot1 {
        return Ok(Some("the target has no SLOT1 cycle".into()));
    }
    if !super::pockets::cuts_across_centre(&s.tool.body.kind) {
        return Ok(Some(
            "SLOT1 plunges inside the slot and the tool does not cut across its centre".into(),
        ));
    }
    slot1(w, s, c, g, circle).map(|()| None)
}

/// The values both cycles share.
/// One slot: NUM 1, RAD 0, the circle's centre at the slot's inner end.
fn common(
    w: &Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    g: &SlotGeom,
    bottom: f64,
    circle: Option<&SlotCircle>,
) -> Vals {
    let leng = g.travel + g.width;
    let x = g.frame.x;
    let one = SlotCircle {
        centre: [
            g.frame.origin[0] - x[0] * leng / 2.0,
            g.frame.origin[1] - x[1] * leng / 2.0,
        ],
        rad: 0.0,
        sta: g.frame.angle_deg(),
        inda: 0.0,
        num: 1,
    };
    let k = circle.unwrap_or(&one);
    Vals::new()
        .set("clear", w.fmt.len(s.clear))
        .set("top", w.fmt.len(s.top))
        .set("sdis", w.fmt.len(s.sdis))
        .set("bottom", w.fmt.len(bottom))
        .set("num", k.num.to_string())
        .set("leng", w.fmt.len(leng))
        .set("cpa", w.fmt.len(k.centre[0]))
        .set("cpo", w.fmt.len(k.centre[1]))
        .set("rad", w.fmt.len(k.rad))
        .set("sta1", w.fmt.angle(k.sta.rem_euclid(360.0)))
        .set("inda", w.fmt.angle(k.inda))
        .set("mid", w.fmt.len(c.ap.unwrap_or(s.top - bottom)))
}

/// LONGHOLE: one plunge-and-feed pass per level along the centre line.
fn longhole(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    g: &SlotGeom,
    circle: Option<&SlotCircle>,
) -> Result<(), PostError> {
    let bottom = s.bottom + if c.finish { 0.0 } else { c.allow_bottom };
    let f = w.fmt.feed(feed(s)?);
    w.comment(&format!(
        "slot as wide as the tool: LONGHOLE{}",
        placed(circle)
    ))?;
    let v = common(w, s, c, g, bottom, circle)
        .set("ffd", f.clone())
        .set("ffp1", f);
    w.emit("slot_longhole.j2", v)
}

/// SLOT1: the slot cleared as a pocket with round ends.
fn slot1(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    c: &Cut<'_>,
    g: &SlotGeom,
    circle: Option<&SlotCircle>,
) -> Result<(), PostError> {
    let ccw = c.ccw(spindle_cw(s)?);
    let (fal, units) = match (c.finish, s.roughed_by) {
        (false, _) => (c.allow_side, 1),
        (true, Some(r)) => (side_allowance(r), 2),
        (true, None) => (0.0, 0),
    };
    if !c.finish && c.allow_bottom > 0.0 {
        w.not_carried("the floor allowance of the roughing pass (SLOT1 reads none)")?;
    }
    let f = w.fmt.feed(feed(s)?);
    w.comment(&format!(
        "slot wider than the tool: SLOT1{}",
        placed(circle)
    ))?;
    let v = common(w, s, c, g, s.bottom, circle)
        .set("wid", w.fmt.len(g.width))
        .set("ffd", f.clone())
        .set("ffp1", f.clone())
        .set("cdir", if ccw { "3" } else { "2" })
        .set("fal", w.fmt.len(fal))
        .set("vari", units.to_string())
        .set("midf", w.fmt.len(c.ap.unwrap_or(s.top - s.bottom)))
        .set("ffp2", f)
        .set("ssf", w.fmt.feed(spindle_rpm(s)?.abs()));
    w.emit("slot1.j2", v)
}

/// How the cycle places the slots, for the comment.
fn placed(circle: Option<&SlotCircle>) -> String {
    match circle {
        None => ", one slot (NUM 1, RAD 0)".into(),
        Some(k) => format!(", {} slots on a circle", k.num),
    }
}

fn side_allowance(op: &crate::stepnc::model::Operation) -> f64 {
    match &op.kind {
        crate::stepnc::model::OperationKind::BottomAndSideMilling { allowance_side, .. } => {
            allowance_side.unwrap_or(0.0)
        }
        _ => 0.0,
    }
}
