//! Writer tests: hand-built programs written in each dialect (snapshots),
//! and the constructs a target cannot express (asserted diagnostics).

pub mod builder;
pub mod programs;
pub mod specs;

use super::write_program;
use crate::diag::Code;
use crate::ir::*;
use builder::*;
use StmtKind as K;

fn written(b: &Builder, spec: &crate::dialect::DialectSpec) -> String {
    match write_program(&b.p, spec) {
        Ok(s) => s,
        Err(ds) => panic!("unexpected diagnostics: {ds:#?}"),
    }
}

fn codes_of(b: &Builder, spec: &crate::dialect::DialectSpec) -> Vec<(Code, crate::span::Span)> {
    let ds = write_program(&b.p, spec).expect_err("expected diagnostics");
    ds.iter().map(|d| (d.code, d.span().unwrap())).collect()
}

#[test]
fn fanuc_program() {
    let b = programs::fanuc();
    insta::assert_snapshot!(written(&b, &specs::fanuc()));
}

#[test]
fn haas_program() {
    let b = programs::haas();
    insta::assert_snapshot!(written(&b, &specs::haas()));
}

#[test]
fn linuxcnc_program() {
    let b = programs::linuxcnc();
    insta::assert_snapshot!(written(&b, &specs::linuxcnc()));
}

#[test]
fn siemens_program() {
    let b = programs::siemens();
    insta::assert_snapshot!(written(&b, &specs::siemens()));
}

#[test]
fn writing_is_deterministic() {
    let b = programs::siemens();
    assert_eq!(
        written(&b, &specs::siemens()),
        written(&b, &specs::siemens())
    );
}

#[test]
fn siemens_for_loop_into_fanuc_is_cannot_express() {
    let mut b = Builder::new("siemens840d");
    let from = b.num("1");
    let to = b.num("10");
    b.line(vec![K::For {
        var: Var::R(1),
        from,
        to,
    }]);
    b.line(vec![K::EndFor]);
    let got = codes_of(&b, &specs::fanuc());
    assert_eq!(
        got,
        vec![
            (Code::CannotExpress, b.stmt_span(0, 0)),
            (Code::CannotExpress, b.stmt_span(1, 0))
        ]
    );
}

#[test]
fn named_cycle_and_oword_sub_into_fanuc_are_errors_and_no_text() {
    let mut b = Builder::new("siemens840d");
    let a = b.num("10");
    let arg = Arg {
        value: Some(a),
        span: b.span(),
    };
    b.line(vec![K::CycleCall(CycleCall {
        name: "CYCLE81".into(),
        args: vec![arg],
        modal: true,
    })]);
    b.line(vec![K::SubStart {
        name: "100".into(),
        params: vec![],
        id: FlowId::OWord("100".into()),
    }]);
    b.line(vec![mv(MotionKind::Linear, &[('X', "1")])]);
    let got = codes_of(&b, &specs::fanuc());
    assert_eq!(
        got,
        vec![
            (Code::CannotExpress, b.stmt_span(0, 0)),
            (Code::CannotExpress, b.stmt_span(1, 0))
        ]
    );
}

#[test]
fn raw_text_only_into_its_own_dialect() {
    let mut b = Builder::new("fanuc");
    b.line(vec![K::Raw {
        dialect: "fanuc".into(),
        text: "G05.1 Q1".into(),
    }]);
    assert_eq!(written(&b, &specs::fanuc()), "G05.1 Q1\n");
    assert_eq!(
        codes_of(&b, &specs::haas()),
        vec![(Code::RawInForeignDialect, b.stmt_span(0, 0))]
    );
}

#[test]
fn dwell_converts_exactly_or_says_why_not() {
    let mut b = Builder::new("siemens840d");
    b.line(vec![K::Dwell {
        value: n("1.5"),
        unit: DwellUnit::Seconds,
    }]);
    // Fanuc has X in seconds: kept as seconds, with its decimal point.
    assert_eq!(written(&b, &specs::fanuc()), "G4 X1.5\n");
    let mut ms = Builder::new("fanuc");
    ms.line(vec![K::Dwell {
        value: n("250"),
        unit: DwellUnit::Milliseconds,
    }]);
    assert_eq!(written(&ms, &specs::fanuc()), "G4 P250\n");
    assert_eq!(written(&ms, &specs::linuxcnc()), "G4 P0.25\n");
    assert_eq!(written(&ms, &specs::siemens()), "G4 F0.25\n");
    let mut fine = Builder::new("linuxcnc");
    fine.line(vec![K::Dwell {
        value: n("0.0005"),
        unit: DwellUnit::Seconds,
    }]);
    let mut fanuc_ms_only = specs::fanuc();
    fanuc_ms_only
        .codes
        .iter_mut()
        .find(|c| c.meaning == crate::dialect::Meaning::Dwell)
        .unwrap()
        .dwell_units = vec![('P', DwellUnit::Milliseconds)];
    fanuc_ms_only.reindex();
    assert_eq!(
        codes_of(&fine, &fanuc_ms_only),
        vec![(Code::InexactNumber, fine.stmt_span(0, 0))]
    );
    let mut revs = Builder::new("siemens840d");
    revs.line(vec![K::Dwell {
        value: n("3"),
        unit: DwellUnit::Revolutions,
    }]);
    assert_eq!(written(&revs, &specs::siemens()), "G4 S3\n");
    assert_eq!(
        codes_of(&revs, &specs::fanuc()),
        vec![(Code::CannotExpress, revs.stmt_span(0, 0))]
    );
}

