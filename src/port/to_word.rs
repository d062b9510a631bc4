//! Named drilling cycles to word-address canned cycles, for a target
//! without named cycles: `MCALL CYCLE8x(..)` + positioning blocks + `MCALL`
//! become `G98|G99 G8x X Y Z R ..` on the first hole, `X Y` on the next
//! ones and `G80`; a direct `CYCLE8x(..)` drills at the current position
//! (`G8x Z R ..` then `G80`). The reverse of [`super::to_named`]:
//!
//! * R = RFP + SDIS; Z = DP, or RFP − DPR when DPR is given and not 0.
//! * RTP = R → G99; otherwise G98, first moving to RTP (`G0 Z<RTP>`) when
//!   the level before the cycle is not RTP (a rapid the source does not
//!   make: `--verify` lists it).
//! * CYCLE82/88/89 DTB → P in the target's unit; CYCLE83 with VARI = 1,
//!   DAM = 0 and FRF 0 or 1 → G83 with Q = the first infeed
//!   (SDIS + FDPR, or RFP + SDIS − FDEP); CYCLE84 PIT → G84/G74 with
//!   F = |PIT| × S (the feed programmed before is set again after G80).
//!
//! Anything else (degression, chip breaking, lift-off, pitch from MPIT...)
//! is E0610.

use super::levels::Modal;
use super::{decimal, follow_block};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{
    Axes, Block, CannedCycle, Coord, CycleCall, CycleKind, Decimal, DwellUnit, ExprKind, Motion,
    MotionKind, Program, Stmt, StmtKind, Value,
};
use crate::span::Span;

/// A mapped call waiting for its hole positions.
struct Pending {
    cycle: CannedCycle,
    return_initial: bool,
    rtp: Value,
    first: bool,
    /// The feed the cycle runs at, when it is not the one in force (tapping).
    feed: Option<Value>,
    /// The feed to set again after the cycle (tapping changed it).
    restore_feed: Option<Value>,
}

struct Pass<'a> {
    from: &'a DialectSpec,
    to: &'a DialectSpec,
    modal: Modal,
    active: Option<Pending>,
    diags: &'a mut Vec<Diagnostic>,
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::NamedCycles) || !from.has(Capability::NamedCycles) {
        return;
    }
    let mut pass = Pass {
        from,
        to,
        modal: Modal::new(from),
        active: None,
        diags,
    };
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        pass.block(p, b, &mut out);
    }
    p.blocks = out;
}

