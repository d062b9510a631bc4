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
    let b = input.text.as_bytes();
    let sp = |l: usize, r: usize| Span::new(input.file, l + input.offset as usize, r + input.offset as usize);
    let mut i = skip_ws(b, 0);
    let mut line = LineSyntax { span: sp(0, b.len()), skip: None, number: None, label: None, items: Vec::new() };
    if i < b.len() && b[i].eq_ignore_ascii_case(&b'N') {
        let (n, end) = seq_number(b, i + 1)?;
        line.number = Some(Spanned::new(n, sp(i, end)));
        i = end;
    }
    loop {
        i = skip_ws(b, i);
        if i >= b.len() {
            return Some(line);
        }
        if b[i] == b'(' {
            let close = i + b[i..].iter().position(|&c| c == b')')?;
            let kind = comment_kind(&input.text[i + 1..close], CommentStyle::Paren);
            line.items.push(Item::Stmt(Stmt::new(kind, sp(i, close + 1))));
            i = close + 1;
            continue;
        }
        let letter = b[i].to_ascii_uppercase();
        if !letter.is_ascii_uppercase() || letter == b'O' {
            return None;
        }
        let end = number_end(b, i + 1)?;
        let value = Decimal::parse(&input.text[i + 1..end]).ok()?;
        line.items.push(Item::Word(WordSyntax {
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

/// The end of `[-+]digits.digits` starting at `i`, if a word may end there.
fn number_end(b: &[u8], i: usize) -> Option<usize> {
    let mut j = i;
    if j < b.len() && matches!(b[j], b'-' | b'+') {
        j += 1;
    }
    let start = j;
    while j < b.len() && (b[j].is_ascii_digit() || b[j] == b'.') {
        j += 1;
    }
    let ends_well = j == b.len() || matches!(b[j], b' ' | b'\t' | b'\r' | b'(') || b[j].is_ascii_alphabetic();
    (j > start && ends_well).then_some(j)
}

/// A sequence number: digits only, fitting a `u32`.
fn seq_number(b: &[u8], i: usize) -> Option<(u32, usize)> {
    let mut j = i;
    let mut n: u32 = 0;
    while j < b.len() && b[j].is_ascii_digit() {
        n = n.checked_mul(10)?.checked_add(u32::from(b[j] - b'0'))?;
        j += 1;
    }
    let ends_well = j == b.len() || matches!(b[j], b' ' | b'\t' | b'\r' | b'(') || b[j].is_ascii_alphabetic();
    (j > i && ends_well).then_some((n, j))
}
