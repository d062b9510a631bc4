//! What the grammar read, to items ([`items`]), and its syntax errors
//! as diagnostics.

use super::build::{Ctx, Node};
use super::token::Tok;
use super::{approach, cycles, flow, functions, path, program};
use crate::diag::{Code, Diagnostic};
use crate::span::Span;
use crate::syntax::Item;
use lalrpop_util::ParseError;

pub(super) fn items(ctx: &mut Ctx<'_>, node: Node, l: usize, r: usize) -> Vec<Item> {
    match node {
        Node::Begin(at) => program::pgm_line(ctx, false, at, l, r),
        Node::End(at) => program::pgm_line(ctx, true, at, l, r),
        Node::BlkForm(n, w) => program::blk_form(ctx, n, &w, l, r),
        Node::ToolDef(t, w) => program::tool_def(ctx, t, &w, l, r),
        Node::ToolCall(t, w) => program::tool_call(ctx, t, &w, l, r),
        Node::Path(k, w) => path::path(ctx, k, &w, l, r),
        Node::Chamfer(s, w) => path::chamfer(ctx, &s, &w, l, r),
        Node::Approach(dep, w) => approach::approach(ctx, dep, &w, l, r),
        Node::Label(id, il, ir) => flow::label(ctx, id, il, ir, l, r),
        Node::CallLabel(at) => flow::call_label(ctx, at, l, r),
        Node::CallPgm(at) => flow::call_pgm(ctx, at, l, r),
        Node::FnAssign(n, (var, ..), rhs) => flow::fn_assign(ctx, n, var, &rhs, l, r),
        Node::FnIf(n, a, op, b, id, ..) => flow::fn_if(ctx, n, &a, &op, &b, id, l, r),
        Node::FnOther(n, at) => functions::fn_other(ctx, n, at, l, r),
        Node::Formula((var, ..), e) => flow::formula(ctx, var, e, l, r),
        Node::CyclDef(at) => cycles::cycl_def(ctx, at, l, r),
        Node::CyclCall(w) => cycles::cycl_call(ctx, &w, l, r),
        Node::PatternDef(at) => cycles::pattern_def(ctx, at, l, r),
        Node::TchProbe(at) => cycles::tch_probe(ctx, at, l, r),
        Node::Stop(w) => program::stop(ctx, &w, l, r),
        Node::Words(w) if w.first().is_some_and(|f| functions::starts_block(&f.name)) => {
            functions::word_block(ctx, &w, l, r)
        }
        Node::Words(w) => program::bare(ctx, &w),
    }
}

pub(super) fn syntax_error(
    e: ParseError<usize, Tok, String>,
    file: crate::span::FileId,
    end: usize,
) -> Diagnostic {
    let (l, r, msg) = match e {
        ParseError::UnrecognizedToken {
            token: (l, t, r),
            expected,
        } => (
            l,
            r,
            format!("unexpected {}{}", describe(&t), expecting(&expected)),
        ),
        ParseError::UnrecognizedEof { location, expected } => (
            location,
            location.max(end),
            format!("the block ends too early{}", expecting(&expected)),
        ),
        ParseError::ExtraToken { token: (l, t, r) } => {
            (l, r, format!("unexpected {}", describe(&t)))
        }
        ParseError::InvalidToken { location } => (location, location + 1, "invalid token".into()),
        ParseError::User { error } => (end, end, error),
    };
    Diagnostic::new(Code::SyntaxError, msg)
        .primary(Span::new(file, l, r), "not expected here")
        .help("check the block against the Klartext form of its function")
}

fn describe(t: &Tok) -> String {
    match t {
        Tok::Kw(k) => format!("`{}`", format!("{k:?}").to_ascii_uppercase()),
        Tok::Name(n) => format!("`{n}`"),
        Tok::Num(d) => format!("number `{}`", d.format(0, false)),
        Tok::Q(b, n) => format!("`{}{n}`", b.prefix()),
        Tok::Str(s) => format!("string \"{s}\""),
        other => format!("`{other:?}`"),
    }
}

fn expecting(expected: &[String]) -> String {
    if expected.is_empty() || expected.len() > 6 {
        return String::new();
    }
    format!("; expected {}", expected.join(", "))
}
