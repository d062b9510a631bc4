//! Number formatting for writers, by the target's [`NumberRules`]: lengths
//! with the decimal point where the target needs one (`X10.`), at most the
//! target's decimal places, never `-0`; integers where a word takes one.
//! A number the target cannot write exactly is an error, never rounded.

use crate::dialect::NumberRules;
use crate::ir::{Decimal, LengthUnit};

/// What a number is, which decides how it is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumKind {
    /// Axes, arc centres and radii, cycle planes and depths.
    Length,
    /// Feeds and spindle speeds.
    Feed,
    /// Angles (rotations, polar angles, opening angles).
    Angle,
    /// Codes, registers, counts, milliseconds: whole numbers only.
    Int,
    /// Anything else: written exactly, minimally.
    Plain,
}

/// Writes `d` as `kind` under `rules` in `units`; `Err` says why it cannot.
/// `units` is `None` before the program says its units (G20/G21): lengths
/// then get the larger of the two precisions.
pub fn format_number(
    d: Decimal,
    kind: NumKind,
    rules: &NumberRules,
    units: Option<LengthUnit>,
) -> Result<String, String> {
    let mut s = String::with_capacity(16);
    format_number_into(&mut s, d, kind, rules, units)?;
    Ok(s)
}

/// [`format_number`] appended to `out` (left as it was on `Err`).
pub fn format_number_into(
    out: &mut String,
    d: Decimal,
    kind: NumKind,
    rules: &NumberRules,
    units: Option<LengthUnit>,
) -> Result<(), String> {
    let n = d.normalized();
    let (places, point) = match kind {
        NumKind::Length => (Some(length_places(rules, units)), rules.point_on_lengths),
        NumKind::Angle => (Some(rules.angle_places), rules.point_on_lengths),
        NumKind::Feed => (Some(rules.feed_places), false),
        NumKind::Int => (Some(0), false),
        NumKind::Plain => (None, false),
    };
    if let Some(p) = places {
        if n.scale > p {
            return Err(match kind {
                NumKind::Int => format!("`{d}` is not a whole number"),
                _ => format!(
                    "`{d}` has {} decimal places; the target writes at most {p}",
                    n.scale
                ),
            });
        }
    }
    n.format_into(out, 0, point);
    Ok(())
}

fn length_places(rules: &NumberRules, units: Option<LengthUnit>) -> u8 {
    match units {
        Some(LengthUnit::Mm) => rules.length_places_mm,
        Some(LengthUnit::Inch) => rules.length_places_inch,
        None => rules.length_places_mm.max(rules.length_places_inch),
    }
}

/// `d * 10^shift` exactly (shift may be negative), if it fits.
pub fn shift_decimal(d: Decimal, shift: i32) -> Option<Decimal> {
    let n = d.normalized();
    if shift >= 0 {
        let mut m = n.mantissa;
        let mut scale = n.scale as i32;
        let mut left = shift;
        while left > 0 && scale > 0 {
            scale -= 1;
            left -= 1;
        }
        m = m.checked_mul(10i64.checked_pow(left as u32)?)?;
        Some(
            Decimal {
                mantissa: m,
                scale: scale as u8,
                point: true,
            }
            .normalized(),
        )
    } else {
        let scale = n.scale as i32 - shift;
        if scale > crate::ir::num::MAX_DIGITS as i32 {
            return None;
        }
        Some(
            Decimal {
                mantissa: n.mantissa,
                scale: scale as u8,
                point: true,
            }
            .normalized(),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::IntegerLengths;

    fn fanuc() -> NumberRules {
        NumberRules {
            integer_lengths: IntegerLengths::Increments,
            increment_mm: Decimal::parse("0.001").unwrap(),
            increment_inch: Decimal::parse("0.0001").unwrap(),
            length_places_mm: 3,
            length_places_inch: 4,
            point_on_lengths: true,
            feed_places: 2,
            angle_places: 3,
            integer_digits: 8,
        }
    }

    fn f(s: &str, k: NumKind, u: Option<LengthUnit>) -> Result<String, String> {
        format_number(Decimal::parse(s).unwrap(), k, &fanuc(), u)
    }

    #[test]
    fn lengths_carry_a_point_and_no_trailing_zeros() {
        assert_eq!(
            f("10", NumKind::Length, Some(LengthUnit::Mm)).unwrap(),
            "10."
        );
        assert_eq!(
            f("-2.500", NumKind::Length, Some(LengthUnit::Mm)).unwrap(),
            "-2.5"
        );
        assert_eq!(
            f("-0.000", NumKind::Length, Some(LengthUnit::Mm)).unwrap(),
            "0."
        );
        assert_eq!(
            f("1.2345", NumKind::Length, Some(LengthUnit::Inch)).unwrap(),
            "1.2345"
        );
        assert!(f("1.2345", NumKind::Length, Some(LengthUnit::Mm)).is_err());
    }

    #[test]
    fn feeds_ints_and_plain() {
        assert_eq!(
            f("100.", NumKind::Feed, Some(LengthUnit::Mm)).unwrap(),
            "100"
        );
        assert_eq!(
            f("12.50", NumKind::Feed, Some(LengthUnit::Mm)).unwrap(),
            "12.5"
        );
        assert_eq!(
            f("1000.0", NumKind::Int, Some(LengthUnit::Mm)).unwrap(),
            "1000"
        );
        assert!(f("1.5", NumKind::Int, Some(LengthUnit::Mm)).is_err());
        assert_eq!(
            f("0.123456", NumKind::Plain, Some(LengthUnit::Mm)).unwrap(),
            "0.123456"
        );
    }

    #[test]
    fn shifts_exactly() {
        let d = |s: &str| Decimal::parse(s).unwrap();
        assert_eq!(shift_decimal(d("1.5"), 3), Some(d("1500")));
        assert_eq!(shift_decimal(d("250"), -3), Some(d("0.25")));
        assert_eq!(shift_decimal(d("0.0005"), 3), Some(d("0.5")));
        assert_eq!(shift_decimal(d("999999999999999999"), 3), None);
    }
}
