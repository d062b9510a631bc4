//! Evaluating expressions and word values to numbers while a program runs.
//! Angles are in degrees; comparisons and logic give 1 or 0.

use super::{Interp, Stop};
use crate::diag::{Code, Diagnostic};
use crate::dialect::spec::Capability;
use crate::ir::{Arena, BinaryOp, Expr, ExprId, ExprKind, Func, UnaryOp, Value, Var};

/// LinuxCNC's tolerance for EQ and NE.
pub const EQ_TOLERANCE: f64 = 1e-4;

/// A number, or vacant (Fanuc `#0`, a parameter never set).
pub type Num = Option<f64>;

impl Interp<'_, '_> {
    /// A word's value as a number (vacant reads as zero).
    pub fn value(&mut self, v: &Value, exprs: &Arena<Expr>) -> Result<f64, Stop> {
        match v {
            Value::Number(d) => Ok(d.to_f64()),
            Value::Expr(e) => Ok(self.eval(*e, exprs)?.unwrap_or(0.0)),
        }
    }

    /// A word's value, keeping vacancy.
    pub fn value_or_vacant(&mut self, v: &Value, exprs: &Arena<Expr>) -> Result<Num, Stop> {
        match v {
            Value::Number(d) => Ok(Some(d.to_f64())),
            Value::Expr(e) => self.eval(*e, exprs),
        }
    }

    /// An expression's value; a result that is NaN or infinite is E0590
    /// where it is computed (as rs274 refuses a negative number to a
    /// fractional power), so no such value reaches a move.
    pub fn eval(&mut self, id: ExprId, exprs: &Arena<Expr>) -> Result<Num, Stop> {
        match self.eval_unchecked(id, exprs)? {
            // A parameter holding a value unknown at check time (FN 18
            // data of the machine): the run-time checks stop where it is
            // used, with a warning, never a false error.
            Some(v) if v.is_nan() && matches!(exprs[id].kind, ExprKind::Var(_)) => {
                Err(self.from_outside_at(exprs[id].span, &expr_name(&exprs[id].kind)))
            }
            Some(v) if !v.is_finite() => {
                let what = if v.is_nan() {
                    "this calculation has no value (NaN)"
                } else {
                    "this calculation overflows to infinity"
                };
                Err(self.error_at(exprs[id].span, Code::NotAFiniteNumber, what))
            }
            v => Ok(v),
        }
    }

    fn eval_unchecked(&mut self, id: ExprId, exprs: &Arena<Expr>) -> Result<Num, Stop> {
        let e = &exprs[id];
        let span = e.span;
        Ok(match &e.kind {
            ExprKind::Number(d) => Some(d.to_f64()),
            ExprKind::Bool(b) => Some(*b as i64 as f64),
            ExprKind::Str(_) => {
                return Err(self.error_at(span, Code::UnsupportedHere, "a string used as a number"))
            }
            ExprKind::Var(v) => self.read_var(v, exprs, span)?,
            ExprKind::Unary(op, a) => {
                let a = self.eval(*a, exprs)?.unwrap_or(0.0);
                Some(match op {
                    UnaryOp::Neg => -a,
                    UnaryOp::Plus => a,
                    UnaryOp::Not => (a == 0.0) as i64 as f64,
                    UnaryOp::BitNot => !(a as i64) as f64,
                })
            }
            ExprKind::Binary(op, a, b) => {
                let a = self.eval(*a, exprs)?;
                let b = self.eval(*b, exprs)?;
                Some(self.binary(*op, a, b, span)?)
            }
            ExprKind::Call(f, args) => {
                let mut vals = Vec::with_capacity(args.len());
                for a in args {
                    vals.push(self.eval(*a, exprs)?.unwrap_or(0.0));
                }
                Some(self.call(*f, &vals, span)?)
            }
            ExprKind::AtanSlash(a, b) => {
                let y = self.eval(*a, exprs)?.unwrap_or(0.0);
                let x = self.eval(*b, exprs)?.unwrap_or(0.0);
                Some(atan2_deg(y, x))
            }
            ExprKind::Exists(name) => Some(self.read_named(name).is_some() as i64 as f64),
            ExprKind::ExistsNumbered(e) => {
                let n = self.eval(*e, exprs)?.unwrap_or(0.0);
                let whole = n.fract() == 0.0 && n >= 0.0 && n <= u32::MAX as f64;
                Some((whole && self.check_number(n as u32, span).is_ok()) as i64 as f64)
            }
            ExprKind::Query(name, _) => {
                return Err(self.error_at(
                    span,
                    Code::UnsupportedHere,
                    format!("the control function {name} reads machine state cncc does not know"),
                ))
            }
            ExprKind::Dimension(_, inner) => self.eval(*inner, exprs)?,
        })
    }

