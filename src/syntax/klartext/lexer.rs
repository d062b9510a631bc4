//! The Klartext lexer: one block's code text (comments already taken off)
//! to grammar tokens with file offsets.
//!
//! Raw tokens come from logos; then the first word of a block (and the
//! second after `CYCL`, `TOOL`, `CALL`, `BEGIN`, `END`, `BLK`, `PATTERN`,
//! and `IF`/`GOTO`/`LBL` inside `FN`) become keywords; `Q12`, `QL3`, `QR5`
//! written together become one parameter token, and a parameter glued to
//! an address (`RQ1832`, `FQ1820`) is split from it. `F MAX` written
//! with a space is the one word `FMAX` (and `F AUTO` `FAUTO`).

use super::token::{Kw, Tok};
use crate::ir::{Decimal, QBank};
use logos::Logos;

#[derive(Logos, Clone, Copy, Debug, PartialEq, Eq)]
#[logos(skip r"[ \t\r\n\f~]+")]
enum Raw {
    /// Letters; an apostrophe between letters belongs to the word (the
    /// French cycle text `PLAN D'USINAGE`).
    #[regex(r"[A-Za-z_]+('[A-Za-z_]+)*")]
    Name,
    #[regex(r"[0-9]+(\.[0-9]*)?|\.[0-9]+")]
    Number,
    #[regex(r#""[^"]*""#)]
    Str,
    #[regex(r#""[^"]*"#)]
    OpenStr,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("/")]
    Slash,
    #[token("^")]
    Caret,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token("=")]
    Eq,
    #[token(":")]
    Colon,
    #[token(",")]
    Comma,
    #[token("#")]
    Hash,
    #[token("\\")]
    Backslash,
    #[token(".")]
    Dot,
}

/// A token with its byte range in the file.
pub type Spanned3 = (usize, Tok, usize);

/// What went wrong while lexing: the byte range and what was found.
pub struct LexError {
    pub start: usize,
    pub end: usize,
    pub what: &'static str,
}

/// Lexes `text`, which starts at file offset `base`, appending to `out`.
pub fn lex(text: &str, base: usize, out: &mut Vec<Spanned3>) -> Result<(), LexError> {
    let mut lx = Raw::lexer(text);
    while let Some(r) = lx.next() {
        let sp = lx.span();
        let (s, e) = (base + sp.start, base + sp.end);
        let slice = lx.slice();
        let tok = match r {
            Err(()) => {
                return Err(LexError {
                    start: s,
                    end: e,
                    what: "a character Klartext does not use",
                })
            }
            Ok(Raw::OpenStr) => {
                return Err(LexError {
                    start: s,
                    end: e,
                    what: "a string without its closing quote",
                })
            }
            Ok(Raw::Name) => {
                name(slice, s, e, text, sp.end, out);
                continue;
            }
            Ok(Raw::Number) => match Decimal::parse(slice) {
                Ok(d) => Tok::Num(d),
                Err(_) => {
                    return Err(LexError {
                        start: s,
                        end: e,
                        what: "a number too long or malformed",
                    })
                }
            },
            Ok(Raw::Str) => Tok::Str(slice[1..slice.len() - 1].to_string()),
            Ok(Raw::Plus) => Tok::Plus,
            Ok(Raw::Minus) => Tok::Minus,
            Ok(Raw::Star) => Tok::Star,
            Ok(Raw::Slash) => Tok::Slash,
            Ok(Raw::Caret) => Tok::Caret,
            Ok(Raw::LParen) => Tok::LParen,
            Ok(Raw::RParen) => Tok::RParen,
            Ok(Raw::Eq) => Tok::Eq,
            Ok(Raw::Colon) => Tok::Colon,
            Ok(Raw::Comma) => Tok::Comma,
            Ok(Raw::Hash) => Tok::Hash,
            Ok(Raw::Backslash) => Tok::Backslash,
            Ok(Raw::Dot) => Tok::Dot,
        };
        out.push((s, tok, e));
    }
    Ok(())
}

