//! Front ends: dialect text to [`LineSyntax`], one line at a time.
//!
//! A front end (one per syntax family, each a logos lexer and a LALRPOP
//! grammar in `grammar/`) reads a line into its address words and the
//! statements its grammar builds directly (comments, assignments, control
//! flow, calls). The shared, data-driven lowering in [`crate::lower`] then
//! turns the words into statements using the dialect spec.
//!
//! Siemens `CIP` and `CT` (arc through an intermediate point, tangential
//! arc) are emitted as words with address `CIP`/`CT` and the value 0; the
//! lowering turns them into `MotionKind::ArcThrough` / `ArcTangent`.

pub mod klartext;
pub mod sinumerik;
pub mod word;

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Arena, DimMode, Expr, Stmt, Value};
use crate::span::{FileId, Span, Spanned};

/// One address word as written: `X10.5`, `G#143`, Siemens `X=AC(5)`, `CR=10`.
#[derive(Clone, Debug, PartialEq)]
pub struct WordSyntax {
    /// Upper case: `X`, `G`, `CR`, `I1`, `TURN`, `AP`, `CHF`.
    pub address: Address,
    pub value: Value,
    /// Siemens `AC(..)` / `IC(..)` around the value.
    pub dim: Option<DimMode>,
    /// Written as `ADDR=value` (Siemens extended address).
    pub extended: bool,
    /// The whole word.
    pub span: Span,
    /// The address letters only.
    pub address_span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    Word(WordSyntax),
    /// A statement the grammar built directly.
    Stmt(Stmt),
}

/// One line as read, before the words become statements.
#[derive(Clone, Debug, PartialEq)]
pub struct LineSyntax {
    /// The whole line, without its line ending.
    pub span: Span,
    pub skip: Option<Spanned<u8>>,
    pub number: Option<Spanned<u32>>,
    pub label: Option<Spanned<String>>,
    pub items: Vec<Item>,
}

/// What a front end needs to read a line.
pub struct LineInput<'a> {
    /// The line's text without its line ending.
    pub text: &'a str,
    pub file: FileId,
    /// Byte offset of the line's start in the file.
    pub offset: u32,
    pub spec: &'a DialectSpec,
}

/// A front end for one syntax family.
pub trait FrontEnd {
    /// Reads one line. Errors are pushed to `diags` with their spans; the
    /// line is still returned with what could be read, or `None` if nothing
    /// could. Must never panic, whatever the text.
    fn parse_line(
        &mut self,
        input: &LineInput<'_>,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<LineSyntax>;

    /// Takes back a line's item vector once its items are used, so that
    /// the next line may reuse its memory (a no-op by default).
    fn recycle(&mut self, _items: Vec<Item>) {}

    /// The file ends: reports what a front end still holds (a block
    /// continued past the last line), a no-op by default.
    fn finish(&mut self, _file: FileId, _diags: &mut Vec<Diagnostic>) {}
}

/// A word's address, kept inline (addresses are short ASCII: `X`, `CR`,
/// `ADISPOS`), so words cost no allocation. Longer text is cut at
/// [`Address::CAPACITY`] bytes, which no dialect's address reaches.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Address {
    bytes: [u8; Address::CAPACITY],
    len: u8,
}

impl Address {
    pub const CAPACITY: usize = 23;

    pub fn new(s: &str) -> Address {
        let mut end = s.len().min(Address::CAPACITY);
        while !s.is_char_boundary(end) {
            end -= 1;
        }
        let mut bytes = [0u8; Address::CAPACITY];
        bytes[..end].copy_from_slice(&s.as_bytes()[..end]);
        Address {
            bytes,
            len: end as u8,
        }
    }

    /// The address's bytes (no UTF-8 check: cheaper than [`Address::as_str`]).
    pub fn as_bytes(&self) -> &[u8] {
        &self.bytes[..self.len as usize]
    }

    pub fn as_str(&self) -> &str {
        // Built from a `&str` cut at a char boundary.
        std::str::from_utf8(&self.bytes[..self.len as usize]).unwrap_or("")
    }
}

impl std::ops::Deref for Address {
    type Target = str;
    fn deref(&self) -> &str {
        self.as_str()
    }
}

impl PartialEq<str> for Address {
    fn eq(&self, o: &str) -> bool {
        self.as_str() == o
    }
}

impl PartialEq<&str> for Address {
    fn eq(&self, o: &&str) -> bool {
        self.as_str() == *o
    }
}

impl From<&str> for Address {
    fn from(s: &str) -> Address {
        Address::new(s)
    }
}

impl From<String> for Address {
    fn from(s: String) -> Address {
        Address::new(&s)
    }
}

impl From<&String> for Address {
    fn from(s: &String) -> Address {
        Address::new(s)
    }
}

impl std::fmt::Display for Address {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.as_str())
    }
}

impl std::fmt::Debug for Address {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{:?}", self.as_str())
    }
}
