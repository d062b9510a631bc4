//! [`Pen`]: moves of a milling cycle in its own plane coordinates
//! (`u`, `v` in the plane, `w` along the tool axis), placed by an origin
//! and an angle in the active plane, with the cycle's feeds.

use crate::canon::Canon;
use crate::interp::host::{plane_axes, MotionHost};

pub struct Pen {
    a: usize,
    b: usize,
    n: usize,
    origin: (f64, f64),
    cos: f64,
    sin: f64,
    /// The feed rate last set by the cycle (None: the caller's).
    feed: Option<f64>,
    /// The caller's feed rate, restored at the end.
    saved: f64,
}

impl Pen {
    pub fn new(host: &dyn MotionHost, origin: (f64, f64), angle_deg: f64) -> Pen {
        let (a, b, n) = plane_axes(host.plane());
        let (sin, cos) = angle_deg.to_radians().sin_cos();
        let (sin, cos) = (crate::geom::snap(sin), crate::geom::snap(cos));
        Pen {
            a,
            b,
            n,
            origin,
            cos,
            sin,
            feed: None,
            saved: host.feed_rate(),
        }
    }

    /// A cycle point in plane coordinates.
    pub fn place(&self, u: f64, v: f64) -> (f64, f64) {
        (
            self.origin.0 + u * self.cos - v * self.sin,
            self.origin.1 + u * self.sin + v * self.cos,
        )
    }

    fn pose(&self, host: &dyn MotionHost, u: f64, v: f64, w: f64) -> crate::canon::Pose {
        let (x, y) = self.place(u, v);
        let mut p = host.position();
        p[self.a] = x;
        p[self.b] = y;
        p[self.n] = w;
        p
    }

    /// Where the tool is along the tool axis.
    pub fn depth(&self, host: &dyn MotionHost) -> f64 {
        host.position()[self.n]
    }

    pub fn rapid(&self, host: &mut dyn MotionHost, u: f64, v: f64, w: f64) {
        let p = self.pose(host, u, v, w);
        if p != host.position() {
            host.rapid(p);
        }
    }

    /// Rapid along the tool axis only.
    pub fn rapid_w(&self, host: &mut dyn MotionHost, w: f64) {
        let mut p = host.position();
        if p[self.n] != w {
            p[self.n] = w;
            host.rapid(p);
        }
    }

    pub fn set_feed(&mut self, host: &mut dyn MotionHost, f: f64) {
        if f > 0.0 && self.feed != Some(f) {
            host.emit(Canon::SetFeedRate(f));
            self.feed = Some(f);
        }
    }

    pub fn feed(&self, host: &mut dyn MotionHost, u: f64, v: f64, w: f64) {
        let p = self.pose(host, u, v, w);
        if p != host.position() {
            host.feed(p);
        }
    }

    /// An arc in the plane to (u, v) about (cu, cv); ccw in cycle terms.
    pub fn arc(&self, host: &mut dyn MotionHost, u: f64, v: f64, cu: f64, cv: f64, ccw: bool) {
        let w = self.depth(host);
        let p = self.pose(host, u, v, w);
        host.arc(p, self.place(cu, cv), if ccw { 1 } else { -1 });
    }

    /// Sets the caller's feed rate again if the cycle changed it.
    pub fn restore(&mut self, host: &mut dyn MotionHost) {
        if self.feed.is_some_and(|f| f != self.saved) && self.saved > 0.0 {
            host.emit(Canon::SetFeedRate(self.saved));
        }
        self.feed = None;
    }
}