    fn binary(
        &mut self,
        op: BinaryOp,
        a: Num,
        b: Num,
        span: crate::span::Span,
    ) -> Result<f64, Stop> {
        use BinaryOp::*;
        // Vacant equals only vacant (Fanuc Macro B: dialects with a `#0`,
        // always vacant); elsewhere it reads as zero.
        let vacancy = self
            .spec
            .variables
            .iter()
            .any(|r| r.prefix == '#' && r.first == 0);
        if vacancy && matches!(op, Eq | Ne) && (a.is_none() || b.is_none()) {
            let same = a.is_none() == b.is_none() && a.unwrap_or(0.0) == b.unwrap_or(0.0);
            return Ok(((op == Eq) == same) as i64 as f64);
        }
        let (a, b) = (a.unwrap_or(0.0), b.unwrap_or(0.0));
        let t = |c: bool| c as i64 as f64;
        // LinuxCNC's EQ/NE compare within 0.0001 (its TOLERANCE_EQUAL);
        // probed: `[0.00005 EQ 0]` is 1 in rs274.
        let tol = if self.spec.has(Capability::EqTolerance) {
            EQ_TOLERANCE
        } else {
            0.0
        };
        let equal = if tol > 0.0 {
            (a - b).abs() < tol
        } else {
            a == b
        };
        Ok(match op {
            Add => a + b,
            Sub => a - b,
            Mul => a * b,
            Div | IntDiv | Mod if b == 0.0 => {
                return Err(self.error_at(span, Code::DivisionByZero, "division by zero"))
            }
            Div => a / b,
            IntDiv => (a / b).trunc(),
            Mod => a - b * (a / b).floor(),
            Pow => a.powf(b),
            Eq => t(equal),
            Ne => t(!equal),
            Gt => t(a > b),
            Ge => t(a >= b),
            Lt => t(a < b),
            Le => t(a <= b),
            And => t(a != 0.0 && b != 0.0),
            Or => t(a != 0.0 || b != 0.0),
            Xor => t((a != 0.0) != (b != 0.0)),
            BitAnd => ((a as i64) & (b as i64)) as f64,
            BitOr => ((a as i64) | (b as i64)) as f64,
            BitXor => ((a as i64) ^ (b as i64)) as f64,
            Concat => {
                return Err(self.error_at(
                    span,
                    Code::UnsupportedHere,
                    "string concatenation is not evaluated",
                ))
            }
        })
    }

    fn call(&mut self, f: Func, v: &[f64], span: crate::span::Span) -> Result<f64, Stop> {
        let a = v.first().copied().unwrap_or(0.0);
        let b = v.get(1).copied().unwrap_or(0.0);
        let domain = |ok: bool| ok;
        // A value unknown at check time (NaN, from FN 18) stays unknown.
        if v.iter().any(|x| x.is_nan()) {
            return Ok(f64::NAN);
        }
        let r = match f {
            Func::Sin => a.to_radians().sin(),
            Func::Cos => a.to_radians().cos(),
            Func::Tan => a.to_radians().tan(),
            Func::Asin if domain((-1.0..=1.0).contains(&a)) => a.asin().to_degrees(),
            Func::Acos if domain((-1.0..=1.0).contains(&a)) => a.acos().to_degrees(),
            Func::Atan => a.atan().to_degrees(),
            Func::Atan2 => atan2_deg(a, b),
            Func::Sqrt if a >= 0.0 => a.sqrt(),
            Func::Abs => a.abs(),
            Func::Round => a.round(),
            Func::Floor => a.floor(),
            Func::Ceil => a.ceil(),
            Func::Trunc => a.trunc(),
            Func::RoundAway => round_away(a),
            Func::Ln if a > 0.0 => a.ln(),
            Func::Exp => a.exp(),
            Func::Pow => a.powf(b),
            Func::Square => a * a,
            Func::Min => v.iter().copied().fold(f64::INFINITY, f64::min),
            Func::Max => v.iter().copied().fold(f64::NEG_INFINITY, f64::max),
            Func::Bin => bcd_to_bin(a),
            Func::Bcd => bin_to_bcd(a),
            Func::PosShortest | Func::PosPlus | Func::PosMinus => a,
            Func::Sign if a == 0.0 => 0.0,
            Func::Sign => a.signum(),
            Func::Log10 if a > 0.0 => a.log10(),
            Func::Asin | Func::Acos | Func::Sqrt | Func::Ln | Func::Log10 => {
                return Err(self.error_at(
                    span,
                    Code::DomainError,
                    format!("{f:?} of {a} is undefined"),
                ))
            }
        };
        Ok(r)
    }

