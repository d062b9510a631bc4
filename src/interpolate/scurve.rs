//! The jerk-limited (S-curve) feed profile of one move: the acceleration
//! ramps up at the jerk limit `j` to at most `a`, holds, and ramps down
//! as the speed nears the feed; cruise; the mirror image down to the exit
//! speed. A move too short to reach the feed peaks lower (found by
//! bisection on the peak speed, whose ramp distances grow with it), and a
//! speed change below `a²/j` never reaches `a` (the acceleration is a
//! triangle). A move starts at its entry speed and ends at its exit speed
//! (both 0 without look-ahead) with zero acceleration at both ends, so
//! consecutive moves join without a step in acceleration.
//!
//! For a ramp from `v0` to `v1` (change `Δ = |v1 − v0|`): with the
//! acceleration reached, `T = Δ/a + a/j`; without, `T = 2·√(Δ/j)`; the
//! distance is `(v0 + v1)·T/2` either way (the speed curve is symmetric
//! about the ramp's middle).

/// A move's speed over time under a jerk and an acceleration limit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SCurve {
    length: f64,
    v0: f64,
    v1: f64,
    /// Peak speed reached, mm/s.
    peak: f64,
    jerk: f64,
    /// Jerk phase and constant-acceleration phase of the ramp up (from
    /// `v0`) and of the ramp down (to `v1`).
    up: (f64, f64),
    down: (f64, f64),
    /// Duration of the cruise phase.
    t_cruise: f64,
}

impl SCurve {
    /// The profile of a move `length` mm long at `speed` mm/s (> 0), with
    /// acceleration `accel` mm/s² and jerk `jerk` mm/s³ (both > 0), from
    /// rest to rest.
    pub fn new(length: f64, speed: f64, accel: f64, jerk: f64) -> Self {
        Self::between(length, 0.0, speed, 0.0, accel, jerk)
    }

