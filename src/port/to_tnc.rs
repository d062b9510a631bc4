//! Word-address drilling, tapping and boring cycles to Heidenhain cycle definitions, for a
//! target whose cycle table gives drilling as Q-parameter cycles (a
//! `drill` cycle with Q200/Q201/Q203/Q204, `dialects/heidenhain.xml`) and
//! has no code for the G8x. Runs after [`super::to_word`], so Siemens
//! `CYCLE81/82/83/84/85/86/89` reach it as G8x.
//!
//! `G98|G99 G8x X Y Z R Q P F` becomes `CYCL DEF 200|203 ...` (written
//! again only when a parameter changes) and `L X Y R0 FMAX M99` per hole
//! (the first hole and every position-only block after it); a cycle block
//! without X/Y is a `CYCL CALL`. `G80` and `G98`/`G99` go (the calls are
//! not modal). The parameters:
//!
//! * Q203 surface = R and Q200 set-up clearance = 0: the workpiece top is
//!   not known, and the R plane is where both controls start feeding.
//! * Q201 depth = Z − R (negative into the material).
//! * Q204 2nd set-up clearance = the retract level − R: G99 → 0; G98 →
//!   the initial level (the Z before the cycle, or R when R is higher).
//! * Q206 = the feed in force; Q210 = 0.
//! * G81 → 200 with Q202 = |Q201| (one plunge), Q211 = 0; G82 → 200 with
//!   Q211 = P in seconds.
//! * G83 → 203 with Q202 = Q, Q212 = 0, Q213 = 0 (full retract to the
//!   set-up clearance after every infeed), Q205 = 0, Q208 = 0 [?: 0
//!   retracts at the plunging feed on some controls; the interpreter and
//!   G83 retract at rapid], Q256 = the G83 re-entry distance.
//! * G73 → 203 with Q213 = 99 breaks (no full retract before the bottom)
//!   and Q256 = the back-off (0.254 mm / 0.010 in, LinuxCNC's G73 value;
//!   Fanuc's is machine parameter 5114 [?]).
//!
//! * G84/G74 → 207 RIGID TAPPING NEW with Q239 = the pitch: F / S under
//!   feed per minute, F under G95; positive right hand (G84), negative
//!   left hand (G74).
//! * G85 → 201 REAMING with Q208 = Q206 (feed out), Q211 = 0; G89 → 201
//!   with Q211 = P.
//! * G86 → 202 BORING with Q211 = P, Q214 = 0 (no disengaging move),
//!   Q336 = 0, Q208 = 0 [?: 0 may retract at the plunging feed on the
//!   control; the interpreter retracts at rapid, as G86 does]. 202 stops
//!   the spindle oriented where G86 stops it free; the moves are the same.
//!
//! R, Z, the initial level, P and S (tapping) must be numbers known here;
//! other cycles (G76, G87, G88) have no mapping: E0610.

use super::levels::Modal;
use super::tnc_labels::label;
use super::{decimal, follow_block};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{
    Block, CannedCycle, CompSide, CycleDef, CycleKind, CycleRunKind, FeedMode, Motion, MotionKind,
    Program, QParam, Stmt, StmtKind, Value,
};
use crate::span::Span;

mod faces;
mod flow;
mod formulas;
mod jumps;
mod labels;
mod loops;
pub mod modes;
pub mod named;
mod osubs;
pub mod sub_text;
pub mod subprograms;
mod values;
mod vars;

/// Variables, loops and jumps in Klartext's forms (Q parameters, `LBL`,
/// `FN 9..12`), for a Klartext target: see [`flow`].
pub(super) fn variables_and_flow(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.family == crate::dialect::Family::Klartext {
        formulas::run(p, diags);
        flow::run(p, diags);
    }
}

/// The target's Q-parameter cycle of `kind` (`drill`, `peck`).
pub(super) fn q_cycle<'a>(to: &'a DialectSpec, kind: &str) -> Option<&'a crate::dialect::CycleSig> {
    to.cycles.iter().find(|c| {
        c.kind == kind
            && c.name.parse::<u32>().is_ok()
            && ["Q200", "Q201", "Q203", "Q204"]
                .iter()
                .all(|q| c.param_index(q).is_some())
    })
}

/// Whether this pass maps the word-address cycle `kind` (to_word hands
/// named cycles over only for these).
pub(super) fn maps(kind: CycleKind) -> bool {
    values::target(kind).is_some()
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::NamedCycles) || q_cycle(to, "drill").is_none() {
        return;
    }
    let mut pass = Pass {
        from,
        to,
        modal: Modal::new(from),
        active: None,
        last_def: None,
        initial: None,
        per_rev: false,
        diags,
    };
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        pass.block(b, &mut out);
    }
    p.blocks = out;
}

