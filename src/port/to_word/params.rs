//! Reading a named drilling cycle's arguments into the words of a canned
//! cycle (see the module doc of [`super`] for the rules).

use super::{Pass, Pending};
use crate::diag::{Code, Diagnostic};
use crate::dialect::Meaning;
use crate::ir::{
    Axes, CannedCycle, Coord, CycleCall, CycleKind, Decimal, DwellUnit, ExprKind, Program, Value,
};
use crate::port::decimal;
use crate::span::Span;

impl Pass<'_> {
    pub(super) fn map_call(
        &mut self,
        p: &mut Program,
        c: &CycleCall,
        span: Span,
    ) -> Option<Pending> {
        let sig = self.from.cycle(&c.name)?.clone();
        // The arguments as values (read once: the depth formula below
        // adds to the program's expressions).
        let values: Vec<Option<Value>> = c
            .args
            .iter()
            .map(|a| {
                a.value.map(|e| match &p.exprs[e].kind {
                    ExprKind::Number(d) => Value::Number(*d),
                    _ => Value::Expr(e),
                })
            })
            .collect();
        let arg = |name: &str| -> Option<Value> { values.get(sig.param_index(name)?)?.clone() };
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
        // SDIS given as an expression: R = RFP + SDIS cannot be written
        // as numbers (taking it as 0 put the R plane on the surface). A
        // DPR expression without a DP: the depth is RFP - ABS(DPR), an
        // expression the target computes [?: a DPR that is 0 at run time
        // leaves the 840D at DP = 0, the formula at RFP].
        let dpr_formula = arg("DPR")
            .filter(|v| v.number().is_none())
            .filter(|_| arg("DP").is_none());
        for name in ["SDIS", "DPR"] {
            let formula = name == "DPR" && dpr_formula.is_some();
            if arg(name).is_some_and(|v| v.number().is_none()) && !formula {
                self.refuse(
                    span,
                    format!("{}: {name} is an expression", c.name),
                    "the R plane and the depth are computed from it",
                );
                return None;
            }
        }
        let sdis = num("SDIS").unwrap_or(0.0).abs();
        let r = if sdis == 0.0 {
            rfp.clone()
        } else {
            match &rfp {
                Value::Number(d) => Value::Number(decimal(d.to_f64() + sdis)),
                // R = RFP + SDIS, an expression the target computes.
                Value::Expr(e) => {
                    let n = crate::port::number_expr(p, decimal(sdis), span);
                    Value::Expr(p.exprs.alloc(crate::ir::Expr {
                        kind: ExprKind::Binary(crate::ir::BinaryOp::Add, *e, n),
                        span,
                    }))
                }
            }
        };
        let bottom = if let Some(Value::Expr(dpr)) = dpr_formula {
            let rfp = match rfp.clone() {
                Value::Number(d) => crate::port::number_expr(p, d, span),
                Value::Expr(e) => e,
            };
            let abs = p.exprs.alloc(crate::ir::Expr {
                kind: ExprKind::Call(crate::ir::Func::Abs, vec![dpr]),
                span,
            });
            Value::Expr(p.exprs.alloc(crate::ir::Expr {
                kind: ExprKind::Binary(crate::ir::BinaryOp::Sub, rfp, abs),
                span,
            }))
        } else if given("DPR") {
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
        // A target with Q-parameter drilling cycles takes the G8x on to
        // `to_tnc` (the kinds it maps; it refuses the rest).
        let tnc = super::super::to_tnc::q_cycle(self.to, "drill").is_some()
            && super::super::to_tnc::maps(kind);
        if self.to.code_for(Meaning::Cycle(kind)).is_none() && !tnc {
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

    pub(super) fn dwell_word(&mut self, seconds: f64, span: Span) -> Option<Value> {
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

    pub(super) fn peck(
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
    pub(super) fn tap(
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
