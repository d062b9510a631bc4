//! Heidenhain `CYCL DEF 232 FACE MILLING` to the target's named face
//! cycle (Siemens `CYCLE71`), the reverse of `to_tnc/faces.rs` and of the
//! interpreter's reading of 232:
//!
//! * RTP = Q227 + |Q204|, RFP = Q227, SDIS = |Q200|, DP = Q386, PA/PO =
//!   Q225/Q226, LENG/WID = Q218/Q219, STA = 0, MID = |Q202|, FDP = |Q357|,
//!   FFP1 = Q207; VARI 31 (roughing, alternating along the 1st axis) for
//!   Q389 = 0, VARI 11 (one way) for Q389 = 2.
//! * The stepover: 232 gives it as a factor of the tool radius (Q370), CYCLE71
//!   as a length (MIDA); Q370 = 1 is MIDA = 0, which CYCLE71 takes as
//!   the tool radius [?: as the interpreter runs it]. Another factor needs
//!   the radius, which only the machine knows: E0610.
//! * No CYCLE71 form (E0610): Q389 = 1 (meander with the stepover inside
//!   the face [?]) and a floor allowance Q369 (232 finishes it, CYCLE71
//!   roughing leaves it).
//!
//! The definition goes; the block that calls it (`CYCL CALL`, `L .. M99`)
//! gets the `CYCLE71(..)` call after its move. Targets without a named
//! face cycle are left to [`super`], which refuses the definition.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{CycleSig, DialectSpec};
use crate::ir::{Arg, CycleCall, CycleDef, Program, Stmt, StmtKind};
use crate::port::{decimal, number_expr};
use crate::span::Span;

/// The target's named face cycle with a width infeed (CYCLE71).
fn face_cycle(to: &DialectSpec) -> Option<&CycleSig> {
    to.cycles
        .iter()
        .find(|c| c.kind == "face" && c.param_index("MIDA").is_some())
}

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let Some(sig) = face_cycle(to) else {
        return;
    };
    let mut def: Option<Result<Vec<(&'static str, f64)>, String>> = None;
    let mut blocks = std::mem::take(&mut p.blocks);
    for b in &mut blocks {
        let mut stmts = Vec::with_capacity(b.stmts.len());
        let mut call = None;
        for s in std::mem::take(&mut b.stmts) {
            match &s.kind {
                StmtKind::CycleDef(d) if d.number == 232 => def = Some(values(d)),
                StmtKind::CycleDef(_) => {
                    def = None;
                    stmts.push(s);
                }
                StmtKind::CycleRun(_) if def.is_some() => call = Some(s.span),
                _ => stmts.push(s),
            }
        }
        if let Some(span) = call {
            match def.as_ref().expect("checked") {
                Ok(vals) => {
                    let c = cycle_call(p, sig, vals, span);
                    stmts.push(Stmt::new(StmtKind::CycleCall(c), span));
                }
                Err(why) => diags.push(
                    Diagnostic::new(Code::PortCycle, format!("CYCL DEF 232: {why}"))
                        .primary(span, "the face milling cycle is called here")
                        .help("use --expand-cycles to write the moves it makes"),
                ),
            }
        }
        b.stmts = stmts;
    }
    p.blocks = blocks;
}

/// The CYCLE71 values by parameter name, or why there are none.
fn values(d: &CycleDef) -> Result<Vec<(&'static str, f64)>, String> {
    let q = |n: u32| -> Result<f64, String> {
        match d.param(n).and_then(|v| v.number()) {
            Some(x) => Ok(x.to_f64()),
            None => Err(format!("Q{n} is not a number known here")),
        }
    };
    let vari = match q(389)? as i64 {
        0 => 31.0,
        2 => 11.0,
        s => return Err(format!("strategy Q389={s} has no CYCLE71 form")),
    };
    if q(369)? != 0.0 {
        return Err("a floor allowance Q369 (232 finishes it, CYCLE71 roughing leaves it)".into());
    }
    if q(370)? != 1.0 {
        return Err(
            "a path overlap Q370 other than 1: CYCLE71's MIDA is a length and the tool radius is known only on the machine"
                .into(),
        );
    }
    let top = q(227)?;
    Ok(vec![
        ("RTP", top + q(204)?.abs()),
        ("RFP", top),
        ("SDIS", q(200)?.abs()),
        ("DP", q(386)?),
        ("PA", q(225)?),
        ("PO", q(226)?),
        ("LENG", q(218)?),
        ("WID", q(219)?),
        ("STA", 0.0),
        ("MID", q(202)?.abs()),
        ("MIDA", 0.0),
        ("FDP", q(357)?.abs()),
        ("FALD", 0.0),
        ("FFP1", q(207)?),
        ("VARI", vari),
    ])
}

fn cycle_call(p: &mut Program, sig: &CycleSig, vals: &[(&str, f64)], span: Span) -> CycleCall {
    let mut args: Vec<Arg> = Vec::new();
    for (name, v) in vals {
        let Some(i) = sig.param_index(name) else {
            continue;
        };
        if args.len() <= i {
            args.resize(i + 1, Arg { value: None, span });
        }
        args[i].value = Some(number_expr(p, decimal(*v), span));
    }
    CycleCall {
        name: sig.name.clone(),
        args,
        modal: false,
    }
}
