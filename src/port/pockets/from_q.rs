//! `CYCL DEF 251/252` to POCKET1/POCKET2 (see the parent module).

use crate::diag::{Code, Diagnostic};
use crate::dialect::CycleSig;
use crate::ir::*;
use crate::port::{decimal, number_expr};
use crate::span::Span;

pub(super) fn from_tnc(
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
                3.0
            } else {
                2.0
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
