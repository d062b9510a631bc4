//! Siemens CYCLE71 face milling as Heidenhain `CYCL DEF 232 FACE
//! MILLING` (the inverse of the interpreter's 232 → CYCLE71 reading,
//! `src/interp/heidenhain/mapping.rs`):
//!
//! * Q225/Q226 start point = PA/PO, Q218/Q219 side lengths = LENG/WID
//!   (signed), Q227 surface = RFP, Q386 bottom = DP, Q200 = SDIS, Q204 =
//!   RTP − RFP, Q202 = MID, Q369 = FALD, Q207 = FFP1, Q357 (clearance to
//!   the side) = FDP; Q385 (finishing feed) and Q253 (pre-positioning
//!   feed [?: CYCLE71 has no such feed]) = FFP1.
//! * VARI tens 3 (alternating along the 1st axis) → Q389 = 0 (meander),
//!   tens 1 (one way along the 1st axis) → Q389 = 2 (line by line); the
//!   2nd-axis strategies (tens 2, 4), finishing (units 2), an angle STA
//!   and the infeed overrun FDP1 have no 232 value: E0610.
//! * MIDA (the stepover, a length) → Q370 (an overlap factor × the tool
//!   radius): MIDA 0 (= the tool radius) is Q370 = 1; any other MIDA is
//!   MIDA / Q108 (the active tool radius the TNC sets at `TOOL CALL`),
//!   computed in a QL parameter just before the definition, because the
//!   radius is only known on the machine.
//!
//! `--verify` runs 232 through the interpreter's CYCLE71 reading, so it
//! proves the parameters map back exactly; where a real TNC's 232 path
//! differs from CYCLE71's (approach and lead-out, Q357, Q389 0 vs 1) it
//! cannot see [?: the cycle geometry is not in our sources].

use super::named::{Args, Named, QVal};
use crate::ir::{BinaryOp, Expr, ExprKind, Program, QBank, Stmt, StmtKind, Var};
use crate::span::Span;

impl Named<'_> {
    /// The 232 values for a CYCLE71 call (None: refused).
    pub(super) fn face(&mut self, a: &Args<'_>, span: Span) -> Option<Vec<(&'static str, QVal)>> {
        let name = a.call.name.clone();
        let need = [
            "RTP", "RFP", "DP", "PA", "PO", "LENG", "WID", "MID", "FFP1", "VARI",
        ];
        if let Some(missing) = need.iter().find(|n| a.num(n).is_none()) {
            self.refuse(
                span,
                format!("{name}: {missing} is not a number known here"),
            );
            return None;
        }
        let v = |n: &str| a.num(n).unwrap_or(0.0);
        let vari = v("VARI").abs() as i64;
        let q389 = match (vari % 10, vari / 10 % 10) {
            (1, 3) => 0.0,
            (1, 1) => 2.0,
            _ => {
                self.refuse(
                    span,
                    format!("{name}: VARI {vari} (232 roughs along the 1st axis only)"),
                );
                return None;
            }
        };
        for n in ["STA", "FDP1"] {
            if a.given(n) {
                self.refuse(span, format!("{name}: {n} has no CYCL DEF 232 parameter"));
                return None;
            }
        }
        let (rfp, ffp1) = (v("RFP"), v("FFP1"));
        let q370 = if a.given("MIDA") {
            QVal::PerRadius(v("MIDA").abs())
        } else {
            QVal::Num(1.0)
        };
        let n = QVal::Num;
        Some(vec![
            ("Q389", n(q389)),
            ("Q225", n(v("PA"))),
            ("Q226", n(v("PO"))),
            ("Q227", n(rfp)),
            ("Q386", n(v("DP"))),
            ("Q218", n(v("LENG"))),
            ("Q219", n(v("WID"))),
            ("Q202", n(v("MID").abs())),
            ("Q369", n(v("FALD").abs())),
            ("Q370", q370),
            ("Q207", n(ffp1)),
            ("Q385", n(ffp1)),
            ("Q253", n(ffp1)),
            ("Q200", n(v("SDIS").abs())),
            ("Q357", n(v("FDP").abs())),
            ("Q204", n(v("RTP") - rfp)),
        ])
    }
}

/// `QLn = width / Q108` (n not used in `p`), pushed to `pre`; the QL parameter.
pub(super) fn per_radius(
    p: &mut Program,
    width: f64,
    span: Span,
    pre: &mut Vec<Stmt>,
) -> crate::ir::ExprId {
    let n = free_local(p);
    let mut node = |kind| p.exprs.alloc(Expr { kind, span });
    let w = node(ExprKind::Number(super::super::decimal(width)));
    let r = node(ExprKind::Var(Var::Q(QBank::Q, 108)));
    let value = node(ExprKind::Binary(BinaryOp::Div, w, r));
    let var = Var::Q(QBank::Local, n);
    pre.push(Stmt::new(
        StmtKind::Assign {
            var: var.clone(),
            value,
        },
        span,
    ));
    node(ExprKind::Var(var))
}

/// A QL parameter number `p` does not use (from 1).
fn free_local(p: &Program) -> u32 {
    let mut used = Vec::new();
    for (_, e) in p.exprs.iter() {
        if let ExprKind::Var(Var::Q(QBank::Local, n)) = e.kind {
            used.push(n);
        }
    }
    (1..).find(|n| !used.contains(n)).unwrap_or(1)
}
