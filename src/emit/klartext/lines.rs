//! One IR block to Klartext blocks: the path line (a move with its radius
//! compensation, feed and M functions), a `TOOL CALL` line, and a line for
//! each other statement, in that order; comments go after the last.

use super::super::number::NumKind;
use super::super::writer::Writer;
use super::expr::{formula, signed, var};
use super::{num_kind_for, unit_word, Out};
use crate::dialect::Meaning;
use crate::ir::{
    ApproachKind, ArcDir, Axes, BinaryOp, Block, CallKind, CallTarget, CommentStyle, CompSide,
    CornerKind, CycleRunKind, CycleWord, DwellUnit, ExprKind, JumpTarget, MotionKind, Stmt,
    StmtKind as K, StockCorner, StopKind, ToolRef, Value,
};
use crate::span::Span;

/// The parts of one block.
#[derive(Default)]
struct Parts<'p> {
    main: Option<&'p Stmt>,
    tool: Vec<&'p Stmt>,
    mods: Vec<String>,
    feed: Option<String>,
    others: Vec<&'p Stmt>,
    comments: Vec<String>,
}

pub fn block(w: &mut Writer<'_>, out: &mut Out, b: &Block) {
    let start = out.lines.len();
    if let Some(l) = &b.label {
        out.lines.push(format!("LBL {}", label(&l.node)));
    }
    let mut parts = Parts::default();
    for s in &b.stmts {
        sort(w, out, s, &mut parts);
    }
    if !parts.tool.is_empty() {
        let line = tool_call(
            w,
            &parts.tool,
            parts.main.is_none().then(|| parts.feed.take()).flatten(),
        );
        out.lines.push(line);
    }
    match parts.main {
        Some(s) => {
            if let Some(line) = main_line(w, out, s, &parts) {
                out.lines.push(line);
            }
            corner_after(w, out, s);
        }
        None if parts.feed.is_some() || parts.mods.iter().any(|m| m.starts_with('R')) => {
            let mut line = "L".to_string();
            push_mods(&mut line, &parts);
            out.lines.push(line);
        }
        None if !parts.mods.is_empty() => out.lines.push(parts.mods.join(" ")),
        None => {}
    }
    for s in &parts.others {
        other(w, out, s);
    }
    if !parts.comments.is_empty() {
        let text = parts.comments.join(" ");
        if out.lines.len() > start && !out.lines.last().is_some_and(|l| l.contains('\n')) {
            let last = out.lines.last_mut().expect("a line");
            last.push_str(&format!(" ;{text}"));
        } else {
            out.lines.push(format!(";{text}"));
        }
    }
}

fn label(n: &str) -> String {
    if !n.is_empty() && n.bytes().all(|c| c.is_ascii_digit()) {
        n.to_string()
    } else {
        format!("\"{n}\"")
    }
}

