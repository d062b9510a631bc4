//! Heidenhain program-section repeats (`LBL m` ... `CALL LBL m REP k`)
//! for a target of another family (see [`super::subprograms`]): a section
//! that holds only one `CALL LBL n` is that call with the repeat count
//! k + 1; with `loops` (LinuxCNC) any section is `o.. repeat [k+1]` ...
//! `o.. endrepeat`; without, another section is E0617.

use super::subprograms::refusal;
use crate::diag::Diagnostic;
use crate::ir::{CallKind, Decimal, Expr, ExprKind, FlowId, Program, Stmt, StmtKind, Value};

/// Section repeats: `LBL m` .. `CALL LBL m REP k`.
pub(super) fn repeats(p: &mut Program, loops: bool, diags: &mut Vec<Diagnostic>) {
    let mut j = 0;
    while j < p.blocks.len() {
        let found = p.blocks[j].stmts.iter().position(|s| {
            matches!(
                s.kind,
                StmtKind::SectionRepeat {
                    end: None,
                    single: false,
                    ..
                }
            )
        });
        let Some(k) = found else {
            j += 1;
            continue;
        };
        let s = p.blocks[j].stmts[k].clone();
        let StmtKind::SectionRepeat { start, count, .. } = &s.kind else {
            unreachable!("matched above")
        };
        let times = count
            .and_then(|c| match &p.exprs[c].kind {
                ExprKind::Number(d) => d.as_int(),
                _ => None,
            })
            .filter(|n| *n >= 0);
        let first = p.blocks[..j]
            .iter()
            .rposition(|b| b.label.as_ref().is_some_and(|l| l.node == *start));
        let (Some(times), Some(i)) = (times, first) else {
            diags.push(refusal(
                s.span,
                "a section repeat whose label or count is not known here".into(),
            ));
            j += 1;
            continue;
        };
        let inside: Vec<(usize, usize)> = (i..=j)
            .flat_map(|bi| (0..p.blocks[bi].stmts.len()).map(move |si| (bi, si)))
            .filter(|&(bi, si)| (bi, si) != (j, k))
            .collect();
        let only_call = match inside.as_slice() {
            [(bi, si)] => matches!(
                p.blocks[*bi].stmts[*si].kind,
                StmtKind::Call {
                    kind: CallKind::Label,
                    ..
                }
            ),
            _ => false,
        };
        if only_call && !loops {
            let (bi, si) = inside[0];
            p.blocks[i].label = None;
            if let StmtKind::Call { repeat, .. } = &mut p.blocks[bi].stmts[si].kind {
                *repeat = Some(Value::Number(Decimal::from_int(times + 1)));
            }
            p.blocks[j].stmts.remove(k);
            if p.blocks[j].stmts.is_empty() {
                p.blocks.remove(j);
            }
            continue;
        }
        if !loops {
            diags.push(refusal(
                s.span,
                "a program-section repeat other than around one subprogram call".into(),
            ));
            j += 1;
            continue;
        }
        let id = FlowId::OWord(format!("{}", 9000 + j));
        let n = p.exprs.alloc(Expr {
            kind: ExprKind::Number(Decimal::from_int(times + 1)),
            span: s.span,
        });
        let label = p.blocks[i].label.take().expect("found by its label");
        let open = Stmt::new(
            StmtKind::Repeat {
                count: n,
                id: id.clone(),
            },
            label.span,
        );
        p.blocks[i].stmts.insert(0, open);
        p.blocks[j].stmts[k] = Stmt::new(StmtKind::EndRepeat { id }, s.span);
        j += 1;
    }
}
