//! Word-address canned cycles to named cycle calls, for a target that has
//! named cycles (capability `named-cycles`) and no code for the G8x.
//!
//! `G98|G99 G8x X Y Z R Q P F` followed by position-only blocks and `G80`
//! becomes `MCALL CYCLE8x(RTP, RFP, SDIS, DP, ...)`, `G0 X Y` per hole and
//! `MCALL`. Parameters are placed by name through the target's cycle
//! signature (its `kind` says which cycle does what):
//!
//! * RTP: G99 → R; G98 → the initial level (the Z before the cycle, or R
//!   when R is higher, as the interpreter retracts).
//! * RFP = R and SDIS = 0: the R plane is where both controls start
//!   feeding; the workpiece top is not known, so the split puts it all in
//!   RFP. DP = Z (absolute); DPR is left empty.
//! * G82/G88/G89 P → DTB in seconds (the source's dwell unit for P).
//! * G83 Q → FDPR = Q, DAM = 0 (equal pecks), VARI = 1 (full retract),
//!   _DIS1 = the G83 re-entry distance (0.254 mm / 0.010 in), FRF = 1.
//! * G84/G74 → CYCLE84 with PIT = F / S (signed by hand), SDAC 3 or 4.
//! * G85 → CYCLE85, G86 → CYCLE86 (no lift-off, POSS 0: W0610, the
//!   spindle is oriented where Fanuc only stops it).
//!
//! G73 (chip breaking backs off at rapid, CYCLE83 VARI=0 at feed), G87 and
//! G76 have no equivalent: E0610 (or `--expand-cycles`).

use super::levels::Modal;
use super::{follow_block, number_expr, value_expr};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec, Meaning};
use crate::ir::{
    Axes, Block, CannedCycle, CycleCall, CycleKind, Motion, MotionKind, Program, Stmt, StmtKind,
    Value,
};
use crate::span::Span;

mod params;
use params::Args;

/// The words of the cycle in force (later blocks may leave them out).
#[derive(Clone)]
struct Active {
    kind: CycleKind,
    r: Value,
    bottom: Value,
    q: Option<Value>,
    p: Option<Value>,
}

pub(super) struct Pass<'a> {
    from: &'a DialectSpec,
    to: &'a DialectSpec,
    modal: Modal,
    active: Option<Active>,
    /// The Z when cycle mode began: where G98 returns to (kept while one
    /// cycle follows another without G80, as the controls keep it).
    initial: Option<Value>,
    /// A rapid to write before the next call (see [`Pass::cycle`]).
    pre: Option<Stmt>,
    diags: &'a mut Vec<Diagnostic>,
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if !to.has(Capability::NamedCycles) {
        return;
    }
    let mut pass = Pass {
        from,
        to,
        modal: Modal::new(from),
        active: None,
        initial: None,
        pre: None,
        diags,
    };
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        pass.block(p, b, &mut out);
    }
    p.blocks = out;
}

fn mapped(to: &DialectSpec, meaning: Meaning) -> bool {
    to.code_for(meaning).is_none()
}

