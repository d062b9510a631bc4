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

use super::follow_block;
use super::levels::Modal;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{
    Axes, Block, CannedCycle, Coord, CycleCall, Motion, MotionKind, Program, Stmt, StmtKind, Value,
};
use crate::span::Span;

mod params;

/// A mapped call waiting for its hole positions.
pub(super) struct Pending {
    cycle: CannedCycle,
    return_initial: bool,
    rtp: Value,
    first: bool,
    /// The feed the cycle runs at, when it is not the one in force (tapping).
    feed: Option<Value>,
    /// The feed to set again after the cycle (tapping changed it).
    restore_feed: Option<Value>,
}

pub(super) struct Pass<'a> {
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
    fn block(&mut self, p: &mut Program, mut b: Block, out: &mut Vec<Block>) {
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

    pub(super) fn refuse(&mut self, span: Span, msg: String, label: &str) {
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
}
