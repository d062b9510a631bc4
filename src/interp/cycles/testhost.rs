//! A recording [`MotionHost`] for tests: prints each call as `rs274` does,
//! and a tiny driver that turns a few lines of LinuxCNC G-code into
//! [`CycleBlock`]s so a test and the oracle can run the same program.

use super::{run_cycle, CycleMemory};
use crate::canon::{format_call, Canon, CanonPlane, CanonUnits, MotionMode, Pose};
use crate::diag::Diagnostic;
use crate::interp::cycle_io::CycleBlock;
use crate::interp::host::{MotionHost, SpindleDir};
use crate::ir::{CycleKind, DwellUnit};
use crate::span::Span;

pub struct RecHost {
    pub pos: Pose,
    pub plane: CanonPlane,
    pub units: CanonUnits,
    pub feed: f64,
    pub spindle: SpindleDir,
    pub speed: f64,
    pub path: (MotionMode, f64),
    pub out: Vec<String>,
    pub diags: Vec<Diagnostic>,
}

impl RecHost {
    pub fn new() -> Self {
        RecHost {
            pos: [0.0; 6],
            plane: CanonPlane::XY,
            units: CanonUnits::Mm,
            feed: 100.0,
            spindle: SpindleDir::Cw,
            speed: 500.0,
            path: (MotionMode::Continuous(0.0), 0.0),
            out: Vec::new(),
            diags: Vec::new(),
        }
    }

    pub fn text(&self) -> String {
        let mut s = self.out.join("\n");
        for d in &self.diags {
            s.push_str(&format!("\nerror: {}", d.message));
        }
        s
    }
}

impl MotionHost for RecHost {
    fn position(&self) -> Pose {
        self.pos
    }
    fn plane(&self) -> CanonPlane {
        self.plane
    }
    fn units(&self) -> CanonUnits {
        self.units
    }
    fn feed_rate(&self) -> f64 {
        self.feed
    }
    fn rapid(&mut self, to: Pose) {
        self.pos = to;
        self.out.push(format_call(&Canon::StraightTraverse(to)));
    }
    fn feed(&mut self, to: Pose) {
        self.pos = to;
        self.out.push(format_call(&Canon::StraightFeed(to)));
    }
    fn arc(&mut self, _to: Pose, _center: (f64, f64), _rotation: i64) {
        self.out.push("ARC (not expected from cycles)".into());
    }
    fn dwell(&mut self, seconds: f64) {
        self.out.push(format_call(&Canon::Dwell(seconds)));
    }
    fn emit(&mut self, call: Canon) {
        match call {
            Canon::SpindleCw => self.spindle = SpindleDir::Cw,
            Canon::SpindleCcw => self.spindle = SpindleDir::Ccw,
            Canon::StopSpindle => self.spindle = SpindleDir::Stopped,
            Canon::SetFeedRate(f) => self.feed = f,
            _ => {}
        }
        self.out.push(format_call(&call));
    }
    fn report(&mut self, diag: Diagnostic) {
        self.diags.push(diag);
    }
    fn spindle(&self) -> SpindleDir {
        self.spindle
    }
    fn spindle_speed(&self) -> f64 {
        self.speed
    }
    fn assume_position(&mut self, to: Pose) {
        self.pos = to;
    }
    fn path_mode(&self) -> (MotionMode, f64) {
        self.path
    }
}

/// Modal state of the little driver.
struct Driver {
    host: RecHost,
    mem: CycleMemory,
    kind: Option<CycleKind>,
    incremental: bool,
    return_initial: bool,
    recording: bool,
    p_unit: DwellUnit,
}

fn words(line: &str) -> Vec<(char, f64)> {
    let clean: String = line
        .split('(')
        .next()
        .unwrap_or("")
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    let mut out = Vec::new();
    let mut chars = clean.chars().peekable();
    while let Some(c) = chars.next() {
        let mut num = String::new();
        while let Some(&d) = chars.peek() {
            if d.is_ascii_digit() || d == '.' || d == '-' || d == '+' {
                num.push(d);
                chars.next();
            } else {
                break;
            }
        }
        out.push((c.to_ascii_uppercase(), num.parse().unwrap_or(0.0)));
    }
    out
}

fn cycle_of(g: f64) -> Option<CycleKind> {
    use CycleKind::*;
    Some(match g as i64 {
        73 => ChipBreak,
        74 => TapLeft,
        76 => FineBore,
        81 => Drill,
        82 => DrillDwell,
        83 => Peck,
        84 => Tap,
        85 => BoreFeedOut,
        86 => BoreStopRapidOut,
        87 => BackBore,
        88 => BoreManual,
        89 => BoreDwellFeedOut,
        _ => return None,
    })
}

