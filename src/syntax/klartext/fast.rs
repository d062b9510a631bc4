//! The fast path for the blocks CAM output is made of: `L` with plain
//! numeric words (`12 L X+10.5 Y-3 Z-1 R0 F500 FMAX M3`), read by a byte
//! scan with no tokens, grammar or allocation beyond the statements. Any
//! other block (Q parameters, comments, spaces inside a word, M functions
//! with a meaning of their own here) returns `None` and takes the full
//! path, which gives the same statements.

use crate::ir::{
    Axes, CompSide, Coord, Decimal, DimMode, Motion, MotionKind, Stmt, StmtKind, Value,
};
use crate::span::{FileId, Span, Spanned};
use crate::syntax::{Address, Item, LineSyntax, WordSyntax};

/// Reads `text` (one whole block at file offset `base`) if it is a plain `L` block.
pub fn line(text: &str, base: usize, file: FileId) -> Option<LineSyntax> {
    let b = text.as_bytes();
    if b.iter()
        .any(|&c| matches!(c, b';' | b'"' | b'~' | b'Q' | b'q' | b'*' | b'('))
    {
        return None;
    }
    let sp = |s: usize, e: usize| Span::new(file, base + s, base + e);
    let mut i = skip_ws(b, 0);
    let mut number = None;
    let d0 = i;
    while i < b.len() && b[i].is_ascii_digit() {
        i += 1;
    }
    if i > d0 {
        if i < b.len() && !b[i].is_ascii_whitespace() {
            return None;
        }
        let n = text[d0..i].parse::<u32>().ok()?;
        number = Some(Spanned::new(n, sp(d0, i)));
        i = skip_ws(b, i);
    }
    if b.get(i) != Some(&b'L') || b.get(i + 1).is_some_and(|c| !c.is_ascii_whitespace()) {
        return None;
    }
    let first = i;
    i += 1;
    let mut axes = Axes::default();
    let mut rapid = false;
    let mut items = Vec::new();
    let mut last = i;
    loop {
        i = skip_ws(b, i);
        if i >= b.len() {
            break;
        }
        let ws = i;
        while i < b.len() && b[i].is_ascii_uppercase() {
            i += 1;
        }
        let name = &text[ws..i];
        let sign = match b.get(i) {
            Some(b'+') => Some(false),
            Some(b'-') => Some(true),
            _ => None,
        };
        if sign.is_some() {
            i += 1;
        }
        let ns = i;
        while i < b.len() && (b[i].is_ascii_digit() || b[i] == b'.') {
            i += 1;
        }
        if i < b.len() && !b[i].is_ascii_whitespace() {
            return None;
        }
        let span = sp(ws, i);
        last = i;
        let value = if i > ns {
            let d = Decimal::parse(&text[ns..i]).ok()?;
            Some(if sign == Some(true) { d.neg() } else { d })
        } else {
            if sign.is_some() {
                return None;
            }
            None
        };
        let comp = |side| StmtKind::RadiusComp {
            side,
            register: None,
            diameter: false,
        };
        match (name, value) {
            ("FMAX", None) => rapid = true,
            ("RL", None) => items.push(stmt(comp(CompSide::Left), span)),
            ("RR", None) => items.push(stmt(comp(CompSide::Right), span)),
            ("R", Some(d)) if d.as_int() == Some(0) && sign.is_none() => {
                items.push(stmt(comp(CompSide::Off), span))
            }
            ("F", Some(d)) => items.push(stmt(StmtKind::Feed(Value::Number(d)), span)),
            ("M", Some(d)) if !matches!(d.as_int(), Some(13 | 14 | 89 | 99) | None) => {
                items.push(Item::Word(WordSyntax {
                    address: Address::new("M"),
                    value: Value::Number(d),
                    dim: None,
                    extended: false,
                    span,
                    address_span: sp(ws, ws + 1),
                }))
            }
            (n, Some(d)) => {
                let (inc, letter) = match n.as_bytes() {
                    [a] => (false, *a as char),
                    [b'I', a] => (true, *a as char),
                    _ => return None,
                };
                let slot = axes.slot_mut(letter)?;
                if slot.is_some() {
                    return None;
                }
                *slot = Some(Coord {
                    value: Value::Number(d),
                    dim: inc.then_some(DimMode::Incremental),
                    span,
                });
            }
            _ => return None,
        }
    }
    let mut m = Motion::new(if rapid {
        MotionKind::Rapid
    } else {
        MotionKind::Linear
    });
    m.target = axes;
    items.insert(0, stmt(StmtKind::Motion(Box::new(m)), sp(first, last)));
    Some(LineSyntax {
        span: sp(0, text.len()),
        skip: None,
        number,
        label: None,
        items,
    })
}

fn stmt(kind: StmtKind, span: Span) -> Item {
    Item::Stmt(Stmt::new(kind, span))
}

fn skip_ws(b: &[u8], mut i: usize) -> usize {
    while i < b.len() && b[i].is_ascii_whitespace() {
        i += 1;
    }
    i
}
