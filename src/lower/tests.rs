//! Tests of the lowering: one per mapping and per check, diagnostics as
//! rendered snapshots.

use super::lower_line;
use super::test_support::{fanuc, line, linuxcnc, siemens};
use crate::diag::{render, Code, Diagnostic, Severity};
use crate::dialect::DialectSpec;
use crate::ir::*;
use crate::source::SourceMap;

struct Out {
    block: Block,
    diags: Vec<Diagnostic>,
    rendered: String,
}

fn run(spec: &DialectSpec, text: &str) -> Out {
    let mut map = SourceMap::new();
    let file = map.add("test.nc", text);
    let mut exprs = Arena::new();
    let l = line(text, file, 0, &mut exprs);
    let mut diags = Vec::new();
    let block = lower_line(l, spec, &exprs, &mut diags);
    let rendered = render::human(&diags, &map, false);
    Out {
        block,
        diags,
        rendered,
    }
}

fn kinds(o: &Out) -> Vec<&StmtKind> {
    o.block.stmts.iter().map(|s| &s.kind).collect()
}

fn num(s: &str) -> Value {
    Value::Number(Decimal::parse(s).unwrap())
}

fn codes(o: &Out) -> Vec<Code> {
    o.diags.iter().map(|d| d.code).collect()
}

fn motion(o: &Out, i: usize) -> &Motion {
    match &o.block.stmts[i].kind {
        StmtKind::Motion(m) => m,
        k => panic!("not a motion: {k:?}"),
    }
}

#[test]
fn linear_move_with_feed_in_source_order() {
    let o = run(&fanuc(), "N10 G1 X10. Y2.5 F100");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    assert_eq!(o.block.number.as_ref().map(|n| n.node), Some(10));
    let m = motion(&o, 0);
    assert_eq!(m.kind, MotionKind::Linear);
    assert_eq!(m.target.x.as_ref().unwrap().value, num("10"));
    assert_eq!(m.target.y.as_ref().unwrap().value, num("2.5"));
    assert_eq!(kinds(&o)[1], &StmtKind::Feed(num("100")));
    assert_eq!(o.block.stmts[0].span.range(), 4..16);
}

#[test]
fn axis_words_alone_are_an_implicit_move() {
    let o = run(&fanuc(), "F50 X1. Y2.");
    assert_eq!(kinds(&o)[0], &StmtKind::Feed(num("50")));
    assert_eq!(motion(&o, 1).kind, MotionKind::Implicit);
    assert_eq!(o.block.stmts[1].span.range(), 4..11);
}

#[test]
fn lengths_without_point_are_increments_once_per_line() {
    let o = run(&fanuc(), "G1 X10 Y0 Z-25 F100");
    let m = motion(&o, 0);
    let x = m.target.x.as_ref().unwrap().value.number().unwrap();
    assert_eq!((x.mantissa, x.scale, x.point), (10, 3, true));
    assert_eq!(m.target.z.as_ref().unwrap().value, num("-0.025"));
    assert_eq!(
        kinds(&o)[1],
        &StmtKind::Feed(num("100")),
        "F is not a length"
    );
    assert_eq!(codes(&o), vec![Code::LengthWithoutPoint]);
    insta::assert_snapshot!(o.rendered);
    assert!(run(&linuxcnc(), "G1 X10").diags.is_empty());
}

#[test]
fn high_speed_code_words_are_switches_not_lengths() {
    let spec = crate::dialect::builtin::builtin("fanuc").unwrap();
    for line in ["G5.1 Q1", "G05 P10000", "G08 P1"] {
        let o = run(&spec, line);
        assert!(o.diags.is_empty(), "{line}: {:?}", codes(&o));
        let StmtKind::Aux { words, .. } = kinds(&o)[0] else {
            panic!("{line}: {:?}", kinds(&o));
        };
        let v = words[0].value.number().unwrap();
        assert!(!v.point && v.scale == 0, "{line}: {v:?}");
    }
}

#[test]
fn two_motion_codes() {
    let o = run(&fanuc(), "G0 G1 X1.");
    assert_eq!(codes(&o), vec![Code::TwoMotionCodes]);
    insta::assert_snapshot!(o.rendered);
    let o = run(&fanuc(), "G1 G81 X1. Z-1. R1.");
    assert_eq!(codes(&o), vec![Code::TwoMotionCodes]);
    assert!(
        run(&fanuc(), "G80 G0 Z10.").diags.is_empty(),
        "G80 is its own group in Fanuc"
    );
}