impl Pass<'_> {
    fn block(&mut self, p: &Program, mut b: Block, out: &mut Vec<Block>) {
        let mut before = Vec::new();
        let mut cur = Vec::new();
        let mut after = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::CycleCall(c) if self.drilling(&c) => {
                    let Some(pend) = self.map_call(p, &c, span) else {
                        continue;
                    };
                    if c.modal {
                        self.active = Some(pend);
                    } else {
                        self.holes(&b, pend, None, span, &mut before, &mut cur);
                        let cancel = Stmt::new(StmtKind::CycleCancel, span);
                        after.push(follow_block(&b, vec![cancel]));
                    }
                }
                StmtKind::ModalCallCancel if self.active.is_some() => {
                    let pend = self.active.take().expect("checked");
                    cur.push(Stmt::new(StmtKind::CycleCancel, span));
                    if let Some(f) = pend.restore_feed {
                        after.push(follow_block(&b, vec![Stmt::new(StmtKind::Feed(f), span)]));
                    }
                }
                StmtKind::ModalCallCancel => cur.push(Stmt::new(StmtKind::CycleCancel, span)),
                StmtKind::Motion(m) if self.active.is_some() => {
                    if let Some(pend) = self.active.take() {
                        let pend = self.holes(&b, pend, Some(&m), span, &mut before, &mut cur);
                        self.active = pend;
                    }
                }
                kind => {
                    let s = Stmt::new(kind, span);
                    self.modal.see(&s);
                    cur.push(s);
                }
            }
        }
        out.extend(before);
        b.stmts = cur;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            out.push(b);
        }
        out.extend(after);
    }

    fn drilling(&self, c: &CycleCall) -> bool {
        self.from.cycle(&c.name).is_some_and(|s| {
            matches!(
                s.kind.as_str(),
                "drill"
                    | "drill-dwell"
                    | "peck"
                    | "tap"
                    | "bore-feed-out"
                    | "bore-stop-rapid-out"
                    | "bore-manual"
                    | "bore-dwell-feed-out"
            )
        })
    }

    fn refuse(&mut self, span: Span, msg: String, label: &str) {
        self.diags.push(
            Diagnostic::new(Code::PortCycle, msg)
                .primary(span, label.to_string())
                .help("use --expand-cycles to write the cycle as the moves it makes"),
        );
    }

    /// One hole (or the call at the current position when `m` is None).
    fn holes(
        &mut self,
        b: &Block,
        mut pend: Pending,
        m: Option<&Motion>,
        span: Span,
        before: &mut Vec<Block>,
        cur: &mut Vec<Stmt>,
    ) -> Option<Pending> {
        let mut target = Axes::default();
        if let Some(m) = m {
            let only_xy = m.target.iter().all(|(a, _)| a == 'X' || a == 'Y');
            let plain = matches!(
                m.kind,
                MotionKind::Implicit | MotionKind::Rapid | MotionKind::Linear
            );
            if !only_xy || !plain || !m.arc.is_empty() {
                self.diags.push(
                    Diagnostic::new(
                        Code::PortCycleBlock,
                        "a block under MCALL that does more than position the next hole",
                    )
                    .primary(
                        span,
                        "only X and Y can follow a modal cycle call in the target",
                    )
                    .help("end the MCALL before this block, or use --expand-cycles"),
                );
                return Some(pend);
            }
            target.x = m.target.x.clone();
            target.y = m.target.y.clone();
        }
        if !pend.first {
            let mut rep = Motion::new(MotionKind::Implicit);
            rep.target = target;
            cur.push(Stmt::new(StmtKind::Motion(Box::new(rep)), span));
            return Some(pend);
        }
        pend.first = false;
        if pend.return_initial && self.modal.z.as_ref() != Some(&pend.rtp) {
            let mut up = Motion::new(MotionKind::Rapid);
            up.target.z = Some(Coord {
                value: pend.rtp.clone(),
                dim: None,
                span,
            });
            before.push(follow_block(
                b,
                vec![Stmt::new(StmtKind::Motion(Box::new(up)), span)],
            ));
        }
        let mut c = pend.cycle.clone();
        let z = c.target.z.take();
        c.target = Axes { z, ..target };
        cur.push(Stmt::new(
            StmtKind::ReturnToInitial(pend.return_initial),
            span,
        ));
        cur.push(Stmt::new(StmtKind::Cycle(Box::new(c)), span));
        if let Some(f) = &pend.feed {
            cur.push(Stmt::new(StmtKind::Feed(f.clone()), span));
        }
        self.modal.z = Some(pend.rtp.clone());
        Some(pend)
    }

    fn map_call(&mut self, p: &Program, c: &CycleCall, span: Span) -> Option<Pending> {
        let sig = self.from.cycle(&c.name)?.clone();
        let arg = |name: &str| -> Option<Value> {
            let i = sig.param_index(name)?;
            let e = c.args.get(i)?.value?;
            Some(match &p.exprs[e].kind {
                ExprKind::Number(d) => Value::Number(*d),
                _ => Value::Expr(e),
            })
        };
        let num = |name: &str| arg(name).and_then(|v| v.number()).map(|d| d.to_f64());
        let given = |name: &str| num(name).is_some_and(|v| v != 0.0);
        let (Some(rtp), Some(rfp)) = (arg("RTP"), arg("RFP")) else {
            self.refuse(
                span,
                format!("{} without RTP or RFP", c.name),
                "the planes are not given",
            );
            return None;
        };
        let sdis = num("SDIS").unwrap_or(0.0).abs();
        let r = if sdis == 0.0 {
            rfp.clone()
        } else {
            match rfp.number() {
                Some(d) => Value::Number(decimal(d.to_f64() + sdis)),
                None => {
                    self.refuse(
                        span,
                        format!("{}: RFP is an expression and SDIS is not 0", c.name),
                        "R = RFP + SDIS cannot be computed",
                    );
                    return None;
                }
            }
        };
        let bottom = if given("DPR") {
            match rfp.number() {
                Some(d) => Value::Number(decimal(d.to_f64() - num("DPR").unwrap_or(0.0).abs())),
                None => {
                    self.refuse(
                        span,
                        format!("{}: DPR relative to an RFP expression", c.name),
                        "Z = RFP - DPR cannot be computed",
                    );
                    return None;
                }
            }
        } else {
            match arg("DP") {
                Some(v) => v,
                None => {
                    self.refuse(span, format!("{} without a depth", c.name), "no DP or DPR");
                    return None;
                }
            }
        };
        let kind = match sig.kind.as_str() {
            "drill" => CycleKind::Drill,
            "drill-dwell" => CycleKind::DrillDwell,
            "peck" => CycleKind::Peck,
            "tap" => {
                if num("PIT").unwrap_or(0.0) < 0.0 {
                    CycleKind::TapLeft
                } else {
                    CycleKind::Tap
                }
            }
            "bore-feed-out" if given("DTB") => CycleKind::BoreDwellFeedOut,
            "bore-feed-out" => CycleKind::BoreFeedOut,
            "bore-stop-rapid-out" => CycleKind::BoreStopRapidOut,
            "bore-manual" => CycleKind::BoreManual,
            _ => CycleKind::BoreDwellFeedOut,
        };
        if self.to.code_for(Meaning::Cycle(kind)).is_none() {
            self.refuse(
                span,
                format!(
                    "{} has no code for `{}` ({})",
                    self.to.name,
                    Meaning::Cycle(kind).name(),
                    c.name
                ),
                "no equivalent canned cycle",
            );
            return None;
        }
        let mut cycle = CannedCycle {
            kind,
            target: Axes::default(),
            r: Some(r.clone()),
            q: None,
            p: None,
            repeat: None,
            i: None,
            j: None,
            k: None,
        };
        cycle.target.z = Some(Coord {
            value: bottom,
            dim: None,
            span,
        });
        let (mut feed, mut restore_feed) = (None, None);
        if given("DTB") || matches!(kind, CycleKind::BoreManual) && arg("DTB").is_some() {
            cycle.p = Some(self.dwell_word(num("DTB").unwrap_or(0.0), span)?);
        }
        match sig.kind.as_str() {
            "peck" => cycle.q = Some(self.peck(&c.name, &num, &given, &rfp, sdis, span)?),
            "tap" => {
                let (tap_feed, before) = self.tap(&c.name, &num, &given, span)?;
                feed = Some(tap_feed);
                restore_feed = Some(before);
            }
            "bore-feed-out" if given("FFR") || given("RFF") => {
                self.refuse(
                    span,
                    format!("{} with its own feeds FFR/RFF", c.name),
                    "the target's cycle feeds at F",
                );
                return None;
            }
            "bore-stop-rapid-out" if ["RPA", "RPO", "RPAP"].iter().any(|n| given(n)) => {
                self.refuse(
                    span,
                    format!("{} with a lift-off", c.name),
                    "G86 has no lift-off",
                );
                return None;
            }
            _ => {}
        }
        let return_initial = rtp != r;
        Some(Pending {
            cycle,
            return_initial,
            rtp,
            first: true,
            feed,
            restore_feed,
        })
    }

    fn dwell_word(&mut self, seconds: f64, span: Span) -> Option<Value> {
        let unit = self.to.code_for(Meaning::Dwell).and_then(|c| {
            c.dwell_units
                .iter()
                .find(|(l, _)| *l == 'P')
                .map(|(_, u)| *u)
        });
        let v = match unit {
            Some(DwellUnit::Milliseconds) => seconds * 1000.0,
            _ => seconds,
        };
        let d = decimal(v);
        if unit == Some(DwellUnit::Milliseconds) && !d.is_integer() {
            self.refuse(
                span,
                format!("a dwell of {seconds} s is not a whole number of milliseconds"),
                "P is in milliseconds in the target",
            );
            return None;
        }
        Some(Value::Number(if d.is_integer() {
            Decimal::from_int(d.as_int()?)
        } else {
            d
        }))
    }

    fn peck(
        &mut self,
        name: &str,
        num: &dyn Fn(&str) -> Option<f64>,
        given: &dyn Fn(&str) -> bool,
        rfp: &Value,
        sdis: f64,
        span: Span,
    ) -> Option<Value> {
        let vari = num("VARI").unwrap_or(0.0);
        let frf = num("FRF").unwrap_or(0.0);
        if vari != 1.0 || given("DAM") || (frf != 0.0 && frf != 1.0) || given("DTB") || given("DTS")
        {
            self.refuse(span, format!("{name} other than equal pecks with full retract (VARI=1, DAM=0, FRF 1, no dwells)"),
                "G83 pecks in equal steps with full retract only");
            return None;
        }
        if given("_DIS1")
            && (num("_DIS1").unwrap_or(0.0) - self.modal.peck_clearance()).abs() > 1e-9
        {
            self.diags.push(
                Diagnostic::new(
                    Code::PortApproximate,
                    format!("{name}: the re-entry distance _DIS1 is a machine parameter for G83"),
                )
                .primary(span, "the target's G83 uses its own re-entry distance")
                .help("check the machine's G83 clearance parameter"),
            );
        }
        let step = if given("FDPR") {
            sdis + num("FDPR")?.abs()
        } else {
            match (rfp.number(), num("FDEP")) {
                (Some(r), Some(f)) => r.to_f64() + sdis - f,
                _ => {
                    self.refuse(
                        span,
                        format!("{name} without a first depth"),
                        "Q needs FDPR or FDEP",
                    );
                    return None;
                }
            }
        };
        Some(Value::Number(decimal(step)))
    }

    /// CYCLE84: the tapping feed F = |PIT| × S and the feed in force before.
    fn tap(
        &mut self,
        name: &str,
        num: &dyn Fn(&str) -> Option<f64>,
        given: &dyn Fn(&str) -> bool,
        span: Span,
    ) -> Option<(Value, Value)> {
        let s = self
            .modal
            .speed
            .as_ref()
            .and_then(Value::number)
            .map(|d| d.to_f64());
        match (num("PIT").filter(|v| *v != 0.0), s, self.modal.feed.clone()) {
            (Some(pit), Some(s), Some(before)) if !given("MPIT") && !given("SST") => {
                Some((Value::Number(decimal(pit.abs() * s)), before))
            }
            _ => {
                self.refuse(
                    span,
                    format!("{name} needs PIT, a known speed S and feed F before it"),
                    "the feed per minute F = PIT × S cannot be computed",
                );
                None
            }
        }
    }
}
