//! Named (Siemens) cycles that have a Heidenhain cycle of their own and
//! go to it straight, not through the word-address G8x of
//! [`super::super::to_word`] (which cannot carry what they say):
//!
//! * CYCLE85 / CYCLE89 with their own feeds FFR / RFF → `CYCL DEF 201
//!   REAMING` with Q206 = FFR and Q208 = RFF (a feed of 0 is the feed in
//!   force, as the Siemens cycle takes it [?]); the other CYCLE85/89 keep
//!   the G85/G89 route.
//! * CYCLE71 face milling → `CYCL DEF 232 FACE MILLING` ([`super::faces`]).
//!
//! `MCALL CYCLEnn(..)` becomes the definition, every following block that
//! positions X/Y `L X Y R0 FMAX M99`, and the closing `MCALL` goes; a call
//! without MCALL is the definition and `CYCL CALL` (where it stands).
//! Runs before `to_word`, only for a target with Q-parameter cycles and no
//! named ones.

use super::super::levels::Modal;
use super::super::{decimal, follow_block};
use super::{hole_stmts, q_cycle, values::label};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, CycleSig, DialectSpec};
use crate::ir::{
    Block, CycleCall, CycleDef, CycleRunKind, ExprKind, MotionKind, Program, QParam, Stmt,
    StmtKind, Value,
};
use crate::span::Span;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::NamedCycles)
        || !from.has(Capability::NamedCycles)
        || q_cycle(to, "drill").is_none()
    {
        return;
    }
    let mut pass = Named {
        from,
        to,
        modal: Modal::new(from),
        modal_call: false,
        pre: Vec::new(),
        diags,
    };
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    for b in blocks {
        pass.block(p, b, &mut out);
    }
    p.blocks = out;
}

pub(super) struct Named<'a> {
    from: &'a DialectSpec,
    to: &'a DialectSpec,
    pub(super) modal: Modal,
    /// An MCALL of a cycle mapped here is in force.
    modal_call: bool,
    /// Statements a definition needs before it (QL parameters).
    pre: Vec<Stmt>,
    pub(super) diags: &'a mut Vec<Diagnostic>,
}

/// A Q value of a mapped cycle.
pub(super) enum QVal {
    Num(f64),
    /// A length as a multiple of the active tool radius (Q108), computed
    /// in a QL parameter before the definition.
    PerRadius(f64),
}

/// A named call's arguments by parameter name.
pub(super) struct Args<'a> {
    sig: &'a CycleSig,
    pub(super) call: &'a CycleCall,
    p: &'a Program,
}

fn args<'a>(from: &'a DialectSpec, p: &'a Program, c: &'a CycleCall) -> Option<Args<'a>> {
    Some(Args {
        sig: from.cycle(&c.name)?,
        call: c,
        p,
    })
}

impl Args<'_> {
    /// The argument `name` when it is given as a number.
    pub(super) fn num(&self, name: &str) -> Option<f64> {
        let e = self.call.args.get(self.sig.param_index(name)?)?.value?;
        match &self.p.exprs[e].kind {
            ExprKind::Number(d) => Some(d.to_f64()),
            _ => None,
        }
    }

    /// Whether `name` is written at all (a number or an expression).
    pub(super) fn written(&self, name: &str) -> bool {
        self.sig
            .param_index(name)
            .and_then(|i| self.call.args.get(i))
            .is_some_and(|a| a.value.is_some())
    }

    /// Given and not 0.
    pub(super) fn given(&self, name: &str) -> bool {
        self.num(name).is_some_and(|v| v != 0.0)
    }
}

