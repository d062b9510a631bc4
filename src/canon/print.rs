//! The text form of canonical calls, exactly as LinuxCNC 2.9's `rs274`
//! prints them (without its line counter and N prefix): `%.4f` numbers,
//! a few `%f` ones, and its own spacing per call.

use super::{Canon, CanonPlane, CanonUnits, MotionMode};
use std::io::Write;

/// `v` with `places` decimals, as C's `%.Nf` prints it (correctly rounded
/// from the exact binary value; `-0.0000` for negatives that round to
/// zero). Integer arithmetic where the rounding is unambiguous, the exact
/// formatter otherwise.
fn fixed_bytes(v: f64, places: u32, out: &mut Vec<u8>) {
    let scale = match places {
        4 => 1e4,
        6 => 1e6,
        _ => 10f64.powi(places as i32),
    };
    if v == 0.0 && places == 4 {
        let zero: &[u8] = if v.is_sign_negative() {
            b"-0.0000"
        } else {
            b"0.0000"
        };
        return out.extend_from_slice(zero);
    }
    let r = (v * scale).abs();
    // `r < 1e12` is false for NaN and infinities: they take the slow path.
    let unambiguous = places <= 12 && r < 1e12 && {
        let frac = r - (r as u64) as f64;
        (frac - 0.5).abs() >= 1e-3
    };
    if !unambiguous {
        let _ = write!(out, "{:.*}", places as usize, v);
        return;
    }
    let n = (r + 0.5) as u64;
    // Written right to left into one buffer: fraction, point, integer
    // part (at least one digit), sign.
    let mut buf = [b'0'; 32];
    let mut i = buf.len();
    let mut rest = n;
    let mut left = places;
    while left >= 2 {
        i -= 2;
        let pair = (rest % 100) as usize * 2;
        buf[i..i + 2].copy_from_slice(&PAIRS[pair..pair + 2]);
        rest /= 100;
        left -= 2;
    }
    if left == 1 {
        i -= 1;
        buf[i] = b'0' + (rest % 10) as u8;
        rest /= 10;
    }
    i -= 1;
    buf[i] = b'.';
    loop {
        i -= 1;
        buf[i] = b'0' + (rest % 10) as u8;
        rest /= 10;
        if rest == 0 {
            break;
        }
    }
    if v.is_sign_negative() {
        i -= 1;
        buf[i] = b'-';
    }
    out.extend_from_slice(&buf[i..]);
}

/// "00" to "99", for writing two digits at a time.
const PAIRS: &[u8; 200] = b"0001020304050607080910111213141516171819\
2021222324252627282930313233343536373839\
4041424344454647484950515253545556575859\
6061626364656667686970717273747576777879\
8081828384858687888990919293949596979899";

/// `n` in decimal.
fn push_int(out: &mut Vec<u8>, mut n: u64) {
    let mut buf = [b'0'; 20];
    let mut i = buf.len();
    loop {
        i -= 1;
        buf[i] = b'0' + (n % 10) as u8;
        n /= 10;
        if n == 0 {
            break;
        }
    }
    out.extend_from_slice(&buf[i..]);
}

/// A call's text, piece by piece, into a byte buffer.
struct Out<'a>(&'a mut Vec<u8>);

impl Out<'_> {
    fn s(&mut self, s: &str) -> &mut Self {
        self.0.extend_from_slice(s.as_bytes());
        self
    }
    fn f4(&mut self, v: f64) -> &mut Self {
        fixed_bytes(v, 4, self.0);
        self
    }
    fn f6(&mut self, v: f64) -> &mut Self {
        fixed_bytes(v, 6, self.0);
        self
    }
    fn int(&mut self, v: i64) -> &mut Self {
        if v < 0 {
            self.0.push(b'-');
        }
        push_int(self.0, v.unsigned_abs());
        self
    }
    /// Numbers `%.4f`, separated by `sep`.
    fn list(&mut self, p: &[f64], sep: &str) -> &mut Self {
        for (i, v) in p.iter().enumerate() {
            if i > 0 {
                self.s(sep);
            }
            self.f4(*v);
        }
        self
    }
    fn quoted(&mut self, text: &str) -> &mut Self {
        self.s("\"").s(text).s("\"")
    }
}

/// One call as `rs274` prints it.
pub fn format_call(c: &Canon) -> String {
    let mut b = Vec::with_capacity(64);
    write_call(&mut b, c);
    match String::from_utf8(b) {
        Ok(s) => s,
        Err(e) => String::from_utf8_lossy(e.as_bytes()).into_owned(),
    }
}

