//! The tokens the Sinumerik grammar reads: raw tokens after classification
//! (keywords recognised, declared names told apart from address words,
//! packed address words such as `T1D1M6` split).

use crate::ir::Decimal;

/// Reserved words of the Sinumerik language that the grammar places.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kw {
    If,
    Else,
    EndIf,
    While,
    EndWhile,
    For,
    To,
    EndFor,
    Repeat,
    RepeatB,
    Until,
    Loop,
    EndLoop,
    Case,
    Of,
    Default,
    Goto,
    GotoF,
    GotoB,
    GotoC,
    Def,
    Proc,
    Ret,
    MCall,
    Call,
    Msg,
    Trans,
    ATrans,
    Rot,
    ARot,
    Scale,
    AScale,
    Mirror,
    AMirror,
    Ac,
    Ic,
    Div,
    Mod,
    And,
    Or,
    Xor,
    Not,
    BAnd,
    BOr,
    BXor,
    BNot,
    True,
    False,
    Cip,
    Ct,
    Real,
    Int,
    Bool,
    Char,
    StringT,
    Axis,
    Frame,
}

/// Keyword spellings (upper case).
pub const KEYWORDS: &[(&str, Kw)] = &[
    ("IF", Kw::If),
    ("ELSE", Kw::Else),
    ("ENDIF", Kw::EndIf),
    ("WHILE", Kw::While),
    ("ENDWHILE", Kw::EndWhile),
    ("FOR", Kw::For),
    ("TO", Kw::To),
    ("ENDFOR", Kw::EndFor),
    ("REPEAT", Kw::Repeat),
    ("REPEATB", Kw::RepeatB),
    ("UNTIL", Kw::Until),
    ("LOOP", Kw::Loop),
    ("ENDLOOP", Kw::EndLoop),
    ("CASE", Kw::Case),
    ("OF", Kw::Of),
    ("DEFAULT", Kw::Default),
    ("GOTO", Kw::Goto),
    ("GOTOF", Kw::GotoF),
    ("GOTOB", Kw::GotoB),
    ("GOTOC", Kw::GotoC),
    ("DEF", Kw::Def),
    ("PROC", Kw::Proc),
    ("RET", Kw::Ret),
    ("MCALL", Kw::MCall),
    ("CALL", Kw::Call),
    ("MSG", Kw::Msg),
    ("TRANS", Kw::Trans),
    ("ATRANS", Kw::ATrans),
    ("ROT", Kw::Rot),
    ("AROT", Kw::ARot),
    ("SCALE", Kw::Scale),
    ("ASCALE", Kw::AScale),
    ("MIRROR", Kw::Mirror),
    ("AMIRROR", Kw::AMirror),
    ("AC", Kw::Ac),
    ("IC", Kw::Ic),
    ("DIV", Kw::Div),
    ("MOD", Kw::Mod),
    ("AND", Kw::And),
    ("OR", Kw::Or),
    ("XOR", Kw::Xor),
    ("NOT", Kw::Not),
    ("B_AND", Kw::BAnd),
    ("B_OR", Kw::BOr),
    ("B_XOR", Kw::BXor),
    ("B_NOT", Kw::BNot),
    ("TRUE", Kw::True),
    ("FALSE", Kw::False),
    ("CIP", Kw::Cip),
    ("CT", Kw::Ct),
    ("REAL", Kw::Real),
    ("INT", Kw::Int),
    ("BOOL", Kw::Bool),
    ("CHAR", Kw::Char),
    ("STRING", Kw::StringT),
    ("AXIS", Kw::Axis),
    ("FRAME", Kw::Frame),
];

pub fn keyword(upper: &str) -> Option<Kw> {
    KEYWORDS.iter().find(|(n, _)| *n == upper).map(|(_, k)| *k)
}

/// A classified token. Names keep their spelling as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Kw(Kw),
    Num(Decimal),
    Str(String),
    SysVar(String),
    /// An address (`X`, `G`, `CR`, `I1`), a value follows.
    Addr(String),
    /// `R12`.
    RParam(u32),
    /// `R` followed by `[`.
    RIndex,
    /// A name declared with DEF or as a PROC parameter.
    UserVar(String),
    /// A function from the spec's function table.
    Func(String),
    /// A named cycle from the spec's cycle table.
    Cycle(String),
    /// A keyword command from the spec's command list.
    Command(String),
    /// Any other name: label, subprogram, undeclared variable.
    Name(String),
    EqEq,
    Ne,
    Le,
    Ge,
    Lt,
    Gt,
    Concat,
    Assign,
    Plus,
    Minus,
    Star,
    Slash,
    LParen,
    RParen,
    LBracket,
    RBracket,
    Comma,
}

impl Tok {
    /// How the token is shown in "expected" lists and messages.
    pub fn describe(&self) -> String {
        match self {
            Tok::Kw(k) => format!("`{}`", kw_name(*k)),
            Tok::Num(d) => format!("number `{d}`"),
            Tok::Str(s) => format!("string \"{s}\""),
            Tok::SysVar(s) => format!("system variable `{s}`"),
            Tok::Addr(a) => format!("address `{a}`"),
            Tok::RParam(n) => format!("`R{n}`"),
            Tok::RIndex => "`R[`".into(),
            Tok::UserVar(n) => format!("variable `{n}`"),
            Tok::Func(n) => format!("function `{n}`"),
            Tok::Cycle(n) => format!("cycle `{n}`"),
            Tok::Command(n) => format!("command `{n}`"),
            Tok::Name(n) => format!("name `{n}`"),
            other => format!("`{}`", punct(other)),
        }
    }
}

pub fn kw_name(k: Kw) -> &'static str {
    KEYWORDS
        .iter()
        .find(|(_, x)| *x == k)
        .map(|(n, _)| *n)
        .unwrap_or("?")
}

fn punct(t: &Tok) -> &'static str {
    match t {
        Tok::EqEq => "==",
        Tok::Ne => "<>",
        Tok::Le => "<=",
        Tok::Ge => ">=",
        Tok::Lt => "<",
        Tok::Gt => ">",
        Tok::Concat => "<<",
        Tok::Assign => "=",
        Tok::Plus => "+",
        Tok::Minus => "-",
        Tok::Star => "*",
        Tok::Slash => "/",
        Tok::LParen => "(",
        Tok::RParen => ")",
        Tok::LBracket => "[",
        Tok::RBracket => "]",
        Tok::Comma => ",",
        _ => "?",
    }
}
