//! The jerk-limited (S-curve) feed profile of one move: the acceleration
//! ramps up at the jerk limit `j` to at most `a`, holds, and ramps down
//! as the speed nears the feed; cruise; the mirror image to rest. A move
//! too short to reach the feed peaks lower (found by bisection on the
//! peak speed, whose ramp distance grows with it), and a peak below
//! `a²/j` never reaches `a` (the acceleration is a triangle). Every move
//! starts and ends at rest, as with the trapezoid ([`super::profile`]).
//!
//! For a ramp from rest to `vp`: with the acceleration reached,
//! `T = vp/a + a/j`; without, `T = 2·√(vp/j)`; the distance is `vp·T/2`
//! either way (the speed curve is symmetric about the ramp's middle).

/// A move's speed over time under a jerk and an acceleration limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SCurve {
    length: f64,
    /// Peak speed reached, mm/s.
    peak: f64,
    jerk: f64,
    /// Duration of the jerk phases (each of the four).
    t_jerk: f64,
    /// Duration of the constant-acceleration phase of each ramp.
    t_const: f64,
    /// Duration of the cruise phase.
    t_cruise: f64,
}

impl SCurve {
    /// The profile of a move `length` mm long at `speed` mm/s (> 0), with
    /// acceleration `accel` mm/s² and jerk `jerk` mm/s³ (both > 0).
    pub fn new(length: f64, speed: f64, accel: f64, jerk: f64) -> Self {
        let length = length.max(0.0);
        let ramp = |vp: f64| ramp_distance(vp, accel, jerk);
        let peak = if 2.0 * ramp(speed) <= length {
            speed
        } else {
            let (mut lo, mut hi) = (0.0, speed);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if 2.0 * ramp(mid) <= length {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        };
        let (t_jerk, t_const) = ramp_phases(peak, accel, jerk);
        let cruise = length - 2.0 * ramp(peak);
        SCurve {
            length,
            peak,
            jerk,
            t_jerk,
            t_const,
            t_cruise: if peak > 0.0 {
                (cruise / peak).max(0.0)
            } else {
                0.0
            },
        }
    }

    /// The move's duration, seconds.
    pub fn duration(&self) -> f64 {
        2.0 * self.ramp_time() + self.t_cruise
    }

    /// The peak speed, mm/s.
    pub fn peak(&self) -> f64 {
        self.peak
    }

    fn ramp_time(&self) -> f64 {
        2.0 * self.t_jerk + self.t_const
    }

    /// Distance travelled and speed (mm, mm/s) `t` seconds into the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let tr = self.ramp_time();
        let end = self.duration();
        if t <= 0.0 {
            (0.0, 0.0)
        } else if t < tr {
            self.ramp(t)
        } else if t <= tr + self.t_cruise {
            (self.ramp(tr).0 + self.peak * (t - tr), self.peak)
        } else if t < end {
            let (s, v) = self.ramp(end - t);
            (self.length - s, v)
        } else {
            (self.length, 0.0)
        }
    }

    /// Distance and speed `t` seconds into the ramp from rest.
    fn ramp(&self, t: f64) -> (f64, f64) {
        let (j, t1, t2) = (self.jerk, self.t_jerk, self.t_const);
        let a = j * t1;
        // End of the first jerk phase, then of the constant acceleration.
        let (s1, v1) = (j * t1.powi(3) / 6.0, 0.5 * j * t1 * t1);
        let (s2, v2) = (s1 + v1 * t2 + 0.5 * a * t2 * t2, v1 + a * t2);
        if t < t1 {
            (j * t.powi(3) / 6.0, 0.5 * j * t * t)
        } else if t < t1 + t2 {
            let u = t - t1;
            (s1 + v1 * u + 0.5 * a * u * u, v1 + a * u)
        } else {
            let u = (t - t1 - t2).min(t1);
            (
                s2 + v2 * u + 0.5 * a * u * u - j * u.powi(3) / 6.0,
                v2 + a * u - 0.5 * j * u * u,
            )
        }
    }
}

/// The jerk phase and constant-acceleration phase of a ramp to `vp`.
fn ramp_phases(vp: f64, accel: f64, jerk: f64) -> (f64, f64) {
    if vp * jerk >= accel * accel {
        (accel / jerk, vp / accel - accel / jerk)
    } else {
        ((vp / jerk).sqrt(), 0.0)
    }
}

/// The distance of a ramp from rest to `vp`.
fn ramp_distance(vp: f64, accel: f64, jerk: f64) -> f64 {
    let (t1, t2) = ramp_phases(vp, accel, jerk);
    vp * (2.0 * t1 + t2) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_long_move_reaches_feed_and_acceleration() {
        // 100 mm at 50 mm/s, 500 mm/s², 5000 mm/s³: each ramp is
        // 50/500 + 500/5000 = 0.2 s and 50 x 0.2 / 2 = 5 mm; 90 mm cruise
        // (1.8 s); 2.2 s in all.
        let p = SCurve::new(100.0, 50.0, 500.0, 5000.0);
        assert!((p.duration() - 2.2).abs() < 1e-12, "{}", p.duration());
        assert!((p.at(0.2).0 - 5.0).abs() < 1e-9);
        assert!((p.at(0.2).1 - 50.0).abs() < 1e-9);
        assert!((p.at(2.2).0 - 100.0).abs() < 1e-12);
    }

    #[test]
    fn a_short_move_peaks_lower() {
        // Without reaching a: T = 2 sqrt(vp/j), d = vp sqrt(vp/j); for
        // 2 mm, j = 5000: 2 vp^1.5 / sqrt(5000) = 2 gives vp = 5000^(1/3).
        let p = SCurve::new(2.0, 50.0, 500.0, 5000.0);
        let vp = 5000f64.cbrt();
        assert!((p.peak() - vp).abs() < 1e-9, "{}", p.peak());
        assert!((p.duration() - 4.0 * (vp / 5000.0).sqrt()).abs() < 1e-9);
    }

    #[test]
    fn speed_acceleration_and_jerk_stay_within_their_limits() {
        let (v, a, j) = (40.0, 300.0, 2000.0);
        for len in [0.05, 1.0, 7.0, 37.0] {
            let p = SCurve::new(len, v, a, j);
            let n = 20_000;
            let dt = p.duration() / n as f64;
            let (mut last_s, mut last_v, mut last_a) = (0.0, 0.0, 0.0);
            for i in 1..=n {
                let (s, sp) = p.at(dt * i as f64);
                let acc = (sp - last_v) / dt;
                assert!(s >= last_s - 1e-12 && sp >= -1e-12 && sp <= v + 1e-9);
                assert!(acc.abs() <= a * (1.0 + 1e-6) + 1e-6, "{len}: a {acc}");
                if i > 1 {
                    assert!(
                        ((acc - last_a) / dt).abs() <= j * 1.01 + 1e-3,
                        "{len}: jerk"
                    );
                }
                (last_s, last_v, last_a) = (s, sp, acc);
            }
            assert!((last_s - len).abs() < 1e-9, "{len}: ends at {last_s}");
        }
    }
}