#[test]
fn lengths_beyond_the_targets_places_are_errors() {
    let mut b = Builder::new("siemens840d");
    b.line(vec![mv(
        MotionKind::Linear,
        &[('X', "1.23456"), ('Y', "-0.000")],
    )]);
    assert_eq!(written(&b, &specs::siemens()), "G1 X1.23456 Y0\n");
    assert_eq!(codes_of(&b, &specs::fanuc()).len(), 1);
}

#[test]
fn comments_follow_the_targets_comment_syntax() {
    let mut b = Builder::new("fanuc");
    b.line(vec![
        mv(MotionKind::Rapid, &[('X', "1")]),
        K::Comment {
            text: " FAST ".into(),
            style: CommentStyle::Paren,
        },
    ]);
    b.line(vec![K::Comment {
        text: "a(b)".into(),
        style: CommentStyle::Semicolon,
    }]);
    b.line(vec![
        K::Comment {
            text: "A".into(),
            style: CommentStyle::Paren,
        },
        mv(MotionKind::Linear, &[('X', "2")]),
        K::Comment {
            text: "B".into(),
            style: CommentStyle::Semicolon,
        },
    ]);
    assert_eq!(
        written(&b, &specs::siemens()),
        "G0 X1 ; FAST \n;a(b)\nG1 X2 ;A B\n"
    );
    assert_eq!(
        written(&b, &specs::linuxcnc()),
        "G0 X1 ( FAST )\n;a(b)\n(A) G1 X2 ;B\n"
    );
    // Fanuc has `( )` comments only: the parentheses are replaced, with a
    // warning, so that the text stays one comment (issue 14).
    assert_eq!(
        written(&b, &specs::fanuc()),
        "G0 X1. ( FAST )\n(a[b])\n(A) G1 X2. (B)\n"
    );
}

#[test]
fn expressions_keep_their_tree_with_few_brackets() {
    use BinaryOp::*;
    let mut b = Builder::new("fanuc");
    let v1 = b.var(Var::Numbered(1));
    let v2 = b.var(Var::Numbered(2));
    let one = b.num("1");
    let sum = b.bin(Add, v2, one);
    let diff = b.bin(Sub, v1, sum); // #1-[#2+1]
    let prod = b.bin(Mul, diff, v2); // [#1-[#2+1]]*#2
    b.line(vec![K::Assign {
        var: Var::Numbered(3),
        value: prod,
    }]);
    assert_eq!(written(&b, &specs::fanuc()), "#3=[[#1-[#2+1]]*#2]\n");
    let mut s = Builder::new("siemens840d");
    let r1 = s.var(Var::R(1));
    let five = s.num("5");
    let r2 = s.var(Var::R(2));
    let three = s.num("3");
    let gt = s.bin(Gt, r1, five);
    let lt = s.bin(Lt, r2, three);
    let and = s.bin(And, gt, lt);
    s.line(vec![K::Goto {
        target: JumpTarget::Label("L1".into()),
        dir: JumpDir::Forward,
        cond: Some(and),
    }]);
    assert_eq!(
        written(&s, &specs::siemens()),
        "IF (R1>5) AND (R2<3) GOTOF L1\n"
    );
}

/// One short program written into every dialect (a row of the matrix).
fn matrix_program() -> Builder {
    let mut b = Builder::new("fanuc");
    b.line(vec![K::Comment {
        text: "FACE".into(),
        style: CommentStyle::Paren,
    }]);
    b.numbered(
        10,
        vec![
            K::Units {
                unit: LengthUnit::Mm,
                with_feeds: false,
            },
            K::Distance(DimMode::Absolute),
            K::WorkOffset {
                index: 1,
                extended: None,
            },
        ],
    );
    b.numbered(
        20,
        vec![K::ToolSelect(ToolRef::Number(n("3"))), K::ToolChange],
    );
    b.numbered(
        30,
        vec![
            K::SpindleSpeed(n("2500")),
            K::Spindle(SpindleState::Cw),
            K::Coolant(Coolant::Flood),
        ],
    );
    b.numbered(
        40,
        vec![mv(
            MotionKind::Rapid,
            &[('X', "-5"), ('Y', "0"), ('Z', "2")],
        )],
    );
    b.numbered(
        50,
        vec![mv(MotionKind::Linear, &[('Z', "-0.5")]), K::Feed(n("300"))],
    );
    b.numbered(
        60,
        vec![StmtKind::Motion(Box::new(Motion {
            target: axes(&[('X', "0"), ('Y', "5")]),
            arc: ArcData {
                i: Some(c("5")),
                j: Some(c("0")),
                ..ArcData::default()
            },
            ..Motion::new(MotionKind::Arc(ArcDir::Ccw))
        }))],
    );
    b.numbered(
        70,
        vec![K::Dwell {
            value: n("0.5"),
            unit: DwellUnit::Seconds,
        }],
    );
    b.numbered(
        80,
        vec![
            K::Spindle(SpindleState::Stop),
            K::Coolant(Coolant::Off),
            K::Stop(StopKind::EndRewind),
        ],
    );
    b
}

