//! Classification: raw tokens to grammar tokens. Knows the dialect spec
//! (functions, cycles, commands, addresses) and the names declared so far
//! (DEF, PROC parameters), so that `VAR1` is a variable, `CYCLE81` a cycle
//! and `T1D1M6` three address words. Also takes off what stands outside
//! the grammar: the archive header `%_N_NAME_MPF`, block delete `/n`, the
//! block number `N10` (or main block `:10`), a `LABEL:` and the trailing
//! `;` comment.

use super::lexer::{lex, Raw};
use super::split::{split, Piece, MULTI_ADDRESSES};
use super::token::{keyword, Kw, Tok};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::num::NumberError;
use crate::ir::Decimal;
use crate::span::{FileId, Span};
use std::collections::HashSet;
use std::ops::Range;

/// A grammar token with its line-relative byte range.
pub type Spanned3 = (usize, Tok, usize);

/// Converts line-relative byte ranges to file spans.
#[derive(Clone, Copy, Debug)]
pub struct Spanner {
    pub file: FileId,
    pub offset: u32,
}

impl Spanner {
    pub fn span(self, start: usize, end: usize) -> Span {
        Span::new(self.file, start, end).shifted(self.offset)
    }
}

/// A line after classification.
#[derive(Debug, Default)]
pub struct Classified {
    pub header: Option<(String, Range<usize>)>,
    pub skip: Option<(u8, Range<usize>)>,
    pub number: Option<(u32, Range<usize>)>,
    pub label: Option<(String, Range<usize>)>,
    pub comment: Option<(String, Range<usize>)>,
    pub toks: Vec<Spanned3>,
    /// A character-level error was reported: the grammar is not run.
    pub lex_error: bool,
}

/// What the identifiers of the current line are read as.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Mode {
    Normal,
    Def,
    Proc,
}

struct Cx<'a> {
    text: &'a str,
    spec: &'a DialectSpec,
    declared: &'a HashSet<String>,
    sp: Spanner,
    out: Classified,
    mode: Mode,
    depth: i32,
    diags: &'a mut Vec<Diagnostic>,
}

/// Classifies one line.
pub fn classify(
    text: &str,
    spec: &DialectSpec,
    declared: &HashSet<String>,
    sp: Spanner,
    diags: &mut Vec<Diagnostic>,
) -> Classified {
    let raws = lex(text);
    let mut cx = Cx {
        text,
        spec,
        declared,
        sp,
        out: Classified::default(),
        mode: Mode::Normal,
        depth: 0,
        diags,
    };
    let mut i = 0;
    while i < raws.len() {
        i = cx.step(&raws, i);
    }
    cx.out
}

