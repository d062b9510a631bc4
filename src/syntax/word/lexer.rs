//! The word-address lexer: one line of text into tokens with byte ranges.
//!
//! Case-insensitive. A single letter is a word address; a run of two or more
//! letters is a keyword (`GOTO`, `EQ`, `endsub`) or a name (`SIN`, `FOO`).
//! No whitespace is needed between tokens (`IF[#1EQ2]GOTO10`), and spaces
//! between tokens are skipped (`G 0 X 1.5`). Comments are tokens too; the
//! front end takes them out of the stream before the grammar runs.

use logos::Logos;

/// Raw tokens as logos finds them.
#[derive(Logos, Clone, Copy, Debug, PartialEq, Eq)]
/// `\x1a` (Ctrl-Z) is the DOS end-of-file mark old DNC software leaves
/// after the closing `%`: read as blank.
#[logos(skip r"[ \t\r\f\v\u{feff}\x1a]+")]
enum Raw {
    #[regex("[A-Za-z]")]
    Letter,
    #[regex("[A-Za-z][A-Za-z_]+")]
    Letters,
    /// LinuxCNC polar words `@` (radius) and `^` (angle).
    #[regex("[@^]")]
    Polar,
    #[regex(r"[0-9.]+")]
    Number,
    #[token("#")]
    Hash,
    #[regex(r"<[^>]*>")]
    Named,
    #[token("[")]
    LBr,
    #[token("]")]
    RBr,
    #[token(",")]
    Comma,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("**")]
    Pow,
    #[token("/")]
    Slash,
    #[token("=")]
    Assign,
    #[token("%")]
    Percent,
    #[token(":")]
    Colon,
    #[regex(r"\([^)]*\)")]
    Comment,
    #[regex(r"\([^)]*")]
    OpenComment,
    #[regex(r";.*", allow_greedy = true)]
    Semi,
}

/// Tokens the grammar reads. Values (which letter, which digits) are read
/// back from the line text through the token's byte range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Tok {
    /// A single address letter, upper-cased (never `O`), or `@` / `^`.
    Letter(u8),
    /// The letter `O` starting a program number `O1234`.
    O,
    /// The letter `O` starting an o-word statement (`o100 sub`): the front
    /// end retags `O` when a number or name and an o-word keyword follow.
    OWord,
    Number,
    Hash,
    /// `<name>`, brackets included.
    Named,
    LBr,
    RBr,
    Comma,
    Plus,
    Minus,
    Star,
    Pow,
    Slash,
    Assign,
    Percent,
    /// `:`: the ISO program number address (`:0097` is `O0097`) where the
    /// dialect has `colon-program-number`; a bad character elsewhere.
    Colon,
    /// A name that is no keyword: a function or an unknown word.
    Name,
    Kw(Kw),
    /// `( ... )`; `closed` is false when the line ends first.
    Comment {
        closed: bool,
    },
    /// `;` to the end of the line.
    Semi,
    /// A character no token starts with.
    Bad,
}

/// Keywords, matched without regard to case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kw {
    Goto,
    If,
    Then,
    While,
    Do,
    End,
    Eq,
    Ne,
    Gt,
    Ge,
    Lt,
    Le,
    And,
    Or,
    Xor,
    Mod,
    Exists,
    Atan,
    Sub,
    EndSub,
    Call,
    Return,
    ElseIf,
    Else,
    EndIf,
    EndWhile,
    Repeat,
    EndRepeat,
    Break,
    Continue,
}

const KEYWORDS: &[(&str, Kw)] = &[
    ("GOTO", Kw::Goto),
    ("IF", Kw::If),
    ("THEN", Kw::Then),
    ("WHILE", Kw::While),
    ("DO", Kw::Do),
    ("END", Kw::End),
    ("EQ", Kw::Eq),
    ("NE", Kw::Ne),
    ("GT", Kw::Gt),
    ("GE", Kw::Ge),
    ("LT", Kw::Lt),
    ("LE", Kw::Le),
    ("AND", Kw::And),
    ("OR", Kw::Or),
    ("XOR", Kw::Xor),
    ("MOD", Kw::Mod),
    ("EXISTS", Kw::Exists),
    ("ATAN", Kw::Atan),
    ("SUB", Kw::Sub),
    ("ENDSUB", Kw::EndSub),
    ("CALL", Kw::Call),
    ("RETURN", Kw::Return),
    ("ELSEIF", Kw::ElseIf),
    ("ELSE", Kw::Else),
    ("ENDIF", Kw::EndIf),
    ("ENDWHILE", Kw::EndWhile),
    ("REPEAT", Kw::Repeat),
    ("ENDREPEAT", Kw::EndRepeat),
    ("BREAK", Kw::Break),
    ("CONTINUE", Kw::Continue),
];

/// Macro B words by their first two letters, for dialects with
/// `macro-word-abbreviations` (Fanuc: `WH[#1LT10]DO1`). Only two-letter
/// forms that are no full keyword of their own; `DO`, `IF`, `EQ`.. are.
const ABBREVIATIONS: &[(&str, Kw)] = &[
    ("WH", Kw::While),
    ("GO", Kw::Goto),
    ("EN", Kw::End),
    ("TH", Kw::Then),
    ("AN", Kw::And),
    ("XO", Kw::Xor),
];

impl Kw {
    /// The keyword `word` (any case) abbreviates, if it is a Macro B
    /// two-letter abbreviation.
    pub fn abbreviated(word: &str) -> Option<Kw> {
        ABBREVIATIONS
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(word))
            .map(|(_, kw)| *kw)
    }

    /// The keyword spelled `word` (any case), if it is one.
    pub fn lookup(word: &str) -> Option<Kw> {
        KEYWORDS
            .iter()
            .find(|(k, _)| k.eq_ignore_ascii_case(word))
            .map(|(_, kw)| *kw)
    }

    /// Its spelling, upper case.
    pub fn text(self) -> &'static str {
        KEYWORDS
            .iter()
            .find(|(_, k)| *k == self)
            .map(|(t, _)| *t)
            .unwrap_or("?")
    }
}

