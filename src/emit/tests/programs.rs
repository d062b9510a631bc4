//! One representative program per dialect, built in the IR.

use super::builder::*;
use crate::ir::*;
use StmtKind as K;

fn motion(kind: MotionKind, list: &[(char, &str)], f: impl FnOnce(&mut Motion)) -> StmtKind {
    let mut m = Motion {
        target: axes(list),
        ..Motion::new(kind)
    };
    f(&mut m);
    K::Motion(Box::new(m))
}

fn cycle(kind: CycleKind, list: &[(char, &str)], f: impl FnOnce(&mut CannedCycle)) -> StmtKind {
    let mut c = CannedCycle {
        kind,
        target: axes(list),
        r: None,
        q: None,
        p: None,
        repeat: None,
        i: None,
        j: None,
        k: None,
    };
    f(&mut c);
    K::Cycle(Box::new(c))
}

fn comment(t: &str) -> StmtKind {
    K::Comment {
        text: t.into(),
        style: CommentStyle::Paren,
    }
}

/// Modes, motion of every kind, canned cycles and subprogram calls shared
/// by the word-address dialects.
fn word_common(b: &mut Builder) {
    b.line(vec![K::Tape]);
    b.line(vec![
        K::ProgramStart {
            number: Some(1234),
            name: None,
        },
        comment("PLATE"),
    ]);
    b.numbered(
        10,
        vec![
            K::Units {
                unit: LengthUnit::Mm,
                with_feeds: false,
            },
            K::Plane(Plane::XY),
            K::Distance(DimMode::Absolute),
            K::FeedMode(FeedMode::PerMinute),
            K::RadiusComp {
                side: CompSide::Off,
                register: None,
                diameter: false,
            },
            K::LengthComp {
                mode: LengthComp::Cancel,
                register: None,
                axes: Box::new(Axes::default()),
            },
            K::CycleCancel,
        ],
    );
    b.numbered(
        20,
        vec![K::ToolSelect(ToolRef::Number(n("1"))), K::ToolChange],
    );
    b.numbered(
        30,
        vec![
            K::WorkOffset {
                index: 1,
                extended: None,
            },
            motion(MotionKind::Rapid, &[('X', "0"), ('Y', "0")], |_| {}),
            K::SpindleSpeed(n("1200")),
            K::Spindle(SpindleState::Cw),
        ],
    );
    b.numbered(
        40,
        vec![
            K::LengthComp {
                mode: LengthComp::Positive,
                register: Some(n("1")),
                axes: Box::new(axes(&[('Z', "50")])),
            },
            K::Coolant(Coolant::Flood),
        ],
    );
    let i = b.numbered(
        50,
        vec![
            motion(MotionKind::Linear, &[('Z', "-2")], |_| {}),
            K::Feed(n("100")),
        ],
    );
    b.skip(i, 0);
    let i = b.line(vec![
        K::RadiusComp {
            side: CompSide::Left,
            register: Some(n("11")),
            diameter: false,
        },
        motion(MotionKind::Linear, &[('X', "5.5")], |_| {}),
    ]);
    b.skip(i, 2);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Cw),
        &[('X', "10"), ('Y', "0")],
        |m| {
            m.arc.i = Some(c("2.5"));
            m.arc.j = Some(c("-0.125"));
        },
    )]);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Ccw),
        &[('X', "0"), ('Y', "0")],
        |m| m.arc.radius = Some(n("-5")),
    )]);
    b.line(vec![
        comment("HELIX"),
        motion(
            MotionKind::Arc(ArcDir::Cw),
            &[('X', "0"), ('Y', "0"), ('Z', "-4")],
            |m| m.arc.i = Some(c("5")),
        ),
    ]);
    b.line(vec![motion(
        MotionKind::Implicit,
        &[('X', "20"), ('A', "90")],
        |_| {},
    )]);
    b.line(vec![
        K::Plane(Plane::ZX),
        K::Distance(DimMode::Incremental),
        K::FeedMode(FeedMode::PerRevolution),
    ]);
    b.line(vec![
        K::Plane(Plane::YZ),
        K::Distance(DimMode::Absolute),
        K::Units {
            unit: LengthUnit::Inch,
            with_feeds: false,
        },
    ]);
    b.line(vec![
        motion(MotionKind::Linear, &[('X', "1.2345")], |_| {}),
        K::Feed(n("12.5")),
    ]);
    b.line(vec![
        K::Units {
            unit: LengthUnit::Mm,
            with_feeds: false,
        },
        K::Plane(Plane::XY),
    ]);
    b.line(vec![
        K::SpindleCss {
            on: true,
            max_rpm: None,
        },
        K::SpindleSpeed(n("200")),
    ]);
    b.line(vec![
        K::SpindleCss {
            on: false,
            max_rpm: None,
        },
        K::Spindle(SpindleState::Ccw),
    ]);
    b.line(vec![
        K::Spindle(SpindleState::Stop),
        K::Coolant(Coolant::Mist),
        K::Coolant(Coolant::Off),
    ]);
    b.line(vec![K::PathMode {
        mode: PathMode::ExactStop,
        words: vec![],
    }]);
    b.line(vec![K::PathMode {
        mode: PathMode::Continuous,
        words: vec![],
    }]);
    b.line(vec![
        K::RefReturn {
            index: 1,
            axes: Box::new(axes(&[('Z', "0")])),
            store: false,
            direct: false,
        },
        K::MachineCoords,
    ]);
    b.line(vec![K::CoordShift {
        kind: CoordShift::Set,
        axes: Box::new(axes(&[('X', "0"), ('Y', "0")])),
    }]);
    b.line(vec![K::CoordShift {
        kind: CoordShift::Local,
        axes: Box::new(axes(&[('X', "10")])),
    }]);
    let p = Word::new('P', n("1"), b.span());
    let x = Word::new('X', n("-100"), b.span());
    b.line(vec![K::SetData {
        l: n("2"),
        words: vec![p, x],
    }]);
    b.line(vec![K::Dwell {
        value: n("0.5"),
        unit: DwellUnit::Seconds,
    }]);
    b.line(vec![
        K::ReturnToInitial(true),
        cycle(
            CycleKind::Peck,
            &[('X', "10"), ('Y', "10"), ('Z', "-5")],
            |c| {
                c.r = Some(n("1"));
                c.q = Some(n("2"));
                c.repeat = Some(n("3"));
            },
        ),
        K::Feed(n("50")),
    ]);
    b.line(vec![
        K::ReturnToInitial(false),
        cycle(CycleKind::DrillDwell, &[('X', "20")], |c| {
            c.r = Some(n("1"));
            c.p = Some(n("500"));
            c.target.z = Some(c_("-3"));
        }),
    ]);
    b.line(vec![cycle(
        CycleKind::Tap,
        &[('X', "30"), ('Z', "-8")],
        |c| c.r = Some(n("2")),
    )]);
    b.line(vec![K::CycleCancel]);
    b.line(vec![K::Call {
        kind: CallKind::Subprogram,
        target: CallTarget::Number(1000),
        args: CallArgs::None,
        repeat: Some(n("2")),
    }]);
    b.line(vec![K::Aux {
        letter: 'M',
        code: d("130"),
        words: vec![],
    }]);
    b.line(vec![K::Stop(StopKind::Optional)]);
}

