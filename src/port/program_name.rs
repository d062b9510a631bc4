//! A program known only by name (`%_N_BRACKET_MPF`, `PROC NAME`'s file)
//! for a target that numbers its programs (capability
//! `numbered-programs`): a name that is a number (`1000`, `O1000`, as
//! cncc writes a Fanuc number for the 840D) becomes the number again;
//! any other name is kept as a comment and the number comes from the
//! file, as the source's name did.

use crate::dialect::{Capability, DialectSpec};
use crate::ir::{CommentStyle, Program, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec) {
    if !to.has(Capability::NumberedPrograms) {
        return;
    }
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let StmtKind::ProgramStart {
                number: None,
                name: Some(name),
            } = &s.kind
            else {
                continue;
            };
            let digits = name.strip_prefix(['O', 'o']).unwrap_or(name);
            s.kind = match digits.parse::<u32>() {
                Ok(n) if !digits.is_empty() && digits.len() <= 8 => StmtKind::ProgramStart {
                    number: Some(n),
                    name: None,
                },
                _ => StmtKind::Comment {
                    text: name.clone(),
                    style: CommentStyle::Paren,
                },
            };
        }
    }
}
