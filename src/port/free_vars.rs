//! The numbered variables a program uses, and the target's common ones it
//! leaves free: where the port puts a variable the target has no name for
//! (a Siemens `DEF`, a LinuxCNC `#<name>`, a PROC parameter's scratch).

use crate::dialect::{DialectSpec, VarClass};
use crate::ir::{ExprKind, Program, StmtKind, Var};
use std::collections::BTreeSet;

/// The numbers the program reads or sets as `#n` or `Rn` (the port
/// writes `Rn` as `#n`), and whether it also picks one at run time.
pub struct Used {
    pub numbers: BTreeSet<u32>,
    pub indirect: bool,
}

pub fn used(p: &Program) -> Used {
    let mut u = Used {
        numbers: BTreeSet::new(),
        indirect: false,
    };
    let mut see = |v: &Var| match v {
        Var::Numbered(n) | Var::R(n) => {
            u.numbers.insert(*n);
        }
        Var::Indirect(_) | Var::RIndirect(_) => u.indirect = true,
        _ => {}
    };
    for (_, e) in p.exprs.iter() {
        if let ExprKind::Var(v) = &e.kind {
            see(v);
        }
    }
    for s in p.blocks.iter().flat_map(|b| &b.stmts) {
        if let StmtKind::Assign { var, .. } | StmtKind::For { var, .. } = &s.kind {
            see(var);
        }
    }
    u
}

/// The target's writable common `#` variables not in `used`, lowest first.
pub fn commons<'a>(to: &'a DialectSpec, used: &'a BTreeSet<u32>) -> impl Iterator<Item = u32> + 'a {
    to.variables
        .iter()
        .filter(|r| r.prefix == '#' && r.class == VarClass::Common && r.writable)
        .flat_map(|r| r.first..=r.last)
        .filter(move |n| !used.contains(n))
}
