//! The words no code took: an implicit move from axis words, `F` `S` `T`
//! and register words on their own, and the rest reported and kept.

use super::checks::{check_index, check_not_negative};
use super::motion::{motion, MOTION_WORDS};
use super::words::{single_letter, Words};
use super::Ctx;
use crate::diag::{Code, Diagnostic, Severity};
use crate::dialect::Capability;
use crate::ir::{Decimal, ExprKind, MotionKind, StmtKind, ToolRef, Value, Word, AXIS_LETTERS};
use crate::span::Span;
use crate::syntax::WordSyntax;

/// A statement with the position and span of what it was made from.
pub(super) type Placed = (u32, crate::ir::Stmt);

/// A line's statements as they are made, each with its position (where
/// its first word is); put in source order at the end.
#[derive(Default)]
pub(super) struct Placement {
    stmts: Vec<crate::ir::Stmt>,
    pos: Vec<u32>,
}

impl Placement {
    pub fn clear(&mut self) {
        self.stmts.clear();
        self.pos.clear();
    }

    #[inline]
    pub fn push(&mut self, (pos, stmt): Placed) {
        self.pos.push(pos);
        self.stmts.push(stmt);
    }

    pub fn extend(&mut self, placed: impl IntoIterator<Item = Placed>) {
        for p in placed {
            self.push(p);
        }
    }

    /// Appends the statements to `out` in source order (a stable sort by
    /// position). Usually already in order, and `out` empty: then the
    /// buffers are swapped and nothing moves.
    pub fn drain_sorted_into(&mut self, out: &mut Vec<crate::ir::Stmt>) {
        if self.pos.is_sorted() {
            if out.is_empty() {
                std::mem::swap(out, &mut self.stmts);
            } else {
                out.append(&mut self.stmts);
            }
            self.pos.clear();
            return;
        }
        let mut placed: Vec<Placed> = self.pos.drain(..).zip(self.stmts.drain(..)).collect();
        placed.sort_by_key(|(pos, _)| *pos);
        out.extend(placed.into_iter().map(|(_, s)| s));
    }
}

fn place(kind: StmtKind, span: Span) -> Placed {
    (span.start, crate::ir::Stmt::new(kind, span))
}

/// Whether free words make an implicit move (a lone `R` does not).
fn has_motion_words(words: &Words) -> bool {
    if !words.any_free() {
        return false;
    }
    words.has_free_axes() || MOTION_WORDS.iter().any(|a| *a != "R" && words.has_free(*a))
}

/// Axis words in a block that cancels cycles and has no move (E0209).
pub(super) fn reject_axes_after_cancel(
    cancel: Span,
    words: &mut Words,
    out: &mut Placement,
    ctx: &mut Ctx<'_>,
) {
    for a in AXIS_LETTERS {
        let Some(w) = words.take(a) else { continue };
        ctx.diags.push(
            Diagnostic::new(
                Code::WordNotAllowed,
                format!(
                    "axis word `{}` in a block that cancels the cycle",
                    w.address
                ),
            )
            .primary(w.span, "nothing moves to this position")
            .secondary(cancel, "cycle cancelled here")
            .help("add a motion code (`G0`, `G1`) or move the axis word to the next block"),
        );
        out.push(place(StmtKind::Word(Word::new(a, w.value, w.span)), w.span));
    }
}

/// The implicit move made by free axis and arc words, if any.
pub(super) fn implicit_motion(words: &mut Words, ctx: &mut Ctx<'_>) -> Option<Placed> {
    if !has_motion_words(words) {
        return None;
    }
    words.begin();
    let m = motion(MotionKind::Implicit, &[], words, ctx);
    let span = words.taken_span()?;
    Some(place(StmtKind::Motion(m), span))
}

/// `F`, `S`, `T`, `D`, `H` standing alone.
pub(super) fn standalone(words: &mut Words, out: &mut Placement, ctx: &mut Ctx<'_>) {
    if !words.any_free() {
        return;
    }
    for addr in ["F", "S", "T", "D", "H"] {
        let Some(w) = words.take(addr) else { continue };
        let kind = match addr {
            "F" => {
                check_not_negative(&w.value, w.span, "feed rate", ctx.diags);
                StmtKind::Feed(w.value.clone())
            }
            "S" => {
                check_not_negative(&w.value, w.span, "spindle speed", ctx.diags);
                StmtKind::SpindleSpeed(w.value.clone())
            }
            "T" => StmtKind::ToolSelect(tool_ref(&w, ctx)),
            _ => register(&w, ctx),
        };
        out.push(place(kind, w.span));
    }
}