#[test]
fn one_program_in_every_dialect() {
    let b = matrix_program();
    let mut out = String::new();
    for spec in [
        specs::fanuc(),
        specs::haas(),
        specs::linuxcnc(),
        specs::siemens(),
    ] {
        out.push_str(&format!("== {}\n{}", spec.id, written(&b, &spec)));
    }
    insta::assert_snapshot!(out);
}

#[test]
fn word_address_cycles_have_no_siemens_code() {
    let b = programs::haas();
    let ds = write_program(&b.p, &specs::siemens()).expect_err("cycles and M98 are not Siemens");
    assert!(ds.iter().all(|d| d.is_error()));
    let cycle_block =
        b.p.blocks
            .iter()
            .position(|bl| bl.stmts.iter().any(|s| matches!(s.kind, K::Cycle(_))))
            .unwrap();
    let cycle_stmt = b.p.blocks[cycle_block]
        .stmts
        .iter()
        .find(|s| matches!(s.kind, K::Cycle(_)))
        .unwrap();
    let hit = ds
        .iter()
        .find(|d| d.span() == Some(cycle_stmt.span))
        .expect("the cycle is reported");
    assert_eq!(hit.code, Code::CannotExpress);
    assert!(hit.message.contains("Siemens 840D"), "{}", hit.message);
}

#[test]
fn cycle_dwell_is_whole_ms_only_where_p_means_ms() {
    let mut b = Builder::new("linuxcnc");
    b.line(vec![K::Cycle(Box::new(CannedCycle {
        kind: CycleKind::DrillDwell,
        target: axes(&[('Z', "-1")]),
        r: Some(n("1")),
        q: None,
        p: Some(n("0.5")),
        repeat: None,
        i: None,
        j: None,
        k: None,
    }))]);
    assert_eq!(written(&b, &specs::linuxcnc()), "G82 Z-1 R1 P0.5\n");
    assert_eq!(
        codes_of(&b, &specs::fanuc()),
        vec![(Code::InexactNumber, b.stmt_span(0, 0))]
    );
}

#[test]
fn siemens_only_constructs_into_fanuc_each_name_their_statement() {
    let mut b = Builder::new("siemens840d");
    b.labelled("START", vec![]);
    b.line(vec![K::Goto {
        target: JumpTarget::Label("START".into()),
        dir: JumpDir::Backward,
        cond: None,
    }]);
    b.line(vec![K::Message(Some("HELLO".into()))]);
    b.line(vec![K::Call {
        kind: CallKind::Named,
        target: CallTarget::Name("POCKET".into()),
        args: CallArgs::None,
        repeat: None,
    }]);
    b.line(vec![K::Transform(Box::new(Transform::Frame {
        op: FrameOp::Rot,
        additive: false,
        axes: axes(&[('Z', "45")]),
        rpl: None,
    }))]);
    b.line(vec![K::ToolSelect(ToolRef::Name("DRILL".into()))]);
    let ds = write_program(&b.p, &specs::fanuc()).expect_err("none of these is Fanuc");
    assert!(ds.iter().all(|d| d.code == Code::CannotExpress));
    let label_span = b.p.blocks[0].label.as_ref().unwrap().span;
    let mut want = vec![label_span];
    want.extend((1..=5).map(|i| b.stmt_span(i, 0)));
    let got: Vec<_> = ds.iter().map(|d| d.span().unwrap()).collect();
    assert_eq!(got, want);
    assert!(ds.iter().all(|d| d.help.is_some()));
}

#[test]
fn siemens_program_start_forms() {
    let mut b = Builder::new("siemens840d");
    b.line(vec![K::ProgramStart {
        number: None,
        name: Some("SUB1_SPF".into()),
    }]);
    b.line(vec![K::ProgramStart {
        number: Some(1234),
        name: None,
    }]);
    assert_eq!(
        written(&b, &specs::siemens()),
        "%_N_SUB1_SPF\n%_N_O1234_MPF\n"
    );
}
