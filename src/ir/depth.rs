//! How deep expressions nest, measured without recursion, so that every
//! recursive walk over an expression (evaluation, writing, printing) is
//! bounded by [`MAX_EXPR_DEPTH`]: a deeper expression is a located error
//! where it is read, and never reaches those walks.

use super::{Arena, Expr, ExprId, ExprKind, Var};

/// The deepest expression a program may hold. Controllers allow far less
/// (Fanuc: 5 levels of brackets); 256 leaves room for generated programs
/// and keeps every recursive walk well inside the stack.
pub const MAX_EXPR_DEPTH: usize = 256;

/// The expressions an expression refers to directly.
pub fn children(kind: &ExprKind, out: &mut Vec<ExprId>) {
    match kind {
        ExprKind::Number(_) | ExprKind::Str(_) | ExprKind::Bool(_) | ExprKind::Exists(_) => {}
        ExprKind::Var(v) => var_children(v, out),
        ExprKind::Unary(_, a) | ExprKind::Dimension(_, a) | ExprKind::ExistsNumbered(a) => {
            out.push(*a)
        }
        ExprKind::Binary(_, a, b) | ExprKind::AtanSlash(a, b) => {
            out.push(*a);
            out.push(*b);
        }
        ExprKind::Call(_, args) | ExprKind::Query(_, args) => out.extend(args.iter().copied()),
    }
}

fn var_children(v: &Var, out: &mut Vec<ExprId>) {
    match v {
        Var::Indirect(e) | Var::RIndirect(e) => out.push(*e),
        Var::User(_, ix) | Var::System(_, ix) => out.extend(ix.iter().copied()),
        Var::Numbered(_) | Var::Named(_) | Var::R(_) | Var::Q(..) => {}
    }
}

/// The first expression from index `from` on that nests deeper than
/// [`MAX_EXPR_DEPTH`]. Children are allocated before their parents, so one
/// pass in index order measures every depth; older expressions count as 1.
pub fn first_too_deep(exprs: &Arena<Expr>, from: usize) -> Option<ExprId> {
    let n = exprs.len();
    let mut depth = vec![0u32; n.saturating_sub(from)];
    let mut kids = Vec::new();
    for (id, e) in exprs.iter_from(from) {
        let i = id.index();
        kids.clear();
        children(&e.kind, &mut kids);
        let deepest = kids
            .iter()
            .map(|k| {
                k.index()
                    .checked_sub(from)
                    .and_then(|j| depth.get(j))
                    .copied()
                    .unwrap_or(1)
            })
            .max()
            .unwrap_or(0);
        depth[i - from] = deepest + 1;
        if deepest as usize + 1 > MAX_EXPR_DEPTH {
            return Some(id);
        }
    }
    None
}