pub(super) fn tool_ref(w: &WordSyntax, ctx: &mut Ctx<'_>) -> ToolRef {
    if let Value::Expr(e) = &w.value {
        if let ExprKind::Str(s) = &ctx.exprs[*e].kind {
            return ToolRef::Name(s.clone());
        }
    }
    check_index(w, "tool number", None, ctx.diags);
    ToolRef::Number(w.value.clone())
}

/// `D`/`H` alone: a cutting edge where the spec gives the address that
/// role (Siemens `D1`), otherwise an offset register.
fn register(w: &WordSyntax, ctx: &mut Ctx<'_>) -> StmtKind {
    check_index(w, "offset number", None, ctx.diags);
    let letter = single_letter(&w.address).unwrap_or('D');
    let edge = ctx
        .spec
        .address(letter)
        .map(|a| a.role == "cutting-edge")
        .unwrap_or(false);
    if edge {
        StmtKind::CuttingEdge(w.value.clone())
    } else {
        StmtKind::OffsetRegister {
            letter,
            value: w.value.clone(),
        }
    }
}

/// A word a modal fixed cycle may take in a block without a code
/// (`X.48 L6` repeats the cycle): kept without a warning.
fn modal_cycle_word(w: &WordSyntax, ctx: &Ctx<'_>) -> bool {
    let letter = single_letter(&w.address);
    letter
        .map(|c| matches!(c, 'Q' | 'P') || c == ctx.spec.repeat_letter)
        .unwrap_or(false)
}

/// What the block offers the words nobody took.
pub(super) struct Free<'a> {
    /// The words of a dynamic code (`G[#1]`), if the block has one.
    pub dynamic: Option<&'a mut Vec<Word>>,
    /// The block moves in a modal cycle (`X.48 L6`).
    pub implicit: bool,
    /// Letters the block's codes declare in `uses` (kept silently).
    pub declared: &'a [char],
}

/// Every word still free: given to a dynamic code if the block has one,
/// kept silently if a code of the block declares it, otherwise reported
/// (E0209 or W0004) and kept.
pub(super) fn unused(words: &mut Words, free_of: Free<'_>, out: &mut Placement, ctx: &mut Ctx<'_>) {
    let free = words.take_free();
    if let Some(dynamic) = free_of.dynamic {
        dynamic.extend(free.iter().map(as_word));
        return;
    }
    for w in free {
        let declared = single_letter(&w.address)
            .is_some_and(|c| free_of.declared.contains(&c.to_ascii_uppercase()));
        if !declared && !(free_of.implicit && modal_cycle_word(&w, ctx)) {
            report_unused(&w, ctx);
        }
        out.push(place(keep(&w, ctx), w.span));
    }
}

fn report_unused(w: &WordSyntax, ctx: &mut Ctx<'_>) {
    let d = Diagnostic::new(
        Code::WordNotAllowed,
        format!("nothing in this block uses `{}`", w.address),
    )
    .help("remove the word, or add the code that uses it");
    let d = if ctx.spec.has(Capability::StrictWords) {
        d.primary(w.span, "unused word")
    } else {
        let d = Diagnostic {
            code: Code::SuspectWord,
            ..d
        };
        d.with_severity(Severity::Warning)
            .primary(w.span, "unused word, kept as written")
    };
    ctx.diags.push(d);
}

/// A word kept as written: one letter as a `Word`, a longer address as raw text.
pub(super) fn keep(w: &WordSyntax, ctx: &Ctx<'_>) -> StmtKind {
    match (single_letter(&w.address), &w.value) {
        (Some(_), _) | (None, Value::Expr(_)) => StmtKind::Word(as_word(w)),
        (None, Value::Number(d)) => StmtKind::Raw {
            dialect: ctx.spec.id.clone(),
            text: raw_text(w, *d),
        },
    }
}

fn raw_text(w: &WordSyntax, d: Decimal) -> String {
    if w.extended {
        format!("{}={}", w.address, d)
    } else {
        format!("{}{}", w.address, d)
    }
}

/// A word as a `Word`; a longer address keeps its first letter.
pub(super) fn as_word(w: &WordSyntax) -> Word {
    let letter = w.address.chars().next().unwrap_or('?');
    let suffix = w.address.chars().skip(1).collect();
    Word {
        letter,
        suffix,
        value: w.value.clone(),
        span: w.span,
    }
}
