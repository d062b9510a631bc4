//! Unit conversion at the Part 21 boundary. ISO 14649 files carry
//! implicit units (Part 10, 4.2.1): speed_measure m/s, rot_speed_measure
//! rev/s with positive = counter-clockwise seen from the holder (M4). The
//! model holds mm/min, m/min and rpm positive clockwise (M3).
//!
//! Writing picks, for a model value m, a file value f whose conversion
//! gives m back exactly (so read → write → read keeps the model equal),
//! and among those the one closest to m / factor.

/// mm/min per m/s.
const FEED: f64 = 60_000.0;
/// m/min per m/s.
const CUT_SPEED: f64 = 60.0;
/// rpm (clockwise positive) per rev/s (counter-clockwise positive).
const SPINDLE: f64 = -60.0;

pub fn feed_from_file(v: f64) -> f64 {
    v * FEED
}
pub fn feed_to_file(m: f64) -> f64 {
    inverse(m, FEED)
}
pub fn cut_speed_from_file(v: f64) -> f64 {
    v * CUT_SPEED
}
pub fn cut_speed_to_file(m: f64) -> f64 {
    inverse(m, CUT_SPEED)
}
pub fn spindle_from_file(v: f64) -> f64 {
    v * SPINDLE
}
pub fn spindle_to_file(m: f64) -> f64 {
    inverse(m, SPINDLE)
}

/// A file value f with f * factor == m when one is within a few units in
/// the last place of m / factor; else m / factor.
fn inverse(m: f64, factor: f64) -> f64 {
    let guess = m / factor;
    if guess * factor == m || !guess.is_finite() {
        return guess;
    }
    let mut up = guess;
    let mut down = guess;
    for _ in 0..8 {
        up = next_up(up);
        down = next_down(down);
        if up * factor == m {
            return up;
        }
        if down * factor == m {
            return down;
        }
    }
    guess
}

fn next_up(x: f64) -> f64 {
    if x == 0.0 {
        return f64::from_bits(1);
    }
    let b = x.to_bits();
    f64::from_bits(if x > 0.0 { b + 1 } else { b - 1 })
}

fn next_down(x: f64) -> f64 {
    -next_up(-x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ex1_values() {
        assert_eq!(feed_from_file(0.04), 2400.0);
        assert_eq!(spindle_from_file(-12.0), 720.0);
    }

    #[test]
    fn inverse_reads_back_exactly() {
        for m in [2400.0, 1000.0, 333.3, 8000.0, 0.1 + 0.2, 1234.5678, 17.0] {
            assert_eq!(feed_from_file(feed_to_file(m)), m, "{m}");
            assert_eq!(spindle_from_file(spindle_to_file(m)), m, "{m}");
            assert_eq!(cut_speed_from_file(cut_speed_to_file(m)), m, "{m}");
        }
    }
}