    fn read_var(
        &mut self,
        v: &Var,
        exprs: &Arena<Expr>,
        span: crate::span::Span,
    ) -> Result<Num, Stop> {
        Ok(match v {
            Var::Numbered(n) => {
                self.check_number(*n, span)?;
                self.known_numbered(*n, span)?;
                self.read_numbered(*n)
            }
            Var::Indirect(e) => {
                let n = self.eval(*e, exprs)?.unwrap_or(0.0).round().max(0.0) as u32;
                self.check_number(n, span)?;
                self.known_numbered(n, span)?;
                self.read_numbered(n)
            }
            Var::Named(name) => match self.read_named(name) {
                Some(v) => Some(v),
                None if self.from_outside => {
                    return Err(self.from_outside_at(span, &format!("#<{name}>")))
                }
                None => {
                    return Err(self.error_at(
                        span,
                        Code::UndefinedVariable,
                        format!("named parameter #<{name}> not defined"),
                    ))
                }
            },
            Var::R(n) => {
                self.known_r(*n, span)?;
                Some(self.params.r(*n))
            }
            Var::Q(bank, n) => {
                if (self.from_outside || self.q_from_control(*bank))
                    && !self.params.q_known(*bank, *n)
                {
                    return Err(self.from_outside_at(span, &format!("{}{n}", bank_name(*bank))));
                }
                Some(self.params.q(*bank, *n))
            }
            Var::RIndirect(e) => {
                let n = self.eval(*e, exprs)?.unwrap_or(0.0).round().max(0.0) as u32;
                self.known_r(n, span)?;
                Some(self.params.r(n))
            }
            Var::User(name, _) => match self.params.user(name).or_else(|| self.constant(name)) {
                Some(v) => Some(v),
                None if self.from_outside => return Err(self.from_outside_at(span, name)),
                None => {
                    return Err(self.error_at(
                        span,
                        Code::UndefinedVariable,
                        format!("variable {name} has no value"),
                    ))
                }
            },
            Var::System(name, _) => {
                return Err(self.error_at(
                    span,
                    Code::UnsupportedHere,
                    format!("system variable {name} is not simulated"),
                ))
            }
        })
    }

    /// A numbered parameter outside every range the dialect lists
    /// (LinuxCNC: #1-#5601, probed) is an error.
    pub fn check_number(&self, n: u32, span: crate::span::Span) -> Result<(), Stop> {
        let ranges = || self.spec.variables.iter().filter(|r| r.prefix == '#');
        if ranges().next().is_none() || ranges().any(|r| (r.first..=r.last).contains(&n)) {
            return Ok(());
        }
        Err(self.error_at(
            span,
            Code::UndefinedVariable,
            format!("parameter #{n} is out of range"),
        ))
    }

    /// Writing a read-only numbered parameter (Fanuc `#0`) is an error.
    pub fn check_writable(&self, n: u32, span: crate::span::Span) -> Result<(), Stop> {
        let ro = self
            .spec
            .variables
            .iter()
            .any(|r| r.prefix == '#' && !r.writable && (r.first..=r.last).contains(&n));
        if ro {
            return Err(self.error_at(
                span,
                Code::UnsupportedHere,
                format!("parameter #{n} is read-only"),
            ));
        }
        self.check_number(n, span)
    }

