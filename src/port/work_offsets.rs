//! Work offsets past the target's numbered codes: Siemens `G515` (work
//! offset 15) for Fanuc is `G54.1 P9`, the extended code whose P1 is the
//! offset the spec's `first-index` names (Fanuc, Haas: 7); Fanuc
//! `G54.1 P9` for the 840D, which has no extended code, is `G515`, the
//! numbered code of offset 9 + 7 - 1 (the source's `first-index`). Nothing else changes: each control's
//! offset of that number is set on the machine, as for G54.

use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{Decimal, Program, StmtKind, Value};

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let first_index = |spec: &DialectSpec| {
        spec.code_for(Meaning::WorkOffsetExtended)
            .and_then(|c| c.first_index)
    };
    let (first, source_first) = (first_index(to), first_index(from));
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::WorkOffset { index, extended } = &s.kind else {
            continue;
        };
        s.kind = match (extended, first) {
            (None, Some(first)) if *index >= first && !numbered(to, *index) => {
                StmtKind::WorkOffset {
                    index: 1,
                    extended: Some(Value::Number(Decimal::from_int(
                        (*index - first + 1) as i64,
                    ))),
                }
            }
            (Some(Value::Number(d)), None) => {
                let index = source_first.zip(number(d)).map(|(f, p)| f + p - 1);
                let Some(n) = index.filter(|n| numbered(to, *n)) else {
                    continue;
                };
                StmtKind::WorkOffset {
                    index: n,
                    extended: None,
                }
            }
            _ => continue,
        };
    }
}

fn numbered(to: &DialectSpec, index: u32) -> bool {
    to.code_for(Meaning::WorkOffset(index)).is_some()
}

fn number(d: &Decimal) -> Option<u32> {
    let v = d.to_f64();
    (v.fract() == 0.0 && (1.0..=1000.0).contains(&v)).then_some(v as u32)
}