impl Driver {
    fn line(&mut self, line: &str) {
        if line.contains("(CYCLES)") {
            self.recording = true;
            self.host.out.clear();
            return;
        }
        let ws = words(line);
        let mut code_in_block = false;
        let mut g0 = false;
        for (c, v) in &ws {
            match (c, *v) {
                ('G', v) if v == 20.0 => self.host.units = CanonUnits::Inches,
                ('G', v) if v == 21.0 => self.host.units = CanonUnits::Mm,
                ('G', v) if v == 17.0 => {
                    self.host.plane = CanonPlane::XY;
                    self.host.emit(Canon::SelectPlane(CanonPlane::XY));
                }
                ('G', v) if v == 18.0 => {
                    self.host.plane = CanonPlane::XZ;
                    self.host.emit(Canon::SelectPlane(CanonPlane::XZ));
                }
                ('G', v) if v == 19.0 => {
                    self.host.plane = CanonPlane::YZ;
                    self.host.emit(Canon::SelectPlane(CanonPlane::YZ));
                }
                ('G', v) if v == 90.0 => self.incremental = false,
                ('G', v) if v == 91.0 => self.incremental = true,
                ('G', v) if v == 98.0 => self.return_initial = true,
                ('G', v) if v == 99.0 => self.return_initial = false,
                ('G', v) if v == 0.0 => g0 = true,
                ('G', v) if v == 80.0 => {
                    self.kind = None;
                    self.mem.cancel();
                }
                ('G', v) if v == 64.0 => {
                    self.host.path = (MotionMode::Continuous(word(&ws, 'P')), word(&ws, 'Q'))
                }
                ('G', v) => {
                    self.kind = cycle_of(v);
                    code_in_block = true;
                }
                ('F', v) => self.host.feed = v,
                ('S', v) => self.host.speed = v,
                ('M', v) if v == 3.0 => self.host.emit(Canon::SpindleCw),
                ('M', v) if v == 4.0 => self.host.emit(Canon::SpindleCcw),
                ('M', v) if v == 5.0 => self.host.emit(Canon::StopSpindle),
                _ => {}
            }
        }
        if g0 {
            self.g0(&ws);
        } else if let Some(kind) = self.kind {
            if ws.iter().any(|(c, _)| "XYZR".contains(*c)) {
                let b = self.block(kind, &ws, code_in_block);
                run_cycle(&mut self.host, &mut self.mem, &b);
            }
        }
    }

    fn g0(&mut self, ws: &[(char, f64)]) {
        self.kind = None;
        self.mem.cancel();
        let mut p = self.host.pos;
        for (c, v) in ws {
            if let Some(i) = "XYZ".find(*c) {
                p[i] = *v;
            }
        }
        self.host.rapid(p);
    }

    fn block(&self, kind: CycleKind, ws: &[(char, f64)], code_in_block: bool) -> CycleBlock {
        let get = |c: char| ws.iter().rev().find(|(w, _)| *w == c).map(|(_, v)| *v);
        CycleBlock {
            kind,
            axes: [get('X'), get('Y'), get('Z'), None, None, None],
            r: get('R'),
            q: get('Q'),
            p: get('P'),
            p_unit: self.p_unit,
            repeat: get('L'),
            i: get('I'),
            j: get('J'),
            k: get('K'),
            incremental: self.incremental,
            return_initial: self.return_initial,
            words_required: true,
            r_above_bottom: true,
            rotary_refused: true,
            code_in_block,
            polar_step: None,
            shift: None,
            span: Span::default(),
        }
    }
}

fn word(ws: &[(char, f64)], c: char) -> f64 {
    ws.iter()
        .find(|(w, _)| *w == c)
        .map(|(_, v)| *v)
        .unwrap_or(0.0)
}

/// Runs a program through the driver; returns the calls made after the
/// `(CYCLES)` line, and the error messages.
pub fn drive(program: &str, p_unit: DwellUnit) -> String {
    let mut d = Driver {
        host: RecHost::new(),
        mem: CycleMemory::new(),
        kind: None,
        incremental: false,
        return_initial: true,
        recording: false,
        p_unit,
    };
    d.host.spindle = SpindleDir::Stopped;
    for line in program.lines() {
        if line.contains("(END)") || !d.host.diags.is_empty() {
            break;
        }
        d.line(line);
    }
    d.host.text()
}
