//! A tiny stand-in for the interpreter core, for tests only: absolute
//! G0/G1/G2/G3 with X Y Z I J, G17-G19, G20/G21, G40-G42.1 with D, F, S,
//! M0-M9, G4 P, comments and M2. Tool diameters are those of rs274-canon's
//! default table (inches).

use super::super::{CompSide, MoveKind, RadiusComp};
use crate::canon::{format_call, Canon, CanonPlane, Pose};

/// The call kinds the driver produces; rs274's output is filtered to these.
pub const MODELLED: &[&str] = &[
    "STRAIGHT_",
    "ARC_FEED",
    "COMMENT",
    "MESSAGE",
    "DWELL",
    "SET_FEED_RATE",
    "SET_SPINDLE_SPEED",
    "START_SPINDLE",
    "STOP_SPINDLE",
    "MIST",
    "FLOOD",
    "PROGRAM_STOP",
    "OPTIONAL_PROGRAM_STOP",
];

const DIAMETERS: [f64; 10] = [
    0.0625, 0.125, 0.1875, 0.25, 0.3125, 0.375, 0.5, 0.625, 0.75, 1.0,
];

struct Block {
    comments: Vec<String>,
    words: Vec<(char, f64)>,
}

impl Block {
    fn get(&self, c: char) -> Option<f64> {
        self.words.iter().find(|w| w.0 == c).map(|w| w.1)
    }
    fn has_g(&self, g: f64) -> bool {
        self.words
            .iter()
            .any(|w| w.0 == 'G' && (w.1 - g).abs() < 1e-9)
    }
    fn has_m(&self, m: f64) -> bool {
        self.words.iter().any(|w| w.0 == 'M' && w.1 == m)
    }
}

fn parse(line: &str) -> Block {
    let mut comments = Vec::new();
    let mut rest = String::new();
    let mut it = line.chars().peekable();
    while let Some(c) = it.next() {
        if c == '(' {
            let t: String = it.by_ref().take_while(|&c| c != ')').collect();
            comments.push(t);
        } else if c == ';' {
            break;
        } else if !c.is_whitespace() {
            rest.push(c.to_ascii_uppercase());
        }
    }
    let mut words = Vec::new();
    let b = rest.as_bytes();
    let mut i = 0;
    while i < b.len() {
        let letter = b[i] as char;
        let mut j = i + 1;
        while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'.' || b[j] == b'-' || b[j] == b'+')
        {
            j += 1;
        }
        words.push((letter, rest[i + 1..j].parse().unwrap_or(0.0)));
        i = j;
    }
    Block { comments, words }
}

struct State {
    comp: RadiusComp,
    pos: Pose,
    motion: f64,
    inch: bool,
    plane: CanonPlane,
    tool: usize,
    out: Vec<String>,
}

/// Runs a program; returns the printed calls, and `ERROR: message` last if
/// the engine reported one.
pub fn run(text: &str) -> Vec<String> {
    let mut st = State {
        comp: RadiusComp::new(),
        pos: [0.0; 6],
        motion: 0.0,
        inch: false,
        plane: CanonPlane::XY,
        tool: 0,
        out: Vec::new(),
    };
    for (n, line) in text.lines().enumerate() {
        st.comp.set_block(n as u64);
        let b = parse(line);
        if let Err(e) = block(&mut st, &b) {
            st.out.push(format!("ERROR: {}", e.kind.message()));
            return st.out;
        }
        if b.has_m(2.0) || b.has_m(30.0) {
            break;
        }
    }
    st.out
}

fn emit(st: &mut State, c: Canon) {
    let out = &mut st.out;
    st.comp.other(c, &mut |c| out.push(format_call(&c)));
}

fn block(st: &mut State, b: &Block) -> Result<(), super::super::CompError> {
    for c in &b.comments {
        match c.strip_prefix("MSG,") {
            Some(m) => emit(st, Canon::Message(m.to_string())),
            None => emit(st, Canon::Comment(c.clone())),
        }
    }
    if let Some(f) = b.get('F') {
        emit(st, Canon::SetFeedRate(f));
    }
    if let Some(s) = b.get('S') {
        emit(st, Canon::SetSpindleSpeed(s));
    }
    for (m, c) in [
        (3.0, Canon::SpindleCw),
        (4.0, Canon::SpindleCcw),
        (5.0, Canon::StopSpindle),
        (7.0, Canon::MistOn),
        (8.0, Canon::FloodOn),
    ] {
        if b.has_m(m) {
            emit(st, c);
        }
    }
    if b.has_m(9.0) {
        emit(st, Canon::MistOff);
        emit(st, Canon::FloodOff);
    }
    if let Some(t) = b.get('T') {
        st.tool = t as usize;
    }
    if b.has_m(6.0) {
        emit(st, Canon::StopSpindle);
    }
    if b.has_g(4.0) {
        emit(st, Canon::Dwell(b.get('P').unwrap_or(0.0)));
    }
    for (g, p) in [
        (17.0, CanonPlane::XY),
        (18.0, CanonPlane::XZ),
        (19.0, CanonPlane::YZ),
    ] {
        if b.has_g(g) {
            st.comp.check_plane_change()?;
            st.plane = p;
        }
    }
    if b.has_g(20.0) {
        st.inch = true;
    }
    if b.has_g(21.0) {
        st.inch = false;
    }
    comp_mode(st, b)?;
    motion(st, b)?;
    stops(st, b);
    Ok(())
}

