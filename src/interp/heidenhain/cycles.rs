//! Heidenhain cycles when called: the numbered drilling cycles (200, 201,
//! 202, 203, 205, 207, 240) and pockets (251, 252) run through the
//! Siemens cycle expansions they correspond to, with Heidenhain's
//! parameters translated (`reference/dialects.md` §0 and §2.6):
//! * Q203 is the surface (Siemens RFP), Q200 the set-up clearance above it
//!   (SDIS), Q201 the depth from Q203, signed (DP = Q203 + Q201), Q204 the
//!   2nd set-up clearance (RTP = Q203 + Q204), Q206 the plunging feed.
//! * 200 with Q202 less than the depth pecks (CYCLE83, full retract to the
//!   set-up clearance after each infeed); else CYCLE82/CYCLE81. 203 and
//!   205 are CYCLE83 with even Q202 infeeds and Q205 as the minimum
//!   infeed [?: the Q212 decrement is not modelled]; chip breaking
//!   (backing off Q256) when 203's Q213 > 0 or after every Q257 of 205
//!   [?: the number of breaks before a full retract is not modelled].
//!   201 → CYCLE85, 202 → CYCLE86, 206 → CYCLE840,
//!   207 → CYCLE84.
//! * 251 → POCKET1, 252 → POCKET2 about the current position (Q367 = 0),
//!   Q215 as their VARI (0 rough + finish, 1 rough, 2 finish); stepover
//!   and finishing as the Siemens expansion does them [?]; 253
//!   (slot) → POCKET1 with full-round ends [?]; 232 (face) → CYCLE71.
//! * `PATTERN DEF` points: [`super::pattern`].
//! * 204, 208, 209, 241, 254, 256, 262 run in `cycles_run` (own
//!   expansions; 254 through SLOT2), see `docs/heidenhain-cycles.md`.
//! * Old cycles 2 and 17 (tapping) run in `cycles_old`; 3, 4, 5 are not
//!   run (E0510 at the call): their sub-number layouts are not confirmed.
//! * Old cycle 1 (pecking): 1.1 set-up clearance, 1.2 depth, 1.3
//!   plunging depth, 1.4 dwell, 1.5 feed, from the current height, which
//!   is the set-up clearance above the surface.
//!
//! Old cycles 7 (datum shift), 8 (mirror), 10 (rotation), 11 (scaling)
//! act when defined and build the programmable frame; 9 dwells at once.

use super::super::siemens::{frame::ProgFrame, milling, FramedHost};
use super::super::{Interp, Stop};
use super::mapping::{numbered, old_pecking, tool_radius};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::interp::cycles::run_named_drill_cycle;
use crate::ir::{Arena, Block, CycleLine, CycleRunKind, Expr, PatternItem};
use crate::span::Span;

/// An old-style cycle block.
pub fn line(
    it: &mut Interp<'_, '_>,
    l: &CycleLine,
    span: Span,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let mut first = None;
    let mut named = Vec::new();
    for w in &l.words {
        if let Some(v) = &w.value {
            let x = it.value(v, exprs)?;
            first.get_or_insert(x);
            named.push((w.name.as_str(), Some(x)));
        } else {
            named.push((w.name.as_str(), None));
        }
    }
    let h = &mut it.heidenhain;
    h.old.retain(|(k, _)| *k != (l.cycle, l.sub));
    if let Some(v) = first {
        h.old.push(((l.cycle, l.sub), v));
    }
    match (l.cycle, l.sub) {
        (1..=5 | 17, 0) => {
            h.old_cycle = Some(l.cycle);
            h.cycle = None;
            h.old.retain(|((c, _), _)| *c != l.cycle);
            Ok(())
        }
        (7, 0) | (8, 0) | (10, 0) | (11, 0) | (9, 0) | (32, _) => Ok(()),
        (7, _) => {
            for (name, v) in named {
                let inc = name.starts_with('I');
                let axis = match name.trim_start_matches('I') {
                    "X" => 0,
                    "Y" => 1,
                    "Z" => 2,
                    _ => continue,
                };
                let v = it.state.to_mm(v.unwrap_or(0.0));
                let s = &mut it.heidenhain.shift[axis];
                *s = if inc { *s + v } else { v };
            }
            if l.words.iter().any(|w| w.name == "#") {
                return Err(it.error_at(
                    span,
                    Code::UnsupportedHere,
                    "a datum shift from the datum table (`#n`) is not simulated",
                ));
            }
            rebuild(it);
            Ok(())
        }
        (8, _) => {
            let mut m = [false; 3];
            for (name, _) in named {
                match name {
                    "X" => m[0] = true,
                    "Y" => m[1] = true,
                    "Z" => m[2] = true,
                    _ => {}
                }
            }
            it.heidenhain.mirror = m;
            rebuild(it);
            Ok(())
        }
        (10, _) => {
            it.heidenhain.rotation = first.unwrap_or(0.0);
            rebuild(it);
            Ok(())
        }
        (11, _) => {
            let f = first.unwrap_or(1.0);
            if f == 0.0 {
                return Err(it.error_at(span, Code::DomainError, "a scaling factor of 0"));
            }
            it.heidenhain.scale = f;
            rebuild(it);
            Ok(())
        }
        (9, _) => {
            it.out(Canon::Dwell(first.unwrap_or(0.0)));
            Ok(())
        }
        (1..=5 | 17, _) => Ok(()),
        // Cycle 19 WORKING PLANE: a tilt is kept, not made (W0518).
        (19, 0) => Ok(()),
        (19, _) => {
            if named.iter().any(|(_, v)| v.is_some_and(|x| x != 0.0)) {
                super::functions::kinematics_not_run(it, "cycle 19 tilts the working plane", span);
            }
            Ok(())
        }
        (c, _) => Err(it.error_at(
            span,
            Code::UnsupportedHere,
            format!("the old cycle {c} is not run by the interpreter yet"),
        )),
    }
}