fn sort<'p>(w: &mut Writer<'_>, out: &mut Out, s: &'p Stmt, parts: &mut Parts<'p>) {
    let m = |w: &mut Writer<'_>, meaning| w.code(meaning, s.span);
    match &s.kind {
        K::Motion(_) | K::Pole(_) | K::Corner { .. } | K::Approach(_) if parts.main.is_none() => {
            parts.main = Some(s)
        }
        K::CycleRun(CycleRunKind::Call | CycleRunKind::Pos(_) | CycleRunKind::Pattern)
            if parts.main.is_none() =>
        {
            parts.main = Some(s)
        }
        K::CycleRun(CycleRunKind::Block) => parts.mods.push("M99".into()),
        K::CycleRun(CycleRunKind::Modal) => parts.mods.push("M89".into()),
        K::ToolSelect(_)
        | K::ToolChange
        | K::Plane(_)
        | K::SpindleSpeed(_)
        | K::ToolOversize { .. } => parts.tool.push(s),
        K::Feed(v) => parts.feed = feed(w, v, s.span),
        K::RadiusComp {
            side,
            register: None,
            diameter: false,
        } => parts.mods.push(match side {
            CompSide::Off => "R0".into(),
            CompSide::Left => "RL".into(),
            CompSide::Right => "RR".into(),
        }),
        K::Spindle(st) => {
            use crate::dialect::SpindleFn;
            let f = match st {
                crate::ir::SpindleState::Cw => SpindleFn::Cw,
                crate::ir::SpindleState::Ccw => SpindleFn::Ccw,
                crate::ir::SpindleState::Stop => SpindleFn::Stop,
                crate::ir::SpindleState::Orient(None) => SpindleFn::Orient,
                crate::ir::SpindleState::Orient(Some(_)) => {
                    w.cannot(
                        s.span,
                        "a spindle orientation to an angle",
                        "orient the spindle with a cycle of the machine",
                    );
                    return;
                }
            };
            parts.mods.extend(m(w, Meaning::Spindle(f)));
        }
        K::Coolant(c) => parts.mods.extend(m(w, Meaning::Coolant(*c))),
        K::Stop(k) if *k != StopKind::Program => parts.mods.extend(m(w, Meaning::Stop(*k))),
        K::MachineCoords => parts.mods.extend(m(w, Meaning::MachineCoords)),
        K::Aux {
            letter: 'M',
            code,
            words,
        } if words.is_empty() => parts.mods.push(format!("M{}", code.format(0, false))),
        K::Comment {
            text,
            style: CommentStyle::Semicolon | CommentStyle::Paren,
        } => parts.comments.push(text.clone()),
        // Siemens D1: TOOL CALL activates the tool's (one) edge [?].
        K::CuttingEdge(Value::Number(d)) if d.as_int() == Some(1) => {}
        K::Distance(d) => out.incremental = *d == crate::ir::DimMode::Incremental,
        K::ArcDistance(d) => out.arc_absolute = *d == crate::ir::DimMode::Absolute,
        // What Klartext does by itself: `%` is the BEGIN/END PGM frame;
        // feeds are per minute; cycles are called, never modal in motion
        // (G80, G98/G99 only shape word-address cycles, which `port`
        // maps); G54 is the active preset; TOOL CALL applies the tool
        // length (G43/G49) [?].
        K::Tape
        | K::FeedMode(crate::ir::FeedMode::PerMinute)
        | K::CycleCancel
        | K::ReturnToInitial(_)
        | K::WorkOffset {
            index: 1,
            extended: None,
        }
        | K::LengthComp {
            mode: crate::ir::LengthComp::Positive | crate::ir::LengthComp::Cancel,
            ..
        } => {}
        K::Units { unit, .. } if Some(*unit) == out.unit || out.unit.is_none() => {}
        _ => parts.others.push(s),
    }
}

fn feed(w: &mut Writer<'_>, v: &Value, span: Span) -> Option<String> {
    match v {
        Value::Number(d) => Some(format!("F{}", w.num(*d, NumKind::Feed, span)?)),
        Value::Expr(e) => match &w.prog.exprs[*e].kind {
            ExprKind::Var(x) => Some(format!("F{}", var(w, x, span)?)),
            _ => {
                w.cannot(
                    span,
                    "a feed given by a formula",
                    "compute the feed into a Q parameter first",
                );
                None
            }
        },
    }
}

fn push_mods(line: &mut String, parts: &Parts<'_>) {
    let (comp, ms): (Vec<&String>, Vec<&String>) =
        parts.mods.iter().partition(|m| m.starts_with('R'));
    for c in comp {
        line.push_str(&format!(" {c}"));
    }
    if let Some(f) = &parts.feed {
        line.push_str(&format!(" {f}"));
    }
    for m in ms {
        line.push_str(&format!(" {m}"));
    }
}

/// ` X+10 Y-5 IZ-2`.
fn axes(w: &mut Writer<'_>, out: &Out, a: &Axes) -> Option<String> {
    let mut s = String::new();
    for (letter, c) in a.iter() {
        let inc = out.incremental || c.dim == Some(crate::ir::DimMode::Incremental);
        let kind = if "ABC".contains(letter) {
            NumKind::Angle
        } else {
            NumKind::Length
        };
        let v = signed(w, &c.value, kind, c.span)?;
        s.push_str(&format!(" {}{letter}{v}", if inc { "I" } else { "" }));
    }
    Some(s)
}

