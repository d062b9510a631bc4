//! [`FramedHost`]: the interpreter's [`MotionHost`] seen through the
//! programmable frame. Cycles compute in programmed coordinates (a Siemens
//! cycle works in the frame in force); the interpreter's own host works in
//! the base (work offset) frame, where positions are printed.

use super::frame::ProgFrame;
use crate::canon::{Canon, CanonPlane, CanonUnits, MotionMode, Pose};
use crate::diag::{Code, Diagnostic};
use crate::interp::host::{plane_axes, MotionHost, SpindleDir};

/// Wraps a base-frame host; every position crosses the frame.
pub struct FramedHost<'h> {
    pub inner: &'h mut dyn MotionHost,
    pub frame: ProgFrame,
    /// mm per program unit (the frame is kept in mm).
    pub scale: f64,
}

impl<'h> FramedHost<'h> {
    pub fn new(inner: &'h mut dyn MotionHost, frame: ProgFrame, scale: f64) -> Self {
        FramedHost {
            inner,
            frame,
            scale,
        }
    }

    fn xyz_mm(&self, p: &Pose) -> [f64; 3] {
        [p[0] * self.scale, p[1] * self.scale, p[2] * self.scale]
    }

    fn with_xyz(&self, p: &Pose, q: [f64; 3]) -> Pose {
        [
            q[0] / self.scale,
            q[1] / self.scale,
            q[2] / self.scale,
            p[3],
            p[4],
            p[5],
        ]
    }

    /// A programmed pose in the base frame.
    pub fn out(&self, p: &Pose) -> Pose {
        self.with_xyz(p, self.frame.to_base(self.xyz_mm(p)))
    }
}

impl MotionHost for FramedHost<'_> {
    fn position(&self) -> Pose {
        let b = self.inner.position();
        match self.frame.from_base(self.xyz_mm(&b)) {
            Some(q) => self.with_xyz(&b, q),
            None => b,
        }
    }
    fn plane(&self) -> CanonPlane {
        self.inner.plane()
    }
    fn units(&self) -> CanonUnits {
        self.inner.units()
    }
    fn feed_rate(&self) -> f64 {
        self.inner.feed_rate()
    }
    fn rapid(&mut self, to: Pose) {
        let p = self.out(&to);
        self.inner.rapid(p);
    }
    fn feed(&mut self, to: Pose) {
        let p = self.out(&to);
        self.inner.feed(p);
    }
    fn arc(&mut self, to: Pose, center: (f64, f64), rotation: i64) {
        let (a, b, n) = plane_axes(self.inner.plane());
        let end = self.out(&to);
        match self.frame.arc_map(a, b, n) {
            Ok(flip) => {
                let mut c = to;
                c[a] = center.0;
                c[b] = center.1;
                let cb = self.out(&c);
                self.inner
                    .arc(end, (cb[a], cb[b]), if flip { -rotation } else { rotation });
            }
            Err(why) => {
                self.inner.report(
                    Diagnostic::new(Code::UnsupportedHere, why)
                        .help("the arc was cut as a straight line"),
                );
                self.inner.feed(end);
            }
        }
    }
    fn dwell(&mut self, seconds: f64) {
        self.inner.dwell(seconds);
    }
    fn emit(&mut self, call: Canon) {
        let call = match call {
            Canon::RigidTap { x, y, z } => {
                let p = self.out(&[x, y, z, 0.0, 0.0, 0.0]);
                Canon::RigidTap {
                    x: p[0],
                    y: p[1],
                    z: p[2],
                }
            }
            other => other,
        };
        self.inner.emit(call);
    }
    fn report(&mut self, diag: Diagnostic) {
        self.inner.report(diag);
    }
    fn spindle(&self) -> SpindleDir {
        self.inner.spindle()
    }
    fn spindle_speed(&self) -> f64 {
        self.inner.spindle_speed()
    }
    fn path_mode(&self) -> (MotionMode, f64) {
        self.inner.path_mode()
    }
    fn assume_position(&mut self, to: Pose) {
        let p = self.out(&to);
        self.inner.assume_position(p);
    }
    fn overrides_enabled(&self) -> (bool, bool) {
        self.inner.overrides_enabled()
    }
}
