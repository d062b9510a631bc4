//! Heidenhain cycle parameters translated to the Siemens cycle that does
//! the same (see [`super::cycles`] for the mapping and its sources).

use super::super::{Interp, Stop};
use crate::ir::{Arena, Expr};

/// The radius of the tool in the spindle (program units), from the tool table.
pub(super) fn tool_radius(it: &Interp<'_, '_>) -> f64 {
    let t = it.state.tool_in_spindle;
    let scale = match it.opts.machine_units {
        crate::ir::LengthUnit::Inch => 25.4,
        crate::ir::LengthUnit::Mm => 1.0,
    };
    it.tool_table
        .get(t)
        .map(|x| it.state.to_prog(x.diameter * scale) / 2.0)
        .unwrap_or(0.0)
}

pub(super) type Call = (Option<String>, Vec<Option<f64>>, Option<f64>);

/// Old cycle 1 as CYCLE83 from the current height.
pub(super) fn old_pecking(it: &mut Interp<'_, '_>) -> Call {
    let v = |s: u32| {
        it.heidenhain
            .old
            .iter()
            .find(|(k, _)| *k == (1, s))
            .map(|(_, v)| *v)
    };
    let (dist, depth, peck, dwell, f) = (
        v(1).unwrap_or(0.0).abs(),
        v(2).unwrap_or(0.0),
        v(3).unwrap_or(0.0).abs(),
        v(4),
        v(5),
    );
    let z = it.state.to_prog(
        super::super::siemens::from_base(it, [it.state.pos[0], it.state.pos[1], it.state.pos[2]])
            [2],
    );
    let rfp = z - dist;
    let dp = rfp - depth.abs();
    let mut a = vec![Some(z), Some(rfp), Some(dist), Some(dp), None];
    if peck > 0.0 && peck < depth.abs() {
        a.extend([None, Some(peck), Some(peck), dwell, None, None, Some(1.0)]);
        (Some("CYCLE83".into()), a, f)
    } else {
        a.push(dwell);
        (Some("CYCLE82".into()), a, f)
    }
}

/// Evaluates a definition's parameters (when it is defined [?: the TNC
/// may read Q parameters given to a cycle when it is called]).
pub fn define(
    it: &mut Interp<'_, '_>,
    def: &crate::ir::CycleDef,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let mut vals = Vec::with_capacity(def.params.len());
    for p in &def.params {
        vals.push((p.q, it.value(&p.value, exprs)?));
    }
    if preset(it, def, &vals) {
        it.heidenhain.cycle = None;
        return Ok(());
    }
    let selects_preset = it
        .spec
        .cycle(&def.number.to_string())
        .is_some_and(|c| c.kind == "datum-preset");
    if selects_preset && it.once("preset") {
        it.diags.push(
            crate::diag::Diagnostic::new(
                crate::diag::Code::UnknownAtCheckTime,
                "cycle 247 activates a preset of the machine's preset table, unknown at check time",
            )
            .primary(it.span, "the run keeps the datum it has")
            .help("coordinates after it are checked against the datum before it (see `cncc explain W0517`)"),
        );
    }
    it.heidenhain.cycle = Some(super::Defined {
        number: def.number,
        params: vals,
    });
    it.heidenhain.old_cycle = None;
    Ok(())
}

/// A `datum-preset` cycle (247) activating preset 1..9: the machine's
/// work offset of that number, as G54..G59.3 select them (preset 1 is
/// G54's, the convention ports and CAM posts use [?: the machine's
/// preset table decides]). Another preset number is not run (W0517).
fn preset(it: &mut Interp<'_, '_>, def: &crate::ir::CycleDef, vals: &[(u32, f64)]) -> bool {
    let Some(sig) = it.spec.cycle(&def.number.to_string()) else {
        return false;
    };
    if sig.kind != "datum-preset" {
        return false;
    }
    let first = sig
        .params
        .first()
        .and_then(|p| p.name.trim_start_matches('Q').parse::<u32>().ok());
    let n = vals
        .iter()
        .find(|(q, _)| Some(*q) == first)
        .map(|(_, v)| *v);
    match n {
        Some(n) if n.fract() == 0.0 && (1.0..=9.0).contains(&n) => {
            crate::interp::offsets::work_offset(it, n as u32);
            true
        }
        _ => false,
    }
}