/// `PA+30` or `IPA+30` (an `IC(..)` value is incremental).
fn polar(w: &mut Writer<'_>, addr: &str, v: &Value, span: Span) -> Option<String> {
    let inc = matches!(v, Value::Expr(e) if matches!(w.prog.exprs[*e].kind, ExprKind::Dimension(crate::ir::DimMode::Incremental, _)));
    let v = match v {
        Value::Expr(e) => match &w.prog.exprs[*e].kind {
            ExprKind::Dimension(_, inner) => Value::Expr(*inner),
            _ => v.clone(),
        },
        _ => v.clone(),
    };
    let kind = num_kind_for(addr);
    let v = match &v {
        Value::Expr(e) => match w.prog.exprs[*e].kind {
            ExprKind::Number(d) => Value::Number(d),
            _ => v.clone(),
        },
        _ => v,
    };
    Some(format!(
        " {}{addr}{}",
        if inc { "I" } else { "" },
        signed(w, &v, kind, span)?
    ))
}

fn dir(d: ArcDir) -> &'static str {
    match d {
        ArcDir::Ccw => " DR+",
        ArcDir::Cw => " DR-",
    }
}

fn main_line(w: &mut Writer<'_>, out: &mut Out, s: &Stmt, parts: &Parts<'_>) -> Option<String> {
    let mut line = match &s.kind {
        K::Motion(m) => motion(w, out, m, s.span)?,
        K::Pole(a) => format!("CC{}", axes(w, out, a)?),
        K::Corner {
            kind: CornerKind::Round,
            size,
        } => format!(
            "RND R{}",
            signed(w, size, NumKind::Length, s.span)?.trim_start_matches('+')
        ),
        K::Corner {
            kind: CornerKind::Chamfer,
            size,
        } => format!(
            "CHF {}",
            signed(w, size, NumKind::Length, s.span)?.trim_start_matches('+')
        ),
        K::Corner { kind, .. } => {
            w.cannot(
                s.span,
                &format!("the corner form {kind:?}"),
                "use RND (rounding) or CHF (chamfer length)",
            );
            return None;
        }
        K::Approach(a) => {
            let kind = match a.kind {
                ApproachKind::LineTangent => "LT",
                ApproachKind::LineNormal => "LN",
                ApproachKind::ArcTangent => "CT",
                ApproachKind::LineArcTangent => "LCT",
            };
            let mut l = format!(
                "{} {kind}{}",
                if a.depart { "DEP" } else { "APPR" },
                axes(w, out, &a.target)?
            );
            for (addr, v) in [("LEN", &a.len), ("CCA", &a.angle), ("R", &a.radius)] {
                if let Some(v) = v {
                    let text = signed(w, v, num_kind_for(addr), s.span)?;
                    l.push_str(&format!(
                        " {addr}{}",
                        if addr == "R" {
                            text
                        } else {
                            text.trim_start_matches('+').to_string()
                        }
                    ));
                }
            }
            l
        }
        K::CycleRun(CycleRunKind::Pos(a)) => format!("CYCL CALL POS{}", axes(w, out, a)?),
        K::CycleRun(CycleRunKind::Pattern) => "CYCL CALL PAT".into(),
        _ => "CYCL CALL".into(),
    };
    if std::mem::take(&mut out.rapid) {
        let mut p = Parts {
            mods: parts.mods.clone(),
            feed: Some("FMAX".into()),
            ..Parts::default()
        };
        if let Some(f) = &parts.feed {
            p.mods.push(f.clone());
        }
        push_mods(&mut line, &p);
    } else {
        push_mods(&mut line, parts);
    }
    Some(line)
}

