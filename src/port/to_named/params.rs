//! The parameters of a named cycle call computed from a canned cycle's
//! words and the modal state (see the module doc of [`super`]), and the
//! argument vector filled by parameter name through the target signature.

use super::Pass;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{CycleSig, Meaning};
use crate::ir::{Arg, CycleKind, DwellUnit, ExprId, Program, Value};
use crate::port::{decimal, number_expr, value_expr};
use crate::span::Span;

impl Pass<'_> {
    pub(super) fn signature(&mut self, kind: CycleKind, span: Span) -> Option<CycleSig> {
        let want = match kind {
            CycleKind::Drill => Some("drill"),
            CycleKind::DrillDwell => Some("drill-dwell"),
            CycleKind::Peck => Some("peck"),
            CycleKind::Tap | CycleKind::TapLeft => Some("tap"),
            CycleKind::BoreFeedOut => Some("bore-feed-out"),
            CycleKind::BoreStopRapidOut => Some("bore-stop-rapid-out"),
            CycleKind::BoreManual => Some("bore-manual"),
            CycleKind::BoreDwellFeedOut => Some("bore-dwell-feed-out"),
            CycleKind::ChipBreak | CycleKind::BackBore | CycleKind::FineBore => None,
        };
        let to = self.to;
        let found = want.and_then(|k| {
            let mut it = to.cycles.iter().filter(|s| s.kind == k);
            let all: Vec<&CycleSig> = it.by_ref().collect();
            // G88 dwells: prefer the signature that has DTB.
            all.iter()
                .find(|s| s.param_index("DTB").is_some())
                .or(all.first())
                .map(|s| (*s).clone())
        });
        if found.is_none() {
            let g = Meaning::Cycle(kind).name();
            let why = match kind {
                CycleKind::ChipBreak => {
                    "its back-off is a rapid; the target's peck cycle backs off at feed"
                }
                _ => "the target has no cycle that cuts the same way",
            };
            self.refuse(
                Code::PortCycle,
                span,
                format!("{} has no equivalent of `{g}`", to.name),
                why,
                "use --expand-cycles to write the cycle as the moves it makes",
            );
        }
        found
    }

    pub(super) fn retract_plane(&mut self, r: &Value, span: Span) -> Option<Value> {
        if !self.modal.return_initial {
            return Some(r.clone());
        }
        match (self.initial.clone(), r.number()) {
            (Some(Value::Number(z)), Some(rn)) => {
                Some(Value::Number(if z.to_f64() >= rn.to_f64() {
                    z
                } else {
                    rn
                }))
            }
            (Some(z), _) => Some(z),
            (None, _) => {
                self.refuse(
                    Code::PortRunTimeValue,
                    span,
                    "the initial level of this G98 cycle is not known here".into(),
                    "G98 returns to the Z before the cycle",
                    "move to a known Z (G0 Z..) before the cycle, use G99, or use --expand-cycles",
                );
                None
            }
        }
    }

    #[allow(clippy::too_many_arguments)]
    pub(super) fn kind_args(
        &mut self,
        p: &mut Program,
        kind: CycleKind,
        a: &mut Args<'_>,
        r: &Value,
        rtp: &Value,
        q: Option<&Value>,
        dwell: Option<&Value>,
        span: Span,
    ) -> Option<()> {
        let dtb = match dwell {
            Some(v) => Some(self.seconds(p, v, span)?),
            None => None,
        };
        match kind {
            CycleKind::Drill => {}
            CycleKind::DrillDwell | CycleKind::BoreDwellFeedOut => a.set(p, "DTB", dtb),
            CycleKind::Peck => {
                let Some(q) = q else {
                    self.refuse(
                        Code::PortRunTimeValue,
                        span,
                        "G83 without Q".into(),
                        "no peck depth",
                        "give Q",
                    );
                    return None;
                };
                let fdpr = value_expr(p, q, span);
                a.set(p, "FDPR", Some(fdpr));
                a.num(p, "DAM", 0.0);
                a.num(p, "FRF", 1.0);
                a.num(p, "VARI", 1.0);
                a.num(p, "_DIS1", self.modal.peck_clearance());
            }
            CycleKind::Tap | CycleKind::TapLeft => {
                let pitch = self.pitch(span)?;
                a.set(p, "DTB", dtb);
                a.num(p, "SDAC", if kind == CycleKind::Tap { 3.0 } else { 4.0 });
                a.num(
                    p,
                    "PIT",
                    if kind == CycleKind::Tap {
                        pitch
                    } else {
                        -pitch
                    },
                );
                self.warn_feed_out(
                    r,
                    rtp,
                    span,
                    "G84 feeds out to the return level; CYCLE84 to RFP+SDIS, then rapids",
                );
            }
            CycleKind::BoreFeedOut => {}
            CycleKind::BoreStopRapidOut | CycleKind::BoreManual => {
                a.set(p, "DTB", dtb);
                a.num(p, "SDIR", if self.modal.ccw { 4.0 } else { 3.0 });
                if kind == CycleKind::BoreStopRapidOut {
                    for n in ["RPA", "RPO", "RPAP", "POSS"] {
                        a.num(p, n, 0.0);
                    }
                    self.diags.push(
                        Diagnostic::new(
                            Code::PortApproximate,
                            "CYCLE86 orients the spindle at the bottom where G86 only stops it",
                        )
                        .primary(span, "spindle oriented at 0 degrees, no lift-off")
                        .help("check that the boring bar may be oriented at POSS=0"),
                    );
                }
            }
            CycleKind::ChipBreak | CycleKind::BackBore | CycleKind::FineBore => return None,
        }
        if kind == CycleKind::BoreDwellFeedOut {
            self.warn_feed_out(
                r,
                rtp,
                span,
                "G89 feeds out to the return level; CYCLE89 to RFP+SDIS, then rapids",
            );
        }
        Some(())
    }

    pub(super) fn warn_feed_out(&mut self, r: &Value, rtp: &Value, span: Span, what: &str) {
        if r != rtp {
            self.diags.push(
                Diagnostic::new(Code::PortApproximate, what.to_string())
                    .primary(span, "with G98 the last part of the way out differs")
                    .help("use G99 for the same moves"),
            );
        }
    }

    /// A dwell word P in seconds (the source's unit for P).
    pub(super) fn seconds(&mut self, p: &mut Program, v: &Value, span: Span) -> Option<ExprId> {
        let unit = self.from.code_for(Meaning::Dwell).and_then(|c| {
            c.dwell_units
                .iter()
                .find(|(l, _)| *l == 'P')
                .map(|(_, u)| *u)
        });
        match (unit, v) {
            (Some(DwellUnit::Milliseconds), Value::Number(d)) => {
                Some(number_expr(p, decimal(d.to_f64() / 1000.0), span))
            }
            (Some(DwellUnit::Seconds) | None, v) => Some(value_expr(p, v, span)),
            _ => {
                self.refuse(
                    Code::PortRunTimeValue,
                    span,
                    "a dwell P the port cannot convert to seconds".into(),
                    "P is an expression in milliseconds or revolutions",
                    "give P as a number",
                );
                None
            }
        }
    }

    /// Thread pitch from the feed per minute and the speed.
    pub(super) fn pitch(&mut self, span: Span) -> Option<f64> {
        let f = self
            .modal
            .feed
            .as_ref()
            .and_then(Value::number)
            .map(|d| d.to_f64());
        let s = self
            .modal
            .speed
            .as_ref()
            .and_then(Value::number)
            .map(|d| d.to_f64());
        match (f, s) {
            (Some(f), Some(s)) if s > 0.0 => Some(f / s),
            _ => {
                self.refuse(
                    Code::PortRunTimeValue,
                    span,
                    "the tapping pitch (F / S) is not known here".into(),
                    "feed and speed must be numbers before the cycle",
                    "program F and S as numbers before the tapping cycle",
                );
                None
            }
        }
    }
}

