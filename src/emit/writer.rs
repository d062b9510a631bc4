//! The state one run of a writer carries: the target spec, the program, the
//! diagnostics so far and the units in force (which decide how many decimal
//! places a length may have), with helpers for the words every family writes.

use super::number::{format_number, format_number_into, NumKind};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{Axes, Coord, DimMode, ExprId, ExprKind, LengthUnit, Program, Value, Word};
use crate::span::Span;

/// How expressions and addressed values are spelled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// `X[#1+2]`, `#<name>`, `SIN[#1]`.
    Bracket,
    /// `X=R1+2`, `SIN(R1)`, `X=AC(5)`.
    Sinumerik,
}

pub struct Writer<'a> {
    pub spec: &'a DialectSpec,
    pub prog: &'a Program,
    pub diags: Vec<Diagnostic>,
    /// The units in force, once the program has said them.
    pub units: Option<LengthUnit>,
    pub style: Style,
    /// `;` comment texts waiting for the end of the current block.
    pub trailing: Vec<String>,
}

impl<'a> Writer<'a> {
    pub fn new(prog: &'a Program, spec: &'a DialectSpec, style: Style) -> Self {
        Writer {
            spec,
            prog,
            diags: Vec::new(),
            units: None,
            style,
            trailing: Vec::new(),
        }
    }

    /// E0601: the target has no form for `what`.
    pub fn cannot(&mut self, span: Span, what: &str, help: &str) {
        let d = Diagnostic::new(
            Code::CannotExpress,
            format!("{} cannot express {what}", self.spec.name),
        )
        .primary(span, format!("{what} written here"))
        .help(help.to_string());
        self.diags.push(d);
    }

    /// `text` made safe for the target's reader in `form` (its spec's
    /// `<text>` table), with a warning at `span` for what was changed.
    pub fn safe_text(
        &mut self,
        text: &str,
        form: crate::dialect::text::TextForm,
        span: Span,
    ) -> String {
        let same = self.spec.answers_to(&self.prog.dialect);
        self.escaped(text, form, span, (same, same))
    }

    /// The text of a message (after `MSG,` or in `MSG("..")`): no word
    /// there makes it a command, only its characters are escaped.
    pub fn safe_message(
        &mut self,
        text: &str,
        form: crate::dialect::text::TextForm,
        span: Span,
    ) -> String {
        let same = self.spec.answers_to(&self.prog.dialect);
        self.escaped(text, form, span, (true, same))
    }

    /// `keep`: keep active words, keep the characters (text from this
    /// same dialect).
    fn escaped(
        &mut self,
        text: &str,
        form: crate::dialect::text::TextForm,
        span: Span,
        keep: (bool, bool),
    ) -> String {
        let e = self.spec.text.escape_as(text, form, keep.0, keep.1);
        if let Some(d) = text_warning(&self.spec.name, &e, Some(span)) {
            self.diags.push(d);
        }
        e.text
    }

    /// E0603: a number the target cannot write exactly.
    pub fn inexact(&mut self, span: Span, why: String) {
        let d = Diagnostic::new(Code::InexactNumber, format!("{} cannot write this number exactly", self.spec.name))
            .primary(span, why)
            .help("round the value in the source program to the target's precision, or choose a spec with more decimal places");
        self.diags.push(d);
    }

    pub fn num(&mut self, d: crate::ir::Decimal, kind: NumKind, span: Span) -> Option<String> {
        let mut s = String::with_capacity(16);
        self.num_into(&mut s, d, kind, span)?;
        Some(s)
    }

    /// [`Writer::num`] appended to `out`.
    pub fn num_into(
        &mut self,
        out: &mut String,
        d: crate::ir::Decimal,
        kind: NumKind,
        span: Span,
    ) -> Option<()> {
        match format_number_into(out, d, kind, &self.spec.numbers, self.units) {
            Ok(()) => Some(()),
            Err(why) => {
                if kind == NumKind::Feed {
                    if let Some(s) = self.rounded_feed(d, span) {
                        out.push_str(&s);
                        return Some(());
                    }
                }
                self.inexact(span, why);
                None
            }
        }
    }

