//! One statement as text: the exhaustive match of the IR printer.

use super::{flow_id, name, Printer};
use crate::ir::stmt::*;
use crate::ir::{ExprId, Value};

impl Printer<'_> {
    pub(super) fn stmt(&self, k: &StmtKind) -> String {
        use StmtKind as K;
        match k {
            K::Comment { text, style } => format!("comment {} {text:?}", name(style)),
            K::Message(Some(t)) => format!("message {t:?}"),
            K::Message(None) => "message clear".into(),
            K::Tape => "tape".into(),
            K::ProgramStart { number, name: n } => {
                let mut s = "program-start".to_string();
                if let Some(num) = number {
                    s.push_str(&format!(" number={num}"));
                }
                if let Some(n) = n {
                    s.push_str(&format!(" name={n:?}"));
                }
                s
            }
            K::Raw { dialect, text } => format!("raw {dialect} {text:?}"),
            K::TncFunction(f) => format!("tnc-function {} {:?}", f.kind.name(), f.text),
            K::ProgramEnd { name: n } => match n {
                Some(n) => format!("program-end name={n:?}"),
                None => "program-end".into(),
            },
            K::Stock { corner, axis, axes } => {
                let a = axis.map(|a| format!(" axis={a}")).unwrap_or_default();
                format!("stock {}{a}{}", name(corner), self.axes(axes))
            }
            K::ToolDef {
                tool,
                length,
                radius,
            } => {
                let mut s = match tool {
                    ToolRef::Number(v) => format!("tool-def {}", self.value(v)),
                    ToolRef::Name(n) => format!("tool-def {n:?}"),
                };
                self.kv(&mut s, "L", length);
                self.kv(&mut s, "R", radius);
                s
            }
            K::ToolOversize { length, radius } => {
                let mut s = "tool-oversize".to_string();
                self.kv(&mut s, "DL", length);
                self.kv(&mut s, "DR", radius);
                s
            }
            K::Word(w) => format!("word {}={}", w.address(), self.value(&w.value)),
            K::Units { unit, with_feeds } => {
                format!(
                    "units {}{}",
                    name(unit),
                    if *with_feeds { " with-feeds" } else { "" }
                )
            }
            K::Plane(p) => format!("plane {p:?}"),
            K::Distance(d) => format!("distance {}", name(d)),
            K::ArcDistance(d) => format!("arc-distance {}", name(d)),
            K::FeedMode(m) => format!("feed-mode {}", name(m)),
            K::Feed(v) => format!("feed {}", self.value(v)),
            K::SpindleSpeed(v) => format!("speed {}", self.value(v)),
            K::SpindleCss { on, max_rpm } => {
                let mut s = format!("css {}", if *on { "on" } else { "off" });
                self.kv(&mut s, "max-rpm", max_rpm);
                s
            }
            K::Spindle(SpindleState::Orient(a)) => {
                let mut s = "spindle orient".to_string();
                self.kv(&mut s, "angle", a);
                s
            }
            K::Spindle(st) => format!("spindle {}", name(st)),
            K::Coolant(c) => format!("coolant {}", name(c)),
            K::ToolSelect(ToolRef::Number(v)) => format!("tool-select {}", self.value(v)),
            K::ToolSelect(ToolRef::Name(n)) => format!("tool-select {n:?}"),
            K::ToolChange => "tool-change".into(),
            K::ToolPreselect(ToolRef::Number(v)) => format!("tool-preselect {}", self.value(v)),
            K::ToolPreselect(ToolRef::Name(n)) => format!("tool-preselect {n:?}"),
            K::CuttingEdge(v) => format!("cutting-edge {}", self.value(v)),
            K::RadiusComp {
                side,
                register,
                diameter,
            } => {
                let mut s = format!("radius-comp {}", name(side));
                if *diameter {
                    s.push_str(" diameter");
                }
                self.kv(&mut s, "D", register);
                s
            }
            K::LengthComp {
                mode,
                register,
                axes,
            } => {
                let mut s = format!("length-comp {}", name(mode));
                self.kv(&mut s, "H", register);
                s + &self.axes(axes)
            }
            K::OffsetRegister { letter, value } => {
                format!("register {letter}={}", self.value(value))
            }
            K::WorkOffset { index, extended } => {
                let mut s = format!("work-offset {index}");
                self.kv(&mut s, "P", extended);
                s
            }
            K::MachineCoords => "machine-coords".into(),
            K::CoordShift { kind, axes } => {
                format!("coord-shift {}{}", name(kind), self.axes(axes))
            }
            K::SetData { l, words } => format!("set-data L={}{}", self.value(l), self.words(words)),
            K::RefReturn {
                index,
                axes,
                store,
                direct,
            } => {
                let st = match (*store, *direct) {
                    (true, _) => " store",
                    (false, true) => " direct",
                    (false, false) => "",
                };
                format!("ref-return {index}{st}{}", self.axes(axes))
            }
            K::PathMode { mode, words } => format!("path {}{}", name(mode), self.words(words)),
            K::ReturnToInitial(b) => {
                format!("return-level {}", if *b { "initial" } else { "r-plane" })
            }
            K::Transform(t) => self.transform(t),
            K::Dwell { value, unit } => format!("dwell {} {}", self.value(value), name(unit)),
            K::Stop(k) => format!("stop {}", name(k)),
            K::Aux {
                letter,
                code,
                words,
            } => format!("aux {letter}{code}{}", self.words(words)),
            K::DynamicCode {
                letter,
                value,
                words,
            } => {
                format!(
                    "dynamic-code {letter}={}{}",
                    self.expr(*value),
                    self.words(words)
                )
            }
            K::Command { name: n, args } => match args {
                None => format!("command {n}"),
                Some(a) => format!("command {n}({})", self.args(a.iter().map(|a| a.value))),
            },
            K::Motion(m) => self.motion(m),
            K::Pole(axes) => format!("pole{}", self.axes(axes)),
            K::Corner { kind, size } => format!("corner {} {}", name(kind), self.value(size)),
            K::Approach(a) => {
                let mut s = format!(
                    "{} {}{}",
                    if a.depart { "depart" } else { "approach" },
                    name(a.kind),
                    self.axes(&a.target)
                );
                self.kv(&mut s, "LEN", &a.len);
                self.kv(&mut s, "R", &a.radius);
                self.kv(&mut s, "CCA", &a.angle);
                s
            }
            K::CycleDef(c) => {
                let mut s = format!("cycle-def {} {:?}", c.number, c.name);
                for p in &c.params {
                    s.push_str(&format!(" Q{}={}", p.q, self.value(&p.value)));
                    if let Some(l) = &p.label {
                        s.push_str(&format!(" ;{l:?}"));
                    }
                }
                s
            }
            K::CycleLine(l) => format!(
                "cycle-line {}.{}{}",
                l.cycle,
                l.sub,
                self.cycle_words(&l.words)
            ),
            K::CycleRun(r) => match r {
                CycleRunKind::Pos { axes, rapid } => format!(
                    "cycle-run pos{}{}",
                    self.axes(axes),
                    if *rapid { " rapid" } else { "" }
                ),
                CycleRunKind::Pattern { rapid } => {
                    format!("cycle-run pattern{}", if *rapid { " rapid" } else { "" })
                }
                other => format!("cycle-run {}", name(other)),
            },
            K::PatternDef(items) => {
                let mut s = "pattern-def".to_string();
                for i in items {
                    s.push_str(&format!(" {}({} )", i.name, self.cycle_words(&i.words)));
                }
                s
            }
            K::Cycle(c) => self.cycle(c),
            K::CycleCancel => "cycle-cancel".into(),
            K::CycleCall(c) => {
                let modal = if c.modal { "MCALL " } else { "" };
                format!(
                    "cycle-call {modal}{}({})",
                    c.name,
                    self.args(c.args.iter().map(|a| a.value))
                )
            }
            K::ModalCallCancel => "modal-call-cancel".into(),
            K::Assign { var, value } => format!("assign {} = {}", self.var(var), self.expr(*value)),
            K::Declare { ty, vars } => format!("declare {} {}", name(ty), self.decls(vars)),
            K::Goto { target, dir, cond } => {
                let t = match target {
                    JumpTarget::Sequence(v) => format!("N{}", self.value(v)),
                    JumpTarget::Label(l) => l.clone(),
                };
                let c = cond
                    .map(|c| format!(" if {}", self.cond(c)))
                    .unwrap_or_default();
                format!("goto {} {t}{c}", name(dir))
            }
            K::IfThen { cond, then } => {
                format!("if {} then {{{}}}", self.cond(*cond), self.stmt(&then.kind))
            }
            K::If { cond, id } => format!("if {}{}", self.cond(*cond), flow_id(id)),
            K::ElseIf { cond, id } => format!("elseif {}{}", self.cond(*cond), flow_id(id)),
            K::Else { id } => format!("else{}", flow_id(id)),
            K::EndIf { id } => format!("endif{}", flow_id(id)),
            K::While { cond, id } => format!("while {}{}", self.cond(*cond), flow_id(id)),
            K::EndWhile { id } => format!("endwhile{}", flow_id(id)),
            K::Do { id } => format!("do{}", flow_id(id)),
            K::DoWhile { cond, id } => format!("do-while {}{}", self.cond(*cond), flow_id(id)),
            K::Repeat { count, id } => format!("repeat {}{}", self.cond(*count), flow_id(id)),
            K::EndRepeat { id } => format!("endrepeat{}", flow_id(id)),
            K::For { var, from, to } => {
                format!(
                    "for {} = {} to {}",
                    self.var(var),
                    self.expr(*from),
                    self.expr(*to)
                )
            }
            K::EndFor => "endfor".into(),
            K::Loop => "loop".into(),
            K::EndLoop => "endloop".into(),
            K::RepeatUntil => "repeat-until".into(),
            K::Until { cond } => format!("until {}", self.cond(*cond)),
            K::Case {
                selector,
                arms,
                default,
            } => self.case(*selector, arms, default),
            K::SectionRepeat {
                start,
                end,
                count,
                single,
            } => {
                let kw = if *single {
                    "section-repeat-block"
                } else {
                    "section-repeat"
                };
                let e = end.as_ref().map(|e| format!(" {e}")).unwrap_or_default();
                let c = count
                    .map(|c| format!(" P={}", self.expr(c)))
                    .unwrap_or_default();
                format!("{kw} {start}{e}{c}")
            }
            K::Break { id } => format!("break{}", flow_id(id)),
            K::Continue { id } => format!("continue{}", flow_id(id)),
            K::SubStart {
                name: n,
                params,
                id,
            } => {
                let p = if params.is_empty() {
                    String::new()
                } else {
                    format!("({})", self.decls(params))
                };
                format!("sub {n}{p}{}", flow_id(id))
            }
            K::SubEnd { id, value } => format!("endsub{}{}", self.opt_expr(*value), flow_id(id)),
            K::Return { id, value } => format!("return{}{}", self.opt_expr(*value), flow_id(id)),
            K::Call {
                kind,
                target,
                args,
                repeat,
            } => self.call(*kind, target, args, repeat),
            K::SubReturn { to } => {
                let mut s = "sub-return".to_string();
                self.kv(&mut s, "P", to);
                s
            }
            K::ModalMacroCancel => "modal-macro-cancel".into(),
        }
    }

    fn args(&self, args: impl Iterator<Item = Option<ExprId>>) -> String {
        let a: Vec<String> = args
            .map(|a| a.map(|e| self.expr(e)).unwrap_or_default())
            .collect();
        a.join(", ")
    }

    fn decls(&self, vars: &[VarDecl]) -> String {
        let v: Vec<String> = vars
            .iter()
            .map(|d| {
                let dims = if d.dims.is_empty() {
                    String::new()
                } else {
                    let ds: Vec<String> = (0..d.dims.len()).map(|i| d.dim_text(i)).collect();
                    format!("[{}]", ds.join(", "))
                };
                let init = d
                    .init
                    .map(|e| format!("={}", self.expr(e)))
                    .unwrap_or_default();
                format!("{}{dims}{init}", d.name)
            })
            .collect();
        v.join(", ")
    }

    fn motion(&self, m: &Motion) -> String {
        let kind = match m.kind {
            MotionKind::Arc(d) => format!("arc-{}", name(d)),
            MotionKind::Probe { toward, error } => {
                format!(
                    "probe-{}{}",
                    if toward { "toward" } else { "away" },
                    if error { "" } else { "-noerror" }
                )
            }
            MotionKind::Other(code) => format!("G{code}"),
            k @ (MotionKind::Implicit
            | MotionKind::Rapid
            | MotionKind::Linear
            | MotionKind::ArcThrough
            | MotionKind::ArcTangent) => name(k),
        };
        let mut s = format!("motion {kind}{}", self.axes(&m.target));
        for (key, c) in [("I", &m.arc.i), ("J", &m.arc.j), ("K", &m.arc.k)] {
            if let Some(c) = c {
                s.push_str(&format!(" {key}={}", self.coord(c)));
            }
        }
        self.kv(&mut s, "R", &m.arc.radius);
        self.kv(&mut s, "angle", &m.arc.angle);
        self.kv(&mut s, "turns", &m.arc.turns);
        if let Some(mid) = &m.arc.mid {
            s.push_str(&format!(" mid({})", self.axes(mid).trim_start()));
        }
        self.kv(&mut s, "polar-radius", &m.polar_radius);
        self.kv(&mut s, "polar-angle", &m.polar_angle);
        if let Some((k, v)) = &m.corner {
            s.push_str(&format!(" {}={}", name(k), self.value(v)));
        }
        s
    }

    fn cycle(&self, c: &CannedCycle) -> String {
        let mut s = format!("cycle {}{}", name(c.kind), self.axes(&c.target));
        for (key, v) in [
            ("R", &c.r),
            ("Q", &c.q),
            ("P", &c.p),
            ("I", &c.i),
            ("J", &c.j),
            ("K", &c.k),
        ] {
            self.kv(&mut s, key, v);
        }
        self.kv(&mut s, "repeat", &c.repeat);
        s
    }

    fn transform(&self, t: &Transform) -> String {
        match t {
            Transform::Frame {
                op,
                additive,
                axes,
                rpl,
            } => {
                let mut s = format!(
                    "frame {}{}{}",
                    name(op),
                    if *additive { " additive" } else { "" },
                    self.axes(axes)
                );
                self.kv(&mut s, "RPL", rpl);
                s
            }
            Transform::RotateOn { center, angle } => {
                let mut s = format!("rotate on{}", self.axes(center));
                self.kv(&mut s, "R", angle);
                s
            }
            Transform::RotateOff => "rotate off".into(),
            Transform::ScaleOn {
                center,
                factor,
                per_axis,
            } => {
                let mut s = format!("scale on{}", self.axes(center));
                self.kv(&mut s, "P", factor);
                for (l, v) in per_axis {
                    s.push_str(&format!(" {l}={}", self.value(v)));
                }
                s
            }
            Transform::ScaleOff => "scale off".into(),
            Transform::MirrorOn { axes } => format!("mirror on{}", self.axes(axes)),
            Transform::MirrorOff => "mirror off".into(),
        }
    }

    fn case(&self, sel: ExprId, arms: &[CaseArm], default: &Option<(String, JumpDir)>) -> String {
        let mut s = format!("case {}", self.cond(sel));
        for a in arms {
            s.push_str(&format!(
                " {} -> goto {} {}",
                self.expr(a.value),
                name(a.dir),
                a.target
            ));
        }
        if let Some((t, d)) = default {
            s.push_str(&format!(" default -> goto {} {t}", name(d)));
        }
        s
    }

    fn call(
        &self,
        kind: CallKind,
        target: &CallTarget,
        args: &CallArgs,
        repeat: &Option<Value>,
    ) -> String {
        let t = match target {
            CallTarget::Number(n) => n.to_string(),
            CallTarget::Name(n) => format!("{n:?}"),
            CallTarget::Computed(e) => format!("[{}]", self.expr(*e)),
        };
        let mut s = format!("call {} {t}", name(kind));
        match args {
            CallArgs::None => {}
            CallArgs::Positional(a) => s.push_str(&format!("({})", self.args(a.iter().copied()))),
            CallArgs::Letters(ls) => {
                for (l, v) in ls {
                    s.push_str(&format!(" {l}={}", self.value(v)));
                }
            }
        }
        self.kv(&mut s, "repeat", repeat);
        s
    }

    fn cycle_words(&self, ws: &[CycleWord]) -> String {
        ws.iter()
            .map(|w| match &w.value {
                Some(v) => format!(" {}={}", w.name, self.value(v)),
                None => format!(" {}", w.name),
            })
            .collect()
    }
}
