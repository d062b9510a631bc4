//! A recorded part of a run written back as statements: moves in
//! absolute program coordinates, and the state changes it made, each as
//! the neutral statement that makes it (the block's own statement where
//! it holds no expression, so the target's passes treat it as usual).

use crate::canon::{Canon, CanonPlane, CanonUnits};
use crate::dialect::DialectSpec;
use crate::interp::host::plane_axes;
use crate::ir::{
    ArcData, ArcDir, Coolant, Coord, Decimal, DwellUnit, LengthUnit, Motion, MotionKind, Plane,
    Program, SpindleState, Stmt, StmtKind, StopKind, ToolRef, Value,
};
use crate::span::Span;
use std::collections::HashMap;

/// Writes calls as statements.
pub struct Writer<'a> {
    pub by_span: &'a HashMap<Span, Stmt>,
    pub to: &'a DialectSpec,
    pub plane: CanonPlane,
    pub inch: bool,
    /// Where the last move ended (canon units).
    pub pos: [f64; 6],
    pub out: Vec<Stmt>,
    /// The motion kind of the last move written.
    pub last_motion: Option<MotionKind>,
    coolant_off: bool,
    /// The G92/G52 offset in force (canon units), and the one the written
    /// part starts in: a shift made and undone inside the part is folded
    /// into its coordinates instead of being written.
    pub g92: [f64; 6],
    pub g92_base: [f64; 6],
}

impl<'a> Writer<'a> {
    pub fn new(by_span: &'a HashMap<Span, Stmt>, to: &'a DialectSpec) -> Self {
        Writer {
            by_span,
            to,
            plane: CanonPlane::XY,
            inch: false,
            pos: [0.0; 6],
            out: Vec::new(),
            last_motion: None,
            coolant_off: false,
            g92: [0.0; 6],
            g92_base: [0.0; 6],
        }
    }

    /// Follows a call made before the part being written (position,
    /// plane, units), writing nothing.
    pub fn follow(&mut self, c: &Canon) {
        match c {
            Canon::StraightTraverse(p) | Canon::StraightFeed(p) | Canon::StraightProbe(p) => {
                self.pos = *p
            }
            Canon::ArcFeed {
                first_end,
                second_end,
                axis_end,
                abc,
                ..
            } => {
                let (f, s, n) = plane_axes(self.plane);
                (self.pos[f], self.pos[s], self.pos[n]) = (*first_end, *second_end, *axis_end);
                self.pos[3..6].copy_from_slice(abc);
            }
            Canon::SelectPlane(pl) => self.plane = *pl,
            Canon::UseLengthUnits(u) => self.inch = *u == CanonUnits::Inches,
            Canon::SetG92Offset(p) => self.g92 = *p,
            _ => {}
        }
    }

    /// Starts writing here: the shift in force now is the one kept.
    pub fn begin(&mut self) {
        self.g92_base = self.g92;
    }

    /// A canon position in the frame the written part keeps.
    fn shifted(&self, p: &[f64; 6]) -> [f64; 6] {
        let mut q = *p;
        for (k, v) in q.iter_mut().enumerate() {
            *v += self.g92[k] - self.g92_base[k];
        }
        q
    }

    fn number(&self, v: f64) -> Value {
        let places = if self.inch {
            self.to.numbers.length_places_inch
        } else {
            self.to.numbers.length_places_mm
        };
        let mut d = Decimal::from_f64(v, places).normalized();
        d.point = true;
        Value::Number(d)
    }

    fn coord(&self, v: f64, span: Span) -> Option<crate::ir::Coord> {
        Some(Coord {
            value: self.number(v),
            dim: None,
            span,
        })
    }

    fn push(&mut self, k: StmtKind, span: Span) {
        self.out.push(Stmt::new(k, span));
    }

    /// The block's own statement, if it holds only literal values.
    fn own(&self, span: Span) -> Option<Stmt> {
        let s = self.by_span.get(&span)?;
        literal(s).then(|| s.clone())
    }

