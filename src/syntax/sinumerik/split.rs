//! Splitting packed address words: `T1D1M6` is `T1 D1 M6`, `G0X10.5` is
//! `G0 X10.5`, `X` before `=` is the address of an extended word.
//!
//! Sinumerik syntax: an address is a single letter the dialect spec lists
//! (or, if the spec lists none, any letter but `R`, which always names an
//! arithmetic parameter), or one of the multi-letter addresses in
//! [`MULTI_ADDRESSES`]. Before `=`, an address may carry a number
//! (`I1=`, `X1=`, `M1=`, `S1=`). Axis words are X Y Z A B C U V W; other
//! configured axis names (`X2`, `Q1`) are not supported yet.

use crate::dialect::DialectSpec;
use crate::ir::num::NumberError;
use crate::ir::Decimal;

/// Multi-letter addresses of the Sinumerik language; they take a value
/// only after `=`.
pub const MULTI_ADDRESSES: &[&str] = &[
    "CR", "AR", "TURN", "AP", "RP", "CHF", "CHR", "RND", "RNDM", "ADIS", "ADISPOS", "RPL", "ANG",
    "SF", "DC", "ACP", "ACN", "OFFN", "SPOS", "SPOSA",
];

/// Letters read as addresses when the spec lists none.
const DEFAULT_LETTERS: &str = "ABCDEFGHIJKLMNOPQSTUVWXYZ";

/// One piece of a split identifier, with its byte range inside it.
#[derive(Clone, Debug, PartialEq)]
pub enum Piece {
    Addr(String, usize, usize),
    Num(Result<Decimal, NumberError>, usize, usize),
}

fn is_single(spec: &DialectSpec, c: char) -> bool {
    if spec.addresses.is_empty() {
        DEFAULT_LETTERS.contains(c)
    } else {
        c != 'R' && spec.address(c).is_some()
    }
}

/// Whether `letters` (upper case) is an address of the dialect.
pub fn is_address(spec: &DialectSpec, letters: &str) -> bool {
    let mut cs = letters.chars();
    match (cs.next(), cs.next()) {
        (Some(c), None) => is_single(spec, c),
        (Some(_), Some(_)) => MULTI_ADDRESSES.contains(&letters),
        _ => false,
    }
}

/// Splits an upper-case identifier into address words, or `None` if it is
/// not made of address words. `before_assign`: the next token is `=`.
pub fn split(spec: &DialectSpec, upper: &str, before_assign: bool) -> Option<Vec<Piece>> {
    let b = upper.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let ls = i;
        while i < b.len() && b[i].is_ascii_uppercase() {
            i += 1;
        }
        let ns = i;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
            i += 1;
        }
        if ls == ns || (i < b.len() && !b[i].is_ascii_uppercase()) {
            return None;
        }
        let letters = &upper[ls..ns];
        if !is_address(spec, letters) {
            return None;
        }
        let last = i == b.len();
        if letters.len() > 1 && !(last && before_assign) {
            return None;
        }
        let digits = &upper[ns..i];
        let numbered = !digits.is_empty() && digits.bytes().all(|c| c.is_ascii_digit());
        if last && before_assign && (digits.is_empty() || numbered) {
            out.push(Piece::Addr(upper[ls..i].to_string(), ls, i));
            break;
        }
        if digits.is_empty() && !last {
            return None;
        }
        out.push(Piece::Addr(letters.to_string(), ls, ns));
        if !digits.is_empty() {
            out.push(Piece::Num(Decimal::parse(digits), ns, i));
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dialect::spec::{IntegerLengths, NumberRules};
    use crate::dialect::Family;

    fn spec() -> DialectSpec {
        let n = NumberRules {
            integer_lengths: IntegerLengths::Units,
            increment_mm: Decimal::parse("0.001").unwrap(),
            increment_inch: Decimal::parse("0.0001").unwrap(),
            length_places_mm: 3,
            length_places_inch: 4,
            point_on_lengths: false,
            feed_places: 1,
            angle_places: 3,
            integer_digits: 8,
        };
        DialectSpec::new("t".into(), "t".into(), Family::Sinumerik, n)
    }

    fn show(s: &str, assign: bool) -> String {
        match split(&spec(), s, assign) {
            None => "-".into(),
            Some(ps) => ps
                .iter()
                .map(|p| match p {
                    Piece::Addr(a, _, _) => a.clone(),
                    Piece::Num(Ok(d), _, _) => format!("{d} "),
                    Piece::Num(Err(e), _, _) => format!("{e:?} "),
                })
                .collect(),
        }
    }

    #[test]
    fn splits_packed_words() {
        assert_eq!(show("T1D1M6", false), "T1 D1 M6 ");
        assert_eq!(show("G0X10.5Y20", false), "G0 X10.5 Y20 ");
        assert_eq!(show("X1.2.3", false), "XMalformed ");
        assert_eq!(show("G0X", true), "G0 X");
        assert_eq!(show("I1", true), "I1");
        assert_eq!(show("CR", true), "CR");
        assert_eq!(show("X", false), "X");
    }

    #[test]
    fn leaves_names_alone() {
        assert_eq!(show("METKA1", false), "-");
        assert_eq!(show("LAST", false), "-");
        assert_eq!(show("R10", false), "-");
        assert_eq!(show("CR10", false), "-");
        assert_eq!(show("LABEL_1", false), "-");
    }
}
