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
use crate::ir::{Arena, Block, Expr, ExprId, LengthComp, Motion, Stmt, StmtKind, Value, Word};
use crate::span::Span;
use crate::syntax::{Item, LineSyntax, WordSyntax};
use codes::CodeWord;
use leftover::Placement;
use words::Words;

/// What the builders share while lowering one line.
pub(crate) struct Ctx<'a> {
    pub spec: &'a DialectSpec,
    pub exprs: &'a Arena<Expr>,
    pub diags: &'a mut Vec<Diagnostic>,
    /// Moves of earlier lines, emptied for reuse (see [`Lowering::recycle`]).
    pub spare_moves: &'a mut SpareMoves,
}

/// Boxes of moves already handed out and given back: the boxes themselves
/// are what is reused (a statement holds its move boxed).
#[allow(clippy::vec_box)]
pub(crate) type SpareMoves = Vec<Box<Motion>>;

/// The words of a line sorted by kind.
#[derive(Default)]
struct Sorted<'s> {
    out: Placement,
    codes: Vec<CodeWord<'s>>,
    dynamic: Vec<(char, ExprId, Span)>,
    plain: Vec<WordSyntax>,
}

impl Sorted<'_> {
    fn clear(&mut self) {
        self.out.clear();
        self.codes.clear();
        self.dynamic.clear();
        self.plain.clear();
    }
}

/// Lowers one line's words to statements (see the module doc).
pub fn lower_line(
    mut line: LineSyntax,
    spec: &DialectSpec,
    exprs: &Arena<Expr>,
    diags: &mut Vec<Diagnostic>,
) -> Block {
    let mut stmts = Vec::new();
    Lowering::new(spec).lower(&mut line.items, exprs, diags, &mut stmts);
    Block {
        span: line.span,
        skip: line.skip,
        number: line.number,
        label: line.label.map(Box::new),
        stmts,
    }
}

/// The lowering of one file's lines, keeping its buffers from line to
/// line (a long program allocates nothing per line for them).
pub struct Lowering<'s> {
    spec: &'s DialectSpec,
    sorted: Sorted<'s>,
    words: Words,
    repeated: Vec<WordSyntax>,
    codes: codes::Cache<'s>,
    spare_moves: SpareMoves,
    /// Diagnostics of words pushed early, given after those of the codes.
    deferred: Vec<Diagnostic>,
}

impl<'s> Lowering<'s> {
    pub fn new(spec: &'s DialectSpec) -> Self {
        let mut words = Words::default();
        words.second_tool = spec.has(crate::dialect::Capability::SecondToolPreselects);
        Lowering {
            spec,
            sorted: Sorted::default(),
            words,
            repeated: Vec::new(),
            codes: codes::Cache::default(),
            spare_moves: Vec::new(),
            deferred: Vec::new(),
        }
    }

    /// Empties `stmts`, keeping the memory of its moves for later lines.
    pub fn recycle(&mut self, stmts: &mut Vec<Stmt>) {
        const KEEP: usize = 16;
        for s in stmts.drain(..) {
            if let StmtKind::Motion(m) = s.kind {
                if self.spare_moves.len() < KEEP {
                    self.spare_moves.push(m);
                }
            }
        }
    }

    /// Lowers the items (which are taken, leaving the vector empty) into
    /// `stmts` (appended, in source order).
    pub fn lower(
        &mut self,
        items: &mut Vec<Item>,
        exprs: &Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
        stmts: &mut Vec<Stmt>,
    ) {
        let spec = self.spec;
        let mut ctx = Ctx {
            spec,
            exprs,
            diags,
            spare_moves: &mut self.spare_moves,
        };
        let s = &mut self.sorted;
        s.clear();
        self.words.clear();
        // Words go straight to the word set unless lengths are converted
        // first (which needs all of them).
        let direct = !words::converts_increments(spec);
        let to = if direct {
            Some((&mut self.words, &mut self.repeated, &mut self.deferred))
        } else {
            None
        };
        sort_items(items, s, to, &mut self.codes, spec, ctx.diags);
        // Repeated words are reported after the codes, as when words come later.
        ctx.diags.append(&mut self.deferred);
        // The words of a high-speed code (`G5.1 Q1`, `G05 P10000`) are
        // switches and levels, not lengths.
        let smoothing = s
            .codes
            .iter()
            .any(|c| c.meaning == Some(Meaning::PathSmoothing));
        if !smoothing {
            words::convert_increments(&mut s.plain, spec, ctx.diags);
        }
        for w in &s.plain {
            self.words.push(w, ctx.diags, &mut self.repeated);
        }
        s.plain.clear();
        codes::drop_repeats(&mut s.codes, spec, ctx.diags);
        codes::check_groups(&s.codes, spec, ctx.diags);
        codes::drop_overridden_cancels(&mut s.codes, ctx.diags);
        for cw in &s.codes {
            checks::check_required(cw, &self.words, spec, ctx.diags);
        }
        lower_codes(&s.codes, &mut self.words, &mut s.out, &mut ctx);
        finish(s, &mut self.words, &mut ctx);
        if let Some(w) = self.words.take_preselect() {
            preselect(w, s, &self.words, &mut self.repeated, &mut ctx);
        }
        for w in self.repeated.drain(..) {
            s.out
                .push((w.span.start, Stmt::new(leftover::keep(&w, &ctx), w.span)));
        }
        s.out.drain_sorted_into(stmts);
    }
}

