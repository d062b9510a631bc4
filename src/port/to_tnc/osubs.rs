//! LinuxCNC o-word subroutines in the program's own file for a Klartext
//! target: `o100 sub` ... `o100 endsub` becomes `LBL 100` ... `LBL 0`
//! after the main program's end, and `o100 call [20] [5]` sets the
//! arguments in Q parameters (`Q1 = 20`, `Q2 = 5`) before `CALL LBL 100`.
//! The subroutine's `#1`..`#30` (its arguments) are read as `Q1`..`Q30`.
//!
//! The TNC's Q parameters are global, where LinuxCNC's `#1`..`#30` are
//! local to each call: a main program that uses `#1`..`#30` itself, a
//! subroutine with `o.. return`, or a call of a subroutine with a
//! computed number cannot be carried this way (E0617).

use crate::diag::{Code, Diagnostic};
use crate::ir::{CallArgs, CallKind, CallTarget, ExprKind, Program, QBank, Stmt, StmtKind, Var};
use crate::span::Span;

/// The highest LinuxCNC subroutine argument (`#30`).
const ARGS: u32 = 30;

/// Moves the subroutines after the main program and reads their
/// arguments as Q parameters.
pub fn move_subs(p: &mut Program, diags: &mut Vec<Diagnostic>) {
    let mut ranges: Vec<(Span, Span)> = Vec::new();
    let mut first = None;
    let blocks = std::mem::take(&mut p.blocks);
    let (main, mut subs) = crate::port::osubs::split_subs(blocks, |x| {
        let s = x.stmt;
        match &s.kind {
            StmtKind::SubStart { name, .. } => {
                first = Some(x.block);
                *x.label = Some(Box::new(crate::span::Spanned {
                    node: name.clone(),
                    span: s.span,
                }));
            }
            StmtKind::SubEnd { value: None, .. } => {
                ranges.push((first.take().unwrap_or(x.block), x.block));
                s.kind = StmtKind::SubReturn { to: None };
            }
            StmtKind::Return { .. } | StmtKind::SubEnd { .. } => {
                diags.push(refusal(
                    s.span,
                    "a subroutine that returns early or a value",
                ));
            }
            _ => {}
        }
    });
    for b in &mut subs {
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::SubStart { .. }));
    }
    if subs.is_empty() {
        p.blocks = main;
        return;
    }
    p.blocks = main;
    args_as_q(p, &ranges, diags);
    p.blocks.extend(subs);
}

fn refusal(span: Span, what: &str) -> Diagnostic {
    Diagnostic::new(
        Code::PortSubprogram,
        format!("{what} has no Heidenhain label form"),
    )
    .primary(span, "here")
    .help("rewrite the subroutine without it, or expand it in the source")
}

/// `#1`..`#30` inside the subroutines (by their text) as `Q1`..`Q30`.
fn args_as_q(p: &mut Program, ranges: &[(Span, Span)], diags: &mut Vec<Diagnostic>) {
    let inside = |sp: Span| {
        ranges
            .iter()
            .any(|(a, b)| sp.file == a.file && sp.start >= a.start && sp.end <= b.end)
    };
    let handles: Vec<_> = p.exprs.iter().map(|(h, _)| h).collect();
    for h in handles {
        let e = &mut p.exprs[h];
        let ExprKind::Var(Var::Numbered(n)) = e.kind else {
            continue;
        };
        if !(1..=ARGS).contains(&n) {
            continue;
        }
        if inside(e.span) {
            e.kind = ExprKind::Var(Var::Q(QBank::Q, n));
        } else {
            diags.push(refusal(
                e.span,
                "a main program's own #1..#30 next to subroutine arguments in Q1..Q30",
            ));
        }
    }
}

/// `o100 call [a] [b]`: `Q1 = a`, `Q2 = b` and `CALL LBL 100`.
pub fn call(
    target: CallTarget,
    args: CallArgs,
    span: Span,
    diags: &mut Vec<Diagnostic>,
) -> Vec<Stmt> {
    let mut out = Vec::new();
    if let CallArgs::Positional(list) = &args {
        for (i, a) in list.iter().enumerate() {
            let Some(value) = a else { continue };
            let n = i as u32 + 1;
            if n > ARGS {
                diags.push(refusal(span, "a call with more than 30 arguments"));
                break;
            }
            out.push(Stmt::new(
                StmtKind::Assign {
                    var: Var::Q(QBank::Q, n),
                    value: *value,
                },
                span,
            ));
        }
    }
    if matches!(target, CallTarget::Computed(_)) || matches!(args, CallArgs::Letters(_)) {
        diags.push(refusal(span, "a call of a computed subroutine"));
        return out;
    }
    out.push(Stmt::new(
        StmtKind::Call {
            kind: CallKind::Label,
            target,
            args: CallArgs::None,
            repeat: None,
        },
        span,
    ));
    out
}