    /// Writes one call; `Err` names what has no statement form.
    pub fn call(&mut self, c: &Canon, span: Span) -> Result<(), String> {
        if !matches!(c, Canon::FloodOff | Canon::MistOff) {
            self.coolant_off = false;
        }
        match c {
            Canon::StraightTraverse(p) | Canon::StraightFeed(p) => {
                let kind = if matches!(c, Canon::StraightTraverse(_)) {
                    MotionKind::Rapid
                } else {
                    MotionKind::Linear
                };
                let p = self.shifted(p);
                self.line(kind, &p, span);
            }
            Canon::ArcFeed { .. } => self.arc(c, span)?,
            Canon::SetFeedRate(f) => self.push(
                StmtKind::Feed(Value::Number(super::super::decimal(*f))),
                span,
            ),
            Canon::SetSpindleSpeed(s) => self.push(
                StmtKind::SpindleSpeed(Value::Number(super::super::decimal(*s))),
                span,
            ),
            Canon::SpindleCw => self.push(StmtKind::Spindle(SpindleState::Cw), span),
            Canon::SpindleCcw => self.push(StmtKind::Spindle(SpindleState::Ccw), span),
            Canon::StopSpindle => self.push(StmtKind::Spindle(SpindleState::Stop), span),
            Canon::FloodOn => self.push(StmtKind::Coolant(Coolant::Flood), span),
            Canon::MistOn => self.push(StmtKind::Coolant(Coolant::Mist), span),
            Canon::FloodOff | Canon::MistOff => {
                if !self.coolant_off {
                    self.push(StmtKind::Coolant(Coolant::Off), span);
                }
                self.coolant_off = true;
            }
            Canon::Dwell(t) => self.push(
                StmtKind::Dwell {
                    value: Value::Number(super::super::decimal(*t)),
                    unit: DwellUnit::Seconds,
                },
                span,
            ),
            Canon::SelectPlane(pl) => {
                self.plane = *pl;
                self.push(StmtKind::Plane(plane_of(*pl)), span);
            }
            Canon::UseLengthUnits(u) => {
                self.inch = *u == CanonUnits::Inches;
                let unit = if self.inch {
                    LengthUnit::Inch
                } else {
                    LengthUnit::Mm
                };
                self.push(
                    StmtKind::Units {
                        unit,
                        with_feeds: false,
                    },
                    span,
                );
            }
            Canon::SelectTool(n) => match self.own(span) {
                Some(s) if matches!(s.kind, StmtKind::ToolSelect(_)) => self.out.push(s),
                _ => self.push(
                    StmtKind::ToolSelect(ToolRef::Number(Value::Number(Decimal::from_f64(
                        *n as f64, 0,
                    )))),
                    span,
                ),
            },
            Canon::ChangeTool(_) => self.push(StmtKind::ToolChange, span),
            Canon::Message(m) => match self.by_span.get(&span).map(|s| &s.kind) {
                Some(StmtKind::Comment { .. }) => {}
                _ => self.push(StmtKind::Message(Some(m.clone())), span),
            },
            // M30's exchange of pallets, written by writing the M30.
            Canon::PalletShuttle
                if matches!(
                    self.by_span.get(&span).map(|s| &s.kind),
                    Some(StmtKind::Stop(StopKind::End | StopKind::EndRewind))
                ) => {}
            Canon::ProgramStop => self.push(StmtKind::Stop(StopKind::Program), span),
            Canon::OptionalProgramStop => self.push(StmtKind::Stop(StopKind::Optional), span),
            Canon::ProgramEnd => match self.own(span) {
                Some(s) if matches!(s.kind, StmtKind::Stop(_)) => self.out.push(s),
                _ => self.push(StmtKind::Stop(StopKind::End), span),
            },
            Canon::SetG92Offset(p) => self.g92 = *p,
            Canon::SetG5xOffset { .. }
            | Canon::SetXyRotation(_)
            | Canon::UseToolLengthOffset(_)
            | Canon::SetFeedMode(_) => self.state(c, span)?,
            Canon::SetMotionControlMode(_) => {
                if let Some(s) = self
                    .own(span)
                    .filter(|s| matches!(s.kind, StmtKind::PathMode { .. }))
                {
                    self.out.push(s);
                }
            }
            Canon::Comment(_)
            | Canon::SetNaivecamTolerance(_)
            | Canon::SetFeedReference
            | Canon::OnReset
            | Canon::Finish
            | Canon::StartChange
            | Canon::ChangeToolNumber(_)
            | Canon::SetSpindleMode(_)
            | Canon::WaitOrientComplete(_)
            | Canon::EnableFeedOverride
            | Canon::DisableFeedOverride
            | Canon::EnableSpeedOverride
            | Canon::DisableSpeedOverride
            | Canon::EnableFeedHold
            | Canon::DisableFeedHold => {}
            other => {
                return Err(format!(
                    "it makes `{}`, which has no statement form",
                    crate::canon::format_call(other)
                ))
            }
        }
        Ok(())
    }

