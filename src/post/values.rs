//! The values a post template is filled with: already-formatted strings,
//! written by the target's number rules (a Fanuc length always has its
//! decimal point, a Siemens one never needs it), keyed by name.
//! Templates never format numbers themselves.

use crate::dialect::NumberRules;
use crate::emit::number::{format_number, NumKind};
use crate::ir::{Decimal, LengthUnit};

/// Formats numbers for one target.
#[derive(Clone, Debug)]
pub struct Fmt {
    rules: NumberRules,
    /// The first value too large for the target's format (or not finite).
    pub too_large: std::cell::Cell<Option<f64>>,
}

impl Fmt {
    pub fn new(rules: &NumberRules) -> Self {
        Fmt {
            rules: rules.clone(),
            too_large: std::cell::Cell::new(None),
        }
    }

    /// A length in mm, rounded to the target's places.
    pub fn len(&self, mm: f64) -> String {
        self.kind(mm, self.rules.length_places_mm, NumKind::Length)
    }

    /// A feed (mm/min) or spindle speed (rpm).
    pub fn feed(&self, v: f64) -> String {
        self.kind(v, self.rules.feed_places, NumKind::Feed)
    }

    /// An angle in degrees.
    pub fn angle(&self, deg: f64) -> String {
        self.kind(deg, self.rules.angle_places, NumKind::Angle)
    }

    /// A plain value with up to `places` decimals, no forced point
    /// (tolerances, dwell times, ratios).
    pub fn plain(&self, v: f64, places: u8) -> String {
        self.kind(v, places, NumKind::Plain)
    }

    fn kind(&self, v: f64, places: u8, kind: NumKind) -> String {
        // Lengths are held to the target's digits; feeds and speeds have
        // formats of their own on most controls [?], so only what no
        // control takes (not finite, or 12 digits and more) is refused.
        let digits = match kind {
            NumKind::Length => self.rules.integer_digits,
            _ => 12,
        };
        if !(v.abs() < 10f64.powi(i32::from(digits))) {
            if self.too_large.get().is_none() {
                self.too_large.set(Some(v));
            }
            return "0".into();
        }
        let d = Decimal::from_f64(clean(v), places);
        // Rounded to the target's places first, so formatting cannot fail.
        format_number(d, kind, &self.rules, Some(LengthUnit::Mm))
            .unwrap_or_else(|_| d.normalized().format(0, false))
    }
}

/// No `-0` from rounding noise.
fn clean(v: f64) -> f64 {
    if v.abs() < 1e-9 {
        0.0
    } else {
        v
    }
}

/// The named values for one template, in insertion order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Vals {
    pub entries: Vec<(&'static str, String)>,
    /// Values computed from others (`depth` = bottom - top) for targets
    /// that want them: a template need not use them.
    pub derived: Vec<&'static str>,
}

impl Vals {
    pub fn new() -> Self {
        Vals::default()
    }

    /// Adds (or replaces) a value.
    pub fn set(mut self, key: &'static str, value: impl Into<String>) -> Self {
        let value = value.into();
        match self.entries.iter_mut().find(|(k, _)| *k == key) {
            Some(e) => e.1 = value,
            None => self.entries.push((key, value)),
        }
        self
    }

    /// Adds a value derived from others (a template may leave it unused).
    pub fn set_derived(mut self, key: &'static str, value: impl Into<String>) -> Self {
        if !self.derived.contains(&key) {
            self.derived.push(key);
        }
        self.set(key, value)
    }

    pub fn get(&self, key: &str) -> Option<&str> {
        self.entries
            .iter()
            .find(|(k, _)| *k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// Comment text that cannot end or open a comment in any dialect;
/// parentheses are kept where the target's comments allow them.
pub fn comment_text(s: &str) -> String {
    comment_text_in(s, false)
}

/// As [`comment_text`], keeping parentheses when `parens_ok`.
pub fn comment_text_in(s: &str, parens_ok: bool) -> String {
    s.chars()
        .map(|c| match c {
            '(' | ')' if parens_ok => c,
            '(' => '[',
            ')' => ']',
            ';' => ',',
            c if c.is_control() => ' ',
            c => c,
        })
        .collect::<String>()
        .trim()
        .to_string()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fanuc_lengths_have_a_point_siemens_do_not() {
        let fanuc = crate::dialect::builtin("fanuc").unwrap();
        let siemens = crate::dialect::builtin("siemens840d").unwrap();
        let f = Fmt::new(&fanuc.numbers);
        let s = Fmt::new(&siemens.numbers);
        assert_eq!(f.len(20.0), "20.");
        assert_eq!(f.len(-0.0000001), "0.");
        assert_eq!(f.len(1.23456), "1.235");
        assert_eq!(s.len(20.0), "20");
        assert_eq!(f.feed(2400.0), "2400");
    }

    #[test]
    fn comment_text_is_neutralised() {
        assert_eq!(comment_text(" HOLE (D=22) ; x "), "HOLE [D=22] , x");
    }
}
