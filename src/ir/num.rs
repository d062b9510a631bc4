//! Exact decimal numbers, as written in a program: `10`, `10.`, `-0.0625`.
//!
//! A number is kept as an integer mantissa and a count of decimal places, so
//! nothing a program says is rounded on the way in. Whether it was written
//! with a decimal point is kept too: Fanuc reads `X10` and `X10.` differently.

use serde::Serialize;
use std::fmt;

/// Most significant digits kept exactly.
pub const MAX_DIGITS: usize = 18;
/// Most places after the point, leading zeros included (a scale of 256
/// overflowed; past 18 places, 10^scale is past an i64).
pub const MAX_SCALE: u8 = 36;

/// `mantissa / 10^scale`, plus whether a decimal point was written.
#[derive(Clone, Copy, Debug, Eq, Serialize)]
pub struct Decimal {
    pub mantissa: i64,
    pub scale: u8,
    pub point: bool,
}

/// Why a number's text could not be read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberError {
    Malformed,
    TooLong,
}

impl Decimal {
    pub const ZERO: Decimal = Decimal {
        mantissa: 0,
        scale: 0,
        point: false,
    };

    pub fn from_int(v: i64) -> Self {
        Decimal {
            mantissa: v,
            scale: 0,
            point: false,
        }
    }

    /// Reads `[+-]digits[.digits]` or `[+-].digits` exactly.
    pub fn parse(text: &str) -> Result<Decimal, NumberError> {
        let (neg, body) = match text.as_bytes().first() {
            Some(b'-') => (true, &text[1..]),
            Some(b'+') => (false, &text[1..]),
            _ => (false, text),
        };
        let mut mantissa: i64 = 0;
        let mut scale: u8 = 0;
        let mut point = false;
        let mut digits = 0usize;
        let mut significant = 0usize;
        for b in body.bytes() {
            match b {
                b'0'..=b'9' => {
                    digits += 1;
                    if significant > 0 || b != b'0' {
                        significant += 1;
                    }
                    if significant > MAX_DIGITS {
                        return Err(NumberError::TooLong);
                    }
                    mantissa = mantissa * 10 + (b - b'0') as i64;
                    if point {
                        // Zeros after the point count too: `0.000…01`.
                        if scale >= MAX_SCALE {
                            return Err(NumberError::TooLong);
                        }
                        scale += 1;
                    }
                }
                b'.' if !point => point = true,
                _ => return Err(NumberError::Malformed),
            }
        }
        if digits == 0 {
            return Err(NumberError::Malformed);
        }
        Ok(Decimal {
            mantissa: if neg { -mantissa } else { mantissa },
            scale,
            point,
        })
    }

    pub fn to_f64(self) -> f64 {
        // Exact for the mantissas and scales programs use; division by an
        // exact power of ten gives the correctly rounded double.
        // Powers of ten up to 1e22 are exact doubles (as powi gives them).
        const POW10: [f64; 23] = [
            1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
            1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
        ];
        let p = POW10
            .get(self.scale as usize)
            .copied()
            .unwrap_or_else(|| 10f64.powi(self.scale as i32));
        self.mantissa as f64 / p
    }

    /// The nearest decimal with at most `places` decimal places, from a double.
    pub fn from_f64(v: f64, places: u8) -> Decimal {
        let m = (v * 10f64.powi(places as i32)).round();
        let mut d = Decimal {
            mantissa: m as i64,
            scale: places,
            point: true,
        };
        d.trim();
        d
    }

    /// True when the value has no fractional part.
    pub fn is_integer(self) -> bool {
        self.as_int().is_some()
    }

    /// The value as an integer, if it is one.
    pub fn as_int(self) -> Option<i64> {
        match 10i64.checked_pow(self.scale as u32) {
            Some(p) => (self.mantissa % p == 0).then(|| self.mantissa / p),
            // 10^scale is past i64, so past the mantissa: a fraction, or 0.
            None => (self.mantissa == 0).then_some(0),
        }
    }

    pub fn is_negative(self) -> bool {
        self.mantissa < 0
    }

    pub fn neg(self) -> Decimal {
        Decimal {
            mantissa: -self.mantissa,
            ..self
        }
    }

    /// Drops trailing zero decimals (the value is unchanged).
    pub fn trim(&mut self) {
        while self.scale > 0 && self.mantissa % 10 == 0 {
            self.mantissa /= 10;
            self.scale -= 1;
        }
    }

    /// The same value, trimmed.
    pub fn normalized(self) -> Decimal {
        let mut d = self;
        d.trim();
        d
    }

    /// Digits as `[-]int[.frac]` with at least `min_places` and no trailing
    /// zeros beyond them; `force_point` writes `10.` for a whole number.
    pub fn format(self, min_places: u8, force_point: bool) -> String {
        let mut s = String::with_capacity(24);
        self.format_into(&mut s, min_places, force_point);
        s
    }

    /// [`Decimal::format`] appended to `out`, digit by digit (no
    /// division wider than the mantissa, no allocation of its own).
    pub fn format_into(self, out: &mut String, min_places: u8, force_point: bool) {
        let n = self.normalized();
        let mut buf = itoa::Buffer::new();
        let digits = buf.format(n.mantissa.unsigned_abs());
        let (len, scale) = (digits.len(), n.scale as usize);
        let places = scale.max(min_places as usize);
        if n.mantissa < 0 {
            out.push('-');
        }
        let zeros = |out: &mut String, k: usize| out.extend(std::iter::repeat_n('0', k));
        if len > scale {
            out.push_str(&digits[..len - scale]);
        } else {
            out.push('0');
        }
        if places > 0 {
            out.push('.');
            zeros(out, scale.saturating_sub(len));
            out.push_str(&digits[len.saturating_sub(scale)..]);
            zeros(out, places - scale);
        } else if force_point {
            out.push('.');
        }
    }
}