#[test]
fn two_codes_of_one_group() {
    let o = run(&fanuc(), "G90 G91 G92 G28 X0");
    assert_eq!(
        codes(&o),
        vec![Code::ModalGroupConflict, Code::ModalGroupConflict]
    );
    insta::assert_snapshot!(o.rendered);
    // rs274 accepts G80 beside a motion code of its group (checked with
    // rs274-canon): the motion code wins, the G80 is noted.
    assert_eq!(
        codes(&run(&linuxcnc(), "G80 G0 Z1")),
        vec![Code::CancelOverridden]
    );
    assert_eq!(
        codes(&run(&linuxcnc(), "G0 G80 G1 Z1")),
        vec![Code::TwoMotionCodes, Code::CancelOverridden]
    );
}

#[test]
fn unknown_codes() {
    let o = run(&fanuc(), "G7 M123");
    assert_eq!(codes(&o), vec![Code::UnknownGCode, Code::UnknownMCode]);
    assert_eq!(o.diags[1].severity, Severity::Warning);
    assert!(matches!(kinds(&o)[1], StmtKind::Aux { letter: 'M', .. }));
    insta::assert_snapshot!(o.rendered);
    let o = run(&linuxcnc(), "M123");
    assert_eq!(o.diags[0].severity, Severity::Error);
    assert!(matches!(kinds(&o)[0], StmtKind::Aux { letter: 'M', .. }));
}

#[test]
fn repeated_word_is_reported_and_kept() {
    let o = run(&fanuc(), "G1 X1. X2.");
    assert_eq!(codes(&o), vec![Code::RepeatedWord]);
    assert!(matches!(
        kinds(&o)[1],
        StmtKind::Word(Word { letter: 'X', .. })
    ));
    insta::assert_snapshot!(o.rendered);
    assert!(run(&fanuc(), "M3 M8").diags.is_empty(), "G and M repeat");
}

#[test]
fn missing_required_words() {
    let o = run(&fanuc(), "G83 X1. Z-5. R1.");
    assert_eq!(codes(&o), vec![Code::MissingWord]);
    insta::assert_snapshot!("missing_q", o.rendered);
    assert_eq!(codes(&run(&fanuc(), "G4")), vec![Code::MissingWord]);
    let o = run(&fanuc(), "G2 X1. Y1.");
    assert_eq!(codes(&o), vec![Code::MissingWord]);
    insta::assert_snapshot!("missing_arc", o.rendered);
    assert!(
        run(&fanuc(), "G2 I5.").diags.is_empty(),
        "full circle by centre"
    );
    assert!(run(&siemens(), "G2 X1 Y1 CR=5").diags.is_empty());
    assert_eq!(
        codes(&run(&siemens(), "CIP X1 Y1")),
        vec![Code::MissingWord]
    );
}

#[test]
fn radius_with_centre() {
    let o = run(&fanuc(), "G2 X1. R1. I1.");
    assert_eq!(codes(&o), vec![Code::MixedArcFormat]);
    insta::assert_snapshot!(o.rendered);
    assert!(
        run(&fanuc(), "G83 X1. Z-1. R1. Q1. I1.").diags.is_empty(),
        "cycles take R and I"
    );
}

#[test]
fn unused_words() {
    let o = run(&fanuc(), "G0 X1. L5");
    assert_eq!(codes(&o), vec![Code::SuspectWord]);
    assert_eq!(o.diags[0].severity, Severity::Warning);
    assert!(matches!(
        kinds(&o)[1],
        StmtKind::Word(Word { letter: 'L', .. })
    ));
    insta::assert_snapshot!("unused_lenient", o.rendered);
    let o = run(&linuxcnc(), "G0 X1 L5");
    assert_eq!(codes(&o), vec![Code::WordNotAllowed]);
    assert!(o.diags[0].is_error());
    let o = run(&fanuc(), "G80 X1. Y1.");
    assert_eq!(codes(&o), vec![Code::WordNotAllowed, Code::WordNotAllowed]);
    insta::assert_snapshot!("axes_after_g80", o.rendered);
}