/// The second `T` of a block (`T1 T2 M6`): the next tool when the block
/// changes tools, otherwise a repeated word (E0205), kept.
fn preselect(
    w: WordSyntax,
    s: &mut Sorted<'_>,
    words: &Words,
    repeated: &mut Vec<WordSyntax>,
    ctx: &mut Ctx<'_>,
) {
    let change = s
        .codes
        .iter()
        .any(|c| c.meaning == Some(Meaning::ToolChange));
    if change {
        let tool = leftover::tool_ref(&w, ctx);
        s.out.push((
            w.span.start,
            Stmt::new(StmtKind::ToolPreselect(tool), w.span),
        ));
        return;
    }
    let first = words.get('T').map_or(w.span, |f| f.span);
    ctx.diags.push(
        crate::diag::Diagnostic::new(
            crate::diag::Code::RepeatedWord,
            "`T` is given twice in this block",
        )
        .primary(w.span, "repeated here")
        .secondary(first, "first given here")
        .help("a second T names the next tool only in the tool-change block (`T1 T2 M6`); keep one T here"),
    );
    repeated.push(w);
}

/// Splits items into statements, code words, dynamic codes and plain words.
fn sort_items<'s>(
    items: &mut Vec<Item>,
    s: &mut Sorted<'s>,
    mut direct: Option<(&mut Words, &mut Vec<WordSyntax>, &mut Vec<Diagnostic>)>,
    cache: &mut codes::Cache<'s>,
    spec: &'s DialectSpec,
    diags: &mut Vec<Diagnostic>,
) {
    // Words are read where they lie (copied once, into their set); the
    // statements are moved out after.
    for item in items.iter() {
        let Item::Word(w) = item else { continue };
        let letter = match w.address.as_bytes() {
            b"G" => 'G',
            b"M" => 'M',
            a => {
                match codes::pseudo_motion(a) {
                    Some(m) => s.codes.push(CodeWord {
                        letter: '\0',
                        code: crate::ir::Decimal::ZERO,
                        span: w.span,
                        meaning: Some(m),
                        def: None,
                    }),
                    None => match &mut direct {
                        Some((words, repeated, deferred)) => words.push(w, deferred, repeated),
                        None => s.plain.push(w.clone()),
                    },
                }
                continue;
            }
        };
        match w.value {
            Value::Number(d) => s
                .codes
                .push(codes::resolve(letter, d, w.span, cache, spec, diags)),
            Value::Expr(e) => s.dynamic.push((letter, e, w.span)),
        }
    }
    if items.iter().any(|i| matches!(i, Item::Stmt(_))) {
        for item in items.drain(..) {
            if let Item::Stmt(st) = item {
                s.out.push((st.span.start, st));
            }
        }
    }
    items.clear();
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

fn lower_codes(codes: &[CodeWord<'_>], words: &mut Words, out: &mut Placement, ctx: &mut Ctx<'_>) {
    // In priority order, then source order (a stable sort, without a buffer).
    let order = (0..3).flat_map(|p| codes.iter().filter(move |cw| priority(cw) == p));
    for cw in order {
        words.begin();
        let kind = match cw.meaning {
            Some(m) => build::code_stmt(cw, m, words, ctx),
            None => build::aux(cw, words),
        };
        let span = words.taken_span().map_or(cw.span, |t| cw.span.to(t));
        out.push((cw.span.start, Stmt::new(kind, span)));
    }
}

/// Everything after the codes: moves, standalone words, dynamic codes, and
/// the words nobody took.
fn finish(s: &mut Sorted<'_>, words: &mut Words, ctx: &mut Ctx<'_>) {
    let cancel = s
        .codes
        .iter()
        .find(|c| c.meaning == Some(Meaning::CycleCancel))
        .map(|c| c.span);
    let has_motion = s.codes.iter().any(|c| c.is_motion());
    let mut implicit = false;
    match cancel {
        Some(span) if !has_motion => {
            leftover::reject_axes_after_cancel(span, words, &mut s.out, ctx)
        }
        _ => {
            let m = leftover::implicit_motion(words, ctx);
            implicit = m.is_some();
            s.out.extend(m);
        }
    }
    leftover::standalone(words, &mut s.out, ctx);
    let mut dynamic_words: Vec<Word> = Vec::new();
    let has_dynamic = !s.dynamic.is_empty();
    // Letters a code of the block declares in `uses` (M19 R Q P) are kept
    // for the interpreter even when the statement has no field for them.
    let declared: Vec<char> = s
        .codes
        .iter()
        .filter_map(|c| c.def)
        .flat_map(|d| d.uses.iter().copied())
        .collect();
    let free = leftover::Free {
        dynamic: has_dynamic.then_some(&mut dynamic_words),
        implicit,
        declared: &declared,
    };
    leftover::unused(words, free, &mut s.out, ctx);
    for (i, (letter, value, span)) in s.dynamic.iter().enumerate() {
        let words = if i == 0 {
            std::mem::take(&mut dynamic_words)
        } else {
            Vec::new()
        };
        s.out.push((
            span.start,
            Stmt::new(
                StmtKind::DynamicCode {
                    letter: *letter,
                    value: *value,
                    words,
                },
                *span,
            ),
        ));
    }
}
