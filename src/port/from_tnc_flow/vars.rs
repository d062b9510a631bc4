//! Heidenhain Q parameters as the target's variables, the reverse of
//! [`crate::port::to_tnc::vars`]:
//!
//! * `Q0..Q99` → `#n` / `Rn`, `Q1600..Q1999` → `#(n-1500)` / `R(n-1500)`,
//!   when the target has that number as a writable, non-system variable.
//! * Every other Q (the rest of those, `QL`, `QR`, `Q200..Q1599`): a
//!   named parameter where the target has them (`QL3` → `#<ql3>`), else
//!   the first free common variable of the target (`#100` up on Fanuc,
//!   `R0` up on Siemens, numbers no other Q took).
//! * `Q100..Q199` hold values the control sets itself (`Q108` the tool
//!   radius): E0621.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Family, VarClass};
use crate::ir::{ExprKind, Program, QBank, StmtKind, Var};
use crate::span::Span;
use std::collections::{BTreeMap, BTreeSet};

/// The number `Qn` goes back to, if it has one.
fn numbered(bank: QBank, n: u32) -> Option<u32> {
    match (bank, n) {
        (QBank::Q, 0..=99) => Some(n),
        (QBank::Q, 1600..=1999) => Some(n - 1500),
        _ => None,
    }
}

struct Target<'a> {
    to: &'a DialectSpec,
    prefix: char,
    named: bool,
}

impl Target<'_> {
    fn var(&self, n: u32) -> Var {
        if self.prefix == 'R' {
            Var::R(n)
        } else {
            Var::Numbered(n)
        }
    }

    fn has(&self, n: u32) -> bool {
        self.to
            .var_range(self.prefix, n)
            .is_some_and(|r| r.writable && r.class != VarClass::System)
    }

    /// The numbers free for the other parameters, in order.
    fn pool(&self) -> Vec<u32> {
        let mut out = Vec::new();
        for class in [VarClass::Common, VarClass::Retained] {
            for r in self.to.variables.iter() {
                if r.prefix == self.prefix && r.class == class && r.writable {
                    out.extend((r.first..=r.last).take(2000));
                }
            }
        }
        out
    }
}

/// Every Q parameter of `p` as a variable of `to`.
pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let t = Target {
        to,
        prefix: if to.family == Family::Sinumerik {
            'R'
        } else {
            '#'
        },
        named: to.has(Capability::NamedParameters),
    };
    let mut seen: BTreeMap<(u8, u32), Span> = BTreeMap::new();
    let key = |b: QBank, n: u32| -> (u8, u32) { (b as u8, n) };
    for (_, e) in p.exprs.iter() {
        if let ExprKind::Var(Var::Q(b, n)) = e.kind {
            seen.entry(key(b, n)).or_insert(e.span);
        }
    }
    for b in &p.blocks {
        for s in &b.stmts {
            if let StmtKind::Assign {
                var: Var::Q(bk, n), ..
            } = s.kind
            {
                seen.entry(key(bk, n)).or_insert(s.span);
            }
        }
    }
    let banks = [QBank::Q, QBank::Local, QBank::Remanent];
    let mut map: BTreeMap<(u8, u32), Var> = BTreeMap::new();
    let mut taken = BTreeSet::new();
    for (&(b, n), &span) in &seen {
        let bank = banks[b as usize];
        if bank == QBank::Q && (100..=199).contains(&n) {
            diags.push(
                Diagnostic::new(
                    Code::PortQParameter,
                    format!(
                        "`Q{n}` is a value the Heidenhain control sets; {} has no such variable",
                        to.name
                    ),
                )
                .primary(span, "this parameter")
                .help("compute the value in the program, or use Q0..Q99"),
            );
            continue;
        }
        if let Some(m) = numbered(bank, n).filter(|&m| t.has(m)) {
            taken.insert(m);
            map.insert((b, n), t.var(m));
        }
    }
    let mut pool = t.pool().into_iter().filter(|m| !taken.contains(m));
    for (&(b, n), &span) in &seen {
        let bank = banks[b as usize];
        if map.contains_key(&(b, n)) || (bank == QBank::Q && (100..=199).contains(&n)) {
            continue;
        }
        let v = if t.named {
            Some(Var::Named(format!(
                "{}{n}",
                bank.prefix().to_ascii_lowercase()
            )))
        } else {
            pool.next().map(|m| t.var(m))
        };
        match v {
            Some(v) => {
                map.insert((b, n), v);
            }
            None => diags.push(
                Diagnostic::new(
                    Code::PortQParameter,
                    format!(
                        "{} has no free variable left for `{}{n}`",
                        to.name,
                        bank.prefix()
                    ),
                )
                .primary(span, "this parameter")
                .help("use fewer Q parameters"),
            ),
        }
    }
    let lookup = |v: &Var| match v {
        Var::Q(b, n) => map.get(&key(*b, *n)).cloned(),
        _ => None,
    };
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        if let ExprKind::Var(v) = &p.exprs[id].kind {
            if let Some(nv) = lookup(v) {
                p.exprs[id].kind = ExprKind::Var(nv);
            }
        }
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            if let StmtKind::Assign { var, .. } = &mut s.kind {
                if let Some(nv) = lookup(var) {
                    *var = nv;
                }
            }
        }
    }
}
