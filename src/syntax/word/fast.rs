//! The fast path: most lines CAM systems write are plain words and closed
//! `( )` comments (`N10 G1 X12.345 Y-3.2 F500`). They are read here byte by
//! byte without the lexer and the LALRPOP parser. Anything else (`;`, `#`, `[`,
//! keywords, `O`, `/`, spaces inside a word, a bad number) returns `None`
//! and the line goes through the grammar, which gives the same result for
//! the lines this path accepts (tested in `tests::fast_path_agrees`).

use super::prefix::comment_kind;
use crate::ir::{CommentStyle, Decimal, Stmt, Value};
use crate::span::{Span, Spanned};
use crate::syntax::Address;
use crate::syntax::{Item, LineInput, LineSyntax, WordSyntax};

/// Reads a line of plain `letter number` words, or `None`.
pub fn fast_line(input: &LineInput<'_>) -> Option<LineSyntax> {
    fast_line_with(input, &mut Vec::new())
}

/// [`fast_line`] with the items built in `spare` (taken on success, so a
/// caller can hand back emptied vectors and lines allocate nothing).
pub fn fast_line_with(input: &LineInput<'_>, spare: &mut Vec<Item>) -> Option<LineSyntax> {
    spare.clear();
    let b = input.text.as_bytes();
    let sp = |l: usize, r: usize| {
        Span::new(
            input.file,
            l + input.offset as usize,
            r + input.offset as usize,
        )
    };
    let mut i = skip_ws(b, 0);
    let mut seq = None;
    if i < b.len() && b[i].eq_ignore_ascii_case(&b'N') {
        let (n, end) = seq_number(b, i + 1)?;
        seq = Some(Spanned::new(n, sp(i, end)));
        i = end;
    }
    let items = spare;
    loop {
        i = skip_ws(b, i);
        if i >= b.len() {
            let items = std::mem::take(items);
            return Some(LineSyntax {
                span: sp(0, b.len()),
                skip: None,
                number: seq,
                label: None,
                items,
            });
        }
        if b[i] == b'(' {
            let close = i + b[i..].iter().position(|&c| c == b')')?;
            let kind = comment_kind(&input.text[i + 1..close], CommentStyle::Paren);
            items.push(Item::Stmt(Stmt::new(kind, sp(i, close + 1))));
            i = close + 1;
            continue;
        }
        let letter = b[i].to_ascii_uppercase();
        if !letter.is_ascii_uppercase() || letter == b'O' {
            return None;
        }
        let (value, end) = number(input.text, i + 1)?;
        items.push(Item::Word(WordSyntax {
            address: Address::new(char::from(letter).encode_utf8(&mut [0u8; 4])),
            value: Value::Number(value),
            dim: None,
            extended: false,
            span: sp(i, end),
            address_span: sp(i, i + 1),
        }));
        i = end;
    }
}

fn skip_ws(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && matches!(b[i], b' ' | b'\t' | b'\r') {
        i += 1;
    }
    i
}

/// The number `[-+]digits.digits` starting at `i` and its end, if a word
/// may end there and [`Decimal::parse`] reads it. Read in the same pass
/// when short (the common case); longer ones are left to `Decimal::parse`.
fn number(text: &str, i: usize) -> Option<(Decimal, usize)> {
    let b = text.as_bytes();
    let mut j = i;
    let neg = j < b.len() && b[j] == b'-';
    if j < b.len() && matches!(b[j], b'-' | b'+') {
        j += 1;
    }
    let start = j;
    let (mut mantissa, mut scale, mut points) = (0i64, 0u8, 0usize);
    while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'.') {
        if b[j] == b'.' {
            points += 1;
        } else {
            mantissa = mantissa
                .wrapping_mul(10)
                .wrapping_add(i64::from(b[j] - b'0'));
            scale = scale.wrapping_add(u8::from(points > 0));
        }
        j += 1;
    }
    let ends_well =
        j == b.len() || matches!(b[j], b' ' | b'\t' | b'\r' | b'(') || b[j].is_ascii_alphabetic();
    if j == start || !ends_well {
        return None;
    }
    let digits = j - start - points;
    if digits == 0 || digits > crate::ir::num::MAX_DIGITS || points > 1 {
        // Nothing, or too long to be sure here: the shared reader decides.
        return Decimal::parse(&text[i..j]).ok().map(|d| (d, j));
    }
    Some((
        Decimal {
            mantissa: if neg { -mantissa } else { mantissa },
            scale,
            point: points == 1,
        },
        j,
    ))
}

/// A sequence number: digits only, fitting a `u32`.
fn seq_number(b: &[u8], i: usize) -> Option<(u32, usize)> {
    let mut j = i;
    let mut n: u32 = 0;
    while j < b.len() && b[j].is_ascii_digit() {
        n = n.checked_mul(10)?.checked_add(u32::from(b[j] - b'0'))?;
        j += 1;
    }
    let ends_well =
        j == b.len() || matches!(b[j], b' ' | b'\t' | b'\r' | b'(') || b[j].is_ascii_alphabetic();
    (j > i && ends_well).then_some((n, j))
}