impl Pass<'_> {
    fn block(&mut self, p: &mut Program, mut b: Block, out: &mut Vec<Block>) {
        // Feed, speed and modes in the cycle's block apply to the cycle.
        for s in &b.stmts {
            if !matches!(s.kind, StmtKind::Cycle(_) | StmtKind::Motion(_)) {
                self.modal.see(s);
            }
        }
        let mut before = Vec::new();
        let mut cur = Vec::new();
        let mut after = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            match s.kind {
                StmtKind::ReturnToInitial(v) if mapped(self.to, Meaning::ReturnMode(v)) => {
                    self.modal.return_initial = v;
                }
                StmtKind::Cycle(c) if mapped(self.to, Meaning::Cycle(c.kind)) => {
                    if let Some((call, pos)) = self.cycle(p, &c, s.span) {
                        if let Some(pre) = self.pre.take() {
                            let cancel = Stmt::new(StmtKind::ModalCallCancel, s.span);
                            after.push(follow_block(&b, vec![cancel]));
                            after.push(follow_block(&b, vec![pre]));
                        }
                        after.push(follow_block(&b, vec![call]));
                        after.extend(pos.map(|m| follow_block(&b, vec![m])));
                    }
                }
                StmtKind::CycleCancel if mapped(self.to, Meaning::CycleCancel) => {
                    // `MCALL` stands alone in its block.
                    self.active = None;
                    let cancel = Stmt::new(StmtKind::ModalCallCancel, s.span);
                    after.push(follow_block(&b, vec![cancel]));
                }
                StmtKind::Motion(m) if self.active.is_some() => {
                    if m.kind == MotionKind::Implicit {
                        cur.extend(self.repeat(&m, s.span));
                    } else {
                        self.active = None;
                        let cancel = Stmt::new(StmtKind::ModalCallCancel, s.span);
                        before.push(follow_block(&b, vec![cancel]));
                        self.modal
                            .see(&Stmt::new(StmtKind::Motion(m.clone()), s.span));
                        cur.push(Stmt::new(StmtKind::Motion(m), s.span));
                    }
                }
                kind => {
                    let s = Stmt::new(kind, s.span);
                    self.modal.see(&s);
                    cur.push(s);
                }
            }
        }
        out.extend(before);
        b.stmts = cur;
        let keep = !b.stmts.is_empty() || b.number.is_some() || b.label.is_some();
        if b.stmts.is_empty() && !after.is_empty() {
            after[0].number = b.number.take();
            after[0].label = b.label.take();
        } else if keep {
            out.push(b);
        }
        out.extend(after);
    }

    /// A position-only block while the cycle is in force: `G0 X Y`.
    fn repeat(&mut self, m: &Motion, span: Span) -> Option<Stmt> {
        let t = &m.target;
        let only_xy = t.iter().all(|(a, _)| a == 'X' || a == 'Y');
        if !only_xy || !m.arc.is_empty() || m.polar_radius.is_some() || m.polar_angle.is_some() {
            self.diags.push(
                Diagnostic::new(
                    Code::PortCycleBlock,
                    "a block in cycle mode that does more than give the next hole position",
                )
                .primary(span, "only X and Y can repeat a cycle in the target")
                .help("cancel the cycle (G80) and start it again with the new words, or use --expand-cycles"),
            );
            return None;
        }
        let mut pos = Motion::new(MotionKind::Rapid);
        pos.target = Axes {
            x: t.x.clone(),
            y: t.y.clone(),
            ..Axes::default()
        };
        Some(Stmt::new(StmtKind::Motion(Box::new(pos)), span))
    }

    pub(super) fn refuse(&mut self, code: Code, span: Span, msg: String, label: &str, help: &str) {
        self.diags.push(
            Diagnostic::new(code, msg)
                .primary(span, label.to_string())
                .help(help.to_string()),
        );
    }

    /// The call statement and the first hole's positioning move.
    fn cycle(
        &mut self,
        p: &mut Program,
        c: &CannedCycle,
        span: Span,
    ) -> Option<(Stmt, Option<Stmt>)> {
        let g = crate::dialect::Meaning::Cycle(c.kind).name();
        if self.active.is_none() {
            self.initial = self.modal.z.clone();
        }
        if !self.modal.absolute {
            self.refuse(
                Code::PortRunTimeValue,
                span,
                format!("`{g}` in incremental mode (G91)"),
                "R and Z are incremental here",
                "write the cycle under G90, or use --expand-cycles",
            );
            return None;
        }
        if c.repeat
            .as_ref()
            .is_some_and(|r| r.number().and_then(|d| d.as_int()) != Some(1))
        {
            self.refuse(
                Code::PortCycle,
                span,
                format!("`{g}` with a repeat count"),
                "K/L repeats the cycle",
                "write one block per hole, or use --expand-cycles",
            );
            return None;
        }
        if c.target.iter().any(|(a, _)| !matches!(a, 'X' | 'Y' | 'Z')) {
            self.refuse(
                Code::PortCycle,
                span,
                format!("`{g}` with axes other than X Y Z"),
                "only the XY plane with Z as the drilling axis is mapped",
                "use --expand-cycles",
            );
            return None;
        }
        let Some(sig) = self.signature(c.kind, span) else {
            return None;
        };
        let sig = &sig;
        let prev = self.active.clone().filter(|a| a.kind == c.kind);
        let r = c.r.clone().or_else(|| prev.as_ref().map(|a| a.r.clone()));
        let bottom = c
            .target
            .z
            .as_ref()
            .map(|z| z.value.clone())
            .or_else(|| prev.as_ref().map(|a| a.bottom.clone()));
        let (Some(r), Some(bottom)) = (r, bottom) else {
            self.refuse(
                Code::PortRunTimeValue,
                span,
                format!("`{g}` without R or Z"),
                "the cycle's planes are not given",
                "give R and Z in the first block of the cycle",
            );
            return None;
        };
        let q =
            c.q.clone()
                .or_else(|| prev.as_ref().and_then(|a| a.q.clone()));
        let dwell =
            c.p.clone()
                .or_else(|| prev.as_ref().and_then(|a| a.p.clone()));
        let rtp = self.retract_plane(&r, span)?;
        let mut args = Args::new(sig, span);
        let rtp_e = value_expr(p, &rtp, span);
        args.set(p, "RTP", Some(rtp_e));
        let rfp = value_expr(p, &r, span);
        args.set(p, "RFP", Some(rfp));
        let zero = number_expr(p, crate::ir::Decimal::from_int(0), span);
        args.set(p, "SDIS", Some(zero));
        let dp = value_expr(p, &bottom, span);
        args.set(p, "DP", Some(dp));
        self.kind_args(
            p,
            c.kind,
            &mut args,
            &r,
            &rtp,
            q.as_ref(),
            dwell.as_ref(),
            span,
        )?;
        let call = args.finish(self.diags)?;
        // The interpreter reaches the first hole of a block at the level
        // the tool is at when that is above R, otherwise in one rapid to
        // the clearance level (a G98 cycle after G99 holes rises to the
        // initial level on the way): the same rapid in the target.
        let num = |v: &Value| v.number().map(|d| d.to_f64());
        // It is written before the call, after cancelling the call in
        // force (a move under MCALL would drill).
        let rise = match (self.modal.z.as_ref().and_then(num), num(&r), num(&rtp)) {
            (Some(cur), Some(rv), Some(t)) if self.active.is_some() && cur <= rv && t > cur => {
                Some(rtp.clone())
            }
            _ => None,
        };
        self.pre = rise.and_then(|value| {
            let (x, y) = (c.target.x.clone(), c.target.y.clone());
            if x.is_none() && y.is_none() {
                return None;
            }
            let mut m = Motion::new(MotionKind::Rapid);
            m.target.x = x;
            m.target.y = y;
            m.target.z = Some(crate::ir::Coord {
                value,
                dim: None,
                span,
            });
            Some(Stmt::new(StmtKind::Motion(Box::new(m)), span))
        });
        self.active = Some(Active {
            kind: c.kind,
            r,
            bottom,
            q,
            p: dwell,
        });
        self.modal.z = Some(rtp);
        let pos = (c.target.x.is_some() || c.target.y.is_some()).then(|| {
            let mut m = Motion::new(MotionKind::Rapid);
            m.target.x = c.target.x.clone();
            m.target.y = c.target.y.clone();
            Stmt::new(StmtKind::Motion(Box::new(m)), span)
        });
        let call = CycleCall {
            name: call.0,
            args: call.1,
            modal: pos.is_some(),
        };
        Some((Stmt::new(StmtKind::CycleCall(call), span), pos))
    }
}
