//! The Part 21 lexer (logos): tokens with byte ranges; comments and
//! whitespace skipped. Also the decoding of string escapes (`''`, `\\`,
//! `\X\hh`, `\X2\...\X0\`, `\X4\...\X0\`) and number reading.

use super::Value;
use logos::Logos;

/// A Part 21 token. Values are read back from the text by range.
#[derive(Logos, Clone, Copy, Debug, PartialEq, Eq)]
#[logos(skip r"[ \t\r\n\f\u{feff}]+")]
#[logos(skip r"/\*([^*]|\*+[^*/])*\*+/")]
pub enum Tok {
    /// `ISO-10303-21`.
    #[token("ISO-10303-21")]
    Begin,
    /// `END-ISO-10303-21`.
    #[token("END-ISO-10303-21")]
    End,
    /// An entity or type name (also HEADER, DATA, ENDSEC), or a user
    /// defined `!NAME`.
    #[regex(r"!?[A-Za-z_][A-Za-z0-9_]*")]
    Keyword,
    #[regex(r"#[0-9]+")]
    InstanceName,
    #[regex(r"[+-]?[0-9]+", priority = 3)]
    Integer,
    #[regex(r"[+-]?[0-9]+\.[0-9]*([eE][+-]?[0-9]+)?")]
    Real,
    #[regex(r"'([^']|'')*'")]
    Str,
    #[regex(r"\.[A-Za-z_][A-Za-z0-9_]*\.")]
    Enumeration,
    #[regex(r#""[0-9A-Fa-f]*""#)]
    Binary,
    #[token("$")]
    Dollar,
    #[token("*")]
    Star,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token(",")]
    Comma,
    #[token("=")]
    Eq,
    #[token(";")]
    Semi,
    /// A comment opened and never closed (an error).
    #[regex(r"/\*([^*]|\*+[^*/])*\**")]
    OpenComment,
    /// A string opened and never closed (an error).
    #[regex(r"'([^']|'')*")]
    OpenString,
}

/// Tokens of a whole text, with ranges; `Err(range)` for characters that
/// start no token.
pub fn tokens(src: &str) -> Vec<Result<(usize, Tok, usize), (usize, usize)>> {
    let mut lex = Tok::lexer(src);
    let mut out = Vec::new();
    while let Some(t) = lex.next() {
        let r = lex.span();
        out.push(match t {
            Ok(t) => Ok((r.start, t, r.end)),
            Err(()) => Err((r.start, r.end)),
        });
    }
    out
}

/// An INTEGER or REAL token's value.
pub fn number_value(text: &str, integer: bool) -> Result<Value, String> {
    if integer {
        text.parse::<i64>()
            .map(Value::Int)
            .map_err(|_| format!("integer `{text}` is out of range"))
    } else {
        match text.parse::<f64>() {
            Ok(v) if v.is_finite() => Ok(Value::Real(v)),
            _ => Err(format!("real `{text}` is out of range")),
        }
    }
}

/// The text of a string token's contents (without the quotes), with the
/// Part 21 escapes decoded. An unknown or broken directive is kept as
/// written.
pub fn decode_string(raw: &str) -> String {
    let b = raw.as_bytes();
    let mut out = String::with_capacity(raw.len());
    let mut i = 0;
    while i < b.len() {
        let rest = &raw[i..];
        if rest.starts_with("''") {
            out.push('\'');
            i += 2;
        } else if rest.starts_with("\\\\") {
            out.push('\\');
            i += 2;
        } else if let Some((c, n)) = x_escape(rest) {
            out.push(c);
            i += n;
        } else if let Some((s, n)) = wide_escape(rest) {
            out.push_str(&s);
            i += n;
        } else {
            let c = rest.chars().next().unwrap_or('\u{fffd}');
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// `\X\hh`: one ISO 8859-1 character.
fn x_escape(s: &str) -> Option<(char, usize)> {
    let hex = s.strip_prefix("\\X\\")?.get(..2)?;
    let v = u8::from_str_radix(hex, 16).ok()?;
    Some((v as char, 5))
}

/// `\X2\hhhh...\X0\` (UCS-2) or `\X4\hhhhhhhh...\X0\` (UCS-4).
fn wide_escape(s: &str) -> Option<(String, usize)> {
    let (width, body) = if let Some(b) = s.strip_prefix("\\X2\\") {
        (4, b)
    } else {
        (8, s.strip_prefix("\\X4\\")?)
    };
    let end = body.find("\\X0\\")?;
    let hex = &body[..end];
    if hex.len() % width != 0 {
        return None;
    }
    let mut out = String::new();
    for k in (0..hex.len()).step_by(width) {
        let v = u32::from_str_radix(hex.get(k..k + width)?, 16).ok()?;
        out.push(char::from_u32(v)?);
    }
    Some((out, 4 + end + 4))
}

/// A string's contents encoded for a Part 21 file: `'` doubled, `\`
/// doubled, characters outside printable ASCII as `\X2\...\X0\`.
pub fn encode_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    for c in s.chars() {
        match c {
            '\'' => out.push_str("''"),
            '\\' => out.push_str("\\\\"),
            ' '..='~' => out.push(c),
            c if (c as u32) <= 0xFFFF => out.push_str(&format!("\\X2\\{:04X}\\X0\\", c as u32)),
            c => out.push_str(&format!("\\X4\\{:08X}\\X0\\", c as u32)),
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn strings_round_trip() {
        for s in ["it's", "a\\b", "Peça", "plain", "😀"] {
            assert_eq!(decode_string(&encode_string(s)), s);
        }
        assert_eq!(decode_string("\\X\\E9t\\X2\\00E9\\X0\\"), "été");
    }

    #[test]
    fn tokens_of_an_instance() {
        let t: Vec<Tok> = tokens("#1=A('x',1.,.T.,$,(#2)); /* c */")
            .into_iter()
            .map(|r| r.unwrap().1)
            .collect();
        assert_eq!(t.len(), 17);
        assert_eq!(t[0], Tok::InstanceName);
        assert_eq!(t[4], Tok::Str);
    }
}
