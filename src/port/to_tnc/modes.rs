//! Work offsets and the continuous-path mode for a target that sets them
//! with cycles instead of codes (Heidenhain: no code for G55, G64), as the
//! target's spec gives those cycles:
//!
//! * a work offset (`G54`, `G55` ..., Siemens `G54`.., no extended `P`)
//!   becomes the `datum-preset` cycle with the offset's number as its
//!   first parameter (`CYCL DEF 247 DATUM SETTING ~ Q339=+2`): G54 is
//!   preset 1, G55 preset 2, the numbering CAM posts for the TNC use
//!   [?: which preset a machine holds for which fixture is the setter's
//!   choice]. In a program that only ever uses G54 it goes, as before:
//!   the active preset is the program's datum;
//! * the continuous-path mode (`G64`, `G64 P0.05`) becomes the old-style
//!   `tolerance` cycle: `CYCL DEF 32.0 TOLERANCE` and `32.1 T0.05`, or
//!   `32.1` alone (the machine's default tolerance) without one. Other
//!   words of the mode (LinuxCNC's `Q` naive-CAM tolerance) have no
//!   counterpart: W0610. Exact stop has no cycle: it stays refused;
//! * a local shift (`G52 X Y Z`, relative to the work offset as the TNC's
//!   datum shift is to the preset) that gives all three axes becomes the
//!   old-style `datum-shift` cycle: `CYCL DEF 7.0 DATUM SHIFT`, `7.1 X..`,
//!   `7.2 Y..`, `7.3 Z..` (the inverse of `port::old_cycles`). Only in a
//!   program without a rotation, mirror or scaling, whose order against
//!   the shift the two controls may apply differently; a shift of fewer
//!   axes leaves the others to the shift before, which the cycle does
//!   not say: it stays refused (E0601).

use crate::diag::{Code, Diagnostic};
use crate::dialect::{CycleSig, DialectSpec, Meaning};
use crate::ir::{
    Axes, CoordShift, CycleDef, CycleLine, CycleWord, PathMode, Program, QParam, Stmt, StmtKind,
    Value, Word,
};
use crate::span::Span;

pub fn run(p: &mut Program, to: &DialectSpec, diags: &mut Vec<Diagnostic>) {
    let preset = cycle(to, "datum-preset").filter(|c| !c.params.is_empty());
    let tolerance = cycle(to, "tolerance").filter(|c| c.name.parse::<u32>().is_ok());
    let shift = cycle(to, "datum-shift")
        .filter(|c| c.name.parse::<u32>().is_ok())
        .filter(|_| !has_transform(p));
    let other_offsets =
        p.blocks.iter().flat_map(|b| &b.stmts).any(
            |s| matches!(s.kind, StmtKind::WorkOffset { index, extended: None } if index != 1),
        );
    for b in &mut p.blocks {
        let mut out = Vec::with_capacity(b.stmts.len());
        for s in std::mem::take(&mut b.stmts) {
            match &s.kind {
                StmtKind::WorkOffset {
                    index,
                    extended: None,
                } if other_offsets && lacks(to, Meaning::WorkOffset(*index)) => match preset {
                    Some(c) => out.push(preset_def(c, *index, s.span)),
                    None => out.push(s),
                },
                StmtKind::PathMode {
                    mode: PathMode::Continuous,
                    words,
                } if lacks(to, Meaning::PathMode(PathMode::Continuous)) => match tolerance {
                    Some(c) => out.extend(tolerance_lines(c, words, s.span, diags)),
                    None => out.push(s),
                },
                StmtKind::CoordShift {
                    kind: CoordShift::Local,
                    axes,
                } if lacks(to, Meaning::CoordShift(CoordShift::Local)) => {
                    match shift.and_then(|c| shift_lines(c, axes, s.span)) {
                        Some(lines) => out.extend(lines),
                        None => out.push(s),
                    }
                }
                _ => out.push(s),
            }
        }
        b.stmts = out;
    }
}

fn cycle<'a>(to: &'a DialectSpec, kind: &str) -> Option<&'a CycleSig> {
    to.cycles.iter().find(|c| c.kind == kind)
}

fn lacks(to: &DialectSpec, m: Meaning) -> bool {
    to.code_for(m).is_none()
}

/// The cycle's name as the TNC writes it after the number: the start of
/// its doc up to the first bracket (`DATUM SETTING`).
fn title(c: &CycleSig) -> String {
    c.doc
        .split(['[', ':'])
        .next()
        .unwrap_or("")
        .trim()
        .to_string()
}