    /// A feed or speed with more decimal places than the target writes,
    /// rounded to its places when that changes it by less than
    /// [`crate::compare::RATE_TOLERANCE`] of its value (a feed of
    /// 33.333333 as 33.333): far below what a machine's feed or speed
    /// control resolves. W0614; a larger change stays E0603.
    fn rounded_feed(&mut self, d: crate::ir::Decimal, span: Span) -> Option<String> {
        let places = self.spec.numbers.feed_places;
        let v = d.to_f64();
        let r = crate::ir::Decimal::from_f64(v, places).normalized();
        let off = (r.to_f64() - v).abs();
        if !(off <= crate::compare::RATE_TOLERANCE * v.abs()) || r.to_f64() == 0.0 {
            return None;
        }
        let text = format_number(r, NumKind::Feed, &self.spec.numbers, self.units).ok()?;
        self.diags.push(
            Diagnostic::new(
                Code::RateRounded,
                format!("`{d}` is written as `{text}`: {} writes feeds and speeds with {places} decimal places", self.spec.name),
            )
            .primary(span, "rounded")
            .help("the difference is below what a machine resolves; round the value in the source to keep it exact"),
        );
        Some(text)
    }

    /// The code the target writes for a meaning (`G1`), or E0601.
    pub fn code(&mut self, meaning: Meaning, span: Span) -> Option<String> {
        match self.spec.code_for(meaning) {
            Some(c) => Some(format!("{}{}", c.letter, c.code.format(0, false))),
            None => {
                let what = format!(
                    "`{}` (no code for it in the target's table)",
                    meaning.name()
                );
                self.cannot(
                    span,
                    &what,
                    "choose a target dialect that has this function, or remove it",
                );
                None
            }
        }
    }

    /// Pushes the code for `meaning` onto `words`, if the target has one.
    pub fn push_code(&mut self, words: &mut Vec<String>, meaning: Meaning, span: Span) {
        if let Some(c) = self.code(meaning, span) {
            words.push(c);
        }
    }

    /// An expression in the target's syntax.
    pub fn expr(&mut self, id: ExprId) -> Option<String> {
        super::expr::write_expr(self, id)
    }

    /// True when an expression can follow an address letter without brackets.
    fn atomic(&self, id: ExprId) -> bool {
        match &self.prog.exprs[id].kind {
            ExprKind::Number(_) | ExprKind::Var(_) => true,
            ExprKind::Unary(crate::ir::UnaryOp::Neg, inner) => {
                matches!(self.prog.exprs[*inner].kind, ExprKind::Var(_))
            }
            _ => false,
        }
    }

    /// A whole addressed word: `X10.`, `X[#1+2]`, `CR=5`, `X=R1*2`.
    pub fn word(&mut self, addr: &str, v: &Value, kind: NumKind, span: Span) -> Option<String> {
        let long = addr.chars().count() > 1;
        match (v, self.style) {
            (Value::Number(d), style) => {
                let mut s = String::with_capacity(addr.len() + 16);
                s.push_str(addr);
                if long && style == Style::Sinumerik {
                    s.push('=');
                }
                self.num_into(&mut s, *d, kind, span)?;
                Some(s)
            }
            (Value::Expr(id), Style::Bracket) => {
                let e = self.expr(*id)?;
                Some(if self.atomic(*id) {
                    format!("{addr}{e}")
                } else {
                    format!("{addr}[{e}]")
                })
            }
            (Value::Expr(id), Style::Sinumerik) => Some(format!("{addr}={}", self.expr(*id)?)),
        }
    }

    pub fn push_word(
        &mut self,
        words: &mut Vec<String>,
        addr: &str,
        v: &Value,
        kind: NumKind,
        span: Span,
    ) {
        if let Some(w) = self.word(addr, v, kind, span) {
            words.push(w);
        }
    }

