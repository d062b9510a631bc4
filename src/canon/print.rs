//! The text form of canonical calls, exactly as LinuxCNC 2.9's `rs274`
//! prints them (without its line counter and N prefix): `%.4f` numbers,
//! a few `%f` ones, and its own spacing per call.

use super::{Canon, CanonPlane, CanonUnits, MotionMode};
use std::fmt::Write;

fn f4(v: f64) -> String {
    let mut s = String::with_capacity(12);
    fixed(v, 4, &mut s);
    s
}

fn f6(v: f64) -> String {
    let mut s = String::with_capacity(14);
    fixed(v, 6, &mut s);
    s
}

/// `v` with `places` decimals, as C's `%.Nf` prints it (correctly rounded
/// from the exact binary value; `-0.0000` for negatives that round to
/// zero). Integer arithmetic where the rounding is unambiguous, the exact
/// formatter otherwise.
pub fn fixed(v: f64, places: u32, out: &mut String) {
    use std::fmt::Write as _;
    let (scale, p) = match places {
        4 => (1e4, 10_000u64),
        6 => (1e6, 1_000_000u64),
        _ => (10f64.powi(places as i32), 10u64.pow(places)),
    };
    let r = (v * scale).abs();
    let frac = r - r.trunc();
    if !v.is_finite() || r >= 1e12 || (frac - 0.5).abs() < 1e-3 {
        let _ = write!(out, "{:.*}", places as usize, v);
        return;
    }
    let n = (r + 0.5) as u64;
    if v.is_sign_negative() {
        out.push('-');
    }
    push_digits(out, n / p, 1);
    out.push('.');
    push_digits(out, n % p, places as usize);
}

/// `n` in decimal, zero-padded to at least `width` digits.
fn push_digits(out: &mut String, mut n: u64, width: usize) {
    let mut buf = [b'0'; 20];
    let mut i = buf.len();
    while n > 0 || buf.len() - i < width.max(1) {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
    }
    out.push_str(std::str::from_utf8(&buf[i..]).unwrap_or("0"));
}

fn pose(p: &[f64]) -> String {
    let mut s = String::with_capacity(p.len() * 12);
    for (i, v) in p.iter().enumerate() {
        if i > 0 {
            s.push_str(", ");
        }
        fixed(*v, 4, &mut s);
    }
    s
}

fn quoted(s: &str) -> String {
    format!("\"{s}\"")
}