fn preset_def(c: &CycleSig, index: u32, span: Span) -> Stmt {
    let first = &c.params[0];
    let q = first
        .name
        .trim_start_matches(['Q', 'q'])
        .parse()
        .unwrap_or(0);
    let def = CycleDef {
        number: c.name.parse().unwrap_or(0),
        name: title(c),
        params: vec![QParam {
            q,
            value: Value::Number(crate::ir::Decimal::from_int(index as i64)),
            label: Some(first.doc.to_ascii_uppercase()),
            span,
        }],
    };
    Stmt::new(StmtKind::CycleDef(Box::new(def)), span)
}

fn tolerance_lines(
    c: &CycleSig,
    words: &[Word],
    span: Span,
    diags: &mut Vec<Diagnostic>,
) -> Vec<Stmt> {
    let cycle = c.name.parse().unwrap_or(0);
    let line = |sub: u32, words: Vec<CycleWord>| {
        Stmt::new(
            StmtKind::CycleLine(Box::new(CycleLine { cycle, sub, words })),
            span,
        )
    };
    let mut t = Vec::new();
    for w in words {
        if w.letter.eq_ignore_ascii_case(&'P') {
            t.push(CycleWord {
                name: "T".into(),
                value: Some(w.value.clone()),
                span: w.span,
            });
        } else {
            diags.push(
                Diagnostic::new(
                    Code::PortApproximate,
                    format!("`{}` of the path mode has no counterpart in the tolerance cycle: left out", w.letter),
                )
                .primary(w.span, "not carried")
                .help("the tolerance cycle takes the contour tolerance (T) only; set the rest on the machine"),
            );
        }
    }
    let head = CycleWord {
        name: title(c),
        value: None,
        span,
    };
    vec![line(0, vec![head]), line(1, t)]
}

/// The reverse, for a target with work-offset codes: a `datum-preset`
/// cycle of the source whose preset number is a number 1..9 becomes
/// that work offset (preset 2 → G55). Run before the cycle passes, which
/// would refuse the cycle.
pub fn presets_to_codes(p: &mut Program, from: &DialectSpec, to: &DialectSpec) {
    let Some(c) = cycle(from, "datum-preset") else {
        return;
    };
    let (Ok(number), Some(first)) = (c.name.parse::<u32>(), c.params.first()) else {
        return;
    };
    let q: u32 = first
        .name
        .trim_start_matches(['Q', 'q'])
        .parse()
        .unwrap_or(0);
    for s in p.blocks.iter_mut().flat_map(|b| b.stmts.iter_mut()) {
        let StmtKind::CycleDef(d) = &s.kind else {
            continue;
        };
        let n = d
            .params
            .iter()
            .find(|x| x.q == q)
            .and_then(|x| x.value.number())
            .and_then(|v| v.as_int())
            .filter(|n| (1..=9).contains(n));
        if let Some(n) = n.filter(|_| d.number == number) {
            if to.code_for(Meaning::WorkOffset(n as u32)).is_some() {
                s.kind = StmtKind::WorkOffset {
                    index: n as u32,
                    extended: None,
                };
            }
        }
    }
}

/// Does the program rotate, mirror or scale its coordinates anywhere?
fn has_transform(p: &Program) -> bool {
    p.blocks
        .iter()
        .flat_map(|b| &b.stmts)
        .any(|s| matches!(s.kind, StmtKind::Transform(_)))
}

/// `G52 X10 Y0 Z-5` as the datum-shift cycle's lines (absolute values).
fn shift_lines(c: &CycleSig, axes: &Axes, span: Span) -> Option<Vec<Stmt>> {
    let cycle = c.name.parse().ok()?;
    let given = [("X", &axes.x), ("Y", &axes.y), ("Z", &axes.z)];
    let others = [&axes.a, &axes.b, &axes.c, &axes.u, &axes.v, &axes.w];
    if others.iter().any(|a| a.is_some()) {
        return None;
    }
    let line = |sub: u32, words: Vec<CycleWord>| {
        Stmt::new(
            StmtKind::CycleLine(Box::new(CycleLine { cycle, sub, words })),
            span,
        )
    };
    let mut out = vec![line(
        0,
        vec![CycleWord {
            name: title(c),
            value: None,
            span,
        }],
    )];
    for (sub, (name, coord)) in (1..).zip(given) {
        let coord = coord.as_ref()?;
        if coord.dim.is_some() {
            return None;
        }
        out.push(line(
            sub,
            vec![CycleWord {
                name: name.into(),
                value: Some(coord.value.clone()),
                span: coord.span,
            }],
        ));
    }
    Some(out)
}
