//! The fast path of the Sinumerik front end: a line of plain address words
//! separated by blanks (`N10 G1 X12.5 Y-3 F500`, most of what CAM posts
//! write) is read by the word front end's byte scanner
//! ([`crate::syntax::word::fast`]) instead of the logos lexer, the
//! classifier and the LALRPOP grammar, which build the same items for such
//! a line (tested in `tests::fast_path_agrees`).
//!
//! A line qualifies only when every blank-separated piece is one address
//! letter the spec lists (not `R`, an arithmetic parameter; not `L`, a
//! subprogram call; `N` only first, as the block number) followed by a
//! number (`[+-]digits[.digits]`), and the identifier the lexer would see
//! (`X12` of `X12.5`) is no keyword, declared variable, function, cycle or
//! command. Anything else (`;`, `=`, `(`, packed words `G0X1`, names) goes
//! the full way.

use super::split::is_address;
use super::token::KEYWORDS;
use crate::dialect::DialectSpec;
use std::collections::HashSet;

/// What the fast path asks per word, computed once per spec and set of
/// declared names (the spec's names are lists searched one by one).
#[derive(Debug, Default)]
pub struct FastTable {
    /// The spec the table was made for (its address).
    spec: usize,
    /// Bit `n`: letter `A + n` is a single-letter address here.
    letters: u32,
    /// Names of the form letter + digits (`X1`, `D`) that are keywords,
    /// functions, cycles, commands or declared variables: a word whose
    /// identifier is one of them goes the full way.
    wordlike: HashSet<String>,
}

impl FastTable {
    pub fn new(spec: &DialectSpec, declared: &HashSet<String>) -> FastTable {
        let mut letters = 0u32;
        for (n, c) in ('A'..='Z').enumerate() {
            if is_address(spec, c.encode_utf8(&mut [0u8; 4])) {
                letters |= 1 << n;
            }
        }
        let names = KEYWORDS.iter().map(|(n, _)| n.to_string());
        let names = names
            .chain(spec.functions.iter().map(|f| f.name.to_ascii_uppercase()))
            .chain(spec.cycles.iter().map(|c| c.name.to_ascii_uppercase()))
            .chain(spec.commands.iter().map(|c| c.to_ascii_uppercase()))
            .chain(declared.iter().cloned());
        let wordlike = names.filter(|n| is_wordlike(n)).collect();
        FastTable {
            spec: spec as *const DialectSpec as usize,
            letters,
            wordlike,
        }
    }

    /// Whether the table was made for `spec`.
    pub fn is_for(&self, spec: &DialectSpec) -> bool {
        self.spec == spec as *const DialectSpec as usize
    }

    /// Whether `text` is plain address words the fast path reads as the
    /// grammar does.
    pub fn plain_words(&self, text: &str) -> bool {
        let mut first = true;
        let mut any = false;
        for piece in text.split([' ', '\t', '\r']).filter(|p| !p.is_empty()) {
            if !self.plain_word(piece, first) {
                return false;
            }
            first = false;
            any = true;
        }
        any
    }

    fn plain_word(&self, piece: &str, first: bool) -> bool {
        let b = piece.as_bytes();
        let letter = b[0].to_ascii_uppercase();
        if !letter.is_ascii_uppercase() || letter == b'L' || letter == b'R' {
            return false;
        }
        let rest = &b[1..];
        let digits_at = usize::from(matches!(rest.first(), Some(b'+' | b'-')));
        let num = &rest[digits_at..];
        if num.is_empty()
            || !num.iter().all(|c| c.is_ascii_digit() || *c == b'.')
            || !num.iter().any(u8::is_ascii_digit)
            || num.iter().filter(|c| **c == b'.').count() > 1
        {
            return false;
        }
        if letter == b'N' {
            return first && digits_at == 0 && num.iter().all(u8::is_ascii_digit);
        }
        if self.letters & (1 << (letter - b'A')) == 0 {
            return false;
        }
        if self.wordlike.is_empty() {
            return true;
        }
        // The identifier the lexer reads: the letter and the digits after it.
        let int_len = if digits_at == 0 {
            num.iter().take_while(|c| c.is_ascii_digit()).count()
        } else {
            0
        };
        let mut ident = [0u8; 24];
        if int_len + 1 > ident.len() {
            return false;
        }
        ident[0] = letter;
        ident[1..=int_len].copy_from_slice(&num[..int_len]);
        std::str::from_utf8(&ident[..=int_len]).is_ok_and(|n| !self.wordlike.contains(n))
    }
}

/// A letter and digits only (`X1`, `D`).
fn is_wordlike(name: &str) -> bool {
    let b = name.as_bytes();
    !b.is_empty() && b[0].is_ascii_alphabetic() && b[1..].iter().all(u8::is_ascii_digit)
}

#[cfg(test)]
mod tests {
    use super::super::SinumerikFrontEnd;
    use crate::dialect::builtin;
    use crate::ir::Arena;
    use crate::span::FileId;
    use crate::syntax::{FrontEnd, LineInput};
    use std::path::Path;

    /// Both front ends over the same lines give the same items and
    /// diagnostics; returns how many lines the fast path took.
    fn agree(text: &str) -> usize {
        let spec = builtin("siemens840d").expect("spec");
        let mut fast = SinumerikFrontEnd::new();
        let mut slow = SinumerikFrontEnd::without_fast_path();
        let (mut ea, mut eb) = (Arena::default(), Arena::default());
        let mut taken = 0;
        let mut offset = 0u32;
        for line in text.lines() {
            let input = LineInput {
                text: line,
                file: FileId(0),
                offset,
                spec: &spec,
            };
            offset += line.len() as u32 + 1;
            let (mut da, mut db) = (Vec::new(), Vec::new());
            let a = fast.parse_line(&input, &mut ea, &mut da);
            let b = slow.parse_line(&input, &mut eb, &mut db);
            assert_eq!(a, b, "{line:?}");
            assert_eq!(format!("{da:?}"), format!("{db:?}"), "{line:?}");
            taken += usize::from(super::FastTable::new(&spec, &fast.declared).plain_words(line));
        }
        taken
    }

    #[test]
    fn fast_path_agrees() {
        let lines = "N10 G1 X12.345 Y-3.2 Z-1. F500\nG0 X1 Y2\nn5 m3 s1000\nX+.5 Y-0.25\n\
                     \nM30\nN010 T1 D1 M6\nG0X1Y2\nL100\nR1=2\nX=R1\nG1 X1 N20\nS1=100\n\
                     DEF REAL X1\nX1 Y2\nG0 X1.5\nT2\nD0\nH1\nN99999999999 X1\nX1..2\nX-\n\
                     CR=5\nG2 X1 Y2 I3 J4\nG17\nM17\nM2\nE5\nP3\nQ1 A1 B2 C3 U1 V2 W3";
        assert!(agree(lines) >= 10);
    }

    #[test]
    fn fast_path_agrees_on_the_field_and_corpus() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        let dirs = [
            root.join("tests/programs/siemens840d"),
            root.join("../shared/field/siemens840d"),
            root.join("../shared/corpus/siemens840d"),
        ];
        let mut taken = 0;
        for dir in dirs {
            let Ok(rd) = std::fs::read_dir(&dir) else {
                continue;
            };
            for e in rd.flatten() {
                let Ok(bytes) = std::fs::read(e.path()) else {
                    continue;
                };
                taken += agree(&String::from_utf8_lossy(&bytes));
            }
        }
        println!("fast path took {taken} lines");
    }
}