#[test]
fn negative_values() {
    let o = run(&fanuc(), "G83 X0 Z-1. R1. Q-1. F-100 S-5");
    assert_eq!(
        codes(&o),
        vec![
            Code::NegativeValue,
            Code::NegativeValue,
            Code::NegativeValue
        ]
    );
    insta::assert_snapshot!(o.rendered);
    assert_eq!(codes(&run(&fanuc(), "G4 P-5")), vec![Code::NegativeValue]);
}

#[test]
fn invalid_values() {
    let o = run(&fanuc(), "M3.5 G10 L2 P12 X0");
    assert_eq!(codes(&run(&fanuc(), "T1.5")), vec![Code::InvalidValue]);
    assert_eq!(codes(&o), vec![Code::InvalidValue, Code::InvalidValue]);
    insta::assert_snapshot!(o.rendered);
}

#[test]
fn subprogram_calls_and_returns() {
    let o = run(&fanuc(), "M98 P1234 L3");
    let call = StmtKind::Call {
        kind: CallKind::Subprogram,
        target: CallTarget::Number(1234),
        args: CallArgs::None,
        repeat: Some(num("3")),
    };
    assert_eq!(kinds(&o), vec![&call]);
    let o = run(&fanuc(), "M98 P00031234");
    assert_eq!(kinds(&o), vec![&call], "packed count and program");
    let o = run(&fanuc(), "M98 P31234");
    assert!(matches!(
        kinds(&o)[0],
        StmtKind::Call {
            target: CallTarget::Number(31234),
            repeat: None,
            ..
        }
    ));
    let o = run(&fanuc(), "M98 P#146");
    assert!(matches!(
        kinds(&o)[0],
        StmtKind::Call {
            target: CallTarget::Computed(_),
            ..
        }
    ));
    assert_eq!(
        kinds(&run(&fanuc(), "M99 P10")),
        vec![&StmtKind::SubReturn {
            to: Some(num("10"))
        }]
    );
    let o = run(&fanuc(), "M97 P100");
    assert!(matches!(
        kinds(&o)[0],
        StmtKind::Call {
            kind: CallKind::Local,
            target: CallTarget::Number(100),
            ..
        }
    ));
    assert_eq!(codes(&run(&fanuc(), "M98")), vec![Code::MissingWord]);
}

#[test]
fn macro_call_takes_every_letter() {
    let o = run(&fanuc(), "G65 P9010 A1. X2. F3.");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    let StmtKind::Call {
        kind: CallKind::Macro,
        target: CallTarget::Number(9010),
        args: CallArgs::Letters(a),
        ..
    } = kinds(&o)[0]
    else {
        panic!("{:?}", kinds(&o))
    };
    let letters: Vec<char> = a.iter().map(|(c, _)| *c).collect();
    assert_eq!(letters, vec!['A', 'X', 'F']);
}

#[test]
fn cycle_words() {
    let o = run(&linuxcnc(), "G99 G83 X1 Y2 Z-5 R1 Q0.5 L3 F100");
    let StmtKind::Cycle(c) = kinds(&o)
        .into_iter()
        .find(|k| matches!(k, StmtKind::Cycle(_)))
        .unwrap()
    else {
        unreachable!()
    };
    assert_eq!(c.kind, CycleKind::Peck);
    assert_eq!(
        (c.r.clone(), c.q.clone(), c.repeat.clone()),
        (Some(num("1")), Some(num("0.5")), Some(num("3")))
    );
    assert_eq!(c.target.z.as_ref().unwrap().value, num("-5"));
    assert_eq!(
        codes(&o),
        vec![Code::UnknownGCode],
        "G99 is not in the LinuxCNC-like table"
    );
}

#[test]
fn modes_tools_and_registers() {
    let o = run(&fanuc(), "G90 G17 G21 G54 T1 M6 G43 H1 D2 M3 S1000 M8");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    assert_eq!(
        kinds(&o),
        vec![
            &StmtKind::Distance(DimMode::Absolute),
            &StmtKind::Plane(Plane::XY),
            &StmtKind::Units {
                unit: LengthUnit::Mm,
                with_feeds: false
            },
            &StmtKind::WorkOffset {
                index: 1,
                extended: None
            },
            &StmtKind::ToolSelect(ToolRef::Number(num("1"))),
            &StmtKind::ToolChange,
            &StmtKind::LengthComp {
                mode: LengthComp::Positive,
                register: Some(num("1")),
                axes: Box::new(Axes::default())
            },
            &StmtKind::OffsetRegister {
                letter: 'D',
                value: num("2")
            },
            &StmtKind::Spindle(SpindleState::Cw),
            &StmtKind::SpindleSpeed(num("1000")),
            &StmtKind::Coolant(Coolant::Flood),
        ]
    );
    assert_eq!(
        kinds(&run(&siemens(), "D1")),
        vec![&StmtKind::CuttingEdge(num("1"))]
    );
    let o = run(&fanuc(), "G54.1 P5 M19 R45.");
    assert_eq!(
        kinds(&o)[0],
        &StmtKind::WorkOffset {
            index: 1,
            extended: Some(num("5"))
        }
    );
    assert_eq!(
        kinds(&o)[1],
        &StmtKind::Spindle(SpindleState::Orient(Some(num("45."))))
    );
}