impl Named<'_> {
    fn block(&mut self, p: &mut Program, mut b: Block, out: &mut Vec<Block>) {
        let mut cur = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::CycleCall(c) if self.claims(p, &c) => {
                    let def = self.define(p, &c, span);
                    if def.is_none() {
                        self.pre.clear();
                    }
                    if let Some(def) = def {
                        for s in std::mem::take(&mut self.pre) {
                            out.push(follow_block(&b, vec![s]));
                        }
                        let d = Stmt::new(StmtKind::CycleDef(Box::new(def)), span);
                        out.push(follow_block(&b, vec![d]));
                        if c.modal {
                            self.modal_call = true;
                        } else {
                            cur.push(Stmt::new(StmtKind::CycleRun(CycleRunKind::Call), span));
                        }
                    }
                }
                StmtKind::ModalCallCancel if self.modal_call => self.modal_call = false,
                StmtKind::Motion(m) if self.modal_call => {
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
                            .primary(span, "only X and Y can follow the cycle call here")
                            .help("end the MCALL before this block, or use --expand-cycles"),
                        );
                        continue;
                    }
                    cur.extend(hole_stmts(m.target.x.clone(), m.target.y.clone(), span));
                }
                kind => {
                    let s = Stmt::new(kind, span);
                    self.modal.see(&s);
                    cur.push(s);
                }
            }
        }
        b.stmts = cur;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            out.push(b);
        }
    }

    /// The calls this pass maps (the rest go on to `to_word`).
    fn claims(&self, p: &Program, c: &CycleCall) -> bool {
        let Some(a) = args(self.from, p, c) else {
            return false;
        };
        match a.sig.kind.as_str() {
            "bore-feed-out" | "bore-dwell-feed-out" => ["FFR", "RFF"]
                .iter()
                .any(|n| a.written(n) && a.num(n) != Some(0.0)),
            "face" => a.sig.param_index("MIDA").is_some(),
            _ => false,
        }
    }

    fn define(&mut self, p: &mut Program, c: &CycleCall, span: Span) -> Option<CycleDef> {
        let (kind, name, vals) = {
            let from = self.from;
            let a = args(from, p, c)?;
            match a.sig.kind.as_str() {
                "face" => ("face", "FACE MILLING", self.face(&a, span)?),
                _ => {
                    let nums = self.boring(&a, span)?;
                    let vals = nums.into_iter().map(|(q, v)| (q, QVal::Num(v))).collect();
                    ("bore-feed-out", "REAMING", vals)
                }
            }
        };
        let Some(sig) = self.to.cycles.iter().find(|s| s.kind == kind) else {
            self.refuse(span, format!("{} has no `{kind}` cycle", self.to.name));
            return None;
        };
        let mut params = Vec::new();
        for ps in &sig.params {
            let Some((_, v)) = vals.iter().find(|(n, _)| *n == ps.name) else {
                self.refuse(span, format!("{}: no value for {}", c.name, ps.name));
                return None;
            };
            params.push(QParam {
                q: ps.name.get(1..)?.parse().ok()?,
                value: match v {
                    QVal::Num(v) => Value::Number(decimal(*v)),
                    QVal::PerRadius(w) => {
                        Value::Expr(super::faces::per_radius(p, *w, span, &mut self.pre))
                    }
                },
                label: Some(label(&ps.name).to_string()),
                span,
            });
        }
        Some(CycleDef {
            number: sig.name.parse().ok()?,
            name: name.into(),
            params,
        })
    }

    /// CYCLE85/89 with FFR/RFF as 201 REAMING.
    fn boring(&mut self, a: &Args<'_>, span: Span) -> Option<Vec<(&'static str, f64)>> {
        let name = &a.call.name;
        let (Some(rtp), Some(rfp)) = (a.num("RTP"), a.num("RFP")) else {
            self.refuse(span, format!("{name}: RTP and RFP must be numbers"));
            return None;
        };
        let depth = if a.given("DPR") {
            -a.num("DPR")?.abs()
        } else {
            match a.num("DP") {
                Some(dp) => dp - rfp,
                None => {
                    self.refuse(span, format!("{name} without a depth known here"));
                    return None;
                }
            }
        };
        let active = self.modal.feed.as_ref().and_then(Value::number);
        let feed = |n: &str| match a.num(n).filter(|v| *v != 0.0) {
            Some(v) => Some(v),
            None => active.map(|d| d.to_f64()),
        };
        let (Some(ffr), Some(rff)) = (feed("FFR"), feed("RFF")) else {
            self.refuse(span, format!("{name}: a feed of 0 and no feed in force"));
            return None;
        };
        Some(vec![
            ("Q200", a.num("SDIS").unwrap_or(0.0).abs()),
            ("Q201", depth),
            ("Q206", ffr),
            ("Q211", a.num("DTB").unwrap_or(0.0)),
            ("Q208", rff),
            ("Q203", rfp),
            ("Q204", rtp - rfp),
        ])
    }

    pub(super) fn refuse(&mut self, span: Span, msg: String) {
        self.diags.push(
            Diagnostic::new(Code::PortCycle, msg)
                .primary(span, "this cycle")
                .help("write the cycle's values as numbers, or use --expand-cycles"),
        );
    }
}
