//! Subprogram calls for a Klartext target: the TNC calls a subprogram by
//! label, `CALL LBL n`, and the subprogram is `LBL n` ... `LBL 0` after
//! the main program's end, in the same file.
//!
//! * `M98 P n` (any numbered program call) → `CALL LBL n`: the label keeps
//!   the program number [?: the label range of older controls may be
//!   smaller than the O-number range; TNC 640 takes 1..65535].
//! * A repeat count `L k` (k > 1): `CALL LBL m REP` repeats a program
//!   *section* (from `LBL m` up to the `CALL LBL m REP` block), it does not
//!   call anything (`reference/dialects.md` §Heidenhain); so the call gets
//!   a section around it, as a TNC programmer writes it: `LBL m`, `CALL
//!   LBL n`, `CALL LBL m REP k-1/k-1` (m a label the program does not use).
//!
//! * Haas `M97 P n` (a local subprogram at `N n` after `M30`) is the same
//!   `CALL LBL n`, the block `N n` its `LBL n`.
//! * Programs after the main one in the same file (`O1000` after `M30`)
//!   are its label subprograms.
//! * LinuxCNC o-word subroutines in the same file: [`super::osubs`].
//!
//! The called programs' text is added to the written program by
//! [`super::sub_text`] (the port of each, with `LBL n` before it).

use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Family};
use crate::ir::{
    Block, CallArgs, CallKind, CallTarget, Decimal, Expr, ExprKind, Program, Stmt, StmtKind, Value,
};
use crate::span::{Span, Spanned};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.family != Family::Klartext || from.family == Family::Klartext {
        return;
    }
    if from.has(crate::dialect::Capability::OWords) {
        super::osubs::move_subs(p, diags);
    }
    programs_as_labels(p);
    local_targets_as_labels(p);
    let mut used: Vec<u32> = called(p);
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for mut b in blocks {
        let mut cur = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::Call {
                    kind: CallKind::Subprogram | CallKind::Local,
                    target: CallTarget::Number(n),
                    args: CallArgs::None,
                    repeat,
                } => {
                    let times = match repeat.as_ref().map(Value::number) {
                        None => 1,
                        Some(Some(d)) if d.as_int().is_some_and(|k| k >= 0) => {
                            d.as_int().unwrap_or(1)
                        }
                        Some(_) => {
                            diags.push(
                                Diagnostic::new(
                                    Code::PortSubprogram,
                                    "a subprogram repeat count that is not a whole number known here",
                                )
                                .primary(span, "this call")
                                .help("write the repeat count L as a number"),
                            );
                            continue;
                        }
                    };
                    let call = label_call(n, span);
                    if times <= 1 {
                        if times == 1 {
                            cur.push(call);
                        }
                        continue;
                    }
                    let m = (1..).find(|m| !used.contains(m)).unwrap_or(1);
                    used.push(m);
                    flush(&mut out, &mut b, &mut cur);
                    let mut lb = crate::port::follow_block(&b, vec![call]);
                    lb.label = Some(Box::new(Spanned {
                        node: m.to_string(),
                        span,
                    }));
                    out.push(lb);
                    cur.push(section_repeat(p, m, times - 1, span));
                }
                StmtKind::Call {
                    kind: CallKind::OWord,
                    target,
                    args,
                    repeat: None,
                } => cur.extend(super::osubs::call(target, args, span, diags)),
                kind => cur.push(Stmt::new(kind, span)),
            }
        }
        b.stmts = cur;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            out.push(b);
        }
    }
    p.blocks = out;
}

/// A file that holds more programs after the main one's end (a Fanuc tape
/// `O3009 .. M30 O1000 .. M99 %`): each `O n` is the subprogram `LBL n`
/// (its `M99` is `LBL 0`); the closing `%` goes.
fn programs_as_labels(p: &mut Program) {
    let mut ended = false;
    for b in &mut p.blocks {
        if ended {
            let mut label = None;
            for s in std::mem::take(&mut b.stmts) {
                match s.kind {
                    StmtKind::ProgramStart {
                        number: Some(n),
                        name,
                    } => {
                        label = Some(Box::new(Spanned {
                            node: n.to_string(),
                            span: s.span,
                        }));
                        // The program's title stays as a comment.
                        if let Some(text) = name {
                            let style = crate::ir::CommentStyle::Semicolon;
                            b.stmts
                                .push(Stmt::new(StmtKind::Comment { text, style }, s.span));
                        }
                    }
                    StmtKind::Tape => {}
                    kind => b.stmts.push(Stmt::new(kind, s.span)),
                }
            }
            if label.is_some() && b.label.is_none() {
                b.label = label;
            }
        }
        ended |= b.stmts.iter().any(|s| {
            matches!(
                s.kind,
                StmtKind::Stop(crate::ir::StopKind::End | crate::ir::StopKind::EndRewind)
            )
        });
    }
}

/// Haas `M97 P n`: the block `N n` after the program's end starts the
/// subprogram `LBL n`.
fn local_targets_as_labels(p: &mut Program) {
    let targets: Vec<u32> = p
        .blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .filter_map(|s| match s.kind {
            StmtKind::Call {
                kind: CallKind::Local,
                target: CallTarget::Number(n),
                ..
            } => Some(n),
            _ => None,
        })
        .collect();
    let mut ended = false;
    for b in &mut p.blocks {
        if ended && b.label.is_none() {
            if let Some(n) = b.number.as_ref().filter(|n| targets.contains(&n.node)) {
                b.label = Some(Box::new(Spanned {
                    node: n.node.to_string(),
                    span: n.span,
                }));
            }
        }
        ended |= b.stmts.iter().any(|s| {
            matches!(
                s.kind,
                StmtKind::Stop(crate::ir::StopKind::End | crate::ir::StopKind::EndRewind)
            )
        });
    }
}

/// The numbered programs `p` calls, in order of first call, and the labels it has.
pub fn called(p: &Program) -> Vec<u32> {
    let mut out = Vec::new();
    for b in &p.blocks {
        if let Some(n) = b.label.as_ref().and_then(|l| l.node.parse().ok()) {
            out.push(n);
        }
        for s in &b.stmts {
            if let StmtKind::Call {
                kind: CallKind::Subprogram | CallKind::Label,
                target: CallTarget::Number(n),
                ..
            } = s.kind
            {
                if !out.contains(&n) {
                    out.push(n);
                }
            }
        }
    }
    out
}

/// The statements before a new labelled block go to a block of their own
/// (with `b`'s number and label).
fn flush(out: &mut Vec<Block>, b: &mut Block, cur: &mut Vec<Stmt>) {
    if !cur.is_empty() {
        let mut first = crate::port::follow_block(b, std::mem::take(cur));
        first.number = b.number.take();
        first.label = b.label.take();
        out.push(first);
    }
}

fn label_call(n: u32, span: Span) -> Stmt {
    Stmt::new(
        StmtKind::Call {
            kind: CallKind::Label,
            target: CallTarget::Number(n),
            args: CallArgs::None,
            repeat: None,
        },
        span,
    )
}

fn section_repeat(p: &mut Program, label: u32, more: i64, span: Span) -> Stmt {
    let count = p.exprs.alloc(Expr {
        kind: ExprKind::Number(Decimal::from_int(more)),
        span,
    });
    Stmt::new(
        StmtKind::SectionRepeat {
            start: label.to_string(),
            end: None,
            count: Some(count),
            single: false,
        },
        span,
    )
}
