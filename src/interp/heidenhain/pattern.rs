//! `PATTERN DEF` expanded into the points `CYCL CALL PAT` calls the cycle
//! at (program units; `Z` the surface, replacing Q203, where given).
//! Forms (`reference/dialects.md` §2.6, [K], not checked on a control):
//! * `POSn (X Y Z)`: one point.
//! * `ROWn (X Y D NUM ROT Z)`: NUM points from (X, Y), D apart, along a
//!   line at ROT degrees.
//! * `PATn (X Y DX DY NUMX NUMY ROT ROTX ROTY Z)`: NUMX x NUMY points from
//!   (X, Y), row by row [?: the order the control visits them]; the whole
//!   turned by ROT, its first axis by ROTX more and its second by ROTY
//!   more [?].
//! * `CIRCn (X Y D START NUM Z)`: NUM points spread over the full circle
//!   of diameter D about (X, Y), the first at START degrees.
//! * `CIRCn`/`PITCHCIRCn` with `STEP`: the points STEP degrees apart [?:
//!   newer manuals name the pitch circle PITCHCIRC].
//!
//! `FRAME` is not expanded.

use super::super::{Interp, Stop};
use crate::diag::Code;
use crate::ir::{Arena, Expr, PatternItem};

/// The most points one item may give (bad input must not allocate
/// without bound).
const MAX_POINTS: f64 = 10_000.0;

pub type Point = [Option<f64>; 3];

/// The points of all items, in order.
pub fn points(
    it: &mut Interp<'_, '_>,
    items: &[PatternItem],
    exprs: &Arena<Expr>,
) -> Result<Vec<Point>, Stop> {
    let mut out = Vec::new();
    for i in items {
        let mut vals: Vec<(&str, f64)> = Vec::new();
        for w in &i.words {
            if let Some(v) = &w.value {
                vals.push((w.name.as_str(), it.value(v, exprs)?));
            }
        }
        let get = |n: &str| vals.iter().find(|(k, _)| *k == n).map(|(_, v)| *v);
        let z = get("Z");
        let form = i.name.trim_end_matches(|c: char| c.is_ascii_digit());
        let count = |it: &mut Interp<'_, '_>, n: &str| -> Result<usize, Stop> {
            let v = get(n).unwrap_or(1.0);
            if !(1.0..=MAX_POINTS).contains(&v) || v.fract() != 0.0 {
                return Err(it.error_at(
                    i.span,
                    Code::DomainError,
                    format!("{n} {v} in {}: a whole number from 1 to 10000", i.name),
                ));
            }
            Ok(v as usize)
        };
        let at = |x: f64, y: f64| [Some(x), Some(y), z];
        let (x0, y0) = (get("X").unwrap_or(0.0), get("Y").unwrap_or(0.0));
        match form {
            "POS" => out.push([get("X"), get("Y"), z]),
            "ROW" => {
                let (d, rot) = (get("D").unwrap_or(0.0), get("ROT").unwrap_or(0.0));
                let (c, s) = (rot.to_radians().cos(), rot.to_radians().sin());
                for k in 0..count(it, "NUM")? {
                    let t = d * k as f64;
                    out.push(at(x0 + t * c, y0 + t * s));
                }
            }
            "PAT" => {
                let (nx, ny) = (count(it, "NUMX")?, count(it, "NUMY")?);
                if nx * ny > MAX_POINTS as usize {
                    return Err(it.error_at(
                        i.span,
                        Code::DomainError,
                        format!("{}: more than 10000 points", i.name),
                    ));
                }
                let rot = get("ROT").unwrap_or(0.0);
                let ax = dir(rot + get("ROTX").unwrap_or(0.0));
                let ay = dir(rot + 90.0 + get("ROTY").unwrap_or(0.0));
                let (dx, dy) = (get("DX").unwrap_or(0.0), get("DY").unwrap_or(0.0));
                for j in 0..ny {
                    for k in 0..nx {
                        let (u, v) = (dx * k as f64, dy * j as f64);
                        out.push(at(x0 + u * ax[0] + v * ay[0], y0 + u * ax[1] + v * ay[1]));
                    }
                }
            }
            "CIRC" | "PITCHCIRC" => {
                let n = count(it, "NUM")?;
                let r = get("D").unwrap_or(0.0) / 2.0;
                let start = get("START").unwrap_or(0.0);
                let step = get("STEP").unwrap_or(360.0 / n as f64);
                for k in 0..n {
                    let a = dir(start + step * k as f64);
                    out.push(at(x0 + r * a[0], y0 + r * a[1]));
                }
            }
            _ => {
                return Err(it.error_at(
                    i.span,
                    Code::UnsupportedHere,
                    format!(
                        "the pattern {} is not expanded (POS, ROW, PAT and CIRC are)",
                        i.name
                    ),
                ))
            }
        }
    }
    if out.iter().flatten().flatten().any(|v: &f64| !v.is_finite()) {
        let span = items.first().map(|i| i.span).unwrap_or_default();
        return Err(it.error_at(
            span,
            Code::DomainError,
            "PATTERN DEF gives a point that is not a finite number",
        ));
    }
    Ok(out)
}

fn dir(deg: f64) -> [f64; 2] {
    let a = deg.to_radians();
    [a.cos(), a.sin()]
}