/// A token with its byte range in the line.
pub type Spanned = (usize, Tok, usize);

/// Lexes `text` into `out` (cleared first).
pub fn lex_into(text: &str, out: &mut Vec<Spanned>) {
    out.clear();
    let mut lx = Raw::lexer(text);
    while let Some(r) = lx.next() {
        let span = lx.span();
        let tok = match r {
            Ok(raw) => convert(raw, lx.slice()),
            Err(()) => Tok::Bad,
        };
        out.push((span.start, tok, span.end));
    }
}

fn convert(raw: Raw, slice: &str) -> Tok {
    match raw {
        Raw::Letter => match slice.as_bytes()[0].to_ascii_uppercase() {
            b'O' => Tok::O,
            c => Tok::Letter(c),
        },
        Raw::Polar => Tok::Letter(slice.as_bytes()[0]),
        Raw::Letters => Kw::lookup(slice).map(Tok::Kw).unwrap_or(Tok::Name),
        Raw::Number => Tok::Number,
        Raw::Hash => Tok::Hash,
        Raw::Named => Tok::Named,
        Raw::LBr => Tok::LBr,
        Raw::RBr => Tok::RBr,
        Raw::Comma => Tok::Comma,
        Raw::Plus => Tok::Plus,
        Raw::Minus => Tok::Minus,
        Raw::Star => Tok::Star,
        Raw::Pow => Tok::Pow,
        Raw::Slash => Tok::Slash,
        Raw::Assign => Tok::Assign,
        Raw::Percent => Tok::Percent,
        Raw::Colon => Tok::Colon,
        Raw::Comment => Tok::Comment { closed: true },
        Raw::OpenComment => Tok::Comment { closed: false },
        Raw::Semi => Tok::Semi,
    }
}

/// A short readable name for a token, for "found ..." messages.
pub fn describe(tok: Tok, slice: &str) -> String {
    match tok {
        Tok::Number => format!("number `{slice}`"),
        Tok::Letter(_) | Tok::O => format!("address `{slice}`"),
        Tok::Name => format!("name `{slice}`"),
        Tok::Kw(k) => format!("keyword `{}`", k.text()),
        Tok::Named => format!("parameter name `{slice}`"),
        Tok::Comment { .. } => "a comment".to_string(),
        _ => format!("`{slice}`"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn toks(text: &str) -> Vec<(Tok, &str)> {
        let mut v = Vec::new();
        lex_into(text, &mut v);
        v.iter().map(|&(s, t, e)| (t, &text[s..e])).collect()
    }

    #[test]
    fn letters_and_numbers_without_spaces() {
        let t = toks("G0G40X#140+.25Y0");
        let kinds: Vec<Tok> = t.iter().map(|(k, _)| *k).collect();
        use Tok::*;
        assert_eq!(
            kinds,
            vec![
                Letter(b'G'),
                Number,
                Letter(b'G'),
                Number,
                Letter(b'X'),
                Hash,
                Number,
                Plus,
                Number,
                Letter(b'Y'),
                Number
            ]
        );
        assert_eq!(t[8].1, ".25");
    }

    #[test]
    fn keywords_any_case_and_glued() {
        let t = toks("IF[#118EQ#116]AND[#119EQ#117]GOTO10");
        assert_eq!(t[4], (Tok::Kw(Kw::Eq), "EQ"));
        assert_eq!(t[8], (Tok::Kw(Kw::And), "AND"));
        assert_eq!(t[16], (Tok::Kw(Kw::Goto), "GOTO"));
        assert_eq!(t[17], (Tok::Number, "10"));
        assert_eq!(toks("o100 endsub")[2].0, Tok::Kw(Kw::EndSub));
        assert_eq!(toks("o100")[0].0, Tok::O);
        assert_eq!(toks("sin")[0].0, Tok::Name);
        assert_eq!(toks("WHILE[#1LT10]DO1")[7], (Tok::Kw(Kw::Do), "DO"));
    }

    #[test]
    fn spaces_inside_words() {
        let t = toks("g 0 x 1.5");
        assert_eq!(
            t,
            vec![
                (Tok::Letter(b'G'), "g"),
                (Tok::Number, "0"),
                (Tok::Letter(b'X'), "x"),
                (Tok::Number, "1.5")
            ]
        );
    }

    #[test]
    fn comments_and_bad_characters() {
        assert_eq!(toks("(a) x")[0], (Tok::Comment { closed: true }, "(a)"));
        assert_eq!(
            toks("G0 (open")[2],
            (Tok::Comment { closed: false }, "(open")
        );
        assert_eq!(toks("G0 ; rest (x)")[2], (Tok::Semi, "; rest (x)"));
        assert_eq!(toks("G0 $")[2], (Tok::Bad, "$"));
        assert_eq!(toks("#<_a b>")[1], (Tok::Named, "<_a b>"));
        assert_eq!(toks("X1.2.3")[1], (Tok::Number, "1.2.3"));
        assert_eq!(toks("2**3")[1], (Tok::Pow, "**"));
        assert_eq!(toks("@1 ^2")[2], (Tok::Letter(b'^'), "^"));
        assert_eq!(toks("\u{feff}G1")[0], (Tok::Letter(b'G'), "G"));
        assert_eq!(toks("%\x1a"), [(Tok::Percent, "%")]);
        assert_eq!(toks(":0097")[0], (Tok::Colon, ":"));
    }
}
