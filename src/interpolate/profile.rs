//! The feed profile of one move: trapezoidal (constant acceleration up to
//! the feed, cruise, constant deceleration), or triangular when the move
//! is too short to reach the feed. A move starts at the speed it enters
//! with and ends at the speed it leaves with (both 0 without look-ahead;
//! the look-ahead planner, [`super::lookahead`], chooses them).

/// The profile a move runs with: trapezoidal, or jerk-limited
/// ([`super::scurve`]) when a jerk limit is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    Trapezoid(Trapezoid),
    SCurve(super::scurve::SCurve),
}

/// The limits a profile keeps: acceleration mm/s² and jerk mm/s³ (0 or
/// less: no limit of that kind).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    pub accel: f64,
    pub jerk: f64,
}

impl Limits {
    fn scurve(&self) -> bool {
        self.jerk > 0.0 && self.jerk.is_finite()
    }

    fn accel_or_inf(&self) -> f64 {
        if self.accel > 0.0 && self.accel.is_finite() {
            self.accel
        } else {
            f64::INFINITY
        }
    }

    /// The highest speed a move `length` mm long can end at when it starts
    /// at `v0` mm/s (by symmetry also the highest it can start at to end at
    /// `v0`), mm/s; infinite with no acceleration limit.
    pub fn reach(&self, v0: f64, length: f64) -> f64 {
        let a = self.accel_or_inf();
        if self.scurve() {
            super::scurve::reach(v0, length, a, self.jerk)
        } else if a.is_finite() {
            (v0 * v0 + 2.0 * a * length).sqrt()
        } else {
            f64::INFINITY
        }
    }
}

impl Profile {
    /// A move `length` mm long at `speed` mm/s, with acceleration `accel`
    /// mm/s² and jerk `jerk` mm/s³ (0 or less: no limit of that kind),
    /// from rest to rest.
    pub fn new(length: f64, speed: f64, accel: f64, jerk: f64) -> Self {
        Self::between(length, 0.0, speed, 0.0, Limits { accel, jerk })
    }

    /// A move `length` mm long at `speed` mm/s at most, entered at `v0`
    /// and left at `v1` mm/s (the planner keeps them reachable: `v1` at
    /// most `reach(v0, length)` and `v0` at most `reach(v1, length)`).
    pub fn between(length: f64, v0: f64, speed: f64, v1: f64, lim: Limits) -> Self {
        if lim.scurve() {
            Profile::SCurve(super::scurve::SCurve::between(
                length,
                v0,
                speed,
                v1,
                lim.accel_or_inf(),
                lim.jerk,
            ))
        } else {
            Profile::Trapezoid(Trapezoid::between(length, v0, speed, v1, lim.accel))
        }
    }

    /// The move's duration, seconds.
    pub fn duration(&self) -> f64 {
        match self {
            Profile::Trapezoid(p) => p.duration(),
            Profile::SCurve(p) => p.duration(),
        }
    }

    /// Distance travelled and speed (mm, mm/s) `t` seconds into the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        match self {
            Profile::Trapezoid(p) => p.at(t),
            Profile::SCurve(p) => p.at(t),
        }
    }
}

/// A move's speed over time: from `v0` up to `peak` (at most the feed) at
/// `accel` mm/s², cruise, down to `v1` (accel 0: no limit, the feed from
/// the first instant).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trapezoid {
    length: f64,
    v0: f64,
    v1: f64,
    /// Peak speed reached, mm/s.
    peak: f64,
    accel: f64,
    /// Durations of the acceleration, cruise and deceleration phases.
    t_acc: f64,
    t_cruise: f64,
    t_dec: f64,
}

impl Trapezoid {
    /// The profile of a move `length` mm long at `speed` mm/s (> 0) with
    /// acceleration `accel` mm/s² (0 or less: unlimited), from rest to
    /// rest.
    pub fn new(length: f64, speed: f64, accel: f64) -> Self {
        Self::between(length, 0.0, speed, 0.0, accel)
    }