fn motion(w: &mut Writer<'_>, out: &mut Out, m: &crate::ir::Motion, span: Span) -> Option<String> {
    let kind = match m.kind {
        MotionKind::Implicit => match out.modal {
            Some(k @ (MotionKind::Rapid | MotionKind::Linear)) => k,
            _ if m.target.is_empty() => MotionKind::Linear,
            _ => {
                w.cannot(
                    span,
                    "a move whose kind comes from an earlier block's arc",
                    "write the arc's G2/G3 in the block",
                );
                return None;
            }
        },
        k => k,
    };
    out.modal = Some(kind);
    let polar_words = m.polar_radius.is_some() || m.polar_angle.is_some();
    let a = axes(w, out, &m.target)?;
    let mut pw = String::new();
    if let Some(r) = &m.polar_radius {
        pw.push_str(&polar(w, "PR", r, span)?);
    }
    if let Some(v) = &m.polar_angle {
        pw.push_str(&polar(w, "PA", v, span)?);
    }
    let arc_centre = m.arc.i.is_some() || m.arc.j.is_some() || m.arc.k.is_some();
    let extra = m.arc.angle.is_some() || m.arc.turns.is_some() || m.arc.mid.is_some();
    if extra || (arc_centre && (m.arc.radius.is_some() || !matches!(kind, MotionKind::Arc(_)))) {
        w.cannot(
            span,
            "an arc given by an opening angle, turns or an intermediate point",
            "give the centre with CC and write C, or write CR with the radius",
        );
        return None;
    }
    if arc_centre {
        // I J K: the centre, as a CC block before the C block (`CC IX..`
        // is relative to the arc's start, as I J K are by default).
        let mut cc = "CC".to_string();
        for (letter, c) in [('X', &m.arc.i), ('Y', &m.arc.j), ('Z', &m.arc.k)] {
            let Some(c) = c else { continue };
            let inc = match c.dim {
                Some(d) => d == crate::ir::DimMode::Incremental,
                None => !out.arc_absolute,
            };
            let v = signed(w, &c.value, NumKind::Length, c.span)?;
            cc.push_str(&format!(" {}{letter}{v}", if inc { "I" } else { "" }));
        }
        out.lines.push(cc);
    }
    let line = match kind {
        MotionKind::Rapid | MotionKind::Linear => {
            out.rapid = kind == MotionKind::Rapid;
            if polar_words {
                format!("LP{pw}{a}")
            } else {
                format!("L{a}")
            }
        }
        MotionKind::Arc(d) => match &m.arc.radius {
            Some(r) => format!("CR{a} R{}{}", signed(w, r, NumKind::Length, span)?, dir(d)),
            None if polar_words => format!("CP{pw}{a}{}", dir(d)),
            None => format!("C{a}{}", dir(d)),
        },
        MotionKind::ArcTangent if polar_words => format!("CTP{pw}{a}"),
        MotionKind::ArcTangent => format!("CT{a}"),
        MotionKind::Implicit
        | MotionKind::ArcThrough
        | MotionKind::Probe { .. }
        | MotionKind::Other(_) => {
            w.cannot(
                span,
                &format!("the motion {:?}", kind),
                "Klartext moves are L, C, CR, CT and their polar forms",
            );
            return None;
        }
    };
    Some(line)
}

/// A Siemens `RND=`/`CHF=` on a move: a Klartext RND/CHF block after it.
fn corner_after(w: &mut Writer<'_>, out: &mut Out, s: &Stmt) {
    let K::Motion(m) = &s.kind else { return };
    let Some((kind, v)) = &m.corner else { return };
    let line = match kind {
        CornerKind::Round => signed(w, v, NumKind::Length, s.span)
            .map(|t| format!("RND R{}", t.trim_start_matches('+'))),
        CornerKind::Chamfer => signed(w, v, NumKind::Length, s.span)
            .map(|t| format!("CHF {}", t.trim_start_matches('+'))),
        CornerKind::ChamferLeg | CornerKind::RoundModal => {
            w.cannot(
                s.span,
                "a chamfer by leg length or a modal rounding",
                "use RND R.. or CHF length after the move",
            );
            None
        }
    };
    out.lines.extend(line);
}