/// Appends one call as `rs274` prints it (no newline) to `out`; the hot
/// calls are written without going through `format!`.
pub fn write_call(out: &mut Vec<u8>, c: &Canon) {
    use Canon::*;
    let mut o = Out(out);
    match c {
        StraightTraverse(p) => o.s("STRAIGHT_TRAVERSE(").list(p, ", ").s(")"),
        StraightFeed(p) => o.s("STRAIGHT_FEED(").list(p, ", ").s(")"),
        StraightProbe(p) => o.s("STRAIGHT_PROBE(").list(p, ", ").s(")"),
        ArcFeed {
            first_end,
            second_end,
            first_axis,
            second_axis,
            rotation,
            axis_end,
            abc,
        } => o
            .s("ARC_FEED(")
            .list(&[*first_end, *second_end, *first_axis, *second_axis], ", ")
            .s(", ")
            .int(*rotation)
            .s(", ")
            .f4(*axis_end)
            .s(", ")
            .list(abc, ", ")
            .s(")"),
        SetFeedRate(f) => o.s("SET_FEED_RATE(").f4(*f).s(")"),
        Comment(s) => o.s("COMMENT(").quoted(s).s(")"),
        Message(s) => o.s("MESSAGE(").quoted(s).s(")"),
        LogOpen(s) => o.s("LOGOPEN(").quoted(s).s(")"),
        LogAppend(s) => o.s("LOGAPPEND(").quoted(s).s(")"),
        Log(s) => o.s("LOG(").quoted(s).s(")"),
        LogClose => o.s("LOGCLOSE()"),
        SetG5xOffset { index, offset } => o
            .s("SET_G5X_OFFSET(")
            .int(*index as i64)
            .s(", ")
            .list(offset, ", ")
            .s(")"),
        SetG92Offset(p) => o.s("SET_G92_OFFSET(").list(p, ", ").s(")"),
        SetXyRotation(r) => o.s("SET_XY_ROTATION(").f4(*r).s(")"),
        SetSpindleSpeed(s) => o.s("SET_SPINDLE_SPEED(0, ").f4(*s).s(")"),
        SetSpindleMode(m) => o.s("SET_SPINDLE_MODE(0 ").f4(*m).s(")"),
        OrientSpindle { angle, mode } => o
            .s("ORIENT_SPINDLE(0, ")
            .f4(*angle)
            .s(", ")
            .int(*mode)
            .s(")"),
        WaitOrientComplete(t) => o.s("SPINDLE.0.WAIT_ORIENT_COMPLETE(").f4(*t).s(")"),
        UseToolLengthOffset(v) => o
            .s("USE_TOOL_LENGTH_OFFSET(")
            .list(&v[0..3], " ")
            .s(", ")
            .list(&v[3..6], " ")
            .s(", ")
            .list(&v[6..9], " ")
            .s(")"),
        Dwell(t) => o.s("DWELL(").f4(*t).s(")"),
        SetMotionControlMode(MotionMode::Continuous(t)) => o
            .s("SET_MOTION_CONTROL_MODE(CANON_CONTINUOUS, ")
            .f6(*t)
            .s(")"),
        SetNaivecamTolerance(t) => o.s("SET_NAIVECAM_TOLERANCE(").f4(*t).s(")"),
        StartSpeedFeedSync {
            pitch,
            velocity_mode,
        } => o
            .s("START_SPEED_FEED_SYNC(")
            .f6(*pitch)
            .s(",")
            .int(*velocity_mode as i64)
            .s(")"),
        RigidTap { x, y, z } => o.s("RIGID_TAP(").list(&[*x, *y, *z], ", ").s(")"),
        // rs274 prints the number of control points only.
        NurbsFeed { points, order: _ } => o.s("NURBS_FEED(").int(points.len() as i64).s(", ...)"),
        // rs274 prints the nine offsets space-separated and no diameter.
        SetToolTableEntry {
            row,
            tool,
            offset,
            diameter: _,
            front,
            back,
            orientation,
        } => {
            let _ = write!(o.0, "SET_TOOL_TABLE_ENTRY({row}, {tool}, ");
            o.list(offset, " ").s(", ").f4(*front).s(", ").f4(*back);
            let _ = write!(o.0, ", {orientation})");
            &mut o
        }
        Io(text) => o.s(text),
        other => o.s(&fixed_text(other)),
    };
}