/// `L X Y R0 FMAX M99`, or `CYCL CALL` where no position is given.
pub(super) fn hole_stmts(
    x: Option<crate::ir::Coord>,
    y: Option<crate::ir::Coord>,
    span: Span,
) -> Vec<Stmt> {
    if x.is_none() && y.is_none() {
        return vec![Stmt::new(StmtKind::CycleRun(CycleRunKind::Call), span)];
    }
    let mut m = Motion::new(MotionKind::Rapid);
    m.target.x = x;
    m.target.y = y;
    vec![
        Stmt::new(StmtKind::Motion(Box::new(m)), span),
        Stmt::new(
            StmtKind::RadiusComp {
                side: CompSide::Off,
                register: None,
                diameter: false,
            },
            span,
        ),
        Stmt::new(StmtKind::CycleRun(CycleRunKind::Block), span),
    ]
}

struct Pass<'a> {
    from: &'a DialectSpec,
    to: &'a DialectSpec,
    modal: Modal,
    /// The cycle in force (for the words later blocks leave out).
    active: Option<CannedCycle>,
    last_def: Option<CycleDef>,
    /// The Z when cycle mode began (the G98 level).
    initial: Option<Value>,
    /// Feed per revolution (G95) in force.
    per_rev: bool,
    diags: &'a mut Vec<Diagnostic>,
}

fn unmapped(to: &DialectSpec, m: Meaning) -> bool {
    to.code_for(m).is_none()
}

