//! Rounding and power functions the target has no name for, written
//! exactly with the ones it has (an exact idiom, keyed on the function and
//! on the target's function table, never on a pair of dialects):
//!
//! * `POT(x)` (x squared) → `x*x`.
//! * Truncation (Siemens `TRUNC`, Fanuc `FIX`, Klartext `INT`) where the
//!   target only rounds down and up (LinuxCNC `FIX` = floor):
//!   `floor(|x|) * s(x)` with `s(x) = 1 + 2*floor(x/(|x|+1))`, which is +1
//!   for x ≥ 0 and -1 below (x/(|x|+1) lies in [0, 1) or (-1, 0)).
//! * Rounding away from zero (Fanuc `FUP`): `trunc(x) + sf(x - trunc(x))`,
//!   where `sf(d)` is the sign of a fraction |d| < 1: `SGN(d)`, `FUP(d)`,
//!   `ceil(d) - ceil(-d)` or `floor(d) - floor(-d)`, whichever the target
//!   has. Where the target has floor and ceiling only:
//!   `ceil(|x|) * s(x)`.
//! * Floor and ceiling (LinuxCNC `FIX`/`FUP`, Siemens `ROUNDUP`):
//!   `-ceil(-x)` / `-floor(-x)`, or `trunc(x) ∓ (|sf(d)| ∓ sf(d))/2`.
//! * The sign (Klartext `SGN`): `sf(x/(|x|+1))`, the quotient being a
//!   fraction of the sign of x.
//! * `ROUND` (half away from zero) where the target lacks it (Klartext):
//!   `trunc(x + sgn(x)/2)`. [?] Exact in decimal arithmetic; in binary
//!   floating point x + 0.5 may round up for the largest double below a
//!   half (0.49999999999999994), which no program writes.
//!
//! All results are integers computed from integers, so the rewrites are
//! exact; the argument is copied where it is needed twice (expressions
//! have no side effects). A function with no rewrite is left for the
//! writer, which names it (E0601).

use crate::dialect::DialectSpec;
use crate::ir::{BinaryOp, Decimal, Expr, ExprId, ExprKind, Func, Program, UnaryOp, Var};
use crate::span::Span;

pub fn run(p: &mut Program, to: &DialectSpec) {
    let ids: Vec<ExprId> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        let ExprKind::Call(f, args) = &p.exprs[id].kind else {
            continue;
        };
        let (f, args) = (*f, args.clone());
        if args.len() != 1 || to.function_name(f).is_some() {
            continue;
        }
        let span = p_span(p, id);
        let mut b = Build { p, to, span };
        let x = args[0];
        let new = match f {
            Func::Square => {
                let y = b.copy(x);
                Some(b.bin(BinaryOp::Mul, x, y))
            }
            Func::Trunc => b.trunc(x),
            Func::RoundAway => b.round_away(x),
            Func::Floor => b.floor(x),
            Func::Ceil => b.ceil(x),
            Func::Round => b.round(x),
            Func::Sign => b.sign(x),
            _ => None,
        };
        if let Some(new) = new {
            let kind = b.p.exprs[new].kind.clone();
            p.exprs[id].kind = kind;
        }
    }
}

/// A fresh copy of the expression tree at `e` (no node shared).
pub(crate) fn copy_expr(p: &mut Program, to: &DialectSpec, e: ExprId) -> ExprId {
    let span = p.exprs[e].span;
    Build { p, to, span }.copy(e)
}

fn p_span(p: &Program, id: ExprId) -> Span {
    p.exprs[id].span
}

struct Build<'a> {
    p: &'a mut Program,
    to: &'a DialectSpec,
    span: Span,
}

