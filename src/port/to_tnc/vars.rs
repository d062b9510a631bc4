//! Variables of a word-address or Sinumerik program as Heidenhain Q
//! parameters. The allocation (the same both ways, see
//! `port::from_tnc_flow`):
//!
//! * `#0..#99` and `R0..R99` → `Q0..Q99`, the same number (the user range
//!   the control leaves free when no SL cycle runs).
//! * `#100..#499` and `R100..R499` → `Q1600..Q1999` (number + 1500):
//!   `Q100..Q199` are values the control writes itself (`Q108` the tool
//!   radius...), `Q200..Q1599` belong to cycles; `Q1600..Q1999` is the
//!   other user range.
//! * Named (`#<depth>`) and declared (`DEF REAL DEPTH`) variables take
//!   local parameters `QL1`, `QL2`, ... in the order they first appear,
//!   and so do the counters the loop forms need (`Alloc::scratch`). `QL`
//!   is local to the program, as LinuxCNC named parameters and Siemens
//!   `DEF` data are, and no cycle reads or writes it; older controls
//!   (TNC 426/430) have no `QL` [?].
//! * Other numbers (Fanuc `#500..#999`, LinuxCNC `#1000` up), indirect
//!   `#[e]`/`R[e]`, arrays and system variables: E0621.
//!
//! A `DEF REAL|INT` becomes the assignment of its initial value, or of 0.
//! An INT is not rounded on assignment as Siemens rounds it: the port
//! keeps the value as computed (as [`crate::port`]'s `decls` does).

use crate::diag::{Code, Diagnostic};
use crate::ir::{Decimal, Expr, ExprKind, Program, QBank, Stmt, StmtKind, Var, VarType};
use crate::span::Span;
use std::collections::HashMap;

/// The Q parameters given to the program's variables.
#[derive(Default)]
pub(super) struct Alloc {
    names: HashMap<String, u32>,
    next_local: u32,
}

/// The Q parameter for `#n` / `Rn`, or None outside the two user ranges.
pub fn numbered_q(n: u32) -> Option<Var> {
    match n {
        0..=99 => Some(Var::Q(QBank::Q, n)),
        100..=499 => Some(Var::Q(QBank::Q, n + 1500)),
        _ => None,
    }
}

impl Alloc {
    fn local(&mut self, name: &str) -> Var {
        let key = name.to_ascii_uppercase();
        let next = &mut self.next_local;
        let n = *self.names.entry(key).or_insert_with(|| {
            *next += 1;
            *next
        });
        Var::Q(QBank::Local, n)
    }

    /// A fresh local parameter for a loop counter or bound.
    pub fn scratch(&mut self) -> Var {
        self.next_local += 1;
        Var::Q(QBank::Local, self.next_local)
    }

    /// The Q parameter for `v`; Err names what has none.
    fn map(&mut self, v: &Var) -> Result<Option<Var>, String> {
        Ok(Some(match v {
            Var::Q(..) => return Ok(None),
            Var::Numbered(n) => numbered_q(*n).ok_or_else(|| format!("`#{n}`"))?,
            Var::R(n) => numbered_q(*n).ok_or_else(|| format!("`R{n}`"))?,
            Var::Named(n) => self.local(n),
            Var::User(n, idx) if idx.is_empty() => self.local(n),
            Var::User(n, _) => return Err(format!("the array element `{n}[..]`")),
            Var::Indirect(_) => return Err("an indirect variable `#[..]`".into()),
            Var::RIndirect(_) => return Err("an indirect parameter `R[..]`".into()),
            Var::System(n, _) => return Err(format!("the system variable `{n}`")),
        }))
    }
}

fn refuse(diags: &mut Vec<Diagnostic>, span: Span, what: &str) {
    diags.push(
        Diagnostic::new(
            Code::PortQParameter,
            format!("Klartext has no Q parameter for {what}"),
        )
        .primary(span, "this variable")
        .help("use #0..#99 or #100..#499 (R0..R499), or named variables"),
    );
}

/// Declarations become assignments, then every variable its Q parameter.
pub(super) fn run(p: &mut Program, alloc: &mut Alloc, diags: &mut Vec<Diagnostic>) {
    declarations(p, alloc, diags);
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        let e = &p.exprs[id];
        let ExprKind::Var(v) = &e.kind else { continue };
        match alloc.map(v) {
            Ok(Some(q)) => p.exprs[id].kind = ExprKind::Var(q),
            Ok(None) => {}
            Err(what) => refuse(diags, e.span, &what),
        }
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            assigned(s, alloc, diags);
        }
    }
}

/// The variable a statement sets (also in `IF [c] THEN #1=..`).
fn assigned(s: &mut Stmt, alloc: &mut Alloc, diags: &mut Vec<Diagnostic>) {
    let var = match &mut s.kind {
        StmtKind::Assign { var, .. } | StmtKind::For { var, .. } => var,
        StmtKind::IfThen { then, .. } => return assigned(then, alloc, diags),
        _ => return,
    };
    match alloc.map(var) {
        Ok(Some(q)) => *var = q,
        Ok(None) => {}
        Err(what) => refuse(diags, s.span, &what),
    }
}

/// `DEF REAL A=1, B` → `A=1` and `B=0` (one block each); other types and
/// arrays: E0621.
fn declarations(p: &mut Program, alloc: &mut Alloc, diags: &mut Vec<Diagnostic>) {
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut kept = Vec::new();
        let mut split: Vec<Stmt> = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let StmtKind::Declare { ty, vars } = &s.kind else {
                kept.push(s);
                continue;
            };
            for v in vars {
                if !matches!(ty, VarType::Real | VarType::Int) || !v.dims.is_empty() {
                    refuse(diags, v.span, &format!("the {ty:?} variable `{}`", v.name));
                    continue;
                }
                let value = v.init.unwrap_or_else(|| {
                    p.exprs.alloc(Expr {
                        kind: ExprKind::Number(Decimal::from_int(0)),
                        span: v.span,
                    })
                });
                // Numbered in the order declared.
                let var = alloc.local(&v.name);
                split.push(Stmt::new(StmtKind::Assign { var, value }, v.span));
            }
        }
        let mut split = split.into_iter();
        if kept.is_empty() {
            kept.extend(split.next());
        }
        b.stmts = kept;
        let rest: Vec<_> = split
            .map(|s| super::super::follow_block(&b, vec![s]))
            .collect();
        if !b.stmts.is_empty() || b.label.is_some() || b.number.is_some() {
            p.blocks.push(b);
        }
        p.blocks.extend(rest);
    }
}
