//! Siemens `POCKET1` / `POCKET2` ↔ Heidenhain `CYCL DEF 251` / `252`,
//! the pair the interpreter runs the same way (`interp/heidenhain/cycles.rs`
//! runs 251/252 as POCKET1/2 about the current position). Both directions
//! need every value as a number known here.
//!
//! * Q203 = RFP, Q200 = SDIS, Q201 = DP − RFP (or −DPR), Q204 = RTP − RFP,
//!   Q218/Q219/Q220 = LENG/WID/CRAD (252: Q223 = 2 × PRAD), Q224 = STA1,
//!   Q206 = FFD, Q207 = Q385 = FFP1, Q202 = MID, Q351 = +1 for CDIR 2 (G2)
//!   and −1 for CDIR 3, Q368 = FAL; Q215 = 0 (roughing and finishing, the
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

use super::{decimal, follow_block, number_expr};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{CycleSig, DialectSpec};
use crate::ir::{
    Arg, CompSide, CycleCall, CycleDef, CycleRunKind, ExprKind, Motion, MotionKind, Program,
    QParam, Stmt, StmtKind, Value,
};
use crate::span::Span;

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

fn arg(p: &Program, sig: &CycleSig, c: &CycleCall, name: &str) -> Result<Option<f64>, String> {
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

type Built = (Stmt, Vec<Stmt>);

fn to_tnc(
    p: &Program,
    s: &CycleSig,
    q: &CycleSig,
    c: &CycleCall,
    span: Span,
) -> Result<Built, String> {
    let get = |n: &str| arg(p, s, c, n);
    let need = |n: &str| get(n)?.ok_or(format!("{n} is not given"));
    for n in ["VARI", "MIDF", "FFP2", "SSF"] {
        if get(n)?.is_some_and(|v| v != 0.0) {
            return Err(format!("{n} (separate finishing) is not carried"));
        }
    }
    let (rtp, rfp, sdis) = (need("RTP")?, need("RFP")?, get("SDIS")?.unwrap_or(0.0));
    let depth = match get("DP")? {
        Some(dp) => dp - rfp,
        None => -need("DPR")?,
    };
    let ffp1 = need("FFP1")?;
    let cdir = if get("CDIR")? == Some(3.0) { -1.0 } else { 1.0 };
    let mut vals = vec![
        ("Q215", 0.0),
        ("Q368", get("FAL")?.unwrap_or(0.0)),
        ("Q224", get("STA1")?.unwrap_or(0.0)),
        ("Q367", 0.0),
        ("Q207", ffp1),
        ("Q351", cdir),
        ("Q201", depth),
        ("Q202", need("MID")?),
        ("Q369", 0.0),
        ("Q206", need("FFD")?),
        ("Q338", 0.0),
        ("Q200", sdis),
        ("Q203", rfp),
        ("Q204", rtp - rfp),
        ("Q370", 1.0),
        ("Q366", 0.0),
        ("Q385", ffp1),
    ];
    if s.param_index("PRAD").is_some() {
        vals.push(("Q223", 2.0 * need("PRAD")?));
    } else {
        vals.extend([
            ("Q218", need("LENG")?),
            ("Q219", need("WID")?),
            ("Q220", get("CRAD")?.unwrap_or(0.0)),
        ]);
    }
    let mut params = Vec::new();
    for ps in &q.params {
        let v = vals
            .iter()
            .find(|(n, _)| *n == ps.name)
            .map(|(_, v)| *v)
            .ok_or(format!("{} has no value", ps.name))?;
        params.push(QParam {
            q: ps.name[1..].parse().map_err(|_| ps.name.clone())?,
            value: Value::Number(decimal(v)),
            label: Some(label(&ps.name).to_string()),
            span,
        });
    }
    let name = if s.kind == "pocket-rect" {
        "RECTANGULAR POCKET"
    } else {
        "CIRCULAR POCKET"
    };
    let def = CycleDef {
        number: q.name.parse().map_err(|_| q.name.clone())?,
        name: name.into(),
        params,
    };
    let mut m = Motion::new(MotionKind::Rapid);
    m.target.x = Some(coord(need("CPA")?, span));
    m.target.y = Some(coord(need("CPO")?, span));
    let call = vec![
        Stmt::new(StmtKind::Motion(Box::new(m)), span),
        Stmt::new(
            StmtKind::RadiusComp {
                side: CompSide::Off,
                register: None,
                diameter: false,
            },
            span,
        ),
        Stmt::new(StmtKind::CycleRun(CycleRunKind::Block), span),
    ];
    Ok((Stmt::new(StmtKind::CycleDef(Box::new(def)), span), call))
}

fn from_tnc(
    p: &mut Program,
    sig: &CycleSig,
    d: &CycleDef,
    at: (Option<f64>, Option<f64>),
    span: Span,
    diags: &mut Vec<Diagnostic>,
) -> Result<CycleCall, String> {
    let q = |n: u32| d.param(n).and_then(Value::number).map(|v| v.to_f64());
    let need = |n: u32| q(n).ok_or(format!("Q{n} is not a number known here"));
    for (n, what) in [
        (215, "machining operation"),
        (367, "pocket position"),
        (369, "floor allowance"),
        (338, "finishing infeed"),
    ] {
        if q(n).unwrap_or(0.0) != 0.0 {
            return Err(format!("Q{n} ({what}) is not carried"));
        }
    }
    for (n, default, what) in [(370, 1.0, "path overlap"), (366, 0.0, "plunging strategy")] {
        if q(n).is_some_and(|v| v != default) {
            diags.push(
                Diagnostic::new(
                    Code::PortApproximate,
                    format!(
                        "Q{n} ({what}) has no POCKET parameter; the Siemens cycle's own is used"
                    ),
                )
                .primary(span, "this pocket")
                .help("check the stepover and plunge of the ported cycle"),
            );
        }
    }
    let (x, y) = match at {
        (Some(x), Some(y)) => (x, y),
        _ => return Err("the pocket centre (the tool position) is not known here".into()),
    };
    let top = need(203)?;
    let mut vals = vec![
        ("RTP", top + need(204)?.abs()),
        ("RFP", top),
        ("SDIS", need(200)?.abs()),
        ("DP", top + need(201)?),
        ("CPA", x),
        ("CPO", y),
        ("FFD", need(206)?),
        ("FFP1", need(207)?),
        ("MID", need(202)?),
        (
            "CDIR",
            if q(351).unwrap_or(1.0) >= 0.0 {
                2.0
            } else {
                3.0
            },
        ),
        ("FAL", q(368).unwrap_or(0.0)),
        ("VARI", 0.0),
    ];
    if d.number == 251 {
        vals.extend([
            ("LENG", need(218)?),
            ("WID", need(219)?),
            ("CRAD", need(220)?),
            ("STA1", q(224).unwrap_or(0.0)),
        ]);
    } else {
        vals.push(("PRAD", need(223)? / 2.0));
    }
    let mut args: Vec<Arg> = sig
        .params
        .iter()
        .map(|_| Arg { value: None, span })
        .collect();
    for (n, v) in vals {
        if let Some(i) = sig.param_index(n) {
            args[i].value = Some(number_expr(p, decimal(v), span));
        }
    }
    while args.last().is_some_and(|a| a.value.is_none()) {
        args.pop();
    }
    Ok(CycleCall {
        name: sig.name.clone(),
        args,
        modal: false,
    })
}

fn coord(v: f64, span: Span) -> crate::ir::Coord {
    crate::ir::Coord {
        value: Value::Number(decimal(v)),
        dim: None,
        span,
    }
}

/// The English label the control writes after each pocket parameter.
fn label(q: &str) -> &'static str {
    match q {
        "Q215" => "MACHINING OPERATION",
        "Q218" => "FIRST SIDE LENGTH",
        "Q219" => "2ND SIDE LENGTH",
        "Q220" => "CORNER RADIUS",
        "Q223" => "CIRCLE DIAMETER",
        "Q368" => "ALLOWANCE FOR SIDE",
        "Q224" => "ANGLE OF ROTATION",
        "Q367" => "POCKET POSITION",
        "Q207" => "FEED RATE FOR MILLING",
        "Q351" => "CLIMB OR UP-CUT",
        "Q201" => "DEPTH",
        "Q202" => "PLUNGING DEPTH",
        "Q369" => "ALLOWANCE FOR FLOOR",
        "Q206" => "FEED RATE FOR PLNGNG",
        "Q338" => "INFEED FOR FINISHING",
        "Q200" => "SET-UP CLEARANCE",
        "Q203" => "SURFACE COORDINATE",
        "Q204" => "2ND SET-UP CLEARANCE",
        "Q370" => "TOOL PATH OVERLAP",
        "Q366" => "PLUNGE",
        "Q385" => "FINISHING FEED RATE",
        _ => "",
    }
}