    /// From `v0` to `v1` (mm/s, at most `speed`): the peak is the feed
    /// when the move is long enough, else `√((2aL + v0² + v1²)/2)`.
    pub fn between(length: f64, v0: f64, speed: f64, v1: f64, accel: f64) -> Self {
        let length = length.max(0.0);
        if accel <= 0.0 || !accel.is_finite() {
            return Trapezoid {
                length,
                v0: speed,
                v1: speed,
                peak: speed,
                accel: 0.0,
                t_acc: 0.0,
                t_cruise: length / speed,
                t_dec: 0.0,
            };
        }
        let (v0, v1) = (v0.clamp(0.0, speed), v1.clamp(0.0, speed));
        let peak = ((2.0 * accel * length + v0 * v0 + v1 * v1) / 2.0)
            .sqrt()
            .min(speed)
            .max(v0.max(v1));
        let d_acc = (peak * peak - v0 * v0) / (2.0 * accel);
        let d_dec = (peak * peak - v1 * v1) / (2.0 * accel);
        Trapezoid {
            length,
            v0,
            v1,
            peak,
            accel,
            t_acc: (peak - v0) / accel,
            t_cruise: if peak > 0.0 {
                ((length - d_acc - d_dec) / peak).max(0.0)
            } else {
                0.0
            },
            t_dec: (peak - v1) / accel,
        }
    }

    /// The move's duration, seconds.
    pub fn duration(&self) -> f64 {
        self.t_acc + self.t_cruise + self.t_dec
    }

    /// The peak speed, mm/s.
    pub fn peak(&self) -> f64 {
        self.peak
    }

    /// Distance travelled and speed (mm, mm/s) `t` seconds into the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let (ta, tc, a) = (self.t_acc, self.t_cruise, self.accel);
        let end = self.duration();
        if t <= 0.0 {
            (0.0, self.v0)
        } else if t < ta {
            (self.v0 * t + 0.5 * a * t * t, self.v0 + a * t)
        } else if t <= ta + tc {
            let d_acc = if ta > 0.0 {
                (self.peak * self.peak - self.v0 * self.v0) / (2.0 * a)
            } else {
                0.0
            };
            (d_acc + self.peak * (t - ta), self.peak)
        } else if t < end {
            let r = end - t;
            (
                self.length - (self.v1 * r + 0.5 * a * r * r),
                self.v1 + a * r,
            )
        } else {
            (self.length, self.v1)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trapezoid_and_triangle_times() {
        // 100 mm at 50 mm/s, 500 mm/s²: 0.1 s up, 0.1 s down, 2.5 mm
        // each, 95 mm cruising (1.9 s).
        let p = Trapezoid::new(100.0, 50.0, 500.0);
        assert!((p.duration() - 2.1).abs() < 1e-12);
        assert!((p.at(0.1).0 - 2.5).abs() < 1e-12);
        assert!((p.at(2.1).0 - 100.0).abs() < 1e-12);
        // 1 mm: never reaches 50 mm/s; peak sqrt(500) mm/s.
        let q = Trapezoid::new(1.0, 50.0, 500.0);
        assert!((q.peak() - 500f64.sqrt()).abs() < 1e-12);
        assert!((q.duration() - 2.0 * 500f64.sqrt() / 500.0).abs() < 1e-12);
        assert!((q.at(q.duration() / 2.0).0 - 0.5).abs() < 1e-12);
        // Entered at 30 and left at 10 mm/s: up to the feed over
        // (50²-30²)/1000 = 1.6 mm, down over 2.4 mm, 6 mm cruising.
        let r = Trapezoid::between(10.0, 30.0, 50.0, 10.0, 500.0);
        assert!((r.duration() - (0.04 + 0.12 + 0.08)).abs() < 1e-12);
        assert_eq!(r.at(0.0).1, 30.0);
        assert!((r.at(r.duration()).1 - 10.0).abs() < 1e-12);
        assert!((r.at(0.16).0 - 7.6).abs() < 1e-12);
        // No acceleration limit: length / speed.
        assert!((Trapezoid::new(10.0, 5.0, 0.0).duration() - 2.0).abs() < 1e-12);
    }

    #[test]
    fn distance_is_monotone_and_continuous() {
        let p = Trapezoid::new(37.0, 40.0, 300.0);
        let mut last = 0.0;
        for i in 0..=1000 {
            let (s, v) = p.at(p.duration() * i as f64 / 1000.0);
            assert!(s >= last - 1e-12 && v >= 0.0 && v <= 40.0 + 1e-9);
            last = s;
        }
        assert!((last - 37.0).abs() < 1e-9);
    }
}
