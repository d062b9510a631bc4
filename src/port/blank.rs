//! The blank (Heidenhain `BLK FORM 0.1 Z X.. Y.. Z..` / `BLK FORM 0.2
//! X.. Y.. Z..`) for a target without a blank statement (capability
//! `blank-form`): a comment that keeps the corners, which reads back as a
//! comment, and a note (W0610) with the `--stock` option that gives the
//! same blank to `cncc plot`/`sim`. A comment only: the blank does not
//! change what the program cuts.
//!
//! [?] Siemens `WORKPIECE(..)` (Operate) is a blank form too, but the
//! meaning of its parameters is not known well enough to write it.

use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::ir::{Axes, ExprKind, Program, StmtKind, StockCorner, Value};
use crate::span::Span;

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    if to.has(Capability::BlankForm) {
        return;
    }
    let style = super::comment_style(to);
    let mut min: Option<[Option<(f64, bool)>; 3]> = None;
    let mut first: Option<Span> = None;
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            let StmtKind::Stock { corner, axis, axes } = &s.kind else {
                continue;
            };
            let values = corner_values(axes, &p.exprs);
            let text = match corner {
                StockCorner::Min => {
                    min = Some(values);
                    first.get_or_insert(s.span);
                    let ax = axis.map(|a| format!(" {a}")).unwrap_or_default();
                    format!("BLANK MIN{ax} {}", words(axes, &p.exprs))
                }
                StockCorner::Max => {
                    if let (Some(lo), Some(span)) = (min.take(), first.take()) {
                        if let Some(opt) = stock_option(&lo, &values) {
                            diags.push(note(span, &opt));
                        }
                    }
                    format!("BLANK MAX {}", words(axes, &p.exprs))
                }
            };
            s.kind = StmtKind::Comment { text, style };
        }
    }
}

fn number(v: &Value, exprs: &crate::ir::Arena<crate::ir::Expr>) -> Option<f64> {
    match v {
        Value::Number(d) => Some(d.to_f64()),
        Value::Expr(e) => match &exprs[*e].kind {
            ExprKind::Number(d) => Some(d.to_f64()),
            _ => None,
        },
    }
}

/// The corner's X Y Z, and whether each is incremental (`IX`: from the
/// minimum corner).
fn corner_values(
    axes: &Axes,
    exprs: &crate::ir::Arena<crate::ir::Expr>,
) -> [Option<(f64, bool)>; 3] {
    let get = |a: char| {
        let c = axes.get(a)?;
        let inc = c.dim == Some(crate::ir::DimMode::Incremental);
        Some((number(&c.value, exprs)?, inc))
    };
    [get('X'), get('Y'), get('Z')]
}

/// `X-200 Y-100 Z-30` (a value that is not a number: `X?`).
fn words(axes: &Axes, exprs: &crate::ir::Arena<crate::ir::Expr>) -> String {
    let mut out = Vec::new();
    for a in ['X', 'Y', 'Z'] {
        if let Some(c) = axes.get(a) {
            let v = number(&c.value, exprs).map_or("?".to_string(), fmt);
            let inc = if c.dim == Some(crate::ir::DimMode::Incremental) {
                "I"
            } else {
                ""
            };
            out.push(format!("{inc}{a}{v}"));
        }
    }
    out.join(" ")
}

fn fmt(v: f64) -> String {
    crate::ir::num::short_text(v, 4)
}

/// `--stock LxWxH+X+Y+Z` for two known corners.
fn stock_option(lo: &[Option<(f64, bool)>; 3], hi: &[Option<(f64, bool)>; 3]) -> Option<String> {
    let mut size = Vec::new();
    let mut corner = Vec::new();
    for i in 0..3 {
        let (a, a_inc) = lo[i]?;
        let (b, b_inc) = hi[i]?;
        if a_inc {
            return None;
        }
        let b = if b_inc { a + b } else { b };
        if b <= a {
            return None;
        }
        size.push(fmt(b - a));
        corner.push(format!("{}{}", if a < 0.0 { "" } else { "+" }, fmt(a)));
    }
    Some(format!("{}{}", size.join("x"), corner.join("")))
}

fn note(span: Span, opt: &str) -> Diagnostic {
    Diagnostic::new(
        Code::PortApproximate,
        "the target has no blank definition: the blank is written as a comment",
    )
    .primary(span, "this blank")
    .help(format!(
        "give `--stock {opt}` to plot or simulate the ported program with it"
    ))
}