impl Cx<'_> {
    fn at_prefix(&self) -> bool {
        self.out.toks.is_empty()
    }

    fn push(&mut self, r: Range<usize>, t: Tok) {
        match t {
            Tok::Kw(Kw::Def) => self.mode = Mode::Def,
            Tok::Kw(Kw::Proc) => self.mode = Mode::Proc,
            Tok::LParen | Tok::LBracket => self.depth += 1,
            Tok::RParen | Tok::RBracket => self.depth -= 1,
            _ => {}
        }
        self.out.toks.push((r.start, t, r.end));
    }

    fn error(&mut self, code: Code, r: Range<usize>, msg: String, label: &str, help: &str) {
        self.out.lex_error = true;
        let d = Diagnostic::new(code, msg)
            .primary(self.sp.span(r.start, r.end), label)
            .help(help);
        self.diags.push(d);
    }

    /// Handles the raw token at `i`; returns the index of the next one.
    fn step(&mut self, raws: &[(Option<Raw>, Range<usize>)], i: usize) -> usize {
        let (kind, r) = (raws[i].0, raws[i].1.clone());
        let next = raws.get(i + 1).map(|(k, _)| *k);
        let Some(kind) = kind else {
            let ch = self.text[r.clone()].chars().next().unwrap_or('?');
            self.error(
                Code::BadCharacter,
                r,
                format!("the character `{ch}` has no meaning here"),
                "unexpected character",
                "remove it, or put it in a `;` comment",
            );
            return i + 1;
        };
        let s = &self.text[r.clone()];
        match kind {
            Raw::Comment => self.out.comment = Some((s[1..].to_string(), r)),
            Raw::Percent if i == 0 => self.out.header = Some((archive_name(s), r)),
            Raw::Slash if i == 0 => return self.skip(raws, r),
            Raw::Colon if self.at_prefix() && self.out.number.is_none() => {
                return self.main_block(raws, i)
            }
            Raw::Ident if next == Some(Some(Raw::Colon)) => {
                self.label(s.to_string(), r);
                return i + 2;
            }
            Raw::Ident => self.ident(s, r, next.flatten()),
            Raw::Number => {
                if let Some(d) = self.number(s, r.clone()) {
                    self.push(r, Tok::Num(d));
                }
            }
            Raw::Str => self.push(r, Tok::Str(s[1..s.len() - 1].to_string())),
            Raw::OpenStr => self.error(
                Code::UnterminatedString,
                r,
                "this string is not closed on its line".into(),
                "string opened here",
                "close it with `\"`",
            ),
            Raw::SysVar => self.push(r, Tok::SysVar(s.to_ascii_uppercase())),
            _ => self.punct(kind, s, r),
        }
        i + 1
    }

    fn punct(&mut self, kind: Raw, s: &str, r: Range<usize>) {
        let t = match kind {
            Raw::EqEq => Tok::EqEq,
            Raw::Ne => Tok::Ne,
            Raw::Le => Tok::Le,
            Raw::Ge => Tok::Ge,
            Raw::Lt => Tok::Lt,
            Raw::Gt => Tok::Gt,
            Raw::Concat => Tok::Concat,
            Raw::Assign => Tok::Assign,
            Raw::Plus => Tok::Plus,
            Raw::Minus => Tok::Minus,
            Raw::Star => Tok::Star,
            Raw::Slash => Tok::Slash,
            Raw::LParen => Tok::LParen,
            Raw::RParen => Tok::RParen,
            Raw::LBracket => Tok::LBracket,
            Raw::RBracket => Tok::RBracket,
            Raw::Comma => Tok::Comma,
            _ => {
                let msg = format!("`{s}` cannot stand here");
                let help = "`%` starts an archive header line; `:` ends a label or starts a main block number";
                return self.error(Code::BadCharacter, r, msg, "unexpected here", help);
            }
        };
        self.push(r, t);
    }

    fn number(&mut self, s: &str, r: Range<usize>) -> Option<Decimal> {
        match Decimal::parse(s) {
            Ok(d) => Some(d),
            Err(e) => {
                self.number_error(e, s, r);
                None
            }
        }
    }

    fn number_error(&mut self, e: NumberError, s: &str, r: Range<usize>) {
        match e {
            NumberError::Malformed => self.error(
                Code::MalformedNumber,
                r,
                format!("`{s}` is not a number"),
                "malformed number",
                "a number has digits and at most one decimal point",
            ),
            NumberError::TooLong => self.error(
                Code::NumberTooLong,
                r,
                format!("`{s}` has too many digits"),
                "too many digits",
                "at most 18 significant digits are kept exactly; shorten the number",
            ),
        }
    }

    fn skip(&mut self, raws: &[(Option<Raw>, Range<usize>)], r: Range<usize>) -> usize {
        if let Some((Some(Raw::Number), nr)) = raws.get(1) {
            let s = &self.text[nr.clone()];
            if nr.start == r.end && s.len() == 1 && s.as_bytes()[0].is_ascii_digit() {
                self.out.skip = Some((s.as_bytes()[0] - b'0', r.start..nr.end));
                return 2;
            }
        }
        self.out.skip = Some((0, r));
        1
    }

    fn main_block(&mut self, raws: &[(Option<Raw>, Range<usize>)], i: usize) -> usize {
        let r = raws[i].1.clone();
        if let Some((Some(Raw::Number), nr)) = raws.get(i + 1) {
            let s = &self.text[nr.clone()];
            if let Ok(n) = s.parse::<u32>() {
                self.out.number = Some((n, r.start..nr.end));
                return i + 2;
            }
        }
        self.error(
            Code::SyntaxError,
            r,
            "`:` must be followed by a main block number".into(),
            "expected a number after this",
            "write a main block as `:10`, a label as `NAME:`",
        );
        i + 1
    }

    fn label(&mut self, name: String, r: Range<usize>) {
        if self.at_prefix() && self.out.label.is_none() {
            self.out.label = Some((name, r.start..r.end + 1));
        } else {
            let msg = format!("the label `{name}:` must stand at the start of the block");
            self.error(
                Code::SyntaxError,
                r,
                msg,
                "label here",
                "put the label first in its block, after the block number",
            );
        }
    }

    /// Whether the previous token leaves an operand to come (an identifier
    /// there is a name, never packed address words).
    fn expects_operand(&self) -> bool {
        use Kw::*;
        match self.out.toks.last().map(|t| &t.1) {
            Some(Tok::Kw(k)) => matches!(
                k,
                If | While
                    | Until
                    | To
                    | Not
                    | And
                    | Or
                    | Xor
                    | BNot
                    | BAnd
                    | BOr
                    | BXor
                    | Div
                    | Mod
                    | Of
                    | Case
                    | Ac
                    | Ic
            ),
            Some(t) => !matches!(
                t,
                Tok::Num(_)
                    | Tok::Str(_)
                    | Tok::RParen
                    | Tok::RBracket
                    | Tok::Name(_)
                    | Tok::UserVar(_)
                    | Tok::RParam(_)
                    | Tok::SysVar(_)
                    | Tok::Addr(_)
                    | Tok::Command(_)
                    | Tok::Cycle(_)
                    | Tok::Func(_)
            ),
            None => false,
        }
    }

    /// Whether an identifier here names something (label, new variable).
    fn names_here(&self, before_assign: bool) -> bool {
        let last = self.out.toks.last().map(|t| &t.1);
        match self.mode {
            Mode::Proc => return true,
            Mode::Def if self.depth == 0 => {
                if matches!(
                    last,
                    Some(Tok::Comma) | Some(Tok::RBracket) | Some(Tok::Kw(_))
                ) {
                    return true;
                }
            }
            _ => {}
        }
        use Kw::*;
        match last {
            Some(Tok::Kw(GotoF | GotoB | Goto | GotoC | Repeat | RepeatB)) => true,
            Some(Tok::Name(_)) => !before_assign && self.line_has(Kw::Repeat, Kw::RepeatB),
            _ => false,
        }
    }

    fn line_has(&self, a: Kw, b: Kw) -> bool {
        self.out
            .toks
            .iter()
            .any(|t| t.1 == Tok::Kw(a) || t.1 == Tok::Kw(b))
    }

    fn ident(&mut self, s: &str, r: Range<usize>, next: Option<Raw>) {
        let upper = s.to_ascii_uppercase();
        let before_assign = next == Some(Raw::Assign);
        if let Some(k) = keyword(&upper) {
            return self.push(r, Tok::Kw(k));
        }
        if self.names_here(before_assign) {
            return self.push(r, Tok::Name(s.to_string()));
        }
        // `SPOS=90`: a multi-letter address before `=` is the address,
        // even where the spec also lists it as a command.
        if before_assign && upper.len() > 1 && MULTI_ADDRESSES.contains(&upper.as_str()) {
            return self.push(r, Tok::Addr(upper));
        }
        if let Some(t) = self.named(s, &upper, next) {
            return self.push(r, t);
        }
        if self.expects_operand() {
            return self.push(r, Tok::Name(s.to_string()));
        }
        match split(self.spec, &upper, before_assign) {
            Some(pieces) => self.pieces(pieces, r.start),
            None => self.push(r, Tok::Name(s.to_string())),
        }
    }

    /// Declared variables, R parameters, functions, cycles, commands.
    fn named(&self, s: &str, upper: &str, next: Option<Raw>) -> Option<Tok> {
        if self.declared.contains(upper) {
            return Some(Tok::UserVar(s.to_string()));
        }
        if let Some(n) = upper.strip_prefix('R') {
            if n.is_empty() && next == Some(Raw::LBracket) {
                return Some(Tok::RIndex);
            }
            if !n.is_empty() && n.len() <= 9 && n.bytes().all(|b| b.is_ascii_digit()) {
                return n.parse().ok().map(Tok::RParam);
            }
        }
        if self.spec.function(upper).is_some() {
            Some(Tok::Func(upper.to_string()))
        } else if self.spec.cycle(upper).is_some() {
            Some(Tok::Cycle(upper.to_string()))
        } else if self.spec.is_command(upper) {
            Some(Tok::Command(upper.to_string()))
        } else {
            None
        }
    }

    fn pieces(&mut self, pieces: Vec<Piece>, base: usize) {
        let mut it = pieces.into_iter().peekable();
        while let Some(p) = it.next() {
            match p {
                Piece::Addr(a, s, e)
                    if a == "N" && self.at_prefix() && self.out.number.is_none() =>
                {
                    if let Some(Piece::Num(Ok(d), _, ne)) = it.peek() {
                        if let Some(n) = d
                            .as_int()
                            .filter(|_| !d.point)
                            .and_then(|n| u32::try_from(n).ok())
                        {
                            self.out.number = Some((n, base + s..base + *ne));
                            it.next();
                            continue;
                        }
                    }
                    self.push(base + s..base + e, Tok::Addr(a));
                }
                Piece::Addr(a, s, e) => self.push(base + s..base + e, Tok::Addr(a)),
                Piece::Num(Ok(d), s, e) => self.push(base + s..base + e, Tok::Num(d)),
                Piece::Num(Err(err), s, e) => {
                    let text = self.text[base + s..base + e].to_string();
                    self.number_error(err, &text, base + s..base + e);
                }
            }
        }
    }
}

/// `%_N_PART1_MPF` → `PART1`.
fn archive_name(s: &str) -> String {
    let s = s.trim_start_matches('%');
    let s = s.strip_prefix("_N_").unwrap_or(s);
    let s = ["_MPF", "_SPF", "_mpf", "_spf"]
        .iter()
        .find_map(|x| s.strip_suffix(x))
        .unwrap_or(s);
    s.to_string()
}