/// A call's argument vector, filled by parameter name.
pub(super) struct Args<'s> {
    sig: &'s CycleSig,
    vals: Vec<Option<ExprId>>,
    span: Span,
    missing: Vec<String>,
}

impl<'s> Args<'s> {
    pub(super) fn new(sig: &'s CycleSig, span: Span) -> Self {
        Args {
            sig,
            vals: Vec::new(),
            span,
            missing: Vec::new(),
        }
    }

    pub(super) fn set(&mut self, _p: &mut Program, name: &str, v: Option<ExprId>) {
        let Some(v) = v else { return };
        match self.sig.param_index(name) {
            Some(i) => {
                if self.vals.len() <= i {
                    self.vals.resize(i + 1, None);
                }
                self.vals[i] = Some(v);
            }
            None => self.missing.push(name.to_string()),
        }
    }

    pub(super) fn num(&mut self, p: &mut Program, name: &str, v: f64) {
        let e = number_expr(p, decimal(v), self.span);
        self.set(p, name, Some(e));
    }

    pub(super) fn finish(self, diags: &mut Vec<Diagnostic>) -> Option<(String, Vec<Arg>)> {
        if !self.missing.is_empty() {
            diags.push(
                Diagnostic::new(
                    Code::PortCycle,
                    format!(
                        "the target's {} has no parameter {}",
                        self.sig.name,
                        self.missing.join(", ")
                    ),
                )
                .primary(self.span, "this cycle needs them")
                .help("use a target spec whose cycle signature has them, or --expand-cycles"),
            );
            return None;
        }
        let span = self.span;
        let args = self
            .vals
            .into_iter()
            .map(|value| Arg { value, span })
            .collect();
        Some((self.sig.name.clone(), args))
    }
}