    /// A state change made by the block's own statement (G54, G92, G43 H1,
    /// G94): written as that statement, which must hold no expression.
    fn state(&mut self, c: &Canon, span: Span) -> Result<(), String> {
        let own = self.by_span.get(&span);
        match (c, own.map(|s| &s.kind)) {
            // A tool change applies the new tool's length itself.
            (
                Canon::UseToolLengthOffset(_),
                Some(StmtKind::ToolChange | StmtKind::ToolSelect(_)),
            ) => return Ok(()),
            (Canon::SetG5xOffset { index, .. }, Some(StmtKind::WorkOffset { .. }) | None)
                if self.own(span).is_none() =>
            {
                self.push(
                    StmtKind::WorkOffset {
                        index: *index,
                        extended: None,
                    },
                    span,
                );
                return Ok(());
            }
            _ => {}
        }
        match self.own(span) {
            Some(s) => {
                if self.out.last() != Some(&s) {
                    self.out.push(s);
                }
                Ok(())
            }
            None => Err(format!(
                "it makes `{}` from a statement with values known only while it runs",
                crate::canon::format_call(c)
            )),
        }
    }

    fn line(&mut self, kind: MotionKind, p: &[f64; 6], span: Span) {
        let mut m = Motion::new(kind);
        m.target.x = self.coord(p[0], span);
        m.target.y = self.coord(p[1], span);
        m.target.z = self.coord(p[2], span);
        self.rotary(&mut m, &p[3..6], span);
        self.pos = *p;
        self.last_motion = Some(kind);
        self.push(StmtKind::Motion(Box::new(m)), span);
    }

    fn rotary(&self, m: &mut Motion, abc: &[f64], span: Span) {
        let slots = [&mut m.target.a, &mut m.target.b, &mut m.target.c];
        for (k, slot) in slots.into_iter().enumerate() {
            if abc[k] != self.pos[3 + k] || abc[k] != 0.0 {
                *slot = self.coord(abc[k], span);
            }
        }
    }

    fn arc(&mut self, c: &Canon, span: Span) -> Result<(), String> {
        let Canon::ArcFeed {
            first_end,
            second_end,
            first_axis,
            second_axis,
            rotation,
            axis_end,
            abc,
        } = c
        else {
            return Ok(());
        };
        if rotation.abs() != 1 {
            return Err("it makes an arc of several turns".into());
        }
        let dir = if *rotation < 0 {
            ArcDir::Cw
        } else {
            ArcDir::Ccw
        };
        let kind = MotionKind::Arc(dir);
        let (f, s, n) = plane_axes(self.plane);
        let mut end = [0.0; 6];
        (end[f], end[s], end[n]) = (*first_end, *second_end, *axis_end);
        end[3..6].copy_from_slice(abc);
        let end = self.shifted(&end);
        let mut at = [0.0; 6];
        (at[f], at[s]) = (*first_axis, *second_axis);
        let at = self.shifted(&at);
        let (first_axis, second_axis) = (at[f], at[s]);
        let mut m = Motion::new(kind);
        m.target.x = self.coord(end[0], span);
        m.target.y = self.coord(end[1], span);
        m.target.z = self.coord(end[2], span);
        self.rotary(&mut m, abc, span);
        let mut centre = [None, None, None];
        centre[f] = self.coord(first_axis - self.pos[f], span);
        centre[s] = self.coord(second_axis - self.pos[s], span);
        let [i, j, k] = centre;
        m.arc = ArcData {
            i,
            j,
            k,
            ..ArcData::default()
        };
        self.pos = end;
        self.last_motion = Some(kind);
        self.push(StmtKind::Motion(Box::new(m)), span);
        Ok(())
    }
}

pub fn plane_of(pl: CanonPlane) -> Plane {
    match pl {
        CanonPlane::XY => Plane::XY,
        CanonPlane::XZ => Plane::ZX,
        CanonPlane::YZ => Plane::YZ,
    }
}

/// A statement with no expression in it (it can be written again as is).
pub fn literal(s: &Stmt) -> bool {
    match serde_json::to_value(&s.kind) {
        Ok(v) => !holds_expr(&v),
        Err(_) => false,
    }
}

fn holds_expr(v: &serde_json::Value) -> bool {
    match v {
        serde_json::Value::Object(m) => m.iter().any(|(k, v)| k == "Expr" || holds_expr(v)),
        serde_json::Value::Array(a) => a.iter().any(holds_expr),
        _ => false,
    }
}

/// The program's statements by span (to write a block's own statement).
pub fn statements_by_span(p: &Program) -> HashMap<Span, Stmt> {
    let mut m = HashMap::new();
    for b in &p.blocks {
        for s in &b.stmts {
            m.entry(s.span).or_insert_with(|| s.clone());
        }
    }
    m
}