impl Build<'_> {
    fn has(&self, f: Func) -> bool {
        self.to.function_name(f).is_some()
    }

    fn node(&mut self, kind: ExprKind) -> ExprId {
        self.p.exprs.alloc(Expr {
            kind,
            span: self.span,
        })
    }

    fn num(&mut self, n: i64) -> ExprId {
        self.node(ExprKind::Number(Decimal::from_f64(n as f64, 0)))
    }

    fn bin(&mut self, op: BinaryOp, a: ExprId, b: ExprId) -> ExprId {
        self.node(ExprKind::Binary(op, a, b))
    }

    fn neg(&mut self, a: ExprId) -> ExprId {
        self.node(ExprKind::Unary(UnaryOp::Neg, a))
    }

    fn call(&mut self, f: Func, a: ExprId) -> ExprId {
        self.node(ExprKind::Call(f, vec![a]))
    }

    /// A fresh copy of the tree at `e` (no node is shared between two
    /// places, so passes that rewrite nodes in place see each once).
    fn copy(&mut self, e: ExprId) -> ExprId {
        let kind = match self.p.exprs[e].kind.clone() {
            ExprKind::Var(v) => ExprKind::Var(self.copy_var(v)),
            ExprKind::Unary(op, a) => ExprKind::Unary(op, self.copy(a)),
            ExprKind::Dimension(m, a) => ExprKind::Dimension(m, self.copy(a)),
            ExprKind::Binary(op, a, b) => ExprKind::Binary(op, self.copy(a), self.copy(b)),
            ExprKind::AtanSlash(a, b) => ExprKind::AtanSlash(self.copy(a), self.copy(b)),
            ExprKind::ExistsNumbered(a) => ExprKind::ExistsNumbered(self.copy(a)),
            ExprKind::Call(f, args) => ExprKind::Call(f, self.copy_all(args)),
            ExprKind::Query(n, args) => ExprKind::Query(n, self.copy_all(args)),
            k @ (ExprKind::Number(_)
            | ExprKind::Str(_)
            | ExprKind::Bool(_)
            | ExprKind::Exists(_)) => k,
        };
        let span = self.p.exprs[e].span;
        self.p.exprs.alloc(Expr { kind, span })
    }

    fn copy_all(&mut self, args: Vec<ExprId>) -> Vec<ExprId> {
        args.into_iter().map(|a| self.copy(a)).collect()
    }

    fn copy_var(&mut self, v: Var) -> Var {
        match v {
            Var::Indirect(i) => Var::Indirect(self.copy(i)),
            Var::RIndirect(i) => Var::RIndirect(self.copy(i)),
            Var::User(n, idx) => Var::User(n, self.copy_all(idx)),
            Var::System(n, idx) => Var::System(n, self.copy_all(idx)),
            v @ (Var::Numbered(_) | Var::Named(_) | Var::R(_) | Var::Q(..)) => v,
        }
    }

    /// floor(y) from the target's floor, or its ceiling: -ceil(-y).
    fn floor_direct(&mut self, y: ExprId) -> Option<ExprId> {
        if self.has(Func::Floor) {
            return Some(self.call(Func::Floor, y));
        }
        if self.has(Func::Ceil) {
            let m = self.neg(y);
            let c = self.call(Func::Ceil, m);
            return Some(self.neg(c));
        }
        None
    }

    /// ceil(y) from the target's ceiling, or its floor: -floor(-y).
    fn ceil_direct(&mut self, y: ExprId) -> Option<ExprId> {
        if self.has(Func::Ceil) {
            return Some(self.call(Func::Ceil, y));
        }
        if self.has(Func::Floor) {
            let m = self.neg(y);
            let c = self.call(Func::Floor, m);
            return Some(self.neg(c));
        }
        None
    }

    /// s(x) = 1 + 2*floor(x/(|x|+1)): +1 for x ≥ 0, -1 below.
    fn side(&mut self, x: ExprId) -> Option<ExprId> {
        if !self.has(Func::Abs) {
            return None;
        }
        let x1 = self.copy(x);
        let x2 = self.copy(x);
        let a = self.call(Func::Abs, x2);
        let one = self.num(1);
        let den = self.bin(BinaryOp::Add, a, one);
        let q = self.bin(BinaryOp::Div, x1, den);
        let f = self.floor_direct(q)?;
        let two = self.num(2);
        let t = self.bin(BinaryOp::Mul, two, f);
        let one = self.num(1);
        Some(self.bin(BinaryOp::Add, one, t))
    }

    /// `g(|x|) * s(x)` for g = floor (truncation) or ceiling (away).
    fn by_magnitude(&mut self, x: ExprId, up: bool) -> Option<ExprId> {
        if !self.has(Func::Abs) {
            return None;
        }
        let s = self.side(x)?;
        let xc = self.copy(x);
        let a = self.call(Func::Abs, xc);
        let g = if up {
            self.ceil_direct(a)?
        } else {
            self.floor_direct(a)?
        };
        Some(self.bin(BinaryOp::Mul, g, s))
    }

    fn trunc(&mut self, x: ExprId) -> Option<ExprId> {
        if self.has(Func::Trunc) {
            let xc = self.copy(x);
            return Some(self.call(Func::Trunc, xc));
        }
        self.by_magnitude(x, false)
    }

    /// The sign of a fraction d (|d| < 1).
    fn frac_sign(&mut self, d: ExprId) -> Option<ExprId> {
        for f in [Func::Sign, Func::RoundAway] {
            if self.has(f) {
                let dc = self.copy(d);
                return Some(self.call(f, dc));
            }
        }
        let d1 = self.copy(d);
        let d2 = self.copy(d);
        let m = self.neg(d2);
        let (a, b) = if self.has(Func::Ceil) {
            (self.call(Func::Ceil, d1), self.call(Func::Ceil, m))
        } else if self.has(Func::Floor) {
            (self.call(Func::Floor, d1), self.call(Func::Floor, m))
        } else {
            return None;
        };
        Some(self.bin(BinaryOp::Sub, a, b))
    }

    /// (trunc(x), the sign of the fraction x - trunc(x)).
    fn parts(&mut self, x: ExprId) -> Option<(ExprId, ExprId)> {
        let t = self.trunc(x)?;
        let xc = self.copy(x);
        let t2 = self.copy(t);
        let d = self.bin(BinaryOp::Sub, xc, t2);
        let s = self.frac_sign(d)?;
        Some((t, s))
    }

    fn round_away(&mut self, x: ExprId) -> Option<ExprId> {
        if !self.has(Func::Trunc) {
            if let Some(e) = self.by_magnitude(x, true) {
                return Some(e);
            }
        }
        if let Some((t, s)) = self.parts(x) {
            return Some(self.bin(BinaryOp::Add, t, s));
        }
        self.by_magnitude(x, true)
    }

    /// trunc(x) ± (|sf| ± sf)/2: one where the fraction has the sign of
    /// the rounding, zero elsewhere.
    fn step(&mut self, x: ExprId, up: bool) -> Option<ExprId> {
        if !self.has(Func::Abs) {
            return None;
        }
        let (t, s) = self.parts(x)?;
        let s2 = self.copy(s);
        let a = self.call(Func::Abs, s2);
        let op = if up { BinaryOp::Add } else { BinaryOp::Sub };
        let n = self.bin(op, a, s);
        let two = self.num(2);
        let half = self.bin(BinaryOp::Div, n, two);
        Some(self.bin(op, t, half))
    }

    fn floor(&mut self, x: ExprId) -> Option<ExprId> {
        if self.has(Func::Ceil) {
            let xc = self.copy(x);
            return self.floor_direct(xc);
        }
        self.step(x, false)
    }

    fn ceil(&mut self, x: ExprId) -> Option<ExprId> {
        if self.has(Func::Floor) {
            let xc = self.copy(x);
            return self.ceil_direct(xc);
        }
        self.step(x, true)
    }

    /// sgn(x) = sf(x/(|x|+1)): the quotient is a fraction of x's sign.
    fn sign(&mut self, x: ExprId) -> Option<ExprId> {
        if !self.has(Func::Abs) {
            return None;
        }
        let x1 = self.copy(x);
        let x2 = self.copy(x);
        let a = self.call(Func::Abs, x2);
        let one = self.num(1);
        let den = self.bin(BinaryOp::Add, a, one);
        let q = self.bin(BinaryOp::Div, x1, den);
        self.frac_sign(q)
    }

    /// ROUND (half away from zero): trunc(x + sgn(x)/2).
    fn round(&mut self, x: ExprId) -> Option<ExprId> {
        if !self.has(Func::Sign) {
            return None;
        }
        let xs = self.copy(x);
        let s = self.call(Func::Sign, xs);
        let two = self.num(2);
        let half = self.bin(BinaryOp::Div, s, two);
        let xc = self.copy(x);
        let sum = self.bin(BinaryOp::Add, xc, half);
        self.trunc(sum)
    }
}

