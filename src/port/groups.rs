//! Codes that share a block in the source but a modal group in the target:
//! Fanuc puts `G80` in its own group (09), so `G0 G90 G80` is one block;
//! LinuxCNC counts `G80` in the motion group, where two codes in one block
//! are an error. The cancel moves to a block of its own just before, which
//! runs in the same order (a cycle cancel comes before motion).

use super::follow_block;
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::{MotionKind, Program, StmtKind};

fn group_of(to: &DialectSpec, kind: &StmtKind) -> Option<String> {
    let meaning = match kind {
        StmtKind::CycleCancel => Meaning::CycleCancel,
        StmtKind::Motion(m) if m.kind != MotionKind::Implicit => Meaning::Motion(m.kind),
        _ => return None,
    };
    let code = to.code_for(meaning)?;
    let exclusive = to.group(&code.group).is_some_and(|g| g.exclusive);
    exclusive.then(|| code.group.clone())
}

pub fn run(p: &mut Program, to: &DialectSpec) {
    let blocks = std::mem::take(&mut p.blocks);
    for mut b in blocks {
        let cancel_group = b
            .stmts
            .iter()
            .find(|s| matches!(s.kind, StmtKind::CycleCancel))
            .and_then(|s| group_of(to, &s.kind));
        let clash = cancel_group.is_some_and(|g| {
            b.stmts.iter().any(|s| {
                !matches!(s.kind, StmtKind::CycleCancel)
                    && group_of(to, &s.kind).as_ref() == Some(&g)
            })
        });
        if clash {
            let i = b
                .stmts
                .iter()
                .position(|s| matches!(s.kind, StmtKind::CycleCancel));
            if let Some(i) = i {
                let cancel = b.stmts.remove(i);
                p.blocks.push(follow_block(&b, vec![cancel]));
            }
        }
        p.blocks.push(b);
    }
}
