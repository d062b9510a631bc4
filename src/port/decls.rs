//! Siemens `DEF` variables for a word-address target: LinuxCNC names them
//! (`DEF REAL DEPTH=2` → `#<depth>=2`), the others give each one a free
//! common numbered variable (`#100` up, numbers the program does not use
//! as `#n` or `Rn`). A `DEF` becomes the assignment of its initial value,
//! or of 0 (Siemens sets a REAL or INT to 0 where Macro B leaves it
//! vacant). Arrays and STRING, FRAME, AXIS, CHAR, BOOL variables have no
//! counterpart: E0613. An INT is not rounded on assignment as Siemens
//! rounds it: the port keeps the value as computed.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Family};
use crate::ir::{CommentStyle, Decimal, Expr, ExprKind, Program, Stmt, StmtKind, Var, VarType};
use std::collections::HashMap;

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.family == Family::Sinumerik
        || !p.blocks.iter().any(|b| {
            b.stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::Declare { .. }))
        })
    {
        return;
    }
    let named = to.has(Capability::NamedParameters);
    let used = super::free_vars::used(p).numbers;
    let mut pool = super::free_vars::commons(to, &used);
    let mut names: HashMap<String, Var> = HashMap::new();
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let mut stmts = Vec::new();
        // One block per declared variable (one assignment per block).
        let mut split: Vec<Vec<Stmt>> = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let StmtKind::Declare { ty, vars } = &s.kind else {
                stmts.push(s);
                continue;
            };
            for v in vars {
                if !matches!(ty, VarType::Real | VarType::Int) || !v.dims.is_empty() {
                    diags.push(
                        Diagnostic::new(
                            Code::PortVariable,
                            format!(
                                "{} has no form for the {ty:?} variable `{}`",
                                to.name, v.name
                            ),
                        )
                        .primary(v.span, "declared here")
                        .help("use REAL or INT scalars, or R parameters"),
                    );
                    continue;
                }
                let var = if named {
                    Some(Var::Named(v.name.to_ascii_lowercase()))
                } else {
                    pool.next().map(Var::Numbered)
                };
                let Some(var) = var else {
                    diags.push(
                        Diagnostic::new(
                            Code::PortVariable,
                            format!("{} has no free common variable for `{}`", to.name, v.name),
                        )
                        .primary(v.span, "declared here")
                        .help("use fewer DEF variables"),
                    );
                    continue;
                };
                names.insert(v.name.to_ascii_uppercase(), var.clone());
                let value = v.init.unwrap_or_else(|| {
                    p.exprs.alloc(Expr {
                        kind: ExprKind::Number(Decimal::from_int(0)),
                        span: v.span,
                    })
                });
                let mut one = vec![Stmt::new(
                    StmtKind::Assign {
                        var: var.clone(),
                        value,
                    },
                    v.span,
                )];
                if !named {
                    // The name stays beside the number it became.
                    let text = format!("{} {}", type_name(*ty), v.name);
                    one.push(Stmt::new(
                        StmtKind::Comment {
                            text,
                            style: CommentStyle::Paren,
                        },
                        v.span,
                    ));
                }
                split.push(one);
            }
        }
        let mut split = split.into_iter();
        if stmts.is_empty() {
            stmts = split.next().unwrap_or_default();
        }
        b.stmts = stmts;
        let rest: Vec<_> = split.map(|one| super::follow_block(&b, one)).collect();
        p.blocks.push(b);
        p.blocks.extend(rest);
    }
    rename(p, &names);
}

/// Uses of the declared names (Siemens user variables, upper-cased keys)
/// become the target's variables.
pub(super) fn rename(p: &mut Program, names: &HashMap<String, Var>) {
    let to_var = |v: &Var| match v {
        Var::User(n, idx) if idx.is_empty() => names.get(&n.to_ascii_uppercase()).cloned(),
        _ => None,
    };
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        if let ExprKind::Var(v) = &p.exprs[id].kind {
            if let Some(nv) = to_var(v) {
                p.exprs[id].kind = ExprKind::Var(nv);
            }
        }
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            if let StmtKind::Assign { var, .. } | StmtKind::For { var, .. } = &mut s.kind {
                if let Some(nv) = to_var(var) {
                    *var = nv;
                }
            }
        }
    }
}

fn type_name(ty: VarType) -> &'static str {
    match ty {
        VarType::Int => "INT",
        VarType::Real
        | VarType::Bool
        | VarType::Char
        | VarType::String
        | VarType::Axis
        | VarType::Frame => "REAL",
    }
}