fn tool_call(w: &mut Writer<'_>, stmts: &[&Stmt], feed: Option<String>) -> String {
    let mut line = "TOOL CALL".to_string();
    let mut rest = String::new();
    let mut deltas = String::new();
    for s in stmts {
        match &s.kind {
            K::ToolSelect(ToolRef::Number(v)) => match v {
                Value::Number(d) => line.push_str(&format!(" {}", d.format(0, false))),
                Value::Expr(e) => {
                    if let ExprKind::Var(x) = &w.prog.exprs[*e].kind {
                        if let Some(t) = var(w, x, s.span) {
                            line.push_str(&format!(" {t}"));
                        }
                    } else {
                        w.cannot(
                            s.span,
                            "a tool number given by a formula",
                            "compute it into a Q parameter",
                        );
                    }
                }
            },
            K::ToolSelect(ToolRef::Name(n)) => line.push_str(&format!(" \"{n}\"")),
            K::Plane(p) => rest.insert_str(
                0,
                match p {
                    crate::ir::Plane::XY => " Z",
                    crate::ir::Plane::ZX => " Y",
                    crate::ir::Plane::YZ => " X",
                },
            ),
            K::SpindleSpeed(v) => {
                if let Some(t) = signed(w, v, NumKind::Feed, s.span) {
                    rest.push_str(&format!(" S{}", t.trim_start_matches('+')));
                }
            }
            K::ToolOversize { length, radius } => {
                for (a, v) in [("DL", length), ("DR", radius)] {
                    if let Some(t) = v
                        .as_ref()
                        .and_then(|v| signed(w, v, NumKind::Length, s.span))
                    {
                        deltas.push_str(&format!(" {a}{t}"));
                    }
                }
            }
            _ => {}
        }
    }
    if let Some(f) = feed {
        rest.push_str(&format!(" {f}"));
    }
    line + &rest + &deltas
}

fn other(w: &mut Writer<'_>, out: &mut Out, s: &Stmt) {
    let span = s.span;
    let line = match &s.kind {
        K::ProgramStart { number, name } => {
            let n = super::program_name(*number, name.as_deref()).unwrap_or_else(|| "PGM".into());
            Some(format!("BEGIN PGM {n} {}", unit_word(out.unit)))
        }
        K::ProgramEnd { name } => Some(format!(
            "END PGM {} {}",
            name.clone()
                .or_else(|| super::first_name(w.prog))
                .unwrap_or_else(|| "PGM".into()),
            unit_word(out.unit)
        )),
        K::Comment {
            text,
            style: CommentStyle::Heading,
        } => Some(format!("* {text}")),
        K::Stop(StopKind::Program) => Some("STOP".into()),
        K::Stock {
            corner,
            axis,
            axes: a,
        } => {
            let head = match corner {
                StockCorner::Min => format!("BLK FORM 0.1 {}", axis.unwrap_or('Z')),
                StockCorner::Max => "BLK FORM 0.2".into(),
            };
            axes(w, out, a).map(|t| head + &t)
        }
        K::ToolDef {
            tool,
            length,
            radius,
        } => {
            let t = match tool {
                ToolRef::Number(Value::Number(d)) => d.format(0, false),
                ToolRef::Number(_) => "0".into(),
                ToolRef::Name(n) => format!("\"{n}\""),
            };
            let mut l = format!("TOOL DEF {t}");
            for (a, v) in [("L", length), ("R", radius)] {
                if let Some(x) = v.as_ref().and_then(|v| signed(w, v, NumKind::Length, span)) {
                    l.push_str(&format!(" {a}{x}"));
                }
            }
            Some(l)
        }
        K::Raw { dialect, text } if dialect == "heidenhain" => Some(text.clone()),
        K::Assign { var: v, value } if super::expr::is_angle(w, *value) => {
            super::expr::fn13(w, v, *value, span)
        }
        K::Assign { var: v, value } => match (var(w, v, span), formula(w, *value)) {
            (Some(a), Some(b)) => Some(format!("{a} = {b}")),
            _ => None,
        },
        K::Goto {
            target: JumpTarget::Label(l),
            cond,
            ..
        } => goto(w, l, *cond, span),
        K::Call {
            kind: CallKind::Label,
            target,
            repeat: None,
            ..
        } => match target {
            CallTarget::Number(n) => Some(format!("CALL LBL {n}")),
            CallTarget::Name(n) => Some(format!("CALL LBL {}", label(n))),
            CallTarget::Computed(_) => cannot(w, span, "a label call to a computed label"),
        },
        K::Call {
            kind: CallKind::Named | CallKind::Subprogram,
            target,
            repeat: None,
            ..
        } => match target {
            CallTarget::Number(n) => Some(format!("CALL PGM {n}")),
            CallTarget::Name(n) => Some(format!("CALL PGM {n}")),
            CallTarget::Computed(_) => cannot(w, span, "a program call to a computed number"),
        },
        K::SectionRepeat {
            start,
            end: None,
            count,
            single: false,
        } => {
            let n = count.and_then(|c| match w.prog.exprs[c].kind {
                ExprKind::Number(d) => Some(d.format(0, false)),
                _ => None,
            });
            match n {
                Some(n) => Some(format!("CALL LBL {} REP {n}/{n}", label(start))),
                None => cannot(w, span, "a section repeat with a computed count"),
            }
        }
        K::SubReturn { to: None } => Some("LBL 0".into()),
        K::Dwell {
            value,
            unit: DwellUnit::Seconds,
        } => {
            out.lines.push("CYCL DEF 9.0 DWELL TIME".into());
            signed(w, value, NumKind::Plain, span)
                .map(|t| format!("CYCL DEF 9.1 DWELL {}", t.trim_start_matches('+')))
        }
        K::CycleDef(c) => cycle_def(w, c, span),
        K::CycleLine(c) => {
            cycle_words(w, &c.words, span).map(|t| format!("CYCL DEF {}.{}{t}", c.cycle, c.sub))
        }
        K::PatternDef(items) => {
            let mut l = "PATTERN DEF".to_string();
            for i in items {
                let t = cycle_words(w, &i.words, span).unwrap_or_default();
                l.push_str(&format!(" ~\n{} ({})", i.name, t.trim_start()));
            }
            Some(l)
        }
        K::Units { .. } => cannot(w, span, "a change of units inside the program"),
        _ => cannot(
            w,
            span,
            &format!("the statement `{}`", variant_name(&s.kind)),
        ),
    };
    out.lines.extend(line);
}