impl Pass<'_> {
    fn block(&mut self, mut b: Block, out: &mut Vec<Block>) {
        for s in &b.stmts {
            if !matches!(s.kind, StmtKind::Cycle(_) | StmtKind::Motion(_)) {
                self.modal.see(s);
            }
            if let StmtKind::FeedMode(m) = &s.kind {
                self.per_rev = *m == FeedMode::PerRevolution;
            }
        }
        let mut cur = Vec::new();
        let mut def = None;
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::ReturnToInitial(v) if unmapped(self.to, Meaning::ReturnMode(v)) => {}
                StmtKind::CycleCancel if unmapped(self.to, Meaning::CycleCancel) => {
                    self.active = None;
                }
                StmtKind::Cycle(c) if unmapped(self.to, Meaning::Cycle(c.kind)) => {
                    if let Some(d) = self.define(&c, span) {
                        if self.last_def.as_ref() != Some(&d) {
                            self.last_def = Some(d.clone());
                            def = Some(Stmt::new(StmtKind::CycleDef(Box::new(d)), span));
                        }
                        cur.extend(self.hole(c.target.x.clone(), c.target.y.clone(), span));
                    }
                }
                StmtKind::Motion(m) if self.active.is_some() && m.kind == MotionKind::Implicit => {
                    self.modal.follow(&m.target);
                    if m.target.iter().any(|(a, _)| a != 'X' && a != 'Y') {
                        self.refuse(
                            Code::PortCycleBlock,
                            span,
                            "a block in cycle mode that does more than give the next hole position",
                        );
                        continue;
                    }
                    cur.extend(self.hole(m.target.x.clone(), m.target.y.clone(), span));
                }
                kind => {
                    let s = Stmt::new(kind, span);
                    if matches!(s.kind, StmtKind::Motion(_)) {
                        self.active = None;
                        self.modal.see(&s);
                    }
                    cur.push(s);
                }
            }
        }
        if let Some(d) = def {
            out.push(follow_block(&b, vec![d]));
        }
        b.stmts = cur;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            out.push(b);
        }
    }

    /// `L X Y R0 FMAX M99`, or `CYCL CALL` where no position is given.
    fn hole(
        &mut self,
        x: Option<crate::ir::Coord>,
        y: Option<crate::ir::Coord>,
        span: Span,
    ) -> Vec<Stmt> {
        hole_stmts(x, y, span)
    }

    fn refuse(&mut self, code: Code, span: Span, msg: &str) {
        self.diags.push(
            Diagnostic::new(code, msg.to_string())
                .primary(span, "here")
                .help("write the cycle with numbers under G90, or use --expand-cycles"),
        );
    }

    fn num(&mut self, v: Option<&Value>, span: Span, what: &str) -> Option<f64> {
        match v.and_then(Value::number) {
            Some(d) => Some(d.to_f64()),
            None => {
                self.refuse(
                    Code::PortRunTimeValue,
                    span,
                    &format!("the cycle's {what} is not a number known here"),
                );
                None
            }
        }
    }

    /// The cycle definition for `c` (words left out come from the cycle in force).
    fn define(&mut self, c: &CannedCycle, span: Span) -> Option<CycleDef> {
        let g = Meaning::Cycle(c.kind).name();
        let Some((kind, name)) = values::target(c.kind) else {
            self.diags.push(
                Diagnostic::new(
                    Code::PortCycle,
                    format!("`{g}` has no Heidenhain-style cycle mapping in the port yet"),
                )
                .primary(span, "this cycle")
                .help("use --expand-cycles to write the moves it makes"),
            );
            return None;
        };
        if !self.modal.absolute || c.repeat.is_some() {
            self.refuse(
                Code::PortCycle,
                span,
                &format!("`{g}` in incremental mode or with a repeat count"),
            );
            return None;
        }
        if self.active.is_none() {
            self.initial = self.modal.z.clone();
        }
        let prev = self.active.clone().filter(|a| a.kind == c.kind);
        let pick = |own: &Option<Value>, old: Option<&Option<Value>>| {
            own.clone().or_else(|| old.cloned().flatten())
        };
        let r = pick(&c.r, prev.as_ref().map(|a| &a.r));
        let z = c.target.z.as_ref().map(|z| z.value.clone()).or_else(|| {
            prev.as_ref()
                .and_then(|a| a.target.z.as_ref().map(|z| z.value.clone()))
        });
        let q = pick(&c.q, prev.as_ref().map(|a| &a.q));
        let dwell = pick(&c.p, prev.as_ref().map(|a| &a.p));
        let r = self.num(r.as_ref(), span, "R plane")?;
        let z = self.num(z.as_ref(), span, "depth Z")?;
        let rtp = if self.modal.return_initial {
            // The initial level is the Z when cycle mode began (a G99
            // cycle before in the same mode leaves the tool at R).
            let init = self.num(self.initial.clone().as_ref(), span, "initial level (G98)")?;
            init.max(r)
        } else {
            r
        };
        let feed = self.num(self.modal.feed.clone().as_ref(), span, "feed")?;
        let sig = q_cycle(self.to, kind)?;
        let levels = values::Levels { r, z, rtp, feed };
        let mut vals = values::common(&levels);
        match c.kind {
            CycleKind::Drill => vals.push(("Q202", (z - r).abs())),
            CycleKind::DrillDwell => {
                vals.push(("Q202", (z - r).abs()));
                let p = self.num(dwell.as_ref(), span, "dwell P")?;
                values::set(&mut vals, "Q211", p * self.dwell_scale());
            }
            CycleKind::Tap | CycleKind::TapLeft => {
                let pitch = self.pitch(feed, span)?;
                let hand = if c.kind == CycleKind::Tap { 1.0 } else { -1.0 };
                vals.push(("Q239", hand * pitch));
            }
            CycleKind::BoreFeedOut | CycleKind::BoreDwellFeedOut => {
                vals.push(("Q208", feed));
                if c.kind == CycleKind::BoreDwellFeedOut {
                    let p = self.num(dwell.as_ref(), span, "dwell P")?;
                    values::set(&mut vals, "Q211", p * self.dwell_scale());
                }
            }
            CycleKind::Peck | CycleKind::ChipBreak => {
                let q = self.num(q.as_ref(), span, "peck Q")?;
                let chip = c.kind == CycleKind::ChipBreak;
                vals.extend([
                    ("Q202", q.abs()),
                    ("Q212", 0.0),
                    ("Q213", if chip { 99.0 } else { 0.0 }),
                    ("Q205", 0.0),
                    ("Q208", 0.0),
                    ("Q256", self.modal.peck_clearance()),
                ]);
            }
            CycleKind::BoreStopRapidOut => {
                let p = self.num(dwell.as_ref(), span, "dwell P")?;
                values::set(&mut vals, "Q211", p * self.dwell_scale());
                vals.extend([("Q208", 0.0), ("Q214", 0.0), ("Q336", 0.0)]);
            }
            CycleKind::BackBore | CycleKind::BoreManual | CycleKind::FineBore => return None,
        }
        let mut params = Vec::new();
        for ps in &sig.params {
            let v = vals.iter().find(|(n, _)| *n == ps.name).map(|(_, v)| *v)?;
            params.push(QParam {
                q: ps.name[1..].parse().ok()?,
                value: Value::Number(decimal(v)),
                label: Some(values::label(&ps.name).to_string()),
                span,
            });
        }
        let mut active = c.clone();
        active.r = Some(Value::Number(decimal(r)));
        active.q = q;
        active.p = dwell;
        if active.target.z.is_none() {
            active.target.z = prev.and_then(|a| a.target.z);
        }
        self.active = Some(active);
        self.modal.z = Some(Value::Number(decimal(rtp)));
        Some(CycleDef {
            number: sig.name.parse().ok()?,
            name: name.into(),
            params,
        })
    }
}
