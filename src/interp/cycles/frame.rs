//! The plane's axes as a canned cycle sees them: two positioning axes and
//! the drilling axis (normal to the plane).

use crate::canon::Pose;
use crate::interp::host::{plane_axes, MotionHost};

/// Axis indices into a pose: positioning axes `a`, `b`; drilling axis `n`.
#[derive(Clone, Copy, Debug)]
pub struct Frame {
    pub a: usize,
    pub b: usize,
    pub n: usize,
}

impl Frame {
    pub fn of(host: &dyn MotionHost) -> Frame {
        let (a, b, n) = plane_axes(host.plane());
        Frame { a, b, n }
    }

    /// The current pose with the positioning axes and drilling axis set.
    pub fn pose(&self, host: &dyn MotionHost, at: (f64, f64), depth: f64) -> Pose {
        let mut p = host.position();
        p[self.a] = at.0;
        p[self.b] = at.1;
        p[self.n] = depth;
        p
    }

    /// Rapid to a point given in plane terms.
    pub fn rapid(&self, host: &mut dyn MotionHost, at: (f64, f64), depth: f64) {
        let p = self.pose(host, at, depth);
        host.rapid(p);
    }

    /// Feed to a point given in plane terms.
    pub fn feed(&self, host: &mut dyn MotionHost, at: (f64, f64), depth: f64) {
        let p = self.pose(host, at, depth);
        host.feed(p);
    }

    /// Where the tool is, in plane terms.
    pub fn here(&self, host: &dyn MotionHost) -> ((f64, f64), f64) {
        let p = host.position();
        ((p[self.a], p[self.b]), p[self.n])
    }
}
