//! LinuxCNC named parameters (`#<depth> = 2`, `#<_safe_z> = 5`) for a
//! target with numbered common variables only (Fanuc, Haas: no
//! `named-parameters` capability): each name the program sets becomes a
//! free common variable (`#100` up, numbers the program does not use),
//! with the name in a comment where it is first set.
//!
//! A global (`#<_name>`) is one variable everywhere. A local (`#<name>`)
//! is one variable per subroutine it is set in (and one for the main
//! program), so a subroutine's locals do not clobber its caller's; a
//! subroutine that calls itself would share them between its levels, so
//! the port refuses a program with a recursive call (E0613).
//!
//! A name only ever read is not the program's own: LinuxCNC's predefined
//! parameters (`#<_x>`, `#<_metric>`) are the control's state, and stay
//! for the writer to report.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{CallTarget, CommentStyle, ExprKind, FlowId, Program, Stmt, StmtKind, Var};
use std::collections::{BTreeSet, HashMap};

/// A parameter: the subroutine it is local to (`None` for globals and
/// the main program's locals), and its name in lower case.
type Key = (Option<String>, String);

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if !to.has(Capability::MacroB) || to.has(Capability::NamedParameters) {
        return;
    }
    let scopes = scopes(p);
    let set = names_set(p, &scopes);
    if set.is_empty() {
        return;
    }
    if let Some(span) = recursive_call(p, &scopes) {
        diags.push(
            Diagnostic::new(
                Code::PortVariable,
                format!(
                    "{} has no local named parameters: a subroutine that calls itself would share them",
                    to.name
                ),
            )
            .primary(span, "a recursive call")
            .help("make the subroutine's values arguments (#1..#30)"),
        );
        return;
    }
    let used = super::free_vars::used(p).numbers;
    let mut pool = super::free_vars::commons(to, &used);
    let mut vars: HashMap<Key, u32> = HashMap::new();
    for key in set {
        let Some(n) = pool.next() else {
            diags.push(
                Diagnostic::new(
                    Code::PortVariable,
                    format!("{} has no free common variable for `#<{}>`", to.name, key.1),
                )
                .help("use fewer named parameters"),
            );
            return;
        };
        vars.insert(key, n);
    }
    rename(p, &vars, &scopes);
}

/// Whether `name` is one variable for the whole program.
fn is_global(name: &str) -> bool {
    name.starts_with('_')
}

fn key(sub: &Option<String>, name: &str) -> Key {
    let name = name.to_ascii_lowercase();
    let scope = if is_global(&name) { None } else { sub.clone() };
    (scope, name)
}

/// The subroutine each block is in (o-word subroutines), in block order.
fn scopes(p: &Program) -> Vec<Option<String>> {
    let mut out = Vec::with_capacity(p.blocks.len());
    let mut current: Option<String> = None;
    for b in &p.blocks {
        for s in &b.stmts {
            if let StmtKind::SubStart {
                id: FlowId::OWord(k),
                ..
            } = &s.kind
            {
                current = Some(k.clone());
            }
        }
        out.push(current.clone());
        if b.stmts.iter().any(|s| {
            matches!(
                s.kind,
                StmtKind::SubEnd {
                    id: FlowId::OWord(_),
                    ..
                }
            )
        }) {
            current = None;
        }
    }
    out
}

/// The parameters the program sets, in the order first set.
fn names_set(p: &Program, scopes: &[Option<String>]) -> Vec<Key> {
    let mut seen = BTreeSet::new();
    let mut out = Vec::new();
    for (b, sub) in p.blocks.iter().zip(scopes) {
        for s in &b.stmts {
            if let StmtKind::Assign {
                var: Var::Named(n), ..
            } = &s.kind
            {
                let k = key(sub, n);
                if seen.insert(k.clone()) {
                    out.push(k);
                }
            }
        }
    }
    out
}

/// A call of an o-word subroutine from inside itself.
fn recursive_call(p: &Program, scopes: &[Option<String>]) -> Option<crate::span::Span> {
    for (b, sub) in p.blocks.iter().zip(scopes) {
        let Some(sub) = sub else { continue };
        for s in &b.stmts {
            if let StmtKind::Call {
                target: CallTarget::Name(n),
                ..
            } = &s.kind
            {
                if sub.trim_matches(['<', '>']).eq_ignore_ascii_case(n) {
                    return Some(s.span);
                }
            }
        }
    }
    None
}

/// Every use and assignment of a set parameter becomes its variable; the
/// first assignment of each keeps the name in a comment.
fn rename(p: &mut Program, vars: &HashMap<Key, u32>, scopes: &[Option<String>]) {
    // The subroutine an expression is in: the one of the block whose
    // text holds it.
    let mut at: Vec<(crate::span::Span, Option<String>)> = p
        .blocks
        .iter()
        .zip(scopes)
        .filter(|(_, sub)| sub.is_some())
        .map(|(b, sub)| (b.span, sub.clone()))
        .collect();
    at.sort_by_key(|(sp, _)| (sp.file, sp.start));
    let scope_of = |sp: crate::span::Span| {
        let i = at.partition_point(|(b, _)| (b.file, b.start) <= (sp.file, sp.start));
        let (b, sub) = at.get(i.checked_sub(1)?)?;
        (b.file == sp.file && sp.end <= b.end)
            .then(|| sub.clone())
            .flatten()
    };
    let ids: Vec<_> = p.exprs.iter().map(|(id, _)| id).collect();
    for id in ids {
        let ExprKind::Var(Var::Named(n)) = &p.exprs[id].kind else {
            continue;
        };
        let sub = scope_of(p.exprs[id].span);
        if let Some(&v) = vars.get(&key(&sub, n)) {
            p.exprs[id].kind = ExprKind::Var(Var::Numbered(v));
        }
    }
    let mut named = BTreeSet::new();
    for (b, sub) in p.blocks.iter_mut().zip(scopes) {
        let mut notes = Vec::new();
        for s in &mut b.stmts {
            let StmtKind::Assign { var, .. } = &mut s.kind else {
                continue;
            };
            let Var::Named(n) = var else { continue };
            let k = key(sub, n);
            let Some(&v) = vars.get(&k) else { continue };
            if named.insert(k) {
                notes.push(Stmt::new(
                    StmtKind::Comment {
                        text: format!("#{v} = {}", n.to_ascii_uppercase()),
                        style: CommentStyle::Paren,
                    },
                    s.span,
                ));
            }
            *var = Var::Numbered(v);
        }
        b.stmts.extend(notes);
    }
}
