//! Angle arithmetic as LinuxCNC's interpreter does it. It adds its `M_PIl`
//! constants (long double) to doubles and stores the result as a double; we
//! reproduce that rounding with a two-part constant, so that values which
//! print as `-0.0000` there print the same here.

use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// The part of pi that does not fit in an f64.
const PI_LO: f64 = 1.2246467991473532e-16;

/// `x + k * pi/2` rounded once to f64, as `x + k*M_PI_2l` stored in a double.
pub fn add_half_pis(x: f64, k: i32) -> f64 {
    let hi = match k {
        -1 => -FRAC_PI_2,
        1 => FRAC_PI_2,
        2 => PI,
        4 => TAU,
        -4 => -TAU,
        _ => k as f64 * FRAC_PI_2,
    };
    let lo = k as f64 * PI_LO / 2.0;
    let s = x + hi;
    let bb = s - x;
    let err = (x - (s - bb)) + (hi - bb);
    s + (err + lo)
}

/// Whether the tool is inside an arc turning `turn` (+ CCW) on `left`.
pub fn tool_inside_arc(left: bool, turn: i64) -> bool {
    (left && turn > 0) || (!left && turn < 0)
}

/// The signed angle an arc sweeps from `p1` to `p2` around `c`, with
/// `turn` full or partial turns (+ CCW); 0 for `turn == 0`.
pub fn find_turn(p1: (f64, f64), c: (f64, f64), turn: i64, p2: (f64, f64)) -> f64 {
    if turn == 0 {
        return 0.0;
    }
    let mut alpha = (p1.1 - c.1).atan2(p1.0 - c.0);
    let mut beta = (p2.1 - c.1).atan2(p2.0 - c.0);
    if turn > 0 {
        if beta <= alpha {
            beta = add_half_pis(beta, 4);
        }
        (beta - alpha) + (turn - 1) as f64 * TAU
    } else {
        if alpha <= beta {
            alpha = add_half_pis(alpha, 4);
        }
        (beta - alpha) + (turn + 1) as f64 * TAU
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn adds_long_double_pi() {
        // pi (f64) + pi/2 (exact) rounds to the f64 nearest 3pi/2.
        assert_eq!(add_half_pis(0.0, 1), FRAC_PI_2);
        assert!((add_half_pis(PI, 1) - 3.0 * FRAC_PI_2).abs() < 1e-15);
        assert_eq!(add_half_pis(-FRAC_PI_2, 1), 6.123233995736766e-17);
    }

    #[test]
    fn turns() {
        let q = find_turn((1.0, 0.0), (0.0, 0.0), 1, (0.0, 1.0));
        assert!((q - FRAC_PI_2).abs() < 1e-12);
        let q = find_turn((1.0, 0.0), (0.0, 0.0), -1, (0.0, 1.0));
        assert!((q + 3.0 * FRAC_PI_2).abs() < 1e-12);
        assert_eq!(find_turn((1.0, 0.0), (0.0, 0.0), 0, (0.0, 1.0)), 0.0);
    }
}