/// A name; a Q parameter prefix glued to the number after it becomes a
/// parameter token (`Q12`, and `R`+`Q1832` from `RQ1832`).
fn name(slice: &str, s: usize, e: usize, text: &str, end: usize, out: &mut Vec<Spanned3>) {
    let up = slice.to_ascii_uppercase();
    let digit_follows = text[end..].starts_with(|c: char| c.is_ascii_digit());
    if digit_follows {
        for (prefix, bank) in [
            ("QL", QBank::Local),
            ("QR", QBank::Remanent),
            ("Q", QBank::Q),
        ] {
            if up.ends_with(prefix) && !(prefix == "Q" && up.ends_with("QL")) {
                let cut = up.len() - prefix.len();
                if cut > 0 {
                    out.push((s, Tok::Name(up[..cut].to_string()), s + cut));
                }
                out.push((s + cut, Tok::QPrefix(bank), e));
                return;
            }
        }
    }
    out.push((s, Tok::Name(up), e));
}

/// Turns names at keyword positions into keywords and joins each
/// parameter prefix with its number (`Q` `12` → `Q12`).
pub fn classify(toks: Vec<Spanned3>) -> Vec<Spanned3> {
    let mut out: Vec<Spanned3> = Vec::with_capacity(toks.len());
    let mut it = toks.into_iter().peekable();
    while let Some((s, t, e)) = it.next() {
        if let Tok::QPrefix(bank) = t {
            if let Some((_, Tok::Num(d), e2)) = it.peek() {
                if let Some(n) = d.as_int().filter(|n| (0..=99_999).contains(n)) {
                    let e2 = *e2;
                    it.next();
                    out.push((s, Tok::Q(bank, n as u32), e2));
                    continue;
                }
            }
            out.push((s, Tok::Name(bank_name(bank).into()), e));
            continue;
        }
        let t = match t {
            Tok::Name(n) => keyword_at(&out, &n).map(Tok::Kw).unwrap_or(Tok::Name(n)),
            t => t,
        };
        // `F MAX` (with a space, as hyperMILL writes it) is `FMAX`, and
        // `F AUTO` (iTNC 530 output) is `FAUTO`.
        if let (Tok::Name(n), Some((_, Tok::Name(m), e2))) = (&t, it.peek()) {
            if n == "F" && (m == "MAX" || m == "AUTO") {
                let (e2, joined) = (*e2, format!("F{m}"));
                it.next();
                out.push((s, Tok::Name(joined), e2));
                continue;
            }
        }
        out.push((s, t, e));
    }
    out
}

fn bank_name(b: QBank) -> &'static str {
    b.prefix()
}

/// The keyword `n` is at this position, if any.
fn keyword_at(before: &[Spanned3], n: &str) -> Option<Kw> {
    let first = before.first().map(|(_, t, _)| t);
    match before.len() {
        0 => Kw::block(n),
        1 => match (first, n) {
            (Some(Tok::Kw(Kw::Cycl | Kw::Tool | Kw::Pattern)), "DEF") => Some(Kw::Def),
            (Some(Tok::Kw(Kw::Cycl | Kw::Tool)), "CALL") => Some(Kw::Call),
            (Some(Tok::Kw(Kw::Call)), "LBL") => Some(Kw::Lbl),
            (Some(Tok::Kw(Kw::Call | Kw::Begin | Kw::End)), "PGM") => Some(Kw::Pgm),
            (Some(Tok::Kw(Kw::Blk)), "FORM") => Some(Kw::Form),
            _ => None,
        },
        _ => match (first, n) {
            (Some(Tok::Kw(Kw::Fn)), "IF") => Some(Kw::If),
            (Some(Tok::Kw(Kw::Fn)), "GOTO") => Some(Kw::Goto),
            (Some(Tok::Kw(Kw::Fn)), "LBL") => Some(Kw::Lbl),
            _ => None,
        },
    }
}