fn comp_mode(st: &mut State, b: &Block) -> Result<(), super::super::CompError> {
    let out = &mut st.out;
    let mut sink = |c: Canon| out.push(format_call(&c));
    if b.has_g(40.0) {
        st.comp.other(
            Canon::Comment("interpreter: cutter radius compensation off".into()),
            &mut sink,
        );
        return st.comp.stop(&mut sink);
    }
    let side = [
        (41.0, CompSide::Left),
        (41.1, CompSide::Left),
        (42.0, CompSide::Right),
        (42.1, CompSide::Right),
    ]
    .into_iter()
    .find(|(g, _)| b.has_g(*g));
    let Some((g, side)) = side else { return Ok(()) };
    let d = b.get('D').unwrap_or(st.tool as f64);
    let radius = if g == 41.0 || g == 42.0 {
        let dia = DIAMETERS
            .get((d as usize).wrapping_sub(1))
            .copied()
            .unwrap_or(0.0);
        if st.inch {
            dia / 2.0
        } else {
            dia * 25.4 / 2.0
        }
    } else {
        d / 2.0
    };
    if st.comp.is_on() {
        return st.comp.start(side, radius, st.plane);
    }
    let name = if side == CompSide::Left {
        "left"
    } else {
        "right"
    };
    st.comp.other(
        Canon::Comment(format!("interpreter: cutter radius compensation on {name}")),
        &mut sink,
    );
    st.comp.start(side, radius, st.plane)
}

fn motion(st: &mut State, b: &Block) -> Result<(), super::super::CompError> {
    for g in [0.0, 1.0, 2.0, 3.0] {
        if b.has_g(g) {
            st.motion = g;
        }
    }
    if !b.words.iter().any(|w| matches!(w.0, 'X' | 'Y' | 'Z')) {
        return Ok(());
    }
    let from = st.pos;
    let mut to = from;
    for (i, c) in ['X', 'Y', 'Z'].into_iter().enumerate() {
        if let Some(v) = b.get(c) {
            to[i] = v;
        }
    }
    let out = &mut st.out;
    let mut sink = |c: Canon| out.push(format_call(&c));
    let r = match st.motion as i64 {
        0 => st.comp.straight(MoveKind::Rapid, from, to, &mut sink),
        1 => st.comp.straight(MoveKind::Feed, from, to, &mut sink),
        g => {
            let centre = match b.get('R') {
                Some(r) => centre_from_r(from, to, r, g == 2),
                None => (
                    from[0] + b.get('I').unwrap_or(0.0),
                    from[1] + b.get('J').unwrap_or(0.0),
                ),
            };
            let turn = if g == 3 { 1 } else { -1 } * b.get('P').unwrap_or(1.0) as i64;
            st.comp.arc(from, to, centre, turn, &mut sink)
        }
    };
    st.pos = to;
    r
}

fn stops(st: &mut State, b: &Block) {
    if b.has_m(0.0) {
        emit(st, Canon::ProgramStop);
    }
    if b.has_m(1.0) {
        emit(st, Canon::OptionalProgramStop);
    }
    if b.has_m(2.0) || b.has_m(30.0) {
        let out = &mut st.out;
        st.comp.flush(&mut |c| out.push(format_call(&c)));
    }
}

/// The centre of an R-form arc, found as LinuxCNC's `arc_data_r` finds it.
fn centre_from_r(from: Pose, to: Pose, r: f64, cw: bool) -> (f64, f64) {
    let mid = ((from[0] + to[0]) / 2.0, (from[1] + to[1]) / 2.0);
    let mut half = (mid.0 - to[0]).hypot(mid.1 - to[1]);
    let abs_r = r.abs();
    if half / abs_r > 1.0 - 1e-12 {
        half = abs_r;
    }
    let dir = (to[1] - from[1]).atan2(to[0] - from[0]);
    let theta = if cw == (r > 0.0) {
        dir - std::f64::consts::FRAC_PI_2
    } else {
        dir + std::f64::consts::FRAC_PI_2
    };
    let offset = abs_r * (half / abs_r).asin().cos();
    (mid.0 + offset * theta.cos(), mid.1 + offset * theta.sin())
}