fn c_(s: &str) -> Coord {
    c(s)
}

/// Fanuc: the common part, Macro B, G65, transforms.
pub fn fanuc() -> Builder {
    use BinaryOp::*;
    let mut b = Builder::new("fanuc");
    word_common(&mut b);
    b.line(vec![K::Transform(Box::new(Transform::RotateOn {
        center: axes(&[('X', "0"), ('Y', "0")]),
        angle: Some(n("45")),
    }))]);
    b.line(vec![K::Transform(Box::new(Transform::RotateOff))]);
    b.line(vec![K::Transform(Box::new(Transform::ScaleOn {
        center: axes(&[('X', "0")]),
        factor: Some(n("2")),
        per_axis: vec![],
    }))]);
    b.line(vec![K::Transform(Box::new(Transform::ScaleOff))]);
    b.line(vec![
        K::Transform(Box::new(Transform::MirrorOn {
            axes: axes(&[('X', "0")]),
        })),
        K::Transform(Box::new(Transform::MirrorOff)),
    ]);
    b.line(vec![K::WorkOffset {
        index: 1,
        extended: Some(n("2")),
    }]);
    b.line(vec![cycle(
        CycleKind::FineBore,
        &[('X', "1"), ('Z', "-10")],
        |c| {
            c.r = Some(n("1"));
            c.q = Some(n("0.2"));
            c.p = Some(n("100"));
        },
    )]);
    // Macro B.
    let v2 = b.var(Var::Numbered(2));
    let one = b.num("1");
    let sum = b.bin(Add, v2, one);
    b.line(vec![K::Assign {
        var: Var::Numbered(1),
        value: sum,
    }]);
    let v1 = b.var(Var::Numbered(1));
    let sin = b.e(ExprKind::Call(Func::Sin, vec![v1]));
    let two = b.num("2");
    let prod = b.bin(Mul, sin, two);
    b.line(vec![K::Assign {
        var: Var::Numbered(100),
        value: prod,
    }]);
    let (a, c2) = (b.var(Var::Numbered(1)), b.var(Var::Numbered(2)));
    let at = b.e(ExprKind::AtanSlash(a, c2));
    b.line(vec![K::Assign {
        var: Var::Numbered(3),
        value: at,
    }]);
    let v2 = b.var(Var::Numbered(2));
    let ind = b.var(Var::Indirect(v2));
    b.line(vec![K::Assign {
        var: Var::Numbered(4),
        value: ind,
    }]);
    let (v1, ten) = (b.var(Var::Numbered(1)), b.num("10"));
    let gt = b.bin(Gt, v1, ten);
    b.line(vec![K::Goto {
        target: JumpTarget::Sequence(n("20")),
        dir: JumpDir::Either,
        cond: Some(gt),
    }]);
    let (v1, one, v2, three) = (
        b.var(Var::Numbered(1)),
        b.num("1"),
        b.var(Var::Numbered(2)),
        b.num("3"),
    );
    let (g, l) = (b.bin(Gt, v1, one), b.bin(Lt, v2, three));
    let and = b.bin(And, g, l);
    let five = b.num("1");
    let then = b.stmt(K::Assign {
        var: Var::Numbered(5),
        value: five,
    });
    b.line(vec![K::IfThen {
        cond: and,
        then: Box::new(then),
    }]);
    let (v1, ten) = (b.var(Var::Numbered(1)), b.num("10"));
    let lt = b.bin(Lt, v1, ten);
    b.line(vec![K::While {
        cond: lt,
        id: FlowId::Do(1),
    }]);
    let v1 = b.var(Var::Numbered(1));
    let neg = b.e(ExprKind::Unary(UnaryOp::Neg, v1));
    b.line(vec![motion(MotionKind::Linear, &[], |m| {
        m.target.x = Some(Coord {
            value: Value::Expr(neg),
            dim: None,
            span: Default::default(),
        })
    })]);
    let (v1, x) = (b.var(Var::Numbered(1)), b.num("0.5"));
    let s = b.bin(Add, v1, x);
    b.line(vec![motion(MotionKind::Implicit, &[], |m| {
        m.target.y = Some(Coord {
            value: Value::Expr(s),
            dim: None,
            span: Default::default(),
        })
    })]);
    b.line(vec![K::EndWhile { id: FlowId::Do(1) }]);
    let e146 = b.var(Var::Numbered(146));
    b.line(vec![K::Call {
        kind: CallKind::Subprogram,
        target: CallTarget::Computed(e146),
        args: CallArgs::None,
        repeat: None,
    }]);
    b.line(vec![K::Call {
        kind: CallKind::Macro,
        target: CallTarget::Number(9010),
        args: CallArgs::Letters(vec![('A', n("1.")), ('B', n("2")), ('S', n("100"))]),
        repeat: None,
    }]);
    b.line(vec![K::Call {
        kind: CallKind::ModalMacro,
        target: CallTarget::Number(9011),
        args: CallArgs::Letters(vec![('Z', n("-1"))]),
        repeat: None,
    }]);
    b.line(vec![K::ModalMacroCancel]);
    b.numbered(20, vec![K::SubReturn { to: Some(n("30")) }]);
    b.line(vec![K::Stop(StopKind::EndRewind)]);
    b.line(vec![K::Tape]);
    b
}

