//! Tests of the structure checker on hand-built blocks, one per check.

use super::StructureChecker;
use crate::diag::{render, Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::*;
use crate::lower::test_support::{fanuc, linuxcnc, siemens};
use crate::source::SourceMap;
use crate::span::{Span, Spanned};

/// One line of a test program: its text, N number, label and statements.
struct L(
    &'static str,
    Option<u32>,
    Option<&'static str>,
    Vec<StmtKind>,
);

fn l(text: &'static str, kinds: Vec<StmtKind>) -> L {
    L(text, None, None, kinds)
}

fn n(text: &'static str, number: u32, kinds: Vec<StmtKind>) -> L {
    L(text, Some(number), None, kinds)
}

fn label(text: &'static str, name: &'static str, kinds: Vec<StmtKind>) -> L {
    L(text, None, Some(name), kinds)
}

fn run(spec: &DialectSpec, lines: Vec<L>) -> (Vec<Code>, String) {
    let text: String = lines.iter().map(|l| format!("{}\n", l.0)).collect();
    let mut map = SourceMap::new();
    let file = map.add("prog.nc", text);
    let exprs = Arena::new();
    let mut checker = StructureChecker::new(spec);
    let mut offset = 0;
    for (i, L(t, number, lab, kinds)) in lines.into_iter().enumerate() {
        let span = Span::new(file, offset, offset + t.len());
        offset += t.len() + 1;
        let block = Block {
            span,
            skip: None,
            number: number.map(|n| Spanned::new(n, span)),
            label: lab.map(|s| Box::new(Spanned::new(s.to_string(), span))),
            stmts: kinds.into_iter().map(|k| Stmt::new(k, span)).collect(),
        };
        checker.block(i, &block, &exprs);
    }
    let diags: Vec<Diagnostic> = checker.finish();
    (
        diags.iter().map(|d| d.code).collect(),
        render::human(&diags, &map, false),
    )
}

fn cond() -> ExprId {
    Arena::<Expr>::new().alloc(Expr {
        kind: ExprKind::Bool(true),
        span: Span::default(),
    })
}

fn ow(s: &str) -> FlowId {
    FlowId::OWord(s.into())
}

fn goto(n: i64) -> StmtKind {
    StmtKind::Goto {
        target: JumpTarget::Sequence(Value::Number(Decimal::from_int(n))),
        dir: JumpDir::Either,
        cond: None,
    }
}

fn goto_label(name: &str, dir: JumpDir) -> StmtKind {
    StmtKind::Goto {
        target: JumpTarget::Label(name.into()),
        dir,
        cond: None,
    }
}

const M30: StmtKind = StmtKind::Stop(StopKind::EndRewind);

#[test]
fn fanuc_do_end_pairs() {
    let ok = vec![
        l(
            "WHILE [1] DO1",
            vec![StmtKind::While {
                cond: cond(),
                id: FlowId::Do(1),
            }],
        ),
        l("DO2", vec![StmtKind::Do { id: FlowId::Do(2) }]),
        l("END2", vec![StmtKind::EndWhile { id: FlowId::Do(2) }]),
        l("END1", vec![StmtKind::EndWhile { id: FlowId::Do(1) }]),
    ];
    assert_eq!(run(&fanuc(), ok).0, vec![]);
    let bad = vec![
        l(
            "WHILE [1] DO1",
            vec![StmtKind::While {
                cond: cond(),
                id: FlowId::Do(1),
            }],
        ),
        l("END2", vec![StmtKind::EndWhile { id: FlowId::Do(2) }]),
    ];
    let (codes, text) = run(&fanuc(), bad);
    assert_eq!(codes, vec![Code::MismatchedEnd]);
    insta::assert_snapshot!(text);
}

#[test]
fn unclosed_and_unopened() {
    let lines = vec![
        l(
            "o100 if [1]",
            vec![StmtKind::If {
                cond: cond(),
                id: ow("100"),
            }],
        ),
        l("o100 else", vec![StmtKind::Else { id: ow("100") }]),
        l("o100 endif", vec![StmtKind::EndIf { id: ow("100") }]),
        l("o200 endwhile", vec![StmtKind::EndWhile { id: ow("200") }]),
        l(
            "o300 sub",
            vec![StmtKind::SubStart {
                name: "300".into(),
                params: vec![],
                id: ow("300"),
            }],
        ),
    ];
    let (codes, text) = run(&fanuc(), lines);
    assert_eq!(codes, vec![Code::UnbalancedBlock, Code::UnbalancedBlock]);
    insta::assert_snapshot!(text);
}

#[test]
fn o_word_mismatch_and_do_while() {
    let lines = vec![
        l(
            "o100 if [1]",
            vec![StmtKind::If {
                cond: cond(),
                id: ow("100"),
            }],
        ),
        l("o101 endwhile", vec![StmtKind::EndWhile { id: ow("101") }]),
        l("o100 endif", vec![StmtKind::EndIf { id: ow("100") }]),
        l("o102 do", vec![StmtKind::Do { id: ow("102") }]),
        l(
            "o102 while [1]",
            vec![StmtKind::While {
                cond: cond(),
                id: ow("102"),
            }],
        ),
        l("M2", vec![StmtKind::Stop(StopKind::End)]),
    ];
    let (codes, text) = run(&linuxcnc(), lines);
    assert_eq!(codes, vec![Code::MismatchedEnd], "the while closes the do");
    insta::assert_snapshot!(text);
}

#[test]
fn siemens_nesting() {
    let lines = vec![
        l(
            "FOR R1=1 TO 3",
            vec![StmtKind::For {
                var: Var::R(1),
                from: cond(),
                to: cond(),
            }],
        ),
        l(
            "IF R1>1",
            vec![StmtKind::If {
                cond: cond(),
                id: FlowId::Nested,
            }],
        ),
        l("ENDFOR", vec![StmtKind::EndFor]),
        l("ENDFOR", vec![StmtKind::EndFor]),
        l("REPEAT", vec![StmtKind::RepeatUntil]),
        l("UNTIL R1>3", vec![StmtKind::Until { cond: cond() }]),
    ];
    let (codes, _) = run(&siemens(), lines);
    assert_eq!(codes, vec![Code::MismatchedEnd, Code::UnbalancedBlock]);
}

#[test]
fn sequence_jumps() {
    let lines = vec![
        l(
            "O1000",
            vec![StmtKind::ProgramStart {
                number: Some(1000),
                name: None,
            }],
        ),
        n("N10 #1=1", 10, vec![]),
        l("IF [#1 GT 2] GOTO 10", vec![goto(10)]),
        l("GOTO 30", vec![goto(30)]),
        l(
            "M97 P10",
            vec![StmtKind::Call {
                kind: CallKind::Local,
                target: CallTarget::Number(10),
                args: CallArgs::None,
                repeat: None,
            }],
        ),
        n("N30 M30", 30, vec![M30]),
        l(
            "O2000",
            vec![StmtKind::ProgramStart {
                number: Some(2000),
                name: None,
            }],
        ),
        l("GOTO 10", vec![goto(10)]),
        l(
            "M99 P40",
            vec![StmtKind::SubReturn {
                to: Some(Value::Number(Decimal::from_int(40))),
            }],
        ),
        l(
            "O1000",
            vec![StmtKind::ProgramStart {
                number: Some(1000),
                name: None,
            }],
        ),
    ];
    let (codes, text) = run(&fanuc(), lines);
    assert_eq!(
        codes,
        vec![
            Code::JumpTargetMissing,
            Code::JumpTargetMissing,
            Code::DuplicateLabel
        ]
    );
    insta::assert_snapshot!(text);
}

#[test]
fn label_directions() {
    let lines = vec![
        label("START: G0 X0", "START", vec![]),
        l("GOTOF START", vec![goto_label("START", JumpDir::Forward)]),
        l("GOTOB START", vec![goto_label("START", JumpDir::Backward)]),
        l("GOTOB LATER", vec![goto_label("LATER", JumpDir::Backward)]),
        l("GOTOF LATER", vec![goto_label("LATER", JumpDir::Forward)]),
        l(
            "GOTOC NOWHERE",
            vec![goto_label("NOWHERE", JumpDir::EitherNoAlarm)],
        ),
        label("LATER: M30", "LATER", vec![M30]),
        label("LATER: M30", "LATER", vec![]),
    ];
    let (codes, text) = run(&siemens(), lines);
    assert_eq!(
        codes,
        vec![
            Code::DuplicateLabel,
            Code::JumpTargetMissing,
            Code::JumpTargetMissing
        ]
    );
    insta::assert_snapshot!(text);
}

#[test]
fn program_end_required() {
    let body = || {
        l(
            "G0 X0",
            vec![StmtKind::Motion(Box::new(Motion::new(MotionKind::Rapid)))],
        )
    };
    let (codes, text) = run(&linuxcnc(), vec![body()]);
    assert_eq!(codes, vec![Code::NoProgramEnd]);
    insta::assert_snapshot!(text);
    assert_eq!(
        run(
            &linuxcnc(),
            vec![body(), l("M2", vec![StmtKind::Stop(StopKind::End)])]
        )
        .0,
        vec![]
    );
    assert_eq!(
        run(
            &linuxcnc(),
            vec![
                l("%", vec![StmtKind::Tape]),
                body(),
                l("%", vec![StmtKind::Tape])
            ]
        )
        .0,
        vec![]
    );
    assert_eq!(
        run(&fanuc(), vec![body()]).0,
        vec![],
        "Fanuc does not require it"
    );
    let subs_only = vec![
        l(
            "o<a> sub",
            vec![StmtKind::SubStart {
                name: "a".into(),
                params: vec![],
                id: ow("<a>"),
            }],
        ),
        body(),
        l(
            "o<a> endsub",
            vec![StmtKind::SubEnd {
                id: ow("<a>"),
                value: None,
            }],
        ),
    ];
    assert_eq!(run(&linuxcnc(), subs_only).0, vec![]);
}

#[test]
fn misplaced_statements() {
    let lines = vec![
        l(
            "o100 return",
            vec![StmtKind::Return {
                id: ow("100"),
                value: None,
            }],
        ),
        l(
            "o101 while [1]",
            vec![StmtKind::While {
                cond: cond(),
                id: ow("101"),
            }],
        ),
        l("o101 break", vec![StmtKind::Break { id: ow("101") }]),
        l("o102 continue", vec![StmtKind::Continue { id: ow("102") }]),
        l("o101 endwhile", vec![StmtKind::EndWhile { id: ow("101") }]),
        l("M2", vec![StmtKind::Stop(StopKind::End)]),
    ];
    let (codes, text) = run(&linuxcnc(), lines);
    assert_eq!(
        codes,
        vec![Code::ControlOutsideSub, Code::ControlOutsideSub]
    );
    insta::assert_snapshot!(text);
    let proc = vec![
        l(
            "PROC P1",
            vec![StmtKind::SubStart {
                name: "P1".into(),
                params: vec![],
                id: FlowId::Nested,
            }],
        ),
        l(
            "RET",
            vec![StmtKind::Return {
                id: FlowId::Nested,
                value: None,
            }],
        ),
    ];
    assert_eq!(run(&siemens(), proc).0, vec![]);
}