#[test]
fn dwell_units_come_from_the_spec() {
    let o = run(&fanuc(), "G4 P500");
    assert_eq!(
        kinds(&o),
        vec![&StmtKind::Dwell {
            value: num("500"),
            unit: DwellUnit::Milliseconds
        }]
    );
    let o = run(&fanuc(), "G4 X1.5");
    assert_eq!(
        kinds(&o),
        vec![&StmtKind::Dwell {
            value: num("1.5"),
            unit: DwellUnit::Seconds
        }]
    );
}

#[test]
fn non_modal_codes_take_the_axes() {
    let o = run(&fanuc(), "G91 G28 Z0");
    assert_eq!(kinds(&o).len(), 2, "no implicit move");
    assert!(
        matches!(kinds(&o)[1], StmtKind::RefReturn { index: 1, store: false, direct: false, axes } if axes.z.is_some())
    );
    let o = run(&fanuc(), "G10 L2 P1 X-100. Y0");
    let StmtKind::SetData { l, words } = kinds(&o)[0] else {
        panic!()
    };
    assert_eq!(l, &num("2"));
    assert_eq!(words.iter().map(|w| w.letter).collect::<String>(), "PXY");
    // F and S are not G10's: they stay the block's (rs274 sets them).
    let o = run(&fanuc(), "F200 S1000 G10 L1 P1 R1");
    let Some(StmtKind::SetData { words, .. }) = kinds(&o)
        .into_iter()
        .find(|k| matches!(k, StmtKind::SetData { .. }))
    else {
        panic!("{:?}", kinds(&o))
    };
    assert_eq!(words.iter().map(|w| w.letter).collect::<String>(), "PR");
    assert!(
        kinds(&o).iter().any(|k| matches!(k, StmtKind::Feed(_))),
        "{:?}",
        kinds(&o)
    );
    let o = run(&fanuc(), "G68 X1. Y2. R45.");
    assert!(
        matches!(kinds(&o)[0], StmtKind::Transform(t) if matches!(**t, Transform::RotateOn { angle: Some(_), .. }))
    );
}

#[test]
fn siemens_arc_words() {
    let o = run(&siemens(), "G2 X10 Y5 CR=5 CHF=1");
    let m = motion(&o, 0);
    assert_eq!(m.arc.radius, Some(num("5")));
    assert_eq!(m.corner, Some((CornerKind::Chamfer, num("1"))));
    let o = run(&siemens(), "CIP X1 Y1 I1=0.5 J1=2");
    let m = motion(&o, 0);
    assert_eq!(m.kind, MotionKind::ArcThrough);
    assert_eq!(
        m.arc.mid.as_ref().unwrap().y.as_ref().unwrap().value,
        num("2")
    );
    assert!(o.diags.is_empty(), "{}", o.rendered);
}

#[test]
fn dynamic_code_keeps_its_words() {
    let o = run(&fanuc(), "G#143 X1. Q2.");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    assert!(
        matches!(kinds(&o)[0], StmtKind::DynamicCode { letter: 'G', words, .. } if words.len() == 1)
    );
    assert_eq!(motion(&o, 1).kind, MotionKind::Implicit);
}

