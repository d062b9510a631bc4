//! Siemens `POCKET1` / `POCKET2` ↔ Heidenhain `CYCL DEF 251` / `252`,
//! the pair the interpreter runs the same way (`interp/heidenhain/cycles.rs`
//! runs 251/252 as POCKET1/2 about the current position). Both directions
//! need every value as a number known here.
//!
//! * Q203 = RFP, Q200 = SDIS, Q201 = DP − RFP (or −DPR), Q204 = RTP − RFP,
//!   Q218/Q219/Q220 = LENG/WID/CRAD (252: Q223 = 2 × PRAD), Q224 = STA1,
//!   Q206 = FFD, Q207 = Q385 = FFP1, Q202 = MID, Q351 = +1 (climb: G3
//!   inside the pocket with M3) for CDIR 3 and −1 for CDIR 2 (G2, as
//!   POCKET1/2 run every CDIR other than 3), Q368 = FAL; Q215 = 0 (roughing and finishing, the
//!   VARI 0 of POCKET1), Q367 = 0 (pocket centre at the tool: the call is
//!   `L X<CPA> Y<CPO> R0 FMAX M99`), Q369 = Q338 = 0, Q370 = 1, Q366 = 0.
//! * Back: the call's position is CPA/CPO.
//!
//! Not carried (E0610, naming the parameter): POCKET1/2 with VARI, MIDF,
//! FFP2 or SSF (separate finishing); 251/252 with Q215 ≠ 0, Q367 ≠ 0
//! (pocket position), Q369 or Q338 (floor finishing). The tool path
//! overlap Q370, the plunging strategy Q366 and the finishing feed Q385
//! have no POCKET1/2 parameter: W0610 when they are not the defaults
//! written here [?: how the control's stepover and plunge compare with
//! the Siemens cycle's is not modelled].

use super::{decimal, follow_block};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{CycleSig, DialectSpec};
use crate::ir::{CycleCall, CycleDef, CycleRunKind, ExprKind, Program, Stmt, StmtKind, Value};
use crate::span::Span;

mod from_q;
mod to_q;
use from_q::from_tnc;
use to_q::to_tnc;

/// The target's cycle of `kind` with a parameter `has`.
fn sig<'a>(spec: &'a DialectSpec, kind: &str, has: &str) -> Option<&'a CycleSig> {
    spec.cycles
        .iter()
        .find(|c| c.kind == kind && c.param_index(has).is_some())
}

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let blocks = std::mem::take(&mut p.blocks);
    let mut out = Vec::with_capacity(blocks.len());
    let mut def: Option<CycleDef> = None;
    let mut at: (Option<f64>, Option<f64>) = (None, None);
    for mut b in blocks {
        let mut keep = Vec::new();
        let mut extra = Vec::new();
        for s in std::mem::take(&mut b.stmts) {
            let span = s.span;
            match s.kind {
                StmtKind::CycleCall(c) if !c.modal && to_tnc_kind(from, to, &c).is_some() => {
                    let (kind, q) = to_tnc_kind(from, to, &c).unwrap();
                    match to_tnc(p, from.cycle(&c.name).unwrap(), q, &c, span) {
                        Ok((d, call)) => {
                            extra.push(follow_block(&b, vec![d]));
                            extra.push(follow_block(&b, call));
                        }
                        Err(why) => refuse(diags, span, &format!("{} to {kind}: {why}", c.name)),
                    }
                }
                StmtKind::CycleDef(d)
                    if matches!(d.number, 251 | 252) && tnc_target(to, d.number).is_some() =>
                {
                    def = Some(*d);
                }
                StmtKind::CycleDef(d) => {
                    def = None;
                    keep.push(Stmt::new(StmtKind::CycleDef(d), span));
                }
                StmtKind::CycleRun(CycleRunKind::Block | CycleRunKind::Call) if def.is_some() => {
                    let d = def.clone().unwrap();
                    let sig = tnc_target(to, d.number).unwrap();
                    match from_tnc(p, sig, &d, at, span, diags) {
                        Ok(call) => extra.push(follow_block(
                            &b,
                            vec![Stmt::new(StmtKind::CycleCall(call), span)],
                        )),
                        Err(why) => refuse(diags, span, &format!("cycle {}: {why}", d.number)),
                    }
                }
                kind => {
                    if let StmtKind::Motion(m) = &kind {
                        let n = |c: &Option<crate::ir::Coord>, old: Option<f64>| match c {
                            Some(c) => c.value.number().map(|d| d.to_f64()),
                            None => old,
                        };
                        at = (n(&m.target.x, at.0), n(&m.target.y, at.1));
                    }
                    keep.push(Stmt::new(kind, span));
                }
            }
        }
        b.stmts = keep;
        if !b.stmts.is_empty() || b.number.is_some() || b.label.is_some() {
            out.push(b);
        }
        out.extend(extra);
    }
    p.blocks = out;
}

fn tnc_target(to: &DialectSpec, number: u32) -> Option<&CycleSig> {
    let (kind, has) = if number == 251 {
        ("pocket-rect", "CPA")
    } else {
        ("pocket-circ", "CPA")
    };
    sig(to, kind, has)
}

fn to_tnc_kind<'a>(
    from: &DialectSpec,
    to: &'a DialectSpec,
    c: &CycleCall,
) -> Option<(&'static str, &'a CycleSig)> {
    let s = from.cycle(&c.name)?;
    s.param_index("CPA")?;
    let q = to.cycles.iter().find(|q| {
        q.kind == s.kind && q.name.parse::<u32>().is_ok() && q.param_index("Q203").is_some()
    })?;
    Some((
        if s.kind == "pocket-rect" {
            "251"
        } else {
            "252"
        },
        q,
    ))
}

fn refuse(diags: &mut Vec<Diagnostic>, span: Span, msg: &str) {
    diags.push(
        Diagnostic::new(
            Code::PortCycle,
            format!("this pocket cannot be ported: {msg}"),
        )
        .primary(span, "the pocket cycle")
        .help("write the pocket with the target's own cycle by hand, or use --expand-cycles"),
    );
}

pub(super) fn arg(
    p: &Program,
    sig: &CycleSig,
    c: &CycleCall,
    name: &str,
) -> Result<Option<f64>, String> {
    let Some(i) = sig.param_index(name) else {
        return Ok(None);
    };
    match c.args.get(i).and_then(|a| a.value) {
        None => Ok(None),
        Some(e) => match &p.exprs[e].kind {
            ExprKind::Number(d) => Ok(Some(d.to_f64())),
            _ => Err(format!("{name} is not a number known here")),
        },
    }
}

pub(super) fn coord(v: f64, span: Span) -> crate::ir::Coord {
    crate::ir::Coord {
        value: Value::Number(decimal(v)),
        dim: None,
        span,
    }
}