/// Calls whose text has no number printed `%.4f` (rare ones).
fn fixed_text(c: &Canon) -> std::borrow::Cow<'static, str> {
    use Canon::*;
    let s: &'static str = match c {
        UseLengthUnits(CanonUnits::Inches) => "USE_LENGTH_UNITS(CANON_UNITS_INCHES)",
        UseLengthUnits(CanonUnits::Mm) => "USE_LENGTH_UNITS(CANON_UNITS_MM)",
        SetFeedReference => "SET_FEED_REFERENCE(CANON_XYZ)",
        OnReset => "ON_RESET()",
        SelectPlane(CanonPlane::XY) => "SELECT_PLANE(CANON_PLANE_XY)",
        SelectPlane(CanonPlane::YZ) => "SELECT_PLANE(CANON_PLANE_YZ)",
        SelectPlane(CanonPlane::XZ) => "SELECT_PLANE(CANON_PLANE_XZ)",
        SetFeedMode(m) => return format!("SET_FEED_MODE(0, {m})").into(),
        SelectTool(t) => return format!("SELECT_TOOL({t})").into(),
        StartChange => "START_CHANGE()",
        ChangeTool(r) => return format!("CHANGE_TOOL({r})").into(),
        ChangeToolNumber(r) => return format!("CHANGE_TOOL_NUMBER({r})").into(),
        StopSpindle => "STOP_SPINDLE_TURNING(0)",
        SpindleCw => "START_SPINDLE_CLOCKWISE(0)",
        SpindleCcw => "START_SPINDLE_COUNTERCLOCKWISE(0)",
        SetMotionControlMode(MotionMode::ExactStop) => "SET_MOTION_CONTROL_MODE(CANON_EXACT_STOP)",
        SetMotionControlMode(MotionMode::ExactPath) => "SET_MOTION_CONTROL_MODE(CANON_EXACT_PATH)",
        FloodOn => "FLOOD_ON()",
        FloodOff => "FLOOD_OFF()",
        MistOn => "MIST_ON()",
        MistOff => "MIST_OFF()",
        ProgramStop => "PROGRAM_STOP()",
        OptionalProgramStop => "OPTIONAL_PROGRAM_STOP()",
        ProgramEnd => "PROGRAM_END()",
        PalletShuttle => "PALLET_SHUTTLE()",
        Finish => "FINISH()",
        EnableFeedOverride => "ENABLE_FEED_OVERRIDE()",
        DisableFeedOverride => "DISABLE_FEED_OVERRIDE()",
        EnableSpeedOverride => "ENABLE_SPEED_OVERRIDE(0)",
        DisableSpeedOverride => "DISABLE_SPEED_OVERRIDE(0)",
        EnableAdaptiveFeed => "ENABLE_ADAPTIVE_FEED()",
        DisableAdaptiveFeed => "DISABLE_ADAPTIVE_FEED()",
        EnableFeedHold => "ENABLE_FEED_HOLD()",
        DisableFeedHold => "DISABLE_FEED_HOLD()",
        StopSpeedFeedSync => "STOP_SPEED_FEED_SYNCH()",
        TurnProbeOn => "TURN_PROBE_ON()",
        TurnProbeOff => "TURN_PROBE_OFF()",
        // Written by `write_call` itself.
        StraightTraverse(_)
        | StraightFeed(_)
        | StraightProbe(_)
        | ArcFeed { .. }
        | SetFeedRate(_)
        | Comment(_)
        | Message(_)
        | SetG5xOffset { .. }
        | SetG92Offset(_)
        | SetXyRotation(_)
        | SetSpindleSpeed(_)
        | SetSpindleMode(_)
        | OrientSpindle { .. }
        | WaitOrientComplete(_)
        | UseToolLengthOffset(_)
        | Dwell(_)
        | SetMotionControlMode(MotionMode::Continuous(_))
        | SetNaivecamTolerance(_)
        | StartSpeedFeedSync { .. }
        | RigidTap { .. }
        | NurbsFeed { .. }
        | SetToolTableEntry { .. }
        | Io(_)
        | LogOpen(_)
        | LogAppend(_)
        | Log(_)
        | LogClose => "",
    };
    s.into()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixed(v: f64, places: u32, out: &mut String) {
        let mut b = Vec::new();
        fixed_bytes(v, places, &mut b);
        out.push_str(std::str::from_utf8(&b).unwrap());
    }

    #[test]
    fn fixed_matches_the_exact_formatter() {
        let mut state = 0x9e3779b97f4a7c15u64;
        for i in 0..200_000u64 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let mag = [1e-6, 1e-3, 1.0, 1e2, 1e4, 1e7, 1e11][(i % 7) as usize];
            let v = ((state >> 11) as f64 / (1u64 << 53) as f64 - 0.5) * 2.0 * mag;
            let v = if i % 5 == 0 {
                (v * 1e5).round() / 1e5 + 0.00005
            } else {
                v
            };
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
            format_call(&Canon::StraightFeed([
                -2.24509, 2.2451, -1.0, 0.0, 0.0, 0.0
            ])),
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
        assert_eq!(
            format_call(&Canon::SetSpindleMode(2000.0)),
            "SET_SPINDLE_MODE(0 2000.0000)"
        );
        assert_eq!(
            format_call(&Canon::StartSpeedFeedSync {
                pitch: 0.5,
                velocity_mode: false
            }),
            "START_SPEED_FEED_SYNC(0.500000,0)"
        );
        assert_eq!(
            format_call(&Canon::SetXyRotation(-0.0)),
            "SET_XY_ROTATION(-0.0000)"
        );
        let pt = |x, y| crate::canon::NurbsPoint { x, y, w: 1.0 };
        assert_eq!(
            format_call(&Canon::NurbsFeed {
                points: vec![pt(0.0, 0.0), pt(1.0, 2.0), pt(3.0, 0.0)],
                order: 3
            }),
            "NURBS_FEED(3, ...)"
        );
    }
}
