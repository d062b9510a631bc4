//! The raw Sinumerik lexer (logos): characters to raw tokens, without
//! knowing which names are keywords, variables or address words. That is
//! decided afterwards by [`super::classify`], which knows the dialect spec
//! and the names declared so far.

use logos::Logos;

/// A raw token. Identifiers may carry a decimal tail (`X10.5`, `F159.0`)
/// so that address words written without spaces stay one token to split.
#[derive(Logos, Clone, Copy, Debug, PartialEq, Eq)]
#[logos(skip r"[ \t\r\f]+")]
pub enum Raw {
    #[regex(r"[A-Za-z_][A-Za-z0-9_]*(\.[0-9.]*)?")]
    Ident,
    #[regex(r"[0-9.]+")]
    Number,
    #[regex(r#""[^"\n]*""#)]
    Str,
    #[regex(r#""[^"\n]*"#)]
    OpenStr,
    #[regex(r";[^\n]*", allow_greedy = true)]
    Comment,
    #[regex(r"\$[A-Za-z_][A-Za-z0-9_]*")]
    SysVar,
    #[regex(r"%[^ \t;]*")]
    Percent,
    #[token("==")]
    EqEq,
    #[token("<>")]
    Ne,
    #[token("<=")]
    Le,
    #[token(">=")]
    Ge,
    #[token("<<")]
    Concat,
    #[token("<")]
    Lt,
    #[token(">")]
    Gt,
    #[token("=")]
    Assign,
    #[token("+")]
    Plus,
    #[token("-")]
    Minus,
    #[token("*")]
    Star,
    #[token("/")]
    Slash,
    #[token("(")]
    LParen,
    #[token(")")]
    RParen,
    #[token("[")]
    LBracket,
    #[token("]")]
    RBracket,
    #[token(",")]
    Comma,
    #[token(":")]
    Colon,
}

/// A raw token with its line-relative byte range; `None` = a character
/// the lexer does not know.
pub type RawItem = (Option<Raw>, std::ops::Range<usize>);

/// All raw tokens of one line.
pub fn lex(text: &str) -> Vec<RawItem> {
    let mut lx = Raw::lexer(text);
    let mut out = Vec::new();
    while let Some(r) = lx.next() {
        out.push((r.ok(), lx.span()));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn kinds(t: &str) -> Vec<Option<Raw>> {
        lex(t).into_iter().map(|(k, _)| k).collect()
    }

    #[test]
    fn needs_no_whitespace() {
        assert_eq!(kinds("T1D1M6"), vec![Some(Raw::Ident)]);
        assert_eq!(
            kinds("X=R1*SIN(R2)Y=1"),
            vec![
                Some(Raw::Ident),
                Some(Raw::Assign),
                Some(Raw::Ident),
                Some(Raw::Star),
                Some(Raw::Ident),
                Some(Raw::LParen),
                Some(Raw::Ident),
                Some(Raw::RParen),
                Some(Raw::Ident),
                Some(Raw::Assign),
                Some(Raw::Number)
            ]
        );
    }

    #[test]
    fn strings_comments_and_bad_characters() {
        assert_eq!(kinds(r#"MSG("a;b") ;c"#)[2], Some(Raw::Str));
        assert_eq!(kinds(r#"MSG("ab"#)[2], Some(Raw::OpenStr));
        assert_eq!(
            kinds("G0 ;x \"y"),
            vec![Some(Raw::Ident), Some(Raw::Comment)]
        );
        assert_eq!(kinds("X1 ?"), vec![Some(Raw::Ident), None]);
        assert_eq!(kinds("$AA_IW[X]")[0], Some(Raw::SysVar));
    }
}
