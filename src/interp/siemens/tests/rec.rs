//! A recording [`MotionHost`] double: prints each call as rs274 does.

use crate::canon::{format_call, Canon, CanonPlane, CanonUnits, Pose};
use crate::diag::Diagnostic;
use crate::interp::host::{plane_axes, MotionHost, SpindleDir};
use crate::interp::siemens::milling;

pub struct Rec {
    pub pos: Pose,
    pub plane: CanonPlane,
    pub feed: f64,
    pub out: Vec<String>,
    pub diags: Vec<Diagnostic>,
}

impl Rec {
    pub fn new() -> Rec {
        Rec {
            pos: [0.0; 6],
            plane: CanonPlane::XY,
            feed: 100.0,
            out: Vec::new(),
            diags: Vec::new(),
        }
    }

    pub fn text(&self) -> String {
        let mut s = self.out.join("\n");
        for d in &self.diags {
            s.push_str(&format!("\n{}: {}", d.code.code(), d.message));
        }
        s
    }
}

impl MotionHost for Rec {
    fn position(&self) -> Pose {
        self.pos
    }
    fn plane(&self) -> CanonPlane {
        self.plane
    }
    fn units(&self) -> CanonUnits {
        CanonUnits::Mm
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
    fn arc(&mut self, to: Pose, center: (f64, f64), rotation: i64) {
        let (a, b, n) = plane_axes(self.plane);
        self.pos = to;
        self.out.push(format_call(&Canon::ArcFeed {
            first_end: to[a],
            second_end: to[b],
            first_axis: center.0,
            second_axis: center.1,
            rotation,
            axis_end: to[n],
            abc: [to[3], to[4], to[5]],
        }));
    }
    fn dwell(&mut self, seconds: f64) {
        self.out.push(format_call(&Canon::Dwell(seconds)));
    }
    fn emit(&mut self, call: Canon) {
        if let Canon::SetFeedRate(f) = call {
            self.feed = f;
        }
        self.out.push(format_call(&call));
    }
    fn report(&mut self, diag: Diagnostic) {
        self.diags.push(diag);
    }
    fn spindle(&self) -> SpindleDir {
        SpindleDir::Cw
    }
    fn spindle_speed(&self) -> f64 {
        1000.0
    }
}

/// Runs one milling cycle on a recording host starting at Z50 (NaN in
/// `args` = an omitted parameter): the moves, then how it ended.
pub fn mill(name: &str, args: &[f64], radius: f64) -> String {
    let mut rec = Rec::new();
    rec.pos = [0.0, 0.0, 50.0, 0.0, 0.0, 0.0];
    let a: Vec<Option<f64>> = args
        .iter()
        .map(|x| if x.is_nan() { None } else { Some(*x) })
        .collect();
    match milling::run(&mut rec, name, &a, radius) {
        Ok(milling::Outcome::Done) => rec.text(),
        Ok(milling::Outcome::NotExpanded(why)) => format!("{}\nnot expanded: {why}", rec.text()),
        Err(d) => format!("{}\nerror {}: {}", rec.text(), d.code.code(), d.message),
    }
}
