//! Words of motion and machine statements both families write from the
//! spec's tables: moves and arcs, spindle, tool, transformations, dwell.
//! Word order within a move: code, axes X Y Z A B C U V W, I J K / radius,
//! then the rest.

use super::number::{shift_decimal, NumKind};
use super::writer::{Style, Writer};
use crate::dialect::{Capability, Meaning, SpindleFn};
use crate::ir::{
    CornerKind, DwellUnit, FrameOp, Motion, MotionKind, SpindleState, ToolRef, Transform, Value,
};
use crate::span::Span;

pub fn motion(w: &mut Writer<'_>, m: &Motion, span: Span, words: &mut Vec<String>) {
    if let Some(code) = motion_code(w, m.kind, span) {
        words.push(code);
    }
    w.push_axes(words, &m.target);
    arc(w, m, span, words);
    polar(w, m, span, words);
    if let Some((kind, v)) = &m.corner {
        if w.style == Style::Bracket {
            w.cannot(
                span,
                "a contour corner element (CHF=, RND=)",
                "program the chamfer or rounding as moves",
            );
        } else {
            let addr = match kind {
                CornerKind::Chamfer => "CHF",
                CornerKind::ChamferLeg => "CHR",
                CornerKind::Round => "RND",
                CornerKind::RoundModal => "RNDM",
            };
            w.push_word(words, addr, v, NumKind::Length, span);
        }
    }
}

fn motion_code(w: &mut Writer<'_>, kind: MotionKind, span: Span) -> Option<String> {
    match kind {
        MotionKind::Implicit => None,
        MotionKind::Other(code) => {
            if w.spec.code('G', code).is_some() {
                Some(format!("G{}", code.format(0, false)))
            } else {
                w.cannot(
                    span,
                    &format!("the motion code G{}", code.format(0, false)),
                    "choose a target that has it",
                );
                None
            }
        }
        MotionKind::ArcThrough | MotionKind::ArcTangent if w.style == Style::Sinumerik => {
            if w.spec.code_for(Meaning::Motion(kind)).is_some() {
                return w.code(Meaning::Motion(kind), span);
            }
            Some(
                if kind == MotionKind::ArcThrough {
                    "CIP"
                } else {
                    "CT"
                }
                .to_string(),
            )
        }
        MotionKind::Rapid
        | MotionKind::Linear
        | MotionKind::Arc(_)
        | MotionKind::ArcThrough
        | MotionKind::ArcTangent
        | MotionKind::Probe { .. } => w.code(Meaning::Motion(kind), span),
    }
}

fn arc(w: &mut Writer<'_>, m: &Motion, span: Span, words: &mut Vec<String>) {
    let a = &m.arc;
    for (addr, c) in [("I", &a.i), ("J", &a.j), ("K", &a.k)] {
        if let Some(c) = c {
            if let Some(s) = w.coord(addr, c, NumKind::Length) {
                words.push(s);
            }
        }
    }
    let siemens = w.style == Style::Sinumerik;
    if let Some(r) = &a.radius {
        w.push_word(
            words,
            if siemens { "CR" } else { "R" },
            r,
            NumKind::Length,
            span,
        );
    }
    if let Some(v) = &a.angle {
        if siemens {
            w.push_word(words, "AR", v, NumKind::Angle, span);
        } else {
            w.cannot(
                span,
                "an arc given by its opening angle (AR=)",
                "give the centre or the radius",
            );
        }
    }
    if let Some(mid) = &a.mid {
        if siemens {
            for (letter, c) in mid.iter() {
                let addr = match letter {
                    'X' => "I1",
                    'Y' => "J1",
                    _ => "K1",
                };
                if let Some(s) = w.coord(addr, c, NumKind::Length) {
                    words.push(s);
                }
            }
        } else {
            w.cannot(
                span,
                "an arc through an intermediate point (CIP)",
                "give the centre or the radius",
            );
        }
    }
    if let Some(t) = &a.turns {
        w.push_word(
            words,
            if siemens { "TURN" } else { "P" },
            t,
            NumKind::Int,
            span,
        );
    }
}

fn polar(w: &mut Writer<'_>, m: &Motion, span: Span, words: &mut Vec<String>) {
    if m.polar_radius.is_none() && m.polar_angle.is_none() {
        return;
    }
    let (r, a) = match w.style {
        Style::Sinumerik => ("RP", "AP"),
        Style::Bracket => {
            if !w.need(Capability::PolarWords, span, "polar coordinates") {
                return;
            }
            ("@", "^")
        }
    };
    if let Some(v) = &m.polar_radius {
        w.push_word(words, r, v, NumKind::Length, span);
    }
    if let Some(v) = &m.polar_angle {
        w.push_word(words, a, v, NumKind::Angle, span);
    }
}

pub fn spindle(w: &mut Writer<'_>, state: &SpindleState, span: Span, words: &mut Vec<String>) {
    let f = match state {
        SpindleState::Cw => SpindleFn::Cw,
        SpindleState::Ccw => SpindleFn::Ccw,
        SpindleState::Stop => SpindleFn::Stop,
        SpindleState::Orient(None) => SpindleFn::Orient,
        SpindleState::Orient(Some(angle)) => return orient_at(w, angle, span, words),
    };
    w.push_code(words, Meaning::Spindle(f), span);
}