/// One call as `rs274` prints it.
pub fn format_call(c: &Canon) -> String {
    use Canon::*;
    match c {
        UseLengthUnits(u) => format!(
            "USE_LENGTH_UNITS({})",
            match u {
                CanonUnits::Inches => "CANON_UNITS_INCHES",
                CanonUnits::Mm => "CANON_UNITS_MM",
            }
        ),
        SetG5xOffset { index, offset } => format!("SET_G5X_OFFSET({index}, {})", pose(offset)),
        SetG92Offset(p) => format!("SET_G92_OFFSET({})", pose(p)),
        SetXyRotation(r) => format!("SET_XY_ROTATION({})", f4(*r)),
        SetFeedReference => "SET_FEED_REFERENCE(CANON_XYZ)".into(),
        OnReset => "ON_RESET()".into(),
        Comment(s) => format!("COMMENT({})", quoted(s)),
        Message(s) => format!("MESSAGE({})", quoted(s)),
        LogOpen(s) => format!("LOGOPEN({})", quoted(s)),
        LogAppend(s) => format!("LOGAPPEND({})", quoted(s)),
        Log(s) => format!("LOG({})", quoted(s)),
        LogClose => "LOGCLOSE()".into(),
        SetFeedRate(f) => format!("SET_FEED_RATE({})", f4(*f)),
        SetFeedMode(m) => format!("SET_FEED_MODE(0, {m})"),
        SelectPlane(p) => format!(
            "SELECT_PLANE({})",
            match p {
                CanonPlane::XY => "CANON_PLANE_XY",
                CanonPlane::YZ => "CANON_PLANE_YZ",
                CanonPlane::XZ => "CANON_PLANE_XZ",
            }
        ),
        SelectTool(t) => format!("SELECT_TOOL({t})"),
        StartChange => "START_CHANGE()".into(),
        ChangeTool(r) => format!("CHANGE_TOOL({r})"),
        ChangeToolNumber(r) => format!("CHANGE_TOOL_NUMBER({r})"),
        StopSpindle => "STOP_SPINDLE_TURNING(0)".into(),
        SpindleCw => "START_SPINDLE_CLOCKWISE(0)".into(),
        SpindleCcw => "START_SPINDLE_COUNTERCLOCKWISE(0)".into(),
        SetSpindleSpeed(s) => format!("SET_SPINDLE_SPEED(0, {})", f4(*s)),
        SetSpindleMode(m) => format!("SET_SPINDLE_MODE(0 {})", f4(*m)),
        OrientSpindle { angle, mode } => format!("ORIENT_SPINDLE(0, {}, {mode})", f4(*angle)),
        WaitOrientComplete(t) => format!("SPINDLE.0.WAIT_ORIENT_COMPLETE({})", f4(*t)),
        UseToolLengthOffset(o) => format!(
            "USE_TOOL_LENGTH_OFFSET({} {} {}, {} {} {}, {} {} {})",
            f4(o[0]), f4(o[1]), f4(o[2]), f4(o[3]), f4(o[4]), f4(o[5]), f4(o[6]), f4(o[7]), f4(o[8])
        ),
        StraightTraverse(p) => format!("STRAIGHT_TRAVERSE({})", pose(p)),
        StraightFeed(p) => format!("STRAIGHT_FEED({})", pose(p)),
        StraightProbe(p) => format!("STRAIGHT_PROBE({})", pose(p)),
        ArcFeed { first_end, second_end, first_axis, second_axis, rotation, axis_end, abc } => {
            let mut s = String::new();
            let _ = write!(
                s,
                "ARC_FEED({}, {}, {}, {}, {rotation}, {}, {})",
                f4(*first_end),
                f4(*second_end),
                f4(*first_axis),
                f4(*second_axis),
                f4(*axis_end),
                pose(abc)
            );
            s
        }
        Dwell(t) => format!("DWELL({})", f4(*t)),
        SetMotionControlMode(m) => match m {
            MotionMode::ExactStop => "SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP)".into(),
            MotionMode::ExactPath => "SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)".into(),
            MotionMode::Continuous(t) => format!("SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, {})", f6(*t)),
        },
        SetNaivecamTolerance(t) => format!("SET_NAIVECAM_TOLERANCE({})", f4(*t)),
        FloodOn => "FLOOD_ON()".into(),
        FloodOff => "FLOOD_OFF()".into(),
        MistOn => "MIST_ON()".into(),
        MistOff => "MIST_OFF()".into(),
        ProgramStop => "PROGRAM_STOP()".into(),
        OptionalProgramStop => "OPTIONAL_PROGRAM_STOP()".into(),
        ProgramEnd => "PROGRAM_END()".into(),
        PalletShuttle => "PALLET_SHUTTLE()".into(),
        Finish => "FINISH()".into(),
        EnableFeedOverride => "ENABLE_FEED_OVERRIDE()".into(),
        DisableFeedOverride => "DISABLE_FEED_OVERRIDE()".into(),
        EnableSpeedOverride => "ENABLE_SPEED_OVERRIDE(0)".into(),
        DisableSpeedOverride => "DISABLE_SPEED_OVERRIDE(0)".into(),
        EnableAdaptiveFeed => "ENABLE_ADAPTIVE_FEED()".into(),
        DisableAdaptiveFeed => "DISABLE_ADAPTIVE_FEED()".into(),
        EnableFeedHold => "ENABLE_FEED_HOLD()".into(),
        DisableFeedHold => "DISABLE_FEED_HOLD()".into(),
        StartSpeedFeedSync { pitch, velocity_mode } => {
            format!("START_SPEED_FEED_SYNC({},{})", f6(*pitch), *velocity_mode as u8)
        }
        StopSpeedFeedSync => "STOP_SPEED_FEED_SYNCH()".into(),
        RigidTap { x, y, z } => format!("RIGID_TAP({}, {}, {})", f4(*x), f4(*y), f4(*z)),
        TurnProbeOn => "TURN_PROBE_ON()".into(),
        TurnProbeOff => "TURN_PROBE_OFF()".into(),
        // rs274 prints the nine offsets space-separated and no diameter.
        SetToolTableEntry { row, tool, offset, diameter: _, front, back, orientation } => format!(
            "SET_TOOL_TABLE_ENTRY({row}, {tool}, {}, {}, {}, {orientation})",
            offset.iter().map(|v| f4(*v)).collect::<Vec<_>>().join(" "),
            f4(*front),
            f4(*back)
        ),
        Io(text) => text.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fixed_matches_the_exact_formatter() {
        let mut state = 0x9e3779b97f4a7c15u64;
        for i in 0..200_000u64 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let mag = [1e-6, 1e-3, 1.0, 1e2, 1e4, 1e7, 1e11][(i % 7) as usize];
            let v = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0 * mag;
            let v = if i % 5 == 0 { (v * 1e5).round() / 1e5 + 0.00005 } else { v };
            for places in [4, 6] {
                let mut s = String::new();
                fixed(v, places, &mut s);
                assert_eq!(s, format!("{:.*}", places as usize, v), "{v:e}");
            }
        }
        for v in [0.0, -0.0, -0.00001, 0.00005, 1.00005, -2.5, f64::NAN, 1e300] {
            let mut s = String::new();
            fixed(v, 4, &mut s);
            assert_eq!(s, format!("{:.4}", v));
        }
    }
    use crate::canon::Canon;

    #[test]
    fn prints_like_rs274() {
        assert_eq!(
            format_call(&Canon::StraightFeed([-2.24509, 2.2451, -1.0, 0.0, 0.0, 0.0])),
            "STRAIGHT_FEED(-2.2451, 2.2451, -1.0000, 0.0000, 0.0000, 0.0000)"
        );
        assert_eq!(
            format_call(&Canon::ArcFeed {
                first_end: 0.0,
                second_end: 3.175,
                first_axis: 0.0,
                second_axis: 0.0,
                rotation: -1,
                axis_end: -1.0,
                abc: [0.0; 3]
            }),
            "ARC_FEED(0.0000, 3.1750, 0.0000, 0.0000, -1, -1.0000, 0.0000, 0.0000, 0.0000)"
        );
        assert_eq!(
            format_call(&Canon::UseToolLengthOffset([0.0, 0.0, 35.56, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0])),
            "USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 35.5600, 0.0000 0.0000 0.0000, 0.0000 0.0000 0.0000)"
        );
        assert_eq!(
            format_call(&Canon::SetMotionControlMode(MotionMode::Continuous(0.0))),
            "SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, 0.000000)"
        );
        assert_eq!(format_call(&Canon::SetSpindleMode(2000.0)), "SET_SPINDLE_MODE(0 2000.0000)");
        assert_eq!(format_call(&Canon::StartSpeedFeedSync { pitch: 0.5, velocity_mode: false }), "START_SPEED_FEED_SYNC(0.500000,0)");
        assert_eq!(format_call(&Canon::SetXyRotation(-0.0)), "SET_XY_ROTATION(-0.0000)");
    }
}
