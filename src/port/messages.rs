//! Operator messages (Siemens `MSG("..")`, LinuxCNC `(MSG,..)`) for a
//! target that shows none without stopping (capability
//! `operator-messages`: Fanuc, Haas, Heidenhain). The text becomes a
//! comment, which those controls show in the program display as the
//! block runs, so the operator still reads it; the part is cut the same.
//! Clearing the message (`MSG()`) becomes a comment that says so. W0610
//! once, at the first message. A message that should stop the machine
//! was written with its own stop (`M0`), which ports as a stop.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Program, StmtKind};

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::OperatorMessages) {
        return;
    }
    let style = super::comment_style(to);
    let mut first = None;
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::Message(text) = &s.kind else {
            continue;
        };
        let text = match text {
            Some(t) => format!("MSG: {t}"),
            None => "MSG cleared".to_string(),
        };
        s.kind = StmtKind::Comment { text, style };
        first.get_or_insert(s.span);
    }
    if let Some(at) = first {
        diags.push(
            Diagnostic::new(
                Code::PortApproximate,
                format!("{} shows no operator message without stopping: messages are written as comments", to.name),
            )
            .primary(at, "the first message")
            .help("the control shows a comment as its block runs; add M0 where the operator must read it before the program goes on"),
        );
    }
}
