//! Tools on the way to the target: the tool map on T numbers and the H/D
//! registers, and tool length between `G43 H` / `G49` and the Siemens
//! cutting edge `D1` / `D0` (see [`super::forms`]).

use super::levels::Modal;
use super::PortOptions;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, Family, Meaning};
use crate::ir::{Axes, Decimal, LengthComp, Program, StmtKind, ToolRef, Value};

fn mapped_number(v: &Value, opts: &PortOptions) -> Value {
    match v.number().and_then(|d| d.as_int()) {
        Some(n) if !opts.tool_map.is_empty() => {
            Value::Number(Decimal::from_int(opts.tool_map.map(n)))
        }
        _ => v.clone(),
    }
}

fn warn(diags: &mut Vec<Diagnostic>, span: crate::span::Span, msg: String, label: &str) {
    diags.push(
        Diagnostic::new(Code::PortApproximate, msg)
            .primary(span, label.to_string())
            .help("check the tool's offsets on the target machine"),
    );
}

pub fn run(p: &mut Program, to: &DialectSpec, opts: &PortOptions, diags: &mut Vec<Diagnostic>) {
    let edge_target = to.family == Family::Sinumerik;
    let no_g43 = to
        .code_for(Meaning::LengthComp(LengthComp::Positive))
        .is_none();
    let mut modal = Modal::new(to);
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let span = s.span;
            match &mut s.kind {
                StmtKind::ToolSelect(ToolRef::Number(v)) => {
                    if !opts.tool_map.is_empty() && v.number().is_none() {
                        warn(
                            diags,
                            span,
                            "a tool number chosen at run time is not renumbered by the tool map"
                                .into(),
                            "T is an expression",
                        );
                    }
                    *v = mapped_number(v, opts);
                }
                StmtKind::LengthComp { mode, register, .. } if edge_target && no_g43 => {
                    match mode {
                        LengthComp::Cancel => {
                            s.kind = StmtKind::CuttingEdge(Value::Number(Decimal::from_int(0)))
                        }
                        LengthComp::Positive => {
                            if let (Some(h), Some(t)) = (register.as_ref(), modal.tool.as_ref()) {
                                if mapped_number(h, opts) != *t {
                                    warn(diags, span, "G43 H is not the tool's number; D1 takes the length of the tool in the spindle".into(), "H register");
                                }
                            }
                            s.kind = StmtKind::CuttingEdge(Value::Number(Decimal::from_int(1)));
                        }
                        _ => {}
                    }
                }
                StmtKind::LengthComp {
                    register: Some(h), ..
                } => *h = mapped_number(h, opts),
                StmtKind::RadiusComp {
                    register: Some(d),
                    diameter: false,
                    ..
                } => *d = mapped_number(d, opts),
                StmtKind::OffsetRegister { value, .. } => *value = mapped_number(value, opts),
                StmtKind::CuttingEdge(v) if !edge_target => {
                    let d = v.number().and_then(|d| d.as_int());
                    match (d, modal.tool.clone()) {
                        (Some(0), _) => {
                            s.kind = StmtKind::LengthComp {
                                mode: LengthComp::Cancel,
                                register: None,
                                axes: Box::new(Axes::default()),
                            }
                        }
                        (Some(d), Some(t)) => {
                            if d != 1 {
                                warn(
                                    diags,
                                    span,
                                    format!(
                                        "cutting edge D{d} becomes the tool's length register H"
                                    ),
                                    "edge number dropped",
                                );
                            }
                            s.kind = StmtKind::LengthComp {
                                mode: LengthComp::Positive,
                                register: Some(t),
                                axes: Box::new(Axes::default()),
                            };
                        }
                        _ => {}
                    }
                }
                _ => {}
            }
            modal.see(s);
        }
    }
}
