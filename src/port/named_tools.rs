//! Tools selected by name (Siemens `T="DRILL"`, Klartext
//! `TOOL CALL "DRILL"`) for a target that selects tools by number
//! (capability `tools-by-name` absent): each name becomes the number the
//! run gives it, so the port cuts with the tools the source's run used.
//! A name the tool table (`--tool-table`) lists takes that row's number;
//! without a table, names are numbered from 1001 up in the order they are
//! first written, as the interpreter numbers them (W0516). Each numbering
//! is reported (W0610): the machine's tool must sit at that number.
//! For a target whose tool table must list every tool (capability
//! `control-holds-tools` absent), the numbers no table gave are listed
//! at the program's head, `(T1001 - DRILL)`, the tool list
//! [`crate::interp::tool_header`] reads: the program says which tool
//! each number is, and reads back with them.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Block, CommentStyle, Decimal, Program, Stmt, StmtKind, ToolRef, Value};
use crate::span::Span;

/// First number given to a named tool the tool table does not list.
const FIRST_UNLISTED: i64 = 1001;

pub fn run(
    p: &mut Program,
    to: &DialectSpec,
    table: &[(String, i64)],
    diags: &mut Vec<Diagnostic>,
) {
    if to.has(Capability::ToolsByName) {
        return;
    }
    let mut given: Vec<(String, i64)> = Vec::new();
    let mut unlisted: Vec<(String, i64, Span)> = Vec::new();
    let mut next = FIRST_UNLISTED;
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::ToolSelect(ToolRef::Name(name)) = &s.kind else {
            continue;
        };
        let key = name.trim().to_ascii_uppercase();
        let number = match given.iter().find(|(k, _)| *k == key) {
            Some((_, n)) => *n,
            None => {
                let n = listed(table, &key).unwrap_or_else(|| {
                    unlisted.push((name.clone(), next, s.span));
                    next += 1;
                    next - 1
                });
                given.push((key, n));
                report(diags, name, n, s.span, table.is_empty());
                n
            }
        };
        s.kind = StmtKind::ToolSelect(ToolRef::Number(Value::Number(Decimal::from_int(number))));
    }
    if !to.has(Capability::ControlHoldsTools) {
        tool_list(p, &unlisted);
    }
}

/// The numbered tools listed after the program's start.
fn tool_list(p: &mut Program, tools: &[(String, i64, Span)]) {
    let Some((_, _, span)) = tools.first() else {
        return;
    };
    let stmts = tools
        .iter()
        .map(|(name, n, span)| {
            let text = crate::interp::tool_header::named_line(*n, name);
            Stmt::new(
                StmtKind::Comment {
                    text,
                    style: CommentStyle::Paren,
                },
                *span,
            )
        })
        .collect();
    let start = p
        .blocks
        .iter()
        .take_while(|b| {
            b.stmts
                .iter()
                .any(|s| matches!(s.kind, StmtKind::Tape | StmtKind::ProgramStart { .. }))
        })
        .count();
    let block = Block {
        span: *span,
        skip: None,
        number: None,
        label: None,
        stmts,
    };
    p.blocks.insert(start, block);
}

fn listed(table: &[(String, i64)], key: &str) -> Option<i64> {
    table
        .iter()
        .find(|(n, _)| n.trim().eq_ignore_ascii_case(key))
        .map(|(_, t)| *t)
}

fn report(diags: &mut Vec<Diagnostic>, name: &str, n: i64, span: Span, no_table: bool) {
    let why = if no_table {
        "no tool table gave its number"
    } else {
        "the tool table's row of that name"
    };
    diags.push(
        Diagnostic::new(
            Code::PortApproximate,
            format!("tool \"{}\" is written as T{n}: the target selects tools by number", name.trim()),
        )
        .primary(span, why)
        .help("load the tool at that number on the machine, or give `--tool-table` with a row named by its comment (`T5 P5 Z2.0 D2.48 ;NAME`) to choose the number"),
    );
}

#[cfg(test)]
mod tests {
    use super::*;

    fn program(names: &[&str]) -> Program {
        let mut p = Program::new(crate::span::FileId(0), "siemens840d");
        for n in names {
            p.blocks.push(crate::ir::Block {
                span: Span::default(),
                skip: None,
                number: None,
                label: None,
                stmts: vec![crate::ir::Stmt::new(
                    StmtKind::ToolSelect(ToolRef::Name(n.to_string())),
                    Span::default(),
                )],
            });
        }
        p
    }

    fn numbers(p: &Program) -> Vec<String> {
        p.blocks
            .iter()
            .map(|b| match &b.stmts[0].kind {
                StmtKind::ToolSelect(ToolRef::Number(Value::Number(d))) => d.to_string(),
                other => format!("{other:?}"),
            })
            .collect()
    }

    #[test]
    fn names_get_the_numbers_the_run_gives_them() {
        let fanuc = crate::dialect::builtin("fanuc").unwrap();
        let mut p = program(&["DRILL", "MILL", "drill"]);
        let mut d = Vec::new();
        run(&mut p, &fanuc, &[], &mut d);
        assert_eq!(numbers(&p), ["1001", "1002", "1001"]);
        assert_eq!(d.len(), 2, "one warning per name");
        let mut p = program(&["MILL"]);
        run(&mut p, &fanuc, &[("mill".into(), 7)], &mut Vec::new());
        assert_eq!(numbers(&p), ["7"]);
    }

    #[test]
    fn a_target_that_needs_every_tool_in_its_table_gets_the_list() {
        let lcnc = crate::dialect::builtin("linuxcnc").unwrap();
        let mut p = program(&["DRILL", "MILL", "drill"]);
        run(&mut p, &lcnc, &[("mill".into(), 7)], &mut Vec::new());
        let StmtKind::Comment { text, .. } = &p.blocks[0].stmts[0].kind else {
            panic!("no tool list: {:?}", p.blocks[0]);
        };
        assert_eq!(text, "T1001 - DRILL");
        assert_eq!(p.blocks[0].stmts.len(), 1, "a listed name needs no line");
        let fanuc = crate::dialect::builtin("fanuc").unwrap();
        let mut p = program(&["DRILL"]);
        run(&mut p, &fanuc, &[], &mut Vec::new());
        assert_eq!(
            p.blocks.len(),
            1,
            "a control that holds its tools needs no list"
        );
    }

    #[test]
    fn a_target_with_named_tools_keeps_the_name() {
        let tnc = crate::dialect::builtin("heidenhain").unwrap();
        let mut p = program(&["DRILL"]);
        run(&mut p, &tnc, &[], &mut Vec::new());
        assert!(matches!(
            p.blocks[0].stmts[0].kind,
            StmtKind::ToolSelect(ToolRef::Name(_))
        ));
    }
}
