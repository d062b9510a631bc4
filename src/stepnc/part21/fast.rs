//! A fast path for well-formed statements: plain recursive descent over a
//! statement's tokens, building exactly what the LALRPOP grammar
//! (`grammar/part21.lalrpop`) builds. Anything it does not accept
//! (complex instances, malformed statements, numbers out of range) goes
//! to the grammar, which reads it or says what is wrong. A test compares
//! the two over every sample.

use super::lexer::{decode_string, number_value, Tok};
use super::{Param, Record, Stmt, Value};
use crate::span::{FileId, Span};

type Spanned = (usize, Tok, usize);

struct P<'s, 't> {
    src: &'s str,
    file: FileId,
    toks: &'t [Spanned],
    at: usize,
}

/// The statement, when it is a simple instance or header entity that
/// reads without error.
pub fn statement(src: &str, file: FileId, toks: &[Spanned]) -> Option<Stmt> {
    let mut p = P {
        src,
        file,
        toks,
        at: 0,
    };
    let stmt = match toks.first()?.1 {
        Tok::InstanceName => {
            let (a, _, b) = p.take(Tok::InstanceName)?;
            let id = src[a + 1..b].parse::<u64>().ok()?;
            p.take(Tok::Eq)?;
            let record = p.record()?;
            Stmt::Instance {
                id,
                id_span: Span::new(file, a, b),
                parts: vec![record],
            }
        }
        Tok::Keyword => Stmt::Header(p.record()?),
        _ => return None,
    };
    (p.at == toks.len()).then_some(stmt)
}

impl P<'_, '_> {
    fn peek(&self) -> Option<Tok> {
        self.toks.get(self.at).map(|t| t.1)
    }

    fn take(&mut self, want: Tok) -> Option<Spanned> {
        let t = *self.toks.get(self.at)?;
        if t.1 != want {
            return None;
        }
        self.at += 1;
        Some(t)
    }

    fn record(&mut self) -> Option<Record> {
        let (a, _, b) = self.take(Tok::Keyword)?;
        let params = self.params()?;
        Some(Record {
            entity: self.src[a..b].to_ascii_uppercase(),
            params,
            span: Span::new(self.file, a, b),
        })
    }

    /// `( p, p, ... )`, possibly empty.
    fn params(&mut self) -> Option<Vec<Param>> {
        self.take(Tok::LParen)?;
        let mut out = Vec::new();
        if self.take(Tok::RParen).is_some() {
            return Some(out);
        }
        loop {
            out.push(self.param()?);
            match self.peek()? {
                Tok::Comma => self.at += 1,
                Tok::RParen => {
                    self.at += 1;
                    return Some(out);
                }
                _ => return None,
            }
        }
    }

    fn param(&mut self) -> Option<Param> {
        let (a, t, b) = *self.toks.get(self.at)?;
        let text = &self.src[a..b];
        let value = match t {
            Tok::LParen => {
                let l = self.params()?;
                let end = self.toks[self.at - 1].2;
                return Some(Param {
                    value: Value::List(l),
                    span: Span::new(self.file, a, end),
                });
            }
            Tok::Keyword => {
                self.at += 1;
                self.take(Tok::LParen)?;
                let inner = self.param()?;
                let (_, _, end) = self.take(Tok::RParen)?;
                return Some(Param {
                    value: Value::Typed(text.to_ascii_uppercase(), Box::new(inner)),
                    span: Span::new(self.file, a, end),
                });
            }
            Tok::Dollar => Value::Null,
            Tok::Star => Value::Derived,
            Tok::Integer => number_value(text, true).ok()?,
            Tok::Real => number_value(text, false).ok()?,
            Tok::Str => Value::Str(decode_string(&text[1..text.len() - 1])),
            Tok::Enumeration => Value::Enum(text[1..text.len() - 1].to_ascii_uppercase()),
            Tok::Binary => Value::Binary(text[1..text.len() - 1].to_string()),
            Tok::InstanceName => Value::Ref(text[1..].parse().ok()?),
            _ => return None,
        };
        self.at += 1;
        Some(Param {
            value,
            span: Span::new(self.file, a, b),
        })
    }
}