/// The programmable frame of cycles 7, 10, 8, 11 (in that order).
fn rebuild(it: &mut Interp<'_, '_>) {
    let h = &it.heidenhain;
    let scale = if h.scale == 0.0 { 1.0 } else { h.scale };
    let f = ProgFrame::trans(h.shift)
        .then(&ProgFrame::rot_about(2, h.rotation))
        .then(&ProgFrame::mirror(h.mirror))
        .then(&ProgFrame::scale([scale; 3]));
    it.siemens.frame = f;
}

/// `PATTERN DEF`: the points it gives (see [`super::pattern`]).
pub fn pattern(
    it: &mut Interp<'_, '_>,
    items: &[PatternItem],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.heidenhain.pattern = super::pattern::points(it, items, exprs)?;
    Ok(())
}

/// `CYCL CALL`, `M99`, `M89`, `CYCL CALL PAT`, `CYCL CALL POS`.
pub fn run(
    it: &mut Interp<'_, '_>,
    kind: &CycleRunKind,
    span: Span,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    super::corner::flush(it)?;
    match kind {
        CycleRunKind::Call | CycleRunKind::Block => call_here(it, span, block, exprs),
        CycleRunKind::Modal => {
            it.heidenhain.modal_call = true;
            call_here(it, span, block, exprs)
        }
        CycleRunKind::Pos { axes, .. } => {
            let w = crate::interp::target::written(it, axes, exprs)?;
            rapid_to(it, w[0], w[1]);
            call_at(it, span, w[2])
        }
        CycleRunKind::Pattern { .. } => {
            let pts = it.heidenhain.pattern.clone();
            if pts.is_empty() {
                return Err(it.error_at(
                    span,
                    Code::UnsupportedHere,
                    "CYCL CALL PAT without a PATTERN DEF before it",
                ));
            }
            for p in pts {
                rapid_to(it, p[0], p[1]);
                call_at(it, span, p[2])?;
            }
            Ok(())
        }
    }
}

fn rapid_to(it: &mut Interp<'_, '_>, x: Option<f64>, y: Option<f64>) {
    let mut to = it.state.pos;
    if let Some(x) = x {
        to[0] = it.state.to_mm(x);
    }
    if let Some(y) = y {
        to[1] = it.state.to_mm(y);
    }
    let b = super::super::siemens::to_base(it, [to[0], to[1], to[2]]);
    to[..3].copy_from_slice(&b);
    if to != it.state.pos {
        let pose = crate::interp::machine::pose6(&it.state, &to);
        let _ = it.straight_move(crate::interp::comp::MoveKind::Rapid, pose);
    }
}

pub fn call_here(
    it: &mut Interp<'_, '_>,
    span: Span,
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let _ = (block, exprs);
    call_at(it, span, None)
}

/// Runs the cycle defined last at the current position; `surface`
/// replaces Q203 (CYCL CALL POS / PAT with Z).
fn call_at(it: &mut Interp<'_, '_>, span: Span, surface: Option<f64>) -> Result<(), Stop> {
    let (name, args, feed) = match (it.heidenhain.cycle.clone(), it.heidenhain.old_cycle) {
        (_, Some(1)) => old_pecking(it),
        (_, Some(c)) if super::cycles_old::expands(c) => {
            return super::cycles_old::call(it, span, c)
        }
        (Some(def), _) if super::cycles_run::expands(def.number) => {
            return super::cycles_run::call(it, span, &def, surface)
        }
        (Some(def), _) => numbered(it, &def, surface),
        (None, Some(c)) => {
            return Err(it.error_at(
                span,
                Code::UnsupportedHere,
                format!("the old cycle {c} is not expanded yet"),
            ))
        }
        (None, None) => {
            return Err(it.error_at(
                span,
                Code::UnsupportedHere,
                "a cycle call with no cycle defined before it",
            ))
        }
    };
    let Some(name) = name else {
        it.diags.push(
            Diagnostic::new(
                Code::CannotExpandCycle,
                "this cycle is not expanded into moves: the call is left out",
            )
            .primary(span, "not expanded")
            .help("the run goes on after the call as if the cycle did nothing"),
        );
        return Ok(());
    };
    let saved_feed = it.state.feed;
    if let Some(f) = feed.filter(|f| *f > 0.0) {
        it.state.feed = f;
        it.out(Canon::SetFeedRate(f));
    }
    let frame = it.siemens.frame;
    let scale = it.state.scale();
    let mark = it.diags.len();
    let result = if name.starts_with("POCKET") || name == "CYCLE71" {
        let radius = tool_radius(it);
        match milling::run(&mut FramedHost::new(it, frame, scale), &name, &args, radius) {
            Ok(milling::Outcome::NotExpanded(why)) => {
                let d = Diagnostic::new(
                    Code::CannotExpandCycle,
                    format!("cycle {name} (as this CYCL DEF) not expanded"),
                )
                .primary(span, "this cycle call is left out of the run")
                .note(why);
                it.diags.push(d);
                Ok(())
            }
            r => r.map(|_| ()),
        }
    } else {
        run_named_drill_cycle(&mut FramedHost::new(it, frame, scale), &name, &args)
    };
    if feed.is_some_and(|f| f > 0.0) && saved_feed != it.state.feed {
        it.state.feed = saved_feed;
        if saved_feed > 0.0 {
            it.out(Canon::SetFeedRate(saved_feed));
        }
    }
    if let Err(d) = result {
        let d = if d.span().is_some() {
            d
        } else {
            d.primary(span, "in this cycle call")
        };
        return Err(Stop::Error(d));
    }
    it.take_error(mark)
}