/// Haas: L repeats, M97, G154.
pub fn haas() -> Builder {
    let mut b = Builder::new("haas");
    word_common(&mut b);
    b.line(vec![K::WorkOffset {
        index: 1,
        extended: Some(n("12")),
    }]);
    b.line(vec![cycle(CycleKind::Peck, &[('Z', "-1")], |c| {
        c.r = Some(n("0.1"));
        c.i = Some(n("0.2"));
        c.j = Some(n("0.05"));
        c.k = Some(n("0.1"));
    })]);
    b.line(vec![K::Call {
        kind: CallKind::Local,
        target: CallTarget::Number(100),
        args: CallArgs::None,
        repeat: None,
    }]);
    b.line(vec![K::Stop(StopKind::EndRewind)]);
    b.numbered(100, vec![motion(MotionKind::Linear, &[('X', "1")], |_| {})]);
    b.line(vec![K::SubReturn { to: None }]);
    b.line(vec![K::Tape]);
    b
}

/// LinuxCNC: o-words, named parameters, polar words, messages, probing.
pub fn linuxcnc() -> Builder {
    use BinaryOp::*;
    let mut b = Builder::new("linuxcnc");
    word_common(&mut b);
    b.line(vec![K::Message(Some("Load the vise".into()))]);
    b.line(vec![K::Comment {
        text: " semicolon".into(),
        style: CommentStyle::Semicolon,
    }]);
    b.line(vec![motion(MotionKind::Linear, &[], |m| {
        m.polar_radius = Some(n("10"));
        m.polar_angle = Some(n("45"));
    })]);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Ccw),
        &[('X', "0"), ('Y', "0"), ('Z', "-1")],
        |m| {
            m.arc.i = Some(c("5"));
            m.arc.turns = Some(n("3"));
        },
    )]);
    b.line(vec![
        motion(
            MotionKind::Probe {
                toward: true,
                error: true,
            },
            &[('Z', "-10")],
            |_| {},
        ),
        K::Feed(n("25")),
    ]);
    b.line(vec![K::Spindle(SpindleState::Orient(Some(n("45"))))]);
    b.line(vec![K::Dwell {
        value: n("1500"),
        unit: DwellUnit::Milliseconds,
    }]);
    let id = FlowId::OWord("100".into());
    b.line(vec![K::SubStart {
        name: "100".into(),
        params: vec![],
        id: id.clone(),
    }]);
    let (p1, two) = (b.var(Var::Numbered(1)), b.num("2"));
    let pw = b.bin(Pow, p1, two);
    b.line(vec![K::Assign {
        var: Var::Named("r2".into()),
        value: pw,
    }]);
    let (r2, hundred) = (b.var(Var::Named("r2".into())), b.num("100"));
    let gt = b.bin(Gt, r2, hundred);
    b.line(vec![K::If {
        cond: gt,
        id: FlowId::OWord("101".into()),
    }]);
    let r2 = b.var(Var::Named("r2".into()));
    b.line(vec![K::Return {
        id: id.clone(),
        value: Some(r2),
    }]);
    let ex = b.e(ExprKind::Exists("_feed".into()));
    b.line(vec![K::ElseIf {
        cond: ex,
        id: FlowId::OWord("101".into()),
    }]);
    b.line(vec![K::Else {
        id: FlowId::OWord("101".into()),
    }]);
    b.line(vec![K::EndIf {
        id: FlowId::OWord("101".into()),
    }]);
    b.line(vec![K::EndIf {
        id: FlowId::OWord("101".into()),
    }]);
    let (i, three) = (b.var(Var::Named("i".into())), b.num("3"));
    let lt = b.bin(Lt, i, three);
    b.line(vec![K::While {
        cond: lt,
        id: FlowId::OWord("102".into()),
    }]);
    b.line(vec![
        K::Break {
            id: FlowId::OWord("102".into()),
        },
        K::Comment {
            text: "out".into(),
            style: CommentStyle::Semicolon,
        },
    ]);
    b.line(vec![K::EndWhile {
        id: FlowId::OWord("102".into()),
    }]);
    b.line(vec![K::Do {
        id: FlowId::OWord("103".into()),
    }]);
    b.line(vec![K::Continue {
        id: FlowId::OWord("103".into()),
    }]);
    let one = b.num("1");
    b.line(vec![K::DoWhile {
        cond: one,
        id: FlowId::OWord("103".into()),
    }]);
    let four = b.num("4");
    b.line(vec![K::Repeat {
        count: four,
        id: FlowId::OWord("104".into()),
    }]);
    b.line(vec![K::EndRepeat {
        id: FlowId::OWord("104".into()),
    }]);
    b.line(vec![K::SubEnd { id, value: None }]);
    let (a, z) = (b.num("1.5"), b.var(Var::Named("_z".into())));
    b.line(vec![K::Call {
        kind: CallKind::OWord,
        target: CallTarget::Number(100),
        args: CallArgs::Positional(vec![Some(a), Some(z)]),
        repeat: None,
    }]);
    b.line(vec![K::Call {
        kind: CallKind::OWord,
        target: CallTarget::Name("probe_hole".into()),
        args: CallArgs::None,
        repeat: None,
    }]);
    b.line(vec![K::Stop(StopKind::End)]);
    b
}