fn orient_at(w: &mut Writer<'_>, angle: &Value, span: Span, words: &mut Vec<String>) {
    if w.style == Style::Sinumerik {
        w.push_word(words, "SPOS", angle, NumKind::Angle, span);
        return;
    }
    let letter = w
        .spec
        .code_for(Meaning::Spindle(SpindleFn::Orient))
        .and_then(|c| c.uses.first().copied());
    w.push_code(words, Meaning::Spindle(SpindleFn::Orient), span);
    match letter {
        Some(l) => w.push_word(words, &l.to_string(), angle, NumKind::Angle, span),
        None => w.cannot(
            span,
            "a spindle orientation angle",
            "the target's orient code takes no angle word",
        ),
    }
}

pub fn tool_select(w: &mut Writer<'_>, t: &ToolRef, span: Span, words: &mut Vec<String>) {
    match (t, w.style) {
        (ToolRef::Number(v), _) => w.push_word(words, "T", v, NumKind::Int, span),
        (ToolRef::Name(n), Style::Sinumerik) => words.push(format!("T=\"{n}\"")),
        (ToolRef::Name(n), Style::Bracket) => w.cannot(
            span,
            &format!("a tool selected by name (`{n}`)"),
            "select the tool by its number",
        ),
    }
}

pub fn transform(w: &mut Writer<'_>, t: &Transform, span: Span, words: &mut Vec<String>) {
    match t {
        Transform::Frame {
            op,
            additive,
            axes,
            rpl,
        } => {
            if !w.need(Capability::Frames, span, "a programmable frame") {
                return;
            }
            let (name, kind) = match op {
                FrameOp::Trans => ("TRANS", NumKind::Length),
                FrameOp::Rot => ("ROT", NumKind::Angle),
                FrameOp::Scale => ("SCALE", NumKind::Plain),
                FrameOp::Mirror => ("MIRROR", NumKind::Length),
            };
            words.push(if *additive {
                format!("A{name}")
            } else {
                name.to_string()
            });
            for (letter, c) in axes.iter() {
                if let Some(s) = w.coord(&letter.to_string(), c, kind) {
                    words.push(s);
                }
            }
            if let Some(v) = rpl {
                w.push_word(words, "RPL", v, NumKind::Angle, span);
            }
        }
        Transform::RotateOn { center, angle } => {
            w.push_code(words, Meaning::Rotate(true), span);
            w.push_axes(words, center);
            if let Some(v) = angle {
                w.push_word(words, "R", v, NumKind::Angle, span);
            }
        }
        Transform::RotateOff => w.push_code(words, Meaning::Rotate(false), span),
        Transform::ScaleOn {
            center,
            factor,
            per_axis,
        } => {
            w.push_code(words, Meaning::Scale(true), span);
            w.push_axes(words, center);
            if let Some(v) = factor {
                w.push_word(words, "P", v, NumKind::Plain, span);
            }
            for (letter, v) in per_axis {
                w.push_word(words, &letter.to_string(), v, NumKind::Plain, span);
            }
        }
        Transform::ScaleOff => w.push_code(words, Meaning::Scale(false), span),
        Transform::MirrorOn { axes } => {
            w.push_code(words, Meaning::Mirror(true), span);
            w.push_axes(words, axes);
        }
        Transform::MirrorOff => w.push_code(words, Meaning::Mirror(false), span),
    }
}

/// `G4` with the time in a word and unit the target's dwell code takes,
/// converted exactly between seconds and milliseconds when needed.
pub fn dwell(
    w: &mut Writer<'_>,
    value: &Value,
    unit: DwellUnit,
    span: Span,
    words: &mut Vec<String>,
) {
    let Some(def) = w.spec.code_for(Meaning::Dwell) else {
        w.push_code(words, Meaning::Dwell, span);
        return;
    };
    let units = def.dwell_units.clone();
    w.push_code(words, Meaning::Dwell, span);
    let pick = units
        .iter()
        .find(|(_, u)| *u == unit)
        .or_else(|| units.iter().find(|(_, u)| convertible(unit, *u)));
    let Some(&(letter, to)) = pick else {
        w.cannot(
            span,
            &format!("a dwell in {unit:?}"),
            "the target's dwell code takes no word in a unit this converts to",
        );
        return;
    };
    let value = match (value, unit == to) {
        (v, true) => v.clone(),
        (Value::Number(d), false) => {
            let shift = if to == DwellUnit::Milliseconds { 3 } else { -3 };
            match shift_decimal(*d, shift) {
                Some(c) => Value::Number(c),
                None => return w.inexact(span, format!("`{d}` does not convert exactly")),
            }
        }
        (Value::Expr(_), false) => {
            return w.cannot(
                span,
                "a computed dwell in another time unit",
                "give the dwell as a number",
            );
        }
    };
    let kind = match to {
        DwellUnit::Milliseconds => NumKind::Int,
        DwellUnit::Seconds if w.spec.is_length_address(letter) => NumKind::Length,
        DwellUnit::Seconds | DwellUnit::Revolutions => NumKind::Plain,
    };
    w.push_word(words, &letter.to_string(), &value, kind, span);
}

fn convertible(from: DwellUnit, to: DwellUnit) -> bool {
    use DwellUnit::*;
    matches!(
        (from, to),
        (Seconds, Milliseconds) | (Milliseconds, Seconds)
    )
}