/// A numbered cycle as the Siemens cycle that does the same.
pub(super) fn numbered(
    it: &mut Interp<'_, '_>,
    def: &super::Defined,
    surface: Option<f64>,
) -> Call {
    let vals = &def.params;
    let q = |n: u32| vals.iter().find(|(k, _)| *k == n).map(|(_, v)| *v);
    let g = |n: u32| q(n).unwrap_or(0.0);
    let top = surface.or(q(203)).unwrap_or(0.0);
    let (rtp, sdis, dp) = (top + g(204).abs(), g(200).abs(), top + g(201));
    let mut a = vec![Some(rtp), Some(top), Some(sdis), Some(dp), None];
    let feed = q(206);
    let name = match def.number {
        200 | 240 => {
            let (depth, peck) = (g(201).abs(), g(202).abs());
            if def.number == 200 && peck > 0.0 && peck < depth {
                a.extend([
                    None,
                    Some(peck),
                    Some(peck),
                    q(211),
                    q(210),
                    None,
                    Some(1.0),
                ]);
                "CYCLE83"
            } else if g(211) > 0.0 {
                a.push(q(211));
                "CYCLE82"
            } else {
                "CYCLE81"
            }
        }
        203 | 205 => {
            // 205 breaks chips after every Q257 (backing off Q256) [?: a
            // full retract after each Q202 as well is not modelled, nor
            // the Q212 decrement of either cycle].
            let breaks_205 = def.number == 205 && g(257) > 0.0;
            let chip = (def.number == 203 && g(213) > 0.0) || breaks_205;
            let infeed = if breaks_205 { g(257) } else { g(202) }.abs();
            a.extend([
                None,
                Some(infeed),
                Some(infeed),
                q(211),
                q(210),
                None,
                Some(if chip { 0.0 } else { 1.0 }),
                None,
                q(205),
                if chip { q(256) } else { None },
            ]);
            "CYCLE83"
        }
        201 => {
            a.extend([q(211), q(206), q(208)]);
            "CYCLE85"
        }
        202 => {
            a.extend([q(211), Some(3.0), None, None, None, q(336)]);
            "CYCLE86"
        }
        // Floating chuck: CYCLE840 at the feed Q206 (ENC 1: no encoder),
        // dwell Q211, automatic reversal (SDR 0).
        206 => {
            a.extend([q(211), Some(0.0), None, Some(1.0)]);
            "CYCLE840"
        }
        207 => {
            a.extend([None, None, None, q(239), None, Some(it.state.speed.abs())]);
            "CYCLE84"
        }
        251 | 252 => {
            let p = super::super::siemens::from_base(
                it,
                [it.state.pos[0], it.state.pos[1], it.state.pos[2]],
            );
            let (cx, cy) = (it.state.to_prog(p[0]), it.state.to_prog(p[1]));
            // Q351 +1 climbs: G3 inside the pocket with M3 (CDIR 3).
            let cdir = if g(351) >= 0.0 { 3.0 } else { 2.0 };
            // Q215 0 rough + finish, 1 rough, 2 finish: POCKET1/2's VARI.
            let tail = [q(206), q(207), q(202), Some(cdir), q(368), Some(g(215))];
            if def.number == 251 {
                a.extend([q(218), q(219), q(220), Some(cx), Some(cy), q(224)]);
                a.extend(tail);
                return (Some("POCKET1".into()), a, None);
            }
            a.extend([q(223).map(|d| d / 2.0), Some(cx), Some(cy)]);
            a.extend(tail);
            return (Some("POCKET2".into()), a, None);
        }
        // [?] A slot is run as a rectangular pocket with full-round ends.
        253 => {
            let p = super::super::siemens::from_base(
                it,
                [it.state.pos[0], it.state.pos[1], it.state.pos[2]],
            );
            let (cx, cy) = (it.state.to_prog(p[0]), it.state.to_prog(p[1]));
            // Q351 +1 climbs: G3 inside the pocket with M3 (CDIR 3).
            let cdir = if g(351) >= 0.0 { 3.0 } else { 2.0 };
            a.extend([
                q(218),
                q(219),
                q(219).map(|w| w / 2.0),
                Some(cx),
                Some(cy),
                q(374),
            ]);
            a.extend([q(206), q(207), q(202), Some(cdir), q(368), Some(g(215))]);
            return (Some("POCKET1".into()), a, None);
        }
        // 232 as CYCLE71: Q227 surface, Q386 bottom (absolute), the face
        // from (Q225, Q226), Q218 x Q219; Q389 0/1 meander, 2 one way;
        // stepover Q370 x tool radius [?].
        232 => {
            let top = g(227);
            let tens = if g(389) as i64 == 2 { 1.0 } else { 3.0 };
            let mida = g(370).abs() * tool_radius(it);
            let a = vec![
                Some(top + g(204).abs()),
                Some(top),
                Some(g(200).abs()),
                q(386),
                q(225),
                q(226),
                q(218),
                q(219),
                Some(0.0),
                q(202),
                Some(mida),
                q(357),
                q(369),
                q(207),
                Some(tens * 10.0 + 1.0),
                None,
            ];
            return (Some("CYCLE71".into()), a, None);
        }
        _ => return (None, Vec::new(), None),
    };
    (Some(name.into()), a, feed)
}
