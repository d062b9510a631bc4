//! LinuxCNC's predefined read-only named parameters (`#<_x>`,
//! `#<_metric>`, ...) and the numbered system parameters that mirror the
//! machine state (#5211 G92, #5220/#5221.. work offsets, #5400 tool,
//! #5420.. position), computed from the machine state when read.

use super::Interp;
use crate::ir::LengthUnit;

/// The value of a predefined named parameter, if `name` is one.
pub fn named(it: &Interp<'_, '_>, name: &str) -> Option<f64> {
    let s = &it.state;
    let axis = |i: usize| {
        let v = s.pos[i];
        Some(if super::state::State::is_linear(i) { s.to_prog(v) } else { v })
    };
    match name.to_ascii_lowercase().as_str() {
        "_x" => axis(0),
        "_y" => axis(1),
        "_z" => axis(2),
        "_a" => axis(3),
        "_b" => axis(4),
        "_c" => axis(5),
        "_u" => axis(6),
        "_v" => axis(7),
        "_w" => axis(8),
        "_metric" => Some((s.units == LengthUnit::Mm) as i64 as f64),
        "_imperial" => Some((s.units == LengthUnit::Inch) as i64 as f64),
        "_absolute" => Some(s.absolute as i64 as f64),
        "_incremental" => Some(!s.absolute as i64 as f64),
        "_feed" => Some(s.feed),
        "_rpm" => Some(s.speed),
        "_current_tool" => Some(s.tool_in_spindle as f64),
        "_selected_tool" => Some(s.tool_selected.unwrap_or(-1) as f64),
        "_coord_system" => Some(match s.g5x_index {
            i @ 1..=6 => 530.0 + 10.0 * i as f64,
            i => 590.0 + (i - 6) as f64,
        }),
        "_call_level" => Some((it.params.depth() - 1) as f64),
        "_plane" => Some(match s.plane {
            crate::canon::CanonPlane::XY => 170.0,
            crate::canon::CanonPlane::XZ => 180.0,
            crate::canon::CanonPlane::YZ => 190.0,
        }),
        "_flood" => Some(s.flood as i64 as f64),
        "_mist" => Some(s.mist as i64 as f64),
        // The standalone interpreter: no task, no remapping, overrides on.
        "_task" | "_remap_level" | "_feed_hold" | "_adaptive_feed" => Some(0.0),
        "_speed_override" | "_feed_override" => Some(1.0),
        "_vmajor" => Some(2.0),
        "_vminor" => Some(9.0),
        _ => None,
    }
}

/// A numbered system parameter that mirrors the machine state, if `n` is
/// one (LinuxCNC numbering; Fanuc's #5221.. work offsets use the same
/// stride). Others (#5161 G28, #5181 G30, probe results) are stored
/// parameters: the core writes them with `params.set_numbered`.
pub fn numbered(it: &Interp<'_, '_>, n: u32) -> Option<f64> {
    let s = &it.state;
    let len = |i: usize, v: f64| if super::state::State::is_linear(i) { s.to_prog(v) } else { v };
    match n {
        5211..=5219 => {
            let i = (n - 5211) as usize;
            Some(if s.g92_applied { len(i, s.g92[i]) } else { 0.0 })
        }
        5220 => Some(s.g5x_index as f64),
        5221..=5399 => {
            let k = (n - 5221) / 20 + 1;
            let i = ((n - 5221) % 20) as usize;
            match i {
                0..=8 => Some(len(i, s.g5x[k as usize][i])),
                9 => Some(s.g5x_rotation[k as usize]),
                _ => None,
            }
        }
        5400 => Some(s.tool_in_spindle as f64),
        5401..=5409 => {
            let i = (n - 5401) as usize;
            Some(len(i, s.tool_offset[i]))
        }
        5420..=5428 => named(it, ["_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v", "_w"][(n - 5420) as usize]),
        _ => None,
    }
}