#[cfg(test)]
mod tests {
    /// Each rewrite, evaluated as the rewritten formula would be, agrees
    /// with the function on integers, fractions and halves of both signs.
    #[test]
    fn identities_hold() {
        let floor = |y: f64| y.floor();
        let ceil = |y: f64| y.ceil();
        let side = |x: f64| 1.0 + 2.0 * floor(x / (x.abs() + 1.0));
        for i in -40..=40 {
            let x = i as f64 * 0.25 + if i % 3 == 0 { 0.1 } else { 0.0 };
            let away = if x < 0.0 { x.floor() } else { x.ceil() };
            assert_eq!(floor(x.abs()) * side(x), x.trunc(), "{x}");
            assert_eq!(ceil(x.abs()) * side(x), away, "{x}");
            let t = x.trunc();
            let d = x - t;
            for sf in [
                d.signum() * (d != 0.0) as i32 as f64,
                ceil(d) - ceil(-d),
                floor(d) - floor(-d),
                if d < 0.0 { d.floor() } else { d.ceil() },
            ] {
                assert_eq!(t + sf, away, "{x}");
                assert_eq!(t - (sf.abs() - sf) / 2.0, x.floor(), "{x}");
                assert_eq!(t + (sf.abs() + sf) / 2.0, x.ceil(), "{x}");
            }
            let sg = if x == 0.0 { 0.0 } else { x.signum() };
            let q = x / (x.abs() + 1.0);
            assert_eq!(ceil(q) - ceil(-q), sg, "{x}");
            assert_eq!(if q < 0.0 { q.floor() } else { q.ceil() }, sg, "{x}");
            assert_eq!((x + sg / 2.0).trunc(), x.round(), "{x}");
        }
    }
}