#[test]
fn statements_from_the_front_end_stay_in_place() {
    let mut map = SourceMap::new();
    let file = map.add("t.nc", "G0 X1. (hi) M8");
    let mut exprs = Arena::new();
    let mut l = line("G0 X1. M8", file, 0, &mut exprs);
    let comment = Stmt::new(
        StmtKind::Comment {
            text: "hi".into(),
            style: CommentStyle::Paren,
        },
        crate::span::Span::new(file, 7, 11),
    );
    let m8 = l.items.pop().unwrap();
    l.items.push(crate::syntax::Item::Stmt(comment));
    if let crate::syntax::Item::Word(mut w) = m8 {
        w.span = crate::span::Span::new(file, 12, 14);
        l.items.push(crate::syntax::Item::Word(w));
    }
    let block = lower_line(l, &fanuc(), &exprs, &mut Vec::new());
    let names: Vec<_> = block
        .stmts
        .iter()
        .map(|s| std::mem::discriminant(&s.kind))
        .collect();
    assert_eq!(
        names[1],
        std::mem::discriminant(&StmtKind::Comment {
            text: String::new(),
            style: CommentStyle::Paren
        })
    );
    assert_eq!(block.stmts[2].kind, StmtKind::Coolant(Coolant::Flood));
}

/// Splits `G01X10.Y-2` into words; `None` for text the helper cannot read.
fn crude_words(text: &str) -> Option<String> {
    let mut out = String::new();
    for (i, c) in text.trim().char_indices() {
        if c.is_ascii_alphabetic() {
            if i > 0 {
                out.push(' ');
            }
            out.push(c.to_ascii_uppercase());
        } else if c.is_ascii_digit() || c == '.' || c == '-' || c == '+' {
            out.push(c);
        } else if !c.is_whitespace() {
            return None;
        }
    }
    let ok = out
        .split(' ')
        .all(|w| w.len() > 1 && Decimal::parse(&w[1..]).is_ok() && !w.starts_with('O'));
    (ok && !out.is_empty()).then_some(out)
}

/// Every plain word line of the corpus lowers without panicking, and every
/// word ends up in a statement or a diagnostic: nothing is dropped.
#[test]
fn corpus_lines_lose_no_word() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    let Ok(dirs) = std::fs::read_dir(&root) else {
        println!("note: {} not found, corpus test skipped", root.display());
        return;
    };
    let mut lines = 0;
    for file in dirs
        .flatten()
        .flat_map(|d| std::fs::read_dir(d.path()).into_iter().flatten().flatten())
    {
        let Ok(text) = std::fs::read_to_string(file.path()) else {
            continue;
        };
        for l in text.lines().filter_map(crude_words) {
            let o = run(&fanuc(), &l);
            for w in l.split(' ').filter(|w| !w.starts_with('N')) {
                let start = l.find(w).unwrap() as u32;
                let covered = o
                    .block
                    .stmts
                    .iter()
                    .any(|s| s.span.start <= start && start < s.span.end)
                    || o.diags
                        .iter()
                        .flat_map(|d| &d.labels)
                        .any(|lab| lab.span.start == start);
                assert!(covered, "`{w}` of `{l}` was dropped");
            }
            lines += 1;
        }
    }
    println!("{lines} corpus lines lowered");
}

#[test]
fn modal_cycle_words_in_a_block_without_code_are_kept_quietly() {
    let o = run(&linuxcnc(), "X0.48 L6 Q1");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    assert!(matches!(
        kinds(&o)[1],
        StmtKind::Word(Word { letter: 'L', .. })
    ));
    assert_eq!(
        codes(&run(&linuxcnc(), "M3 L6")),
        vec![Code::WordNotAllowed],
        "no move: reported"
    );
}

#[test]
fn g41_1_d_is_a_diameter_and_m19_keeps_its_declared_words() {
    let spec = crate::dialect::builtin::builtin("linuxcnc").expect("linuxcnc");
    let o = run(&spec, "G41.1 D0.5");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    assert!(kinds(&o).iter().any(|k| matches!(
        k,
        StmtKind::RadiusComp {
            side: CompSide::Left,
            diameter: true,
            ..
        }
    )));
    let o = run(&spec, "G41 D1");
    assert!(kinds(&o).iter().any(|k| matches!(
        k,
        StmtKind::RadiusComp {
            side: CompSide::Left,
            diameter: false,
            ..
        }
    )));
    // M19 declares R Q P: Q and P stay in the block for the interpreter.
    let o = run(&spec, "M19 R90 Q2 P1");
    assert!(o.diags.is_empty(), "{}", o.rendered);
    let ks = kinds(&o);
    assert!(ks
        .iter()
        .any(|k| matches!(k, StmtKind::Word(Word { letter: 'Q', .. }))));
    assert!(ks
        .iter()
        .any(|k| matches!(k, StmtKind::Word(Word { letter: 'P', .. }))));
}