    /// `#n`, with the system parameters the interpreter keeps.
    pub fn read_numbered(&self, n: u32) -> Num {
        super::predefined::numbered(self, n).or_else(|| self.params.numbered(n))
    }

    /// `#<name>`, with LinuxCNC's predefined read-only ones.
    /// A name the control defines for every program (`<constant>`).
    fn constant(&self, name: &str) -> Option<f64> {
        self.spec.constant(name).map(|d| d.to_f64())
    }

    pub fn read_named(&self, name: &str) -> Option<f64> {
        self.params
            .named(name)
            .or_else(|| super::predefined::named(self, name))
    }

    /// In a file checked alone ([`Interp::from_outside`]), `#n` that
    /// neither the machine nor this run has set comes from the caller.
    fn known_numbered(&self, n: u32, span: crate::span::Span) -> Result<(), Stop> {
        if self.from_outside
            && !self.params.numbered_known(n)
            && super::predefined::numbered(self, n).is_none()
        {
            return Err(self.from_outside_at(span, &format!("#{n}")));
        }
        Ok(())
    }

    /// A Q or QR parameter on a control whose Q parameters outlive the
    /// program ([`Capability::GlobalQParameters`]): one this run has not
    /// set holds what an earlier program left. QL are the program's own.
    fn q_from_control(&self, bank: crate::ir::QBank) -> bool {
        bank != crate::ir::QBank::Local
            && self
                .spec
                .has(crate::dialect::spec::Capability::GlobalQParameters)
    }

    fn known_r(&self, n: u32, span: crate::span::Span) -> Result<(), Stop> {
        if self.from_outside && !self.params.r_known(n) {
            return Err(self.from_outside_at(span, &format!("R{n}")));
        }
        Ok(())
    }

    /// The run of a file checked alone stops at `what`, a value only its
    /// caller (or the machine) gives.
    pub fn from_outside_at(&self, span: crate::span::Span, what: &str) -> Stop {
        Stop::Unknown(
            Diagnostic::new(
                Code::ValueFromOutside,
                format!("`{what}` gets its value from the caller or the machine: the run-time checks stop here"),
            )
            .primary(span, "not known at check time")
            .help("every block was checked for syntax and structure; a caller's values are known when the calling program is checked with this file beside it, the machine's only on the machine"),
        )
    }

    /// A run-time error at a span: the run stops here.
    pub fn error_at(&self, span: crate::span::Span, code: Code, msg: impl Into<String>) -> Stop {
        Stop::Error(Diagnostic::new(code, msg).primary(span, "here"))
    }
}

/// Fanuc `FUP`: the integer away from zero (`FUP[-1.2]` = -2).
fn round_away(a: f64) -> f64 {
    if a < 0.0 {
        a.floor()
    } else {
        a.ceil()
    }
}

fn atan2_deg(y: f64, x: f64) -> f64 {
    y.atan2(x).to_degrees()
}

fn bcd_to_bin(a: f64) -> f64 {
    let mut v = a as i64;
    let (mut out, mut mul) = (0i64, 1i64);
    while v > 0 {
        out += (v & 0xF) * mul;
        mul *= 10;
        v >>= 4;
    }
    out as f64
}

fn bin_to_bcd(a: f64) -> f64 {
    let mut v = a as i64;
    let (mut out, mut shift) = (0i64, 0);
    while v > 0 {
        out |= (v % 10) << shift;
        shift += 4;
        v /= 10;
    }
    out as f64
}

fn bank_name(bank: crate::ir::QBank) -> &'static str {
    match bank {
        crate::ir::QBank::Q => "Q",
        crate::ir::QBank::Local => "QL",
        crate::ir::QBank::Remanent => "QR",
    }
}

/// How a variable expression is written, for messages.
fn expr_name(kind: &ExprKind) -> String {
    let ExprKind::Var(v) = kind else {
        return "this value".into();
    };
    match v {
        Var::Numbered(n) => format!("#{n}"),
        Var::Named(n) => format!("#<{n}>"),
        Var::R(n) => format!("R{n}"),
        Var::Q(bank, n) => format!("{}{n}", bank_name(*bank)),
        Var::User(n, _) | Var::System(n, _) => n.clone(),
        Var::Indirect(_) | Var::RIndirect(_) => "this parameter".into(),
    }
}