    /// A coordinate, with Siemens `AC()`/`IC()` where it was written.
    pub fn coord(&mut self, addr: &str, c: &Coord, kind: NumKind) -> Option<String> {
        let Some(dim) = c.dim else {
            return self.word(addr, &c.value, kind, c.span);
        };
        if self.style != Style::Sinumerik {
            self.cannot(
                c.span,
                "a per-value AC()/IC() dimension",
                "use G90/G91 around the block instead",
            );
            return None;
        }
        let inner = match &c.value {
            Value::Number(d) => self.num(*d, kind, c.span)?,
            Value::Expr(id) => self.expr(*id)?,
        };
        let f = match dim {
            DimMode::Absolute => "AC",
            DimMode::Incremental => "IC",
        };
        Some(format!("{addr}={f}({inner})"))
    }

    /// The axis words X Y Z A B C U V W that are given.
    pub fn push_axes(&mut self, words: &mut Vec<String>, axes: &Axes) {
        for (letter, c) in axes.iter() {
            let mut buf = [0; 4];
            if let Some(w) = self.coord(letter.encode_utf8(&mut buf), c, NumKind::Length) {
                words.push(w);
            }
        }
    }

    /// The axes a direct reference return names, as machine axes `Z1=0`.
    pub fn push_machine_axes(&mut self, words: &mut Vec<String>, axes: &Axes) {
        for (letter, c) in axes.iter() {
            if let Some(w) = self.coord(&format!("{letter}1"), c, NumKind::Plain) {
                words.push(w);
            }
        }
    }

    /// Kept letter-value words, lengths by the target's address table.
    pub fn push_words(&mut self, words: &mut Vec<String>, list: &[Word]) {
        for w in list {
            let kind = if self.spec.is_length_address(w.letter) {
                NumKind::Length
            } else {
                NumKind::Plain
            };
            self.push_word(words, &w.address(), &w.value, kind, w.span);
        }
    }
}

impl Writer<'_> {
    /// True if the target has `cap`; otherwise E0601 naming `what`.
    pub fn need(&mut self, cap: crate::dialect::Capability, span: Span, what: &str) -> bool {
        if self.spec.has(cap) {
            return true;
        }
        let help = format!("the target lacks the `{}` capability", cap.name());
        self.cannot(span, what, &help);
        false
    }
}

/// W0690/W0691 for text a writer changed, located at `span` (none when the
/// text is unchanged). Shared by every writer (port and post).
pub fn text_warning(
    target: &str,
    e: &crate::dialect::text::Escaped,
    span: Option<Span>,
) -> Option<Diagnostic> {
    let at = |d: Diagnostic, label: &str| match span {
        Some(s) => d.primary(s, label.to_string()),
        None => d,
    };
    if let Some(word) = &e.neutralised {
        return Some(
            at(
                Diagnostic::new(
                    Code::ActiveTextNeutralised,
                    format!("{target} would run this comment as a command (`{word}`)"),
                ),
                "written as a plain comment",
            )
            .note(format!("written as `{}`", e.text))
            .help("write the command itself if it was meant, not as a comment"),
        );
    }
    if !e.replaced.is_empty() {
        let chars: Vec<String> = e.replaced.iter().map(|c| format!("{c:?}")).collect();
        return Some(
            at(
                Diagnostic::new(
                    Code::ActiveTextNeutralised,
                    format!(
                        "characters {target} would read as syntax in a comment: {}",
                        chars.join(" ")
                    ),
                ),
                "replaced so that the text stays a comment",
            )
            .note(format!("written as `{}`", e.text)),
        );
    }
    e.transliterated.then(|| {
        at(
            Diagnostic::new(
                Code::TextTransliterated,
                format!("{target} reads 7-bit text: characters written as the nearest ASCII"),
            ),
            "transliterated",
        )
        .note(format!("written as `{}`", e.text))
    })
}