fn cannot(w: &mut Writer<'_>, span: Span, what: &str) -> Option<String> {
    w.cannot(
        span,
        what,
        "Klartext has no function for it; rewrite this part by hand",
    );
    None
}

fn goto(
    w: &mut Writer<'_>,
    l: &str,
    cond: Option<crate::ir::ExprId>,
    span: Span,
) -> Option<String> {
    let (n, op, a, b) = match cond.map(|c| w.prog.exprs[c].kind.clone()) {
        None => return Some(format!("FN 9: IF +0 EQU +0 GOTO LBL {}", label(l))),
        Some(ExprKind::Binary(op, a, b)) => match op {
            BinaryOp::Eq => (9, "EQU", a, b),
            BinaryOp::Ne => (10, "NE", a, b),
            BinaryOp::Gt => (11, "GT", a, b),
            BinaryOp::Lt => (12, "LT", a, b),
            _ => return cannot(w, span, "a jump condition other than EQU NE GT LT"),
        },
        Some(_) => return cannot(w, span, "a jump condition that is not a comparison"),
    };
    let a = signed(w, &Value::Expr(a), NumKind::Plain, span)?;
    let b = signed(w, &Value::Expr(b), NumKind::Plain, span)?;
    Some(format!("FN {n}: IF {a} {op} {b} GOTO LBL {}", label(l)))
}

fn cycle_def(w: &mut Writer<'_>, c: &crate::ir::CycleDef, span: Span) -> Option<String> {
    let mut l = format!("CYCL DEF {}", c.number);
    if !c.name.is_empty() {
        l.push_str(&format!(" {}", c.name));
    }
    for p in &c.params {
        let v = signed(w, &p.value, NumKind::Plain, span)?;
        l.push_str(&format!(" ~\n  Q{}={v}", p.q));
        if let Some(t) = &p.label {
            l.push_str(&format!(" ;{t}"));
        }
    }
    Some(l)
}

fn cycle_words(w: &mut Writer<'_>, words: &[CycleWord], span: Span) -> Option<String> {
    let mut s = String::new();
    for cw in words {
        match &cw.value {
            Some(v) if cw.name.is_empty() => s.push_str(&format!(
                " {}",
                signed(w, v, NumKind::Plain, span)?.trim_start_matches('+')
            )),
            Some(v) => s.push_str(&format!(
                " {}{}",
                cw.name,
                signed(w, v, NumKind::Plain, span)?
            )),
            None => s.push_str(&format!(" {}", cw.name)),
        }
    }
    Some(s)
}

/// `WorkOffset`, `LengthComp`: the statement's kind for messages.
fn variant_name(k: &K) -> String {
    let d = format!("{k:?}");
    d.split(|c: char| !c.is_alphanumeric())
        .next()
        .unwrap_or("")
        .to_string()
}