/// Equal values are equal, whatever their scale or point.
impl PartialEq for Decimal {
    fn eq(&self, other: &Self) -> bool {
        let (a, b) = (self.normalized(), other.normalized());
        a.mantissa == b.mantissa && a.scale == b.scale
    }
}

impl std::hash::Hash for Decimal {
    fn hash<H: std::hash::Hasher>(&self, state: &mut H) {
        let n = self.normalized();
        n.mantissa.hash(state);
        n.scale.hash(state);
    }
}

/// As written, minimally: `10`, `10.`, `-0.5`.
impl fmt::Display for Decimal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let s = Decimal {
            point: false,
            ..*self
        }
        .format(self.scale, false);
        f.write_str(&s)?;
        if self.point && self.scale == 0 {
            f.write_str(".")?;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Found by fuzzing (sinumerik, 277 s): `D.0349334934933493493` has 19
    /// places; 10^19 overflowed an i64 in `as_int`.
    #[test]
    fn more_places_than_an_i64_holds_are_not_an_overflow() {
        let d = Decimal::parse(".0349334934933493493").unwrap();
        assert_eq!((d.as_int(), d.is_integer()), (None, false));
        let zero = Decimal::parse("0.0000000000000000000000").unwrap();
        assert_eq!(zero.as_int(), Some(0));
        let tiny = format!("0.{}1", "0".repeat(300));
        assert_eq!(Decimal::parse(&tiny), Err(NumberError::TooLong));
        assert!(Decimal::parse(&format!("0.{}1", "0".repeat(34))).is_ok());
    }

    #[test]
    fn reads_exactly() {
        let d = Decimal::parse("-0.0625").unwrap();
        assert_eq!((d.mantissa, d.scale, d.point), (-625, 4, true));
        assert_eq!(
            Decimal::parse("10.").unwrap(),
            Decimal::parse("10").unwrap()
        );
        assert!(Decimal::parse("10.").unwrap().point);
        assert!(!Decimal::parse("10").unwrap().point);
        assert_eq!(Decimal::parse(".5").unwrap().to_f64(), 0.5);
        assert_eq!(Decimal::parse("1.2.3"), Err(NumberError::Malformed));
        assert_eq!(Decimal::parse("."), Err(NumberError::Malformed));
        assert_eq!(
            Decimal::parse("1234567890123456789"),
            Err(NumberError::TooLong)
        );
        assert_eq!(
            Decimal::parse("0000000000000000000001").unwrap(),
            Decimal::from_int(1)
        );
    }

    #[test]
    fn formats() {
        let d = Decimal::parse("10").unwrap();
        assert_eq!(d.format(0, true), "10.");
        assert_eq!(d.format(3, false), "10.000");
        assert_eq!(Decimal::parse("-0.50").unwrap().format(0, true), "-0.5");
        assert_eq!(Decimal::parse("-0.50").unwrap().to_string(), "-0.50");
        assert_eq!(Decimal::parse("10.").unwrap().to_string(), "10.");
        assert_eq!(Decimal::from_f64(1.23456, 4).to_string(), "1.2346");
    }

    /// The digit-by-digit writer against the arithmetic it replaced
    /// (integer and fraction by a u128 division), over mantissas at the
    /// edges of an i64 and every scale up to [`MAX_SCALE`].
    #[test]
    fn formats_as_the_division_did() {
        let by_division = |d: Decimal, min: u8, point: bool| {
            let n = d.normalized();
            let scale = n.scale.max(min);
            let m = n.mantissa.unsigned_abs() as u128 * 10u128.pow((scale - n.scale) as u32);
            let p = 10u128.pow(scale as u32);
            let sign = if n.mantissa < 0 { "-" } else { "" };
            match (scale, point) {
                (0, true) => format!("{sign}{}.", m / p),
                (0, false) => format!("{sign}{}", m / p),
                _ => format!("{sign}{}.{:0w$}", m / p, m % p, w = scale as usize),
            }
        };
        let mantissas = [
            0,
            1,
            -1,
            7,
            10,
            -120,
            123456,
            -9_999_999,
            i64::MAX,
            i64::MIN + 1,
            i64::MIN,
        ];
        for &mantissa in &mantissas {
            for scale in 0..=MAX_SCALE {
                for (min, point) in [(0, false), (0, true), (3, false), (4, true)] {
                    let d = Decimal {
                        mantissa,
                        scale,
                        point: false,
                    };
                    assert_eq!(
                        d.format(min, point),
                        by_division(d, min, point),
                        "{mantissa} {scale}"
                    );
                }
            }
        }
    }
}

/// A computed value for a message or a name: rounded to `places`
/// decimals, trailing zeros and a bare point dropped, never `-0`.
pub fn short_text(v: f64, places: usize) -> String {
    let s = format!("{v:.places$}");
    let s = if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.')
    } else {
        &s
    };
    match s {
        "-0" | "" => "0".into(),
        s => s.into(),
    }
}

#[cfg(test)]
mod short_text_tests {
    use super::short_text;

    #[test]
    fn drops_trailing_zeros_and_negative_zero() {
        assert_eq!(short_text(12.5, 3), "12.5");
        assert_eq!(short_text(-0.0001, 3), "0");
        assert_eq!(short_text(100.0, 4), "100");
        assert_eq!(short_text(-1.23456, 4), "-1.2346");
    }
}
