//! Lowering: a line's words to meta-model statements, by the dialect spec.
//!
//! Shared by every front end. It never asks which dialect it is in: G and M
//! words are looked up in the spec's code table and become the statement of
//! their meaning, taking the words the meaning and the spec's `uses` name;
//! the words left over become an implicit move, feed, speed, tool and
//! register statements, or are reported and kept. Statements come out in
//! source order (a statement sits where its first word is).

mod build;
mod checks;
mod codes;
mod leftover;
mod motion;
mod words;

#[cfg(test)]
pub(crate) mod test_support;
#[cfg(test)]
mod tests;

use crate::diag::Diagnostic;
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{Arena, Block, Expr, ExprId, LengthComp, Stmt, StmtKind, Value, Word};
use crate::span::Span;
use crate::syntax::{Item, LineSyntax, WordSyntax};
use codes::CodeWord;
use leftover::Placed;
use words::Words;

/// What the builders share while lowering one line.
pub(crate) struct Ctx<'a> {
    pub spec: &'a DialectSpec,
    pub exprs: &'a Arena<Expr>,
    pub diags: &'a mut Vec<Diagnostic>,
}

/// The words of a line sorted by kind.
#[derive(Default)]
struct Sorted<'s> {
    out: Vec<Placed>,
    codes: Vec<CodeWord<'s>>,
    dynamic: Vec<(char, ExprId, Span)>,
    plain: Vec<WordSyntax>,
}

/// Lowers one line's words to statements (see the module doc).
pub fn lower_line(line: LineSyntax, spec: &DialectSpec, exprs: &Arena<Expr>, diags: &mut Vec<Diagnostic>) -> Block {
    let mut ctx = Ctx { spec, exprs, diags };
    let mut s = sort_items(line.items, &mut ctx);
    words::convert_increments(&mut s.plain, spec, ctx.diags);
    let mut words = Words::with_capacity(s.plain.len());
    let mut repeated = Vec::new();
    for w in s.plain.drain(..) {
        words.push(w, ctx.diags, &mut repeated);
    }
    codes::check_groups(&s.codes, spec, ctx.diags);
    for cw in &s.codes {
        checks::check_required(cw, &words, ctx.diags);
    }
    lower_codes(&s.codes, &mut words, &mut s.out, &mut ctx);
    let mut out = finish(s, &mut words, &mut ctx);
    for w in repeated {
        out.push((w.span.start, Stmt::new(leftover::keep(&w, &ctx), w.span)));
    }
    out.sort_by_key(|(pos, _)| *pos);
    Block {
        span: line.span,
        skip: line.skip,
        number: line.number,
        label: line.label,
        stmts: out.into_iter().map(|(_, s)| s).collect(),
    }
}

/// Splits items into statements, code words, dynamic codes and plain words.
fn sort_items<'s>(items: Vec<Item>, ctx: &mut Ctx<'s>) -> Sorted<'s> {
    let n = items.len();
    let mut s = Sorted { out: Vec::with_capacity(n + 1), codes: Vec::with_capacity(4), dynamic: Vec::new(), plain: Vec::with_capacity(n) };
    for item in items {
        let w = match item {
            Item::Stmt(st) => {
                s.out.push((st.span.start, st));
                continue;
            }
            Item::Word(w) => w,
        };
        let letter = match w.address.as_str() {
            "G" => 'G',
            "M" => 'M',
            a => {
                match codes::pseudo_motion(a) {
                    Some(m) => s.codes.push(CodeWord { letter: '\0', code: crate::ir::Decimal::ZERO, span: w.span, meaning: Some(m), def: None }),
                    None => s.plain.push(w),
                }
                continue;
            }
        };
        match w.value {
            Value::Number(d) => s.codes.push(codes::resolve(letter, d, w.span, ctx.spec, ctx.diags)),
            Value::Expr(e) => s.dynamic.push((letter, e, w.span)),
        }
    }
    s
}

/// Which codes take their words first: those taking every word, then those
/// taking axis words away from the move, then the rest in source order.
fn priority(cw: &CodeWord<'_>) -> u8 {
    use Meaning as M;
    match cw.meaning {
        Some(M::SetData | M::MacroCall | M::ModalMacroCall) => 0,
        Some(M::CoordShift(_) | M::RefReturn { .. } | M::LengthComp(LengthComp::Dynamic)) => 1,
        Some(M::Rotate(true) | M::Scale(true) | M::Mirror(true)) => 1,
        _ => 2,
    }
}

fn lower_codes(codes: &[CodeWord<'_>], words: &mut Words, out: &mut Vec<Placed>, ctx: &mut Ctx<'_>) {
    let mut order: Vec<&CodeWord<'_>> = codes.iter().collect();
    order.sort_by_key(|cw| priority(cw));
    for cw in order {
        words.begin();
        let kind = match cw.meaning {
            Some(m) => build::code_stmt(cw, m, words, ctx),
            None => build::aux(cw, words),
        };
        let span = words.taken_spans().iter().fold(cw.span, |a, b| a.to(*b));
        out.push((cw.span.start, Stmt::new(kind, span)));
    }
}

/// Everything after the codes: moves, standalone words, dynamic codes, and
/// the words nobody took.
fn finish(mut s: Sorted<'_>, words: &mut Words, ctx: &mut Ctx<'_>) -> Vec<Placed> {
    let cancel = s.codes.iter().find(|c| c.meaning == Some(Meaning::CycleCancel)).map(|c| c.span);
    let has_motion = s.codes.iter().any(|c| c.is_motion());
    let mut implicit = false;
    match cancel {
        Some(span) if !has_motion => leftover::reject_axes_after_cancel(span, words, &mut s.out, ctx),
        _ => {
            let m = leftover::implicit_motion(words, ctx);
            implicit = m.is_some();
            s.out.extend(m);
        }
    }
    leftover::standalone(words, &mut s.out, ctx);
    let mut dynamic_words: Vec<Word> = Vec::new();
    let has_dynamic = !s.dynamic.is_empty();
    leftover::unused(words, has_dynamic.then_some(&mut dynamic_words), implicit, &mut s.out, ctx);
    for (i, (letter, value, span)) in s.dynamic.iter().enumerate() {
        let words = if i == 0 { std::mem::take(&mut dynamic_words) } else { Vec::new() };
        s.out.push((span.start, Stmt::new(StmtKind::DynamicCode { letter: *letter, value: *value, words }, *span)));
    }
    s.out
}
