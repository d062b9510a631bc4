//! POCKET1/POCKET2 to `CYCL DEF 251/252` (see the parent module).

use super::{arg, coord};
use crate::dialect::CycleSig;
use crate::ir::*;
use crate::port::decimal;
use crate::port::tnc_labels::label;
use crate::span::Span;

type Built = (Stmt, Vec<Stmt>);

pub(super) fn to_tnc(
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
    // Q351 +1 climbs (G3 inside a pocket with M3); POCKET1/2 run G3 only
    // for CDIR 3 and G2 for any other value.
    let cdir = if get("CDIR")? == Some(3.0) { 1.0 } else { -1.0 };
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
