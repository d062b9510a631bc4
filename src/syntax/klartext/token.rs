//! The tokens the Klartext grammar reads.

use crate::ir::{Decimal, QBank};

/// Klartext keywords, recognised only where a block can have them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kw {
    Begin,
    End,
    Pgm,
    Blk,
    Form,
    Tool,
    Def,
    Call,
    L,
    C,
    Cc,
    Cr,
    Ct,
    Lp,
    Cp,
    Ctp,
    Rnd,
    Chf,
    Appr,
    Dep,
    Lbl,
    Fn,
    If,
    Goto,
    Cycl,
    Pattern,
    Stop,
    /// `TCH PROBE`: a touch probe cycle.
    Tch,
}

impl Kw {
    /// A keyword that can open a block.
    pub fn block(n: &str) -> Option<Kw> {
        Some(match n {
            "BEGIN" => Kw::Begin,
            "END" => Kw::End,
            "BLK" => Kw::Blk,
            "TOOL" => Kw::Tool,
            "CALL" => Kw::Call,
            "L" => Kw::L,
            "C" => Kw::C,
            "CC" => Kw::Cc,
            "CR" => Kw::Cr,
            "CT" => Kw::Ct,
            "LP" => Kw::Lp,
            "CP" => Kw::Cp,
            "CTP" => Kw::Ctp,
            "RND" => Kw::Rnd,
            "CHF" => Kw::Chf,
            "APPR" => Kw::Appr,
            "DEP" => Kw::Dep,
            "LBL" => Kw::Lbl,
            "FN" => Kw::Fn,
            "CYCL" => Kw::Cycl,
            "PATTERN" => Kw::Pattern,
            "STOP" => Kw::Stop,
            "TCH" => Kw::Tch,
            _ => return None,
        })
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    Kw(Kw),
    /// A name (upper case): an address (`X`, `IX`, `FMAX`, `DR`), a
    /// function (`SIN`), a cycle or pattern word.
    Name(String),
    Num(Decimal),
    /// A Q parameter `Q12`, `QL3`, `QR5`.
    Q(QBank, u32),
    /// A parameter prefix not (yet) joined to its number.
    QPrefix(QBank),
    Str(String),
    Plus,
    Minus,
    Star,
    Slash,
    Caret,
    LParen,
    RParen,
    Eq,
    Colon,
    Comma,
    Hash,
    Backslash,
    Dot,
}