    /// Entered at `v0` and left at `v1` mm/s (at most `speed`).
    pub fn between(length: f64, v0: f64, speed: f64, v1: f64, accel: f64, jerk: f64) -> Self {
        let length = length.max(0.0);
        let (v0, v1) = (v0.clamp(0.0, speed), v1.clamp(0.0, speed));
        let both =
            |vp: f64| ramp_distance(v0, vp, accel, jerk) + ramp_distance(vp, v1, accel, jerk);
        let floor = v0.max(v1);
        let peak = if both(speed) <= length {
            speed
        } else {
            let (mut lo, mut hi) = (floor, speed);
            for _ in 0..100 {
                let mid = 0.5 * (lo + hi);
                if both(mid) <= length {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            lo
        };
        let cruise = length - both(peak);
        SCurve {
            length,
            v0,
            v1,
            peak,
            jerk,
            up: ramp_phases(peak - v0, accel, jerk),
            down: ramp_phases(peak - v1, accel, jerk),
            t_cruise: if peak > 0.0 {
                (cruise / peak).max(0.0)
            } else {
                0.0
            },
        }
    }

    /// The move's duration, seconds.
    pub fn duration(&self) -> f64 {
        ramp_time(self.up) + self.t_cruise + ramp_time(self.down)
    }

    /// The peak speed, mm/s.
    pub fn peak(&self) -> f64 {
        self.peak
    }

    /// Distance travelled and speed (mm, mm/s) `t` seconds into the move.
    pub fn at(&self, t: f64) -> (f64, f64) {
        let tu = ramp_time(self.up);
        let end = self.duration();
        if t <= 0.0 {
            (0.0, self.v0)
        } else if t < tu {
            self.ramp(self.v0, self.up, t)
        } else if t <= tu + self.t_cruise {
            (
                self.ramp(self.v0, self.up, tu).0 + self.peak * (t - tu),
                self.peak,
            )
        } else if t < end {
            let (s, v) = self.ramp(self.v1, self.down, end - t);
            (self.length - s, v)
        } else {
            (self.length, self.v1)
        }
    }

    /// Distance and speed `t` seconds into a ramp up from `v0` with the
    /// phases `(t1, t2)` (the ramp down, run backwards from its end, is
    /// such a ramp from the exit speed).
    fn ramp(&self, v0: f64, (t1, t2): (f64, f64), t: f64) -> (f64, f64) {
        let j = self.jerk;
        let t = t.min(2.0 * t1 + t2);
        let a = j * t1;
        // End of the first jerk phase, then of the constant acceleration.
        let (s1, w1) = (j * t1.powi(3) / 6.0, 0.5 * j * t1 * t1);
        let (s2, w2) = (s1 + w1 * t2 + 0.5 * a * t2 * t2, w1 + a * t2);
        let (s, w) = if t < t1 {
            (j * t.powi(3) / 6.0, 0.5 * j * t * t)
        } else if t < t1 + t2 {
            let u = t - t1;
            (s1 + w1 * u + 0.5 * a * u * u, w1 + a * u)
        } else {
            let u = (t - t1 - t2).min(t1);
            (
                s2 + w2 * u + 0.5 * a * u * u - j * u.powi(3) / 6.0,
                w2 + a * u - 0.5 * j * u * u,
            )
        };
        (s + v0 * t, w + v0)
    }
}

fn ramp_time((t1, t2): (f64, f64)) -> f64 {
    2.0 * t1 + t2
}

/// The jerk phase and constant-acceleration phase of a ramp changing the
/// speed by `dv` (≥ 0).
fn ramp_phases(dv: f64, accel: f64, jerk: f64) -> (f64, f64) {
    let dv = dv.max(0.0);
    if dv * jerk >= accel * accel {
        (accel / jerk, dv / accel - accel / jerk)
    } else {
        ((dv / jerk).sqrt(), 0.0)
    }
}

/// The distance of a ramp between the speeds `va` and `vb` (either way).
fn ramp_distance(va: f64, vb: f64, accel: f64, jerk: f64) -> f64 {
    0.5 * (va + vb) * ramp_time(ramp_phases((vb - va).abs(), accel, jerk))
}

/// The highest speed reachable from `v0` over `length` mm (the inverse of
/// [`ramp_distance`] in its upper speed), mm/s.
pub fn reach(v0: f64, length: f64, accel: f64, jerk: f64) -> f64 {
    let length = length.max(0.0);
    let knee = accel * accel / jerk;
    if accel.is_finite() && ramp_distance(v0, v0 + knee, accel, jerk) <= length {
        // (2 v0 + Δ)(Δ/a + a/j) = 2L: Δ² + Δ(2 v0 + a²/j) + 2 v0 a²/j − 2aL = 0.
        let b = 2.0 * v0 + knee;
        let c = 2.0 * v0 * knee - 2.0 * accel * length;
        v0 + 0.5 * (-b + (b * b - 4.0 * c).max(0.0).sqrt())
    } else {
        // (2 v0 + s²)·s = L√j with s = √Δ: Newton from above (the cubic
        // is convex and increasing for s > 0).
        let k = length * jerk.sqrt();
        let mut s = k.cbrt();
        for _ in 0..60 {
            let f = s * s * s + 2.0 * v0 * s - k;
            let next = s - f / (3.0 * s * s + 2.0 * v0);
            if !(next < s) || next <= 0.0 {
                break;
            }
            s = next;
        }
        v0 + s * s
    }
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

    #[test]
    fn reach_inverts_the_ramp_distance() {
        let (a, j) = (300.0, 2000.0);
        for v0 in [0.0, 3.0, 40.0] {
            for len in [0.001, 0.3, 5.0, 80.0] {
                let v = reach(v0, len, a, j);
                let d = ramp_distance(v0, v, a, j);
                assert!((d - len).abs() < 1e-9 * len.max(1.0), "{v0} {len}: {d}");
            }
        }
        // Entered at 10, left at 20 mm/s: continuous at both ends.
        let p = SCurve::between(3.0, 10.0, 40.0, 20.0, a, j);
        assert_eq!(p.at(0.0).1, 10.0);
        assert!((p.at(p.duration() - 1e-9).1 - 20.0).abs() < 1e-6);
        assert!((p.at(p.duration()).0 - 3.0).abs() < 1e-12);
    }
}
