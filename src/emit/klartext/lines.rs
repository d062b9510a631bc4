//! One IR block to Klartext blocks: the path line (a move with its radius
//! compensation, feed and M functions), a `TOOL CALL` line, and a line for
//! each other statement ([`super::others`]), in that order; comments go
//! after the last.

use super::super::number::NumKind;
use super::super::writer::Writer;
use super::expr::{signed, var};
use super::{num_kind_for, Out};
use crate::dialect::Meaning;
use crate::ir::{
    ApproachKind, Axes, Block, CommentStyle, CompSide, CornerKind, CycleRunKind, ExprKind, Stmt,
    StmtKind as K, StopKind, Value,
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

/// A tool selected in a block that changes no tool (`T2` after `T1 M6`
/// loads nothing yet): `TOOL DEF 2`, the TNC's preselection. The
/// selection leaves the tool statements; what is left of them (plane,
/// speed) still makes a `TOOL CALL`.
fn preselect(w: &mut Writer<'_>, tool: &mut Vec<&Stmt>) -> Option<String> {
    if tool.iter().any(|s| matches!(s.kind, K::ToolChange)) {
        return None;
    }
    let at = tool
        .iter()
        .position(|s| matches!(s.kind, K::ToolSelect(_)))?;
    let s = tool.remove(at);
    let call = super::others::tool_call(w, &[s], None);
    Some(call.replacen("TOOL CALL", "TOOL DEF", 1))
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
    if let Some(line) = preselect(w, &mut parts.tool) {
        out.lines.push(line);
    }
    if !parts.tool.is_empty() {
        let line = super::others::tool_call(
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
            super::moves::corner_after(w, out, s);
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
        super::others::other(w, out, s);
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
    // Block skip: `/` before the number of each block this one became.
    if b.skip.is_some() {
        for l in &mut out.lines[start..] {
            l.insert(0, '/');
        }
    }
}

pub(super) fn label(n: &str) -> String {
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
        K::CycleRun(
            CycleRunKind::Call | CycleRunKind::Pos { .. } | CycleRunKind::Pattern { .. },
        ) if parts.main.is_none() => parts.main = Some(s),
        K::CycleRun(CycleRunKind::Block) => parts.mods.push("M99".into()),
        K::TncFunction(f)
            if matches!(
                f.kind,
                crate::ir::TncFunctionKind::Paraxial(_) | crate::ir::TncFunctionKind::Retract(_)
            ) =>
        {
            parts.mods.push(f.text.clone())
        }
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
        } => {
            let t = w.safe_text(text, crate::dialect::text::TextForm::Semicolon, s.span);
            parts.comments.push(t)
        }
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
pub(super) fn axes(w: &mut Writer<'_>, out: &Out, a: &Axes) -> Option<String> {
    let mut s = String::new();
    for (letter, c) in a.iter() {
        let inc = match c.dim {
            Some(d) => d == crate::ir::DimMode::Incremental,
            None => out.incremental,
        };
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

fn main_line(w: &mut Writer<'_>, out: &mut Out, s: &Stmt, parts: &Parts<'_>) -> Option<String> {
    let mut line = match &s.kind {
        K::Motion(m) => super::moves::motion(w, out, m, s.span)?,
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
        K::CycleRun(CycleRunKind::Pos { axes: a, rapid }) => {
            out.rapid = *rapid;
            format!("CYCL CALL POS{}", axes(w, out, a)?)
        }
        K::CycleRun(CycleRunKind::Pattern { rapid }) => {
            out.rapid = *rapid;
            "CYCL CALL PAT".into()
        }
        _ => "CYCL CALL".into(),
    };
    if std::mem::take(&mut out.rapid) {
        let p = Parts {
            mods: parts.mods.clone(),
            feed: Some("FMAX".into()),
            ..Parts::default()
        };
        if let Some(f) = &parts.feed {
            out.pending_feed = Some(f.clone());
        }
        push_mods(&mut line, &p);
    } else if parts.feed.is_none() && matches!(s.kind, K::Motion(_)) {
        let p = Parts {
            mods: parts.mods.clone(),
            feed: out.pending_feed.take(),
            ..Parts::default()
        };
        push_mods(&mut line, &p);
    } else {
        if parts.feed.is_some() {
            out.pending_feed = None;
        }
        push_mods(&mut line, parts);
    }
    Some(line)
}
