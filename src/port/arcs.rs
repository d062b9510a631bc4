//! Siemens arcs through an intermediate point (`CIP X Y I1= J1=`) as
//! `G2`/`G3` with the centre (`I J`, incremental from the start) for a
//! word-address target, which has no such form.
//!
//! The centre is the one circle through start, intermediate point and end;
//! the turn is clockwise when the intermediate point lies to the right of
//! the chord from start to end. It needs the XY plane, absolute numbers
//! and a known start point; otherwise the arc stays as written and the
//! writer reports it (E0601). The centre is rounded to 0.001 mm / 0.0001 in
//! (within the 1 µm `--verify` allows).

use super::levels::Modal;
use crate::dialect::{DialectSpec, Family};
use crate::ir::{
    ArcData, ArcDir, Coord, Decimal, LengthUnit, Motion, MotionKind, Program, StmtKind, Value,
};
use crate::span::Span;

pub fn run(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    if to.family == Family::Sinumerik {
        return;
    }
    let mut modal = Modal::new(from);
    for b in &mut p.blocks {
        for s in &mut b.stmts {
            if let StmtKind::Motion(m) = &mut s.kind {
                if m.kind == MotionKind::ArcThrough {
                    through_to_centre(m, &modal, s.span);
                }
            }
            modal.see(s);
        }
    }
}

fn num(v: &Option<Value>) -> Option<f64> {
    v.as_ref().and_then(Value::number).map(|d| d.to_f64())
}

fn coord_num(c: &Option<Coord>) -> Option<f64> {
    match c {
        Some(Coord {
            value: Value::Number(d),
            dim: None,
            ..
        }) => Some(d.to_f64()),
        _ => None,
    }
}

fn through_to_centre(m: &mut Motion, modal: &Modal, span: Span) {
    if !modal.absolute || !modal.plane_xy {
        return;
    }
    let Some(mid) = m.arc.mid.as_deref() else {
        return;
    };
    let (Some(sx), Some(sy)) = (num(&modal.x), num(&modal.y)) else {
        return;
    };
    let end = (
        coord_num(&m.target.x).or((m.target.x.is_none()).then_some(sx)),
        coord_num(&m.target.y).or((m.target.y.is_none()).then_some(sy)),
    );
    let (Some(ex), Some(ey)) = end else { return };
    let (Some(mx), Some(my)) = (coord_num(&mid.x), coord_num(&mid.y)) else {
        return;
    };
    if mid.z.is_some() {
        return;
    }
    let Some((cx, cy)) = circumcentre((sx, sy), (mx, my), (ex, ey)) else {
        return;
    };
    let cross = (mx - sx) * (ey - sy) - (my - sy) * (ex - sx);
    let places = if modal.unit == LengthUnit::Mm { 3 } else { 4 };
    let word = |v: f64| Coord {
        value: Value::Number(rounded(v, places)),
        dim: None,
        span,
    };
    m.kind = MotionKind::Arc(if cross < 0.0 { ArcDir::Cw } else { ArcDir::Ccw });
    m.arc = ArcData {
        i: Some(word(cx - sx)),
        j: Some(word(cy - sy)),
        ..ArcData::default()
    };
}

fn rounded(v: f64, places: u8) -> Decimal {
    let mut d = Decimal::from_f64(v, places).normalized();
    d.point = true;
    d
}

/// The centre of the circle through three points (None: on one line).
fn circumcentre(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> Option<(f64, f64)> {
    let d = 2.0 * (a.0 * (b.1 - c.1) + b.0 * (c.1 - a.1) + c.0 * (a.1 - b.1));
    if d.abs() < 1e-12 {
        return None;
    }
    let sq = |p: (f64, f64)| p.0 * p.0 + p.1 * p.1;
    let ux = (sq(a) * (b.1 - c.1) + sq(b) * (c.1 - a.1) + sq(c) * (a.1 - b.1)) / d;
    let uy = (sq(a) * (c.0 - b.0) + sq(b) * (a.0 - c.0) + sq(c) * (b.0 - a.0)) / d;
    Some((ux, uy))
}

#[cfg(test)]
mod tests {
    #[test]
    fn centre_of_three_points() {
        let c = super::circumcentre((40.0, 0.0), (50.0, 10.0), (60.0, 0.0)).unwrap();
        assert!((c.0 - 50.0).abs() < 1e-12 && c.1.abs() < 1e-12);
        assert!(super::circumcentre((0.0, 0.0), (1.0, 1.0), (2.0, 2.0)).is_none());
    }
}
