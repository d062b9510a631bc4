//! Heidenhain drilling cycle definitions to word-address canned cycles,
//! for a target without Q-parameter cycles. Runs before
//! [`super::to_named`], so a Siemens target gets `MCALL CYCLE8x` from the
//! G8x made here. The reverse of [`super::to_tnc`]:
//!
//! * `CYCL DEF 200|201|203` is remembered; each call (`L X Y .. M99`,
//!   `CYCL CALL`, `CYCL CALL POS X Y`) drills one hole: the first call
//!   after the definition (or after any other block) is
//!   `G98|G99 G8x X Y Z R [Q] [P] F`, the next calls `X Y`, and `G80`
//!   comes before the next block that is not a call.
//! * R = Q203 + Q200, Z = Q203 + Q201, F = Q206.
//! * The retract level is Q203 + |Q204| (as the interpreter runs it): at
//!   or below R → G99; above R → G98, with a `G0 Z<level>` first when the
//!   Z before the cycle is not that level (a rapid the source does not
//!   make: `--verify` lists it).
//! * 200: Q211 > 0 → G82 P (in the target's dwell unit); Q202 less than
//!   the depth → G83 Q = Q202; else G81. 203: Q213 = 0 → G83 Q = Q202;
//!   Q213 > 0 → G73 Q = Q202 (the back-off Q256 is the control's own in
//!   the target [?]). 201: Q211 = 0 → G85, Q211 > 0 → G89 P; its
//!   retraction feed Q208 must be 0 or Q206 (G85/G89 feed out at F).
//! * 207 RIGID TAPPING: Q239 > 0 → G84, Q239 < 0 → G74 (left hand),
//!   F = |Q239| × S (feed per minute; S must be a number known here, and
//!   the spindle must already turn the way the hand needs: M3 for G84,
//!   M4 for G74, since G84/G74 do not set it as 207 does). The interpreter
//!   runs 207 as CYCLE84 (a rigid tap back to the set-up clearance), G84
//!   feeds out to the retract level: the same as long as Q204 ≤ Q200
//!   (G99); a higher Q204 (G98) adds a feed from R up to it.
//! * 206 TAPPING with a floating holder: G84 under M3, G74 under M4 (the
//!   hand is the spindle's: 206 has no pitch), F = Q206, P = Q211.
//! * No equivalent (E0610): a dwell at the top (Q210), a decrement
//!   (Q212), a dwell together with pecking, 203 with a dwell, the other
//!   numbered cycles, `CYCL CALL PAT` and `M89` calls.

mod faces;
pub(super) mod inline;
mod sections;
pub(super) mod subprograms;

use super::levels::Modal;
use super::{decimal, follow_block};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::DwellUnit;
use crate::ir::{
    Axes, Block, CannedCycle, CompSide, Coord, CycleDef, CycleKind, CycleRunKind, Motion,
    MotionKind, Program, Stmt, StmtKind, Value,
};
use crate::span::Span;

mod tap;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    subprograms::number_main(p, from, to);
    if super::to_tnc::q_cycle(to, "drill").is_some() {
        return;
    }
    faces::run(p, to, diags);
    let mut pass = Pass {
        to,
        modal: Modal::new(from),
        def: None,
        in_cycle: false,
        fresh: false,
        cycle_feed: None,
        diags,
    };
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        pass.block(b, &mut out);
    }
    p.blocks = out;
}

/// A definition mapped to its canned cycle (without the hole position).
#[derive(Clone)]
struct Mapped {
    cycle: CannedCycle,
    r: f64,
    rtp: f64,
    feed: f64,
}

struct Pass<'a> {
    to: &'a DialectSpec,
    modal: Modal,
    /// The definition in force: mapped, or the reason it cannot be.
    def: Option<Result<Mapped, String>>,
    /// A canned cycle is in force in the output (G80 still to come).
    in_cycle: bool,
    /// A definition came since the last canned cycle was written.
    fresh: bool,
    /// The feed the canned cycle set (Q206).
    cycle_feed: Option<f64>,
    diags: &'a mut Vec<Diagnostic>,
}

