//! Tapping (ISO 14649-11 TAPPING) into the target's tapping cycle:
//! G84 (right hand) / G74 (left hand) on the word-address targets,
//! `CYCLE84` on the 840D, `CYCL DEF 207` on Heidenhain.
//!
//! The thread pitch is the technology's feed over its spindle speed
//! (ISO 14649 synchronises the two for tapping; the TAP body of the schema
//! we follow has no pitch attribute). The hand is the spindle's sign
//! (negative = M4 = left hand); a TAP body whose `hand_of_cut` says the
//! other hand is an error (E0907), as is a pitch that cannot be worked
//! out (E0906). Values the templates get beyond the hole cycle's:
//! `g` (84 or 74), `pitch` (unsigned), `spitch` (signed: negative for a
//! left hand, as CYCLE84's PIT and 207's Q239 take it), `s` (unsigned
//! rpm), `sdir` (3 or 4: the spindle after the cycle), `dwell_s`,
//! `dwell_ms`. A compensating chuck is posted with `tap_float.j2` where
//! the target has it (840D `CYCLE840`, Heidenhain `CYCL DEF 206`); else it
//! is named in a comment (not carried: G84/G74 are the same cycle; whether
//! the machine taps rigidly is its own setting [?]).

use super::plan::Step;
use super::step::{feed, spindle_rpm};
use super::values::Vals;
use super::{PostError, Writer};
use crate::diag::Code;
use crate::stepnc::model::*;

/// The tapping values added to the hole cycle's `base`.
pub fn values(
    w: &mut Writer<'_>,
    s: &Step<'_>,
    base: Vals,
    drill: &DrillCommon,
    compensation_chuck: bool,
) -> Result<Vals, PostError> {
    let (pitch, rpm) = pitch_and_rpm(s)?;
    let left = rpm < 0.0;
    check_hand(s, left)?;
    if compensation_chuck && template(w, true) == "tap.j2" {
        w.not_carried(
            "compensation chuck (G84/G74 do not say whether the tap floats: the machine's setting decides)",
        )?;
    }
    let dwell = drill.dwell_time_bottom.unwrap_or(0.0).max(0.0);
    let takes_dwell = !w.post.ignores("tap.j2", "dwell_s") || !w.post.ignores("tap.j2", "dwell_ms");
    if dwell > 0.0 && !takes_dwell {
        w.not_carried(&format!(
            "dwell {} s at the bottom of the tap",
            w.fmt.plain(dwell, 3)
        ))?;
    }
    let spitch = if left { -pitch } else { pitch };
    Ok(base
        .set_derived("g", if left { "74" } else { "84" })
        .set_derived("pitch", w.fmt.len(pitch))
        .set_derived("spitch", w.fmt.len(spitch))
        .set_derived("s", w.fmt.plain(rpm.abs(), 0))
        .set_derived("sdir", if left { "4" } else { "3" })
        .set("dwell_s", w.fmt.plain(dwell, 3))
        .set("dwell_ms", w.fmt.plain((dwell * 1000.0).round(), 0)))
}

/// The template: `tap_float.j2` for a compensating chuck where the target
/// has one (840D `CYCLE840`, Heidenhain `CYCL DEF 206`), else `tap.j2`.
pub fn template(w: &Writer<'_>, compensation_chuck: bool) -> &'static str {
    if compensation_chuck && w.post.has("tap_float.j2") {
        "tap_float.j2"
    } else {
        "tap.j2"
    }
}

/// The pitch (mm per revolution, positive) and the signed spindle speed.
fn pitch_and_rpm(s: &Step<'_>) -> Result<(f64, f64), PostError> {
    let bad = |why: &str| {
        PostError {
        code: Code::PostTapPitch,
        message: format!("`{}`: {why}", s.op.id),
        help: "give the tapping operation's technology a feed and a spindle speed whose ratio is the pitch".into(),
    }
    };
    let rpm =
        spindle_rpm(s).map_err(|_| bad("its technology gives no spindle speed, so no pitch"))?;
    if rpm == 0.0 || !rpm.is_finite() {
        return Err(bad("its spindle speed is zero, so no pitch"));
    }
    let f = feed(s).map_err(|_| bad("its technology gives no feed, so no pitch"))?;
    let pitch = f / rpm.abs();
    if !(pitch > 0.0 && pitch.is_finite()) {
        return Err(bad(&format!(
            "feed {f} over speed {rpm} gives no positive pitch"
        )));
    }
    Ok((pitch, rpm))
}

fn check_hand(s: &Step<'_>, left: bool) -> Result<(), PostError> {
    let hand = s.tool.body.hand_of_cut;
    let clash = match hand {
        Some(Hand::Left) => !left,
        Some(Hand::Right) => left,
        Some(Hand::Neutral) | None => false,
    };
    if !clash {
        return Ok(());
    }
    let (tool, turn) = if left {
        ("right-hand", "counter-clockwise (M4)")
    } else {
        ("left-hand", "clockwise (M3)")
    };
    Err(PostError {
        code: Code::PostTapHand,
        message: format!(
            "`{}`: a {tool} tap with the spindle turning {turn}",
            s.op.id
        ),
        help: "make the TAP's hand_of_cut and the sign of the spindle speed agree".into(),
    })
}