fn arg(b: &mut Builder, v: Option<&str>) -> Arg {
    let value = v.map(|s| b.num(s));
    Arg {
        value,
        span: b.span(),
    }
}

/// Siemens 840D: structured control, R parameters, DEF, frames, cycles.
pub fn siemens() -> Builder {
    use BinaryOp::*;
    let mut b = Builder::new("siemens840d");
    b.line(vec![K::ProgramStart {
        number: None,
        name: Some("PART1".into()),
    }]);
    b.line(vec![K::Comment {
        text: "$PATH=/_N_MPF_DIR".into(),
        style: CommentStyle::Semicolon,
    }]);
    let init = b.num("2.5");
    let (s1, s2, s3) = (b.span(), b.span(), b.span());
    b.line(vec![K::Declare {
        ty: VarType::Real,
        vars: vec![
            VarDecl {
                name: "A".into(),
                dims: vec![],
                dim_names: vec![],
                init: None,
                span: s1,
            },
            VarDecl {
                name: "B".into(),
                dims: vec![],
                dim_names: vec![],
                init: Some(init),
                span: s2,
            },
            VarDecl {
                name: "T".into(),
                dims: vec![3, 4],
                dim_names: vec![],
                init: None,
                span: s3,
            },
        ],
    }]);
    let s4 = b.span();
    b.line(vec![K::Declare {
        ty: VarType::String,
        vars: vec![VarDecl {
            name: "S".into(),
            dims: vec![32],
            dim_names: vec![],
            init: None,
            span: s4,
        }],
    }]);
    b.numbered(
        10,
        vec![
            K::Units {
                unit: LengthUnit::Mm,
                with_feeds: false,
            },
            K::Plane(Plane::XY),
            K::Distance(DimMode::Absolute),
            K::WorkOffset {
                index: 1,
                extended: None,
            },
            K::FeedMode(FeedMode::PerMinute),
        ],
    );
    b.numbered(
        20,
        vec![
            K::ToolSelect(ToolRef::Name("MILL10".into())),
            K::ToolChange,
            K::CuttingEdge(n("1")),
        ],
    );
    b.numbered(
        30,
        vec![
            K::SpindleSpeed(n("3000")),
            K::Spindle(SpindleState::Cw),
            K::Message(Some("ROUGHING".into())),
        ],
    );
    let (r5, r17) = (b.var(Var::R(5)), b.var(Var::R(17)));
    let cos = b.e(ExprKind::Call(Func::Cos, vec![r5]));
    let m = b.bin(Mul, r17, cos);
    b.line(vec![K::Assign {
        var: Var::R(4),
        value: m,
    }]);
    let (r1, five) = (b.var(Var::R(1)), b.num("5"));
    let add = b.bin(Add, r1, five);
    b.line(vec![motion(MotionKind::Rapid, &[('Y', "130")], |m| {
        m.target.x = Some(Coord {
            value: Value::Expr(add),
            dim: None,
            span: Default::default(),
        });
        m.target.z = Some(Coord {
            value: n("2"),
            dim: Some(DimMode::Incremental),
            span: Default::default(),
        });
    })]);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Cw),
        &[('X', "10"), ('Y', "0")],
        |m| m.arc.radius = Some(n("-5")),
    )]);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Ccw),
        &[('X', "0")],
        |m| {
            m.arc.i = Some(Coord {
                value: n("5"),
                dim: Some(DimMode::Absolute),
                span: Default::default(),
            });
            m.arc.angle = Some(n("90"));
        },
    )]);
    b.line(vec![motion(
        MotionKind::Arc(ArcDir::Cw),
        &[('X', "0"), ('Y', "0"), ('Z', "-6")],
        |m| {
            m.arc.i = Some(c("5"));
            m.arc.turns = Some(n("2"));
        },
    )]);
    b.line(vec![motion(
        MotionKind::ArcThrough,
        &[('X', "10"), ('Y', "10")],
        |m| m.arc.mid = Some(Box::new(axes(&[('X', "5"), ('Y', "8")]))),
    )]);
    b.line(vec![motion(
        MotionKind::ArcTangent,
        &[('X', "20"), ('Y', "0")],
        |_| {},
    )]);
    b.line(vec![motion(MotionKind::Linear, &[], |m| {
        m.polar_radius = Some(n("30"));
        m.polar_angle = Some(n("45"));
        m.corner = Some((CornerKind::Chamfer, n("1")));
    })]);
    b.line(vec![K::Transform(Box::new(Transform::Frame {
        op: FrameOp::Trans,
        additive: false,
        axes: axes(&[('X', "10"), ('Y', "5")]),
        rpl: None,
    }))]);
    b.line(vec![K::Transform(Box::new(Transform::Frame {
        op: FrameOp::Rot,
        additive: true,
        axes: Axes::default(),
        rpl: Some(n("45")),
    }))]);
    b.line(vec![K::Transform(Box::new(Transform::Frame {
        op: FrameOp::Mirror,
        additive: false,
        axes: axes(&[('X', "0")]),
        rpl: None,
    }))]);
    b.line(vec![K::Transform(Box::new(Transform::Frame {
        op: FrameOp::Trans,
        additive: false,
        axes: Axes::default(),
        rpl: None,
    }))]);
    b.line(vec![K::Dwell {
        value: n("2"),
        unit: DwellUnit::Seconds,
    }]);
    let args: Vec<Arg> = [Some("10"), Some("0"), Some("2"), Some("-5")]
        .iter()
        .map(|v| arg(&mut b, *v))
        .collect();
    b.line(vec![K::CycleCall(CycleCall {
        name: "CYCLE81".into(),
        args,
        modal: true,
    })]);
    b.line(vec![motion(
        MotionKind::Implicit,
        &[('X', "10"), ('Y', "10")],
        |_| {},
    )]);
    b.line(vec![K::ModalCallCancel]);
    let slots = [
        Some("10"),
        Some("0"),
        Some("5"),
        None,
        Some("20"),
        None,
        Some("4"),
    ];
    let args: Vec<Arg> = slots.iter().map(|v| arg(&mut b, *v)).collect();
    b.line(vec![K::CycleCall(CycleCall {
        name: "CYCLE83".into(),
        args,
        modal: false,
    })]);
    b.line(vec![K::Command {
        name: "SOFT".into(),
        args: None,
    }]);
    let r1 = b.var(Var::R(1));
    let one = b.num("1");
    let ten = b.num("10");
    b.line(vec![K::For {
        var: Var::R(1),
        from: one,
        to: ten,
    }]);
    b.line(vec![K::EndFor]);
    let _ = r1;
    let (r2, z) = (b.var(Var::R(2)), b.num("0"));
    let gt = b.bin(Gt, r2, z);
    b.line(vec![K::If {
        cond: gt,
        id: FlowId::Nested,
    }]);
    b.line(vec![K::Else { id: FlowId::Nested }]);
    b.line(vec![K::EndIf { id: FlowId::Nested }]);
    let (r3, hundred) = (b.var(Var::R(3)), b.num("100"));
    let lt = b.bin(Lt, r3, hundred);
    b.line(vec![K::While {
        cond: lt,
        id: FlowId::Nested,
    }]);
    b.line(vec![K::EndWhile { id: FlowId::Nested }]);
    b.line(vec![K::RepeatUntil]);
    let (r3, hundred) = (b.var(Var::R(3)), b.num("100"));
    let ge = b.bin(Ge, r3, hundred);
    b.line(vec![K::Until { cond: ge }]);
    b.line(vec![K::Loop]);
    b.line(vec![K::EndLoop]);
    let sel = b.var(Var::R(6));
    let (v8, v6) = (b.num("8"), b.num("6"));
    b.line(vec![K::Case {
        selector: sel,
        arms: vec![
            CaseArm {
                value: v8,
                target: "L1".into(),
                dir: JumpDir::Forward,
            },
            CaseArm {
                value: v6,
                target: "L2".into(),
                dir: JumpDir::Forward,
            },
        ],
        default: Some(("L3".into(), JumpDir::Forward)),
    }]);
    b.labelled(
        "L1",
        vec![K::Goto {
            target: JumpTarget::Label("L3".into()),
            dir: JumpDir::Forward,
            cond: None,
        }],
    );
    b.labelled(
        "L2",
        vec![K::Goto {
            target: JumpTarget::Label("L1".into()),
            dir: JumpDir::Backward,
            cond: None,
        }],
    );
    let three = b.num("3");
    b.labelled(
        "L3",
        vec![K::SectionRepeat {
            start: "L1".into(),
            end: Some("L2".into()),
            count: Some(three),
            single: false,
        }],
    );
    b.line(vec![K::Call {
        kind: CallKind::Named,
        target: CallTarget::Number(123),
        args: CallArgs::None,
        repeat: Some(n("2")),
    }]);
    let (a1, a3) = (b.num("1"), b.num("3"));
    b.line(vec![K::Call {
        kind: CallKind::Named,
        target: CallTarget::Name("POCKET_A".into()),
        args: CallArgs::Positional(vec![Some(a1), None, Some(a3)]),
        repeat: None,
    }]);
    b.line(vec![K::Spindle(SpindleState::Orient(Some(n("90"))))]);
    b.line(vec![K::Message(None)]);
    let i = b.numbered(
        900,
        vec![
            K::Stop(StopKind::EndRewind),
            K::Comment {
                text: " END".into(),
                style: CommentStyle::Semicolon,
            },
        ],
    );
    b.skip(i, 1);
    b
}
