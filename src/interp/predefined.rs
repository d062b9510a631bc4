//! LinuxCNC's predefined read-only named parameters (`#<_x>`,
//! `#<_metric>`, ...), computed from the machine state.

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
        _ => None,
    }
}
