//! The feed profile of one move: trapezoidal (constant acceleration up to
//! the feed, cruise, constant deceleration to rest), or triangular when
//! the move is too short to reach the feed. Every move starts and ends at
//! rest (no look-ahead blending across moves).

/// The profile a move runs with: trapezoidal, or jerk-limited
/// ([`super::scurve`]) when a jerk limit is given.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Profile {
    Trapezoid(Trapezoid),
    SCurve(super::scurve::SCurve),
}

impl Profile {
    /// A move `length` mm long at `speed` mm/s, with acceleration `accel`
    /// mm/s² and jerk `jerk` mm/s³ (0 or less: no limit of that kind).
    pub fn new(length: f64, speed: f64, accel: f64, jerk: f64) -> Self {
        if jerk > 0.0 && jerk.is_finite() {
            let accel = if accel > 0.0 { accel } else { f64::INFINITY };
            Profile::SCurve(super::scurve::SCurve::new(length, speed, accel, jerk))
        } else {
            Profile::Trapezoid(Trapezoid::new(length, speed, accel))
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

/// A move's speed over time: `v` mm/s at most, `a` mm/s² (0: no limit,
/// the feed from the first instant).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Trapezoid {
    length: f64,
    /// Peak speed reached, mm/s.
    peak: f64,
    accel: f64,
    /// Duration of the acceleration phase (= of the deceleration phase).
    t_acc: f64,
    /// Duration of the cruise phase.
    t_cruise: f64,
}

impl Trapezoid {
    /// The profile of a move `length` mm long at `speed` mm/s (> 0) with
    /// acceleration `accel` mm/s² (0 or less: unlimited).
    pub fn new(length: f64, speed: f64, accel: f64) -> Self {
        let length = length.max(0.0);
        if accel <= 0.0 || !accel.is_finite() {
            return Trapezoid {
                length,
                peak: speed,
                accel: 0.0,
                t_acc: 0.0,
                t_cruise: length / speed,
            };
        }
        let d_acc = speed * speed / (2.0 * accel);
        if 2.0 * d_acc <= length {
            Trapezoid {
                length,
                peak: speed,
                accel,
                t_acc: speed / accel,
                t_cruise: (length - 2.0 * d_acc) / speed,
            }
        } else {
            let peak = (length * accel).sqrt();
            Trapezoid {
                length,
                peak,
                accel,
                t_acc: peak / accel,
                t_cruise: 0.0,
            }
        }
    }

    /// The move's duration, seconds.
    pub fn duration(&self) -> f64 {
        2.0 * self.t_acc + self.t_cruise
    }

    /// The peak speed, mm/s.
    pub fn peak(&self) -> f64 {
        self.peak
    }

    /// Distance travelled and speed (mm, mm/s) `t` seconds into the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let (ta, tc) = (self.t_acc, self.t_cruise);
        let d_acc = 0.5 * self.accel * ta * ta;
        if t <= 0.0 {
            (0.0, if ta == 0.0 { self.peak } else { 0.0 })
        } else if t < ta {
            (0.5 * self.accel * t * t, self.accel * t)
        } else if t <= ta + tc {
            (d_acc + self.peak * (t - ta), self.peak)
        } else if t < 2.0 * ta + tc {
            let r = 2.0 * ta + tc - t;
            (self.length - 0.5 * self.accel * r * r, self.accel * r)
        } else {
            (self.length, 0.0)
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
