//! Expressions and variables: Fanuc Macro B `[#1+2]`, LinuxCNC `#<name>`,
//! Siemens `R1*COS(R5)`. Stored in the program's expression arena.

use super::arena::Handle;
use super::num::Decimal;
use crate::span::Span;
use serde::Serialize;

pub type ExprId = Handle<Expr>;

#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum ExprKind {
    Number(Decimal),
    Str(String),
    /// Boolean literal (Siemens `TRUE`/`FALSE`).
    Bool(bool),
    Var(Var),
    Unary(UnaryOp, ExprId),
    Binary(BinaryOp, ExprId, ExprId),
    Call(Func, Vec<ExprId>),
    /// LinuxCNC `EXISTS[#<name>]`.
    Exists(String),
    /// LinuxCNC `EXISTS[#1]`, `EXISTS[##1]`: whether the numbered parameter
    /// whose number is the expression is in the dialect's range.
    ExistsNumbered(ExprId),
    /// Fanuc `ATAN[a]/[b]` and LinuxCNC `ATAN[y]/[x]`, kept in that form.
    AtanSlash(ExprId, ExprId),
    /// Siemens `AC(expr)` / `IC(expr)` inside an address value.
    Dimension(DimMode, ExprId),
    /// A call of a control function that is not in the dialect's function
    /// table, kept by name (Siemens `ISAXIS(1)`, `GETT("DRILL",1)`): its
    /// value is machine or tool-management state cncc cannot know, so the
    /// run stops where it is needed (W0511) instead of guessing.
    Query(String, Vec<ExprId>),
}

/// Absolute or incremental, for a whole program (G90/G91) or one value (AC/IC).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum DimMode {
    Absolute,
    Incremental,
}

/// A variable reference.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum Var {
    /// `#100`: a numbered parameter (Fanuc, Haas, LinuxCNC).
    Numbered(u32),
    /// `#[expr]`: a numbered parameter chosen by an expression.
    Indirect(ExprId),
    /// `#<name>` (LinuxCNC; a leading `_` makes it global).
    Named(String),
    /// `R12` (Siemens arithmetic parameter).
    R(u32),
    /// `R[expr]`.
    RIndirect(ExprId),
    /// A user variable declared with DEF (Siemens), possibly indexed.
    User(String, Vec<ExprId>),
    /// A system variable `$P_UIFR[1]`, `$AA_IW[X]`, kept by name.
    System(String, Vec<ExprId>),
    /// Heidenhain `Q12`, `QL3`, `QR7`.
    Q(QBank, u32),
}

/// The banks of Heidenhain Q parameters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum QBank {
    /// `Q`: global.
    Q,
    /// `QL`: local to the program.
    Local,
    /// `QR`: kept across power-off.
    Remanent,
}

impl QBank {
    /// The prefix as written: `Q`, `QL`, `QR`.
    pub fn prefix(self) -> &'static str {
        match self {
            QBank::Q => "Q",
            QBank::Local => "QL",
            QBank::Remanent => "QR",
        }
    }
}

impl Var {
    pub fn is_global_named(&self) -> bool {
        matches!(self, Var::Named(n) if n.starts_with('_'))
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum UnaryOp {
    Neg,
    Plus,
    Not,
    BitNot,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    /// `**` (LinuxCNC).
    Pow,
    Mod,
    /// Siemens `DIV` (integer division).
    IntDiv,
    Eq,
    Ne,
    Gt,
    Ge,
    Lt,
    Le,
    And,
    Or,
    Xor,
    BitAnd,
    BitOr,
    BitXor,
    /// Siemens `<<` string concatenation.
    Concat,
}

impl BinaryOp {
    /// Binding strength; higher binds tighter.
    pub fn precedence(self) -> u8 {
        use BinaryOp::*;
        match self {
            Or | Xor | BitOr | BitXor => 1,
            And | BitAnd => 2,
            Eq | Ne | Gt | Ge | Lt | Le => 3,
            Concat => 4,
            Add | Sub => 5,
            Mul | Div | Mod | IntDiv => 6,
            Pow => 7,
        }
    }

    pub fn is_comparison(self) -> bool {
        use BinaryOp::*;
        matches!(self, Eq | Ne | Gt | Ge | Lt | Le)
    }
}

/// Built-in functions. Dialects name them (Fanuc `FIX`, Siemens `TRUNC`);
/// the dialect spec maps its names to these meanings.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
pub enum Func {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    /// One argument: the arc tangent of a value.
    Atan,
    /// Two arguments (y, x): Fanuc `ATAN[y,x]`, Siemens `ATAN2(y,x)`.
    Atan2,
    Sqrt,
    Abs,
    Round,
    /// Round toward minus infinity (LinuxCNC `FIX`).
    Floor,
    /// Round toward plus infinity (LinuxCNC `FUP`, Siemens `ROUNDUP`).
    Ceil,
    /// Round toward zero: drop the fraction (Siemens `TRUNC`, Fanuc `FIX`,
    /// Heidenhain `INT`).
    Trunc,
    /// Round away from zero to an integer (Fanuc `FUP`: `FUP[1.2]` = 2,
    /// `FUP[-1.2]` = -2).
    RoundAway,
    Ln,
    Exp,
    /// `POW(a, b)` (Fanuc, Siemens `POT` is a square: see [`Func::Square`]).
    Pow,
    /// Siemens `POT(x)`: x squared.
    Square,
    Bin,
    Bcd,
    Min,
    Max,
    /// Siemens `DC(a)`: an absolute position of a rotary axis or spindle
    /// reached the shortest way. Its value is the position; the direction
    /// is not simulated.
    PosShortest,
    /// Siemens `ACP(a)`: the absolute position, approached in the positive
    /// direction.
    PosPlus,
    /// Siemens `ACN(a)`: the absolute position, approached in the negative
    /// direction.
    PosMinus,
    /// The sign of a value: -1, 0 or +1 (Heidenhain `SGN`).
    Sign,
    /// The common (base 10) logarithm (Heidenhain `LOG`).
    Log10,
}

/// A word's value: a number as written, or an expression.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub enum Value {
    Number(Decimal),
    Expr(ExprId),
}

impl Value {
    pub fn number(&self) -> Option<Decimal> {
        match self {
            Value::Number(d) => Some(*d),
            Value::Expr(_) => None,
        }
    }
}