impl Pass<'_> {
    fn block(&mut self, mut b: Block, out: &mut Vec<Block>) {
        let call = b.stmts.iter().find_map(|s| match &s.kind {
            StmtKind::CycleRun(k) => Some((k.clone(), s.span)),
            _ => None,
        });
        let def = b.stmts.iter().find_map(|s| match &s.kind {
            StmtKind::CycleDef(d) => Some(((**d).clone(), s.span)),
            _ => None,
        });
        if let Some((d, span)) = &def {
            self.def = Some(self.map(d, *span));
            self.fresh = true;
            b.stmts.retain(|s| !matches!(s.kind, StmtKind::CycleDef(_)));
        }
        let Some((kind, span)) = call else {
            if self.in_cycle && !b.stmts.is_empty() {
                out.push(self.cancel(&b, b.span));
            }
            for s in &b.stmts {
                self.modal.see(s);
            }
            if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() || def.is_none() {
                out.push(b);
            }
            return;
        };
        let m = match self.def.clone() {
            Some(Ok(m)) => m,
            Some(Err(why)) => return self.refuse(span, &why, b, out),
            None => return out.push(b),
        };
        let mut stmts = Vec::new();
        let mut pos = Axes::default();
        let mut other = Axes::default();
        for s in std::mem::take(&mut b.stmts) {
            match s.kind {
                StmtKind::CycleRun(_) => {}
                // The cycle runs at Q206; a feed here is the one in force
                // after it (set again with G80).
                StmtKind::Feed(v) => self.modal.feed = Some(v),
                StmtKind::RadiusComp {
                    side: CompSide::Off,
                    ..
                } => {}
                StmtKind::Motion(mv) if mv.kind == MotionKind::Rapid && mv.arc.is_empty() => {
                    pos.x = mv.target.x.clone();
                    pos.y = mv.target.y.clone();
                    other = mv.target.clone();
                    other.x = None;
                    other.y = None;
                }
                kind => stmts.push(Stmt::new(kind, s.span)),
            }
        }
        match &kind {
            CycleRunKind::Block | CycleRunKind::Call => {}
            CycleRunKind::Pos { axes: a, .. } => {
                pos.x = a.x.clone();
                pos.y = a.y.clone();
                other.z = a.z.clone();
            }
            CycleRunKind::Pattern { .. } | CycleRunKind::Modal => {
                let why = "a pattern or modal (M89) cycle call has no mapping".to_string();
                b.stmts = stmts;
                return self.refuse(span, &why, b, out);
            }
        }
        if [&pos.x, &pos.y, &other.z].iter().any(|c| incremental(c)) || !self.modal.absolute {
            let why = "an incremental hole position".to_string();
            b.stmts = stmts;
            return self.refuse(span, &why, b, out);
        }
        let mut before = Vec::new();
        if !other.is_empty() {
            let mut mv = Motion::new(MotionKind::Rapid);
            mv.target = other;
            let s = Stmt::new(StmtKind::Motion(Box::new(mv)), span);
            self.modal.see(&s);
            if self.in_cycle {
                before.push(self.cancel(&b, span));
            }
            before.push(follow_block(&b, vec![s]));
        }
        self.modal.follow(&pos);
        if self.in_cycle && before.is_empty() && !self.fresh {
            let mut mv = Motion::new(MotionKind::Implicit);
            mv.target = pos;
            stmts.insert(0, Stmt::new(StmtKind::Motion(Box::new(mv)), span));
        } else {
            let level = self
                .modal
                .z
                .as_ref()
                .and_then(Value::number)
                .map(|d| d.to_f64());
            let initial = m.rtp > m.r + 1e-9;
            if initial && level.is_none_or(|z| (z - m.rtp).abs() > 1e-9) {
                let mut mv = Motion::new(MotionKind::Rapid);
                mv.target.z = Some(coord(m.rtp, span));
                before.push(follow_block(
                    &b,
                    vec![Stmt::new(StmtKind::Motion(Box::new(mv)), span)],
                ));
            }
            let mut c = m.cycle.clone();
            // `CYCL CALL` drills where the tool is: the position is
            // written so that the next `X Y` blocks repeat the cycle.
            let here = |v: &Option<Value>, span| {
                v.as_ref().map(|v| Coord {
                    value: v.clone(),
                    dim: None,
                    span,
                })
            };
            c.target.x = pos.x.or_else(|| here(&self.modal.x, span));
            c.target.y = pos.y.or_else(|| here(&self.modal.y, span));
            stmts.insert(0, Stmt::new(StmtKind::ReturnToInitial(initial), span));
            stmts.insert(1, Stmt::new(StmtKind::Cycle(Box::new(c)), span));
            stmts.push(Stmt::new(
                StmtKind::Feed(Value::Number(decimal(m.feed))),
                span,
            ));
            self.cycle_feed = Some(m.feed);
            self.in_cycle = true;
            self.fresh = false;
        }
        self.modal.z = Some(Value::Number(decimal(m.rtp)));
        out.extend(before);
        b.stmts = stmts;
        out.push(b);
    }

    /// `G80`, with the feed in force before the cycle set again.
    fn cancel(&mut self, like: &Block, span: Span) -> Block {
        self.in_cycle = false;
        let mut stmts = vec![Stmt::new(StmtKind::CycleCancel, span)];
        let old = self.modal.feed.as_ref().and_then(Value::number);
        if let (Some(old), Some(new)) = (old, self.cycle_feed.take()) {
            if (old.to_f64() - new).abs() > 1e-9 {
                stmts.push(Stmt::new(StmtKind::Feed(Value::Number(old)), span));
            }
        }
        follow_block(like, stmts)
    }

    fn refuse(&mut self, span: Span, why: &str, b: Block, out: &mut Vec<Block>) {
        self.diags.push(
            Diagnostic::new(
                Code::PortCycle,
                format!("this cycle call cannot be ported: {why}"),
            )
            .primary(span, "the cycle is called here")
            .help("write the cycle with the target's own means, or use --expand-cycles"),
        );
        out.push(b);
    }

    /// The canned cycle for a definition, or why there is none.
    fn map(&mut self, d: &CycleDef, span: Span) -> Result<Mapped, String> {
        let q = |n: u32| d.param(n).and_then(Value::number).map(|v| v.to_f64());
        let need = |n: u32| q(n).ok_or(format!("Q{n} is not a number known here"));
        if d.number == 207 {
            return self.map_tap(d, span);
        }
        if d.number == 206 {
            return self.map_float_tap(d, span);
        }
        if !matches!(d.number, 200 | 201 | 203) {
            return Err(format!(
                "cycle {} {} has no canned-cycle equivalent",
                d.number, d.name
            ));
        }
        let (top, sdis, depth) = (need(203)?, need(200)?.abs(), need(201)?);
        let (feed, peck) = (need(206)?, q(202).unwrap_or(0.0).abs());
        let (dwell, top_dwell) = (q(211).unwrap_or(0.0), q(210).unwrap_or(0.0));
        if top_dwell != 0.0 {
            return Err("a dwell at the top (Q210)".into());
        }
        let pecking = d.number == 203 || (peck > 0.0 && peck < depth.abs());
        if pecking && dwell != 0.0 {
            return Err(format!("pecking with a dwell at the bottom (Q211={dwell})"));
        }
        if pecking && q(212).unwrap_or(0.0) != 0.0 {
            return Err("pecking with a decrement (Q212)".into());
        }
        if d.number == 201 && !matches!(q(208), Some(f) if f == 0.0 || f == feed) {
            return Err("reaming with a retraction feed Q208 other than Q206".into());
        }
        let kind = match (d.number, pecking, dwell > 0.0) {
            (201, _, true) => CycleKind::BoreDwellFeedOut,
            (201, _, false) => CycleKind::BoreFeedOut,
            (203, _, _) if q(213).unwrap_or(0.0) > 0.0 => CycleKind::ChipBreak,
            (_, true, _) => CycleKind::Peck,
            (_, false, true) => CycleKind::DrillDwell,
            _ => CycleKind::Drill,
        };
        self.target_has(kind)?;
        let (r, rtp) = (top + sdis, top + q(204).unwrap_or(0.0).abs());
        let mut c = plain_cycle(kind, r);
        c.target.z = Some(coord(top + depth, span));
        if pecking {
            c.q = Some(Value::Number(decimal(peck)));
        } else if dwell > 0.0 {
            c.p = Some(Value::Number(self.dwell_word(dwell)?));
        }
        Ok(Mapped {
            cycle: c,
            r,
            rtp,
            feed,
        })
    }

    /// Err when the target has no word for the cycle and no named cycles.
    pub(super) fn target_has(&self, kind: CycleKind) -> Result<(), String> {
        if self.to.code_for(Meaning::Cycle(kind)).is_none()
            && !self.to.has(crate::dialect::Capability::NamedCycles)
        {
            return Err(format!(
                "{} has no `{}`",
                self.to.name,
                Meaning::Cycle(kind).name()
            ));
        }
        Ok(())
    }

    /// A dwell in seconds as the target's P.
    pub(super) fn dwell_word(&self, seconds: f64) -> Result<crate::ir::Decimal, String> {
        let ms = self.to.code_for(Meaning::Dwell).is_some_and(|c| {
            c.dwell_units
                .iter()
                .any(|(l, u)| *l == 'P' && *u == DwellUnit::Milliseconds)
        });
        let v = if ms { seconds * 1000.0 } else { seconds };
        let d = decimal(v);
        if ms && !d.is_integer() {
            return Err(format!(
                "a dwell of {seconds} s is not a whole number of milliseconds"
            ));
        }
        Ok(d)
    }
}

/// A canned cycle with its R level and nothing else yet.
fn plain_cycle(kind: CycleKind, r: f64) -> CannedCycle {
    CannedCycle {
        kind,
        target: Axes::default(),
        r: Some(Value::Number(decimal(r))),
        q: None,
        p: None,
        repeat: None,
        i: None,
        j: None,
        k: None,
    }
}

fn incremental(c: &Option<Coord>) -> bool {
    c.as_ref()
        .is_some_and(|c| c.dim == Some(crate::ir::DimMode::Incremental))
}

fn coord(v: f64, span: Span) -> Coord {
    Coord {
        value: Value::Number(decimal(v)),
        dim: None,
        span,
    }
}
