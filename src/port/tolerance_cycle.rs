//! A tolerance cycle (the 840D's `CYCLE832(_TOL, _TOLM)`: the source spec's
//! cycle of kind `tolerance`) for a target without that cycle becomes the
//! continuous-path mode with the tolerance as its `P` word (`G64 P0.02`),
//! which is how the interpreter runs it
//! (`interp::siemens::calls::tolerance`: the same two calls as LinuxCNC's
//! `G64 P`). The later passes write the mode in the target's form:
//! LinuxCNC `G64 P0.02`; Heidenhain cycle 32 with `T0.02`
//! ([`super::to_tnc::modes`]); a target whose G64 takes no tolerance
//! (Fanuc, Haas) gets `G64` and W0610 for the tolerance left to the
//! machine ([`super::path_words`]). Before this the call was "written as
//! the moves it makes", which for a mode is a bare `G1`.
//!
//! Deselection (`CYCLE832()`, a tolerance of 0, a machining type whose
//! units digit is 0, `_OFF`) is `G64` without a tolerance, as the
//! interpreter runs it [?: the 840D returns to its configured path mode,
//! usually G64]. A tolerance or type given as an expression (not a
//! number, not a name the spec defines as a constant) stays a call: it is
//! refused or expanded as before.

use crate::dialect::DialectSpec;
use crate::ir::{
    CycleCall, Decimal, ExprKind, PathMode, Program, Stmt, StmtKind, Value, Var, Word,
};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    for bi in 0..p.blocks.len() {
        for si in 0..p.blocks[bi].stmts.len() {
            let s = &p.blocks[bi].stmts[si];
            let StmtKind::CycleCall(c) = &s.kind else {
                continue;
            };
            if !is_tolerance(c, from, to) {
                continue;
            }
            if let Some(mode) = path_mode(p, c, from, s.span) {
                p.blocks[bi].stmts[si] = mode;
            }
        }
    }
}

/// A call of the source's tolerance cycle, which the target lacks.
fn is_tolerance(c: &CycleCall, from: &DialectSpec, to: &DialectSpec) -> bool {
    !c.modal
        && from.cycle(&c.name).is_some_and(|s| s.kind == "tolerance")
        && to.cycle(&c.name).is_none()
}

/// The continuous-path mode the call sets, where its arguments are known.
fn path_mode(
    p: &Program,
    c: &CycleCall,
    from: &DialectSpec,
    span: crate::span::Span,
) -> Option<Stmt> {
    let arg = |i: usize| -> Option<Option<(Decimal, crate::span::Span)>> {
        match c.args.get(i).and_then(|a| a.value.map(|e| (e, a.span))) {
            None => Some(None),
            Some((e, sp)) => number(p, e, from).map(|d| Some((d, sp))),
        }
    };
    let tol = arg(0)?;
    let kind = arg(1)?;
    let tol = tol.filter(|(d, _)| d.to_f64() != 0.0);
    // [?] A tolerance without a machining type selects finishing (as the
    // interpreter runs it); a type whose units digit is 0 deselects.
    let deselect = kind.is_some_and(|(k, _)| (k.to_f64().abs() as i64) % 10 == 0);
    let words = match tol {
        Some((d, sp)) if !deselect => vec![Word {
            letter: 'P',
            suffix: String::new(),
            value: Value::Number(abs(d)),
            span: sp,
        }],
        _ => Vec::new(),
    };
    Some(Stmt::new(
        StmtKind::PathMode {
            mode: PathMode::Continuous,
            words,
        },
        span,
    ))
}

/// A literal, or a name the source spec defines as a constant (`_FINISH`).
fn number(p: &Program, e: crate::ir::ExprId, from: &DialectSpec) -> Option<Decimal> {
    match &p.exprs[e].kind {
        ExprKind::Number(d) => Some(*d),
        ExprKind::Var(Var::User(name, index)) if index.is_empty() => from.constant(name),
        _ => None,
    }
}

/// `d` without its sign, exactly as written (no trip through f64).
fn abs(d: Decimal) -> Decimal {
    if d.to_f64() < 0.0 {
        d.neg()
    } else {
        d
    }
}
