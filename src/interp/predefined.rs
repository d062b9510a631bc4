//! LinuxCNC's predefined read-only named parameters (`#<_x>`,
//! `#<_metric>`, ...) and the numbered system parameters that mirror the
//! machine state (#5210/#5211 G92, #5220/#5221.. work offsets,
//! #5420.. position), computed from the machine state when read.

use super::host::SpindleDir;
use super::state::ModalMotion;
use super::Interp;
use crate::ir::{ArcDir, CompSide, CycleKind, FeedMode, LengthUnit, MotionKind};

/// The value of a predefined named parameter, if `name` is one.
pub fn named(it: &Interp<'_, '_>, name: &str) -> Option<f64> {
    let s = &it.state;
    let axis = |i: usize| {
        // Reading a lathe cycle's contour: its point is the position.
        if let Some(p) = it.lathe.contour_point().filter(|_| i == 0 || i == 2) {
            return Some(if i == 0 { p.im } else { p.re });
        }
        let v = s.pos[i];
        Some(if super::state::State::is_linear(i) {
            s.to_prog(v)
        } else {
            v
        })
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
            0 => 541.0, // Fanuc G54.1 P (extended)
            i => 590.0 + (i - 6) as f64,
        }),
        // rs274's sequence number: the line being run, counted from 1.
        "_line" => Some(it.line as f64),
        "_call_level" => Some((it.params.depth() - 1) as f64),
        "_plane" => Some(match s.plane {
            crate::canon::CanonPlane::XY => 170.0,
            crate::canon::CanonPlane::XZ => 180.0,
            crate::canon::CanonPlane::YZ => 190.0,
        }),
        "_flood" => Some(s.flood as i64 as f64),
        "_mist" => Some(s.mist as i64 as f64),
        // The standalone interpreter: no task, no remapping, no adaptive
        // feed; the overrides and feed hold are enabled (rs274 prints 1).
        "_task" | "_remap_level" | "_adaptive_feed" => Some(0.0),
        // What the last o-word return gave: 0 before any (rs274 2.9, its
        // return-value test); a return sets the parameters themselves.
        "_value" | "_value_returned" => Some(0.0),
        "_speed_override" | "_feed_override" | "_feed_hold" => Some(1.0),
        // LinuxCNC 2.9 reports `_vmajor` 2.9 and `_vminor` 0 (rs274 2.9.x).
        "_vmajor" => Some(2.9),
        "_vminor" => Some(0.0),
        _ => modal(it, name).or_else(|| ini_var(it, name)),
    }
}

/// `#<_ini[SECTION]NAME>`: a number from the INI file when
/// `[RS274NGC]INI_VARS` lets the program read it (`--ini`); section and
/// name are looked up in capitals, as rs274 does. Not a number, or not
/// there: undefined.
fn ini_var(it: &Interp<'_, '_>, name: &str) -> Option<f64> {
    let ini = it.opts.rs274.ini_vars.as_ref()?;
    let rest = name
        .get(..5)?
        .eq_ignore_ascii_case("_ini[")
        .then(|| &name[5..])?;
    let (section, key) = rest.split_once(']')?;
    ini.number(section, key)
}

/// The modal-state parameters (`#<_motion_mode>`, `#<_ccomp>`, ...) and the
/// absolute-position ones (`#<_abs_x>`: machine frame, program units).
fn modal(it: &Interp<'_, '_>, name: &str) -> Option<f64> {
    let s = &it.state;
    let b = |v: bool| Some(v as i64 as f64);
    let lower = name.to_ascii_lowercase();
    if let Some(axis) = lower.strip_prefix("_abs_") {
        let i = "xyzabcuvw".find(axis).filter(|_| axis.len() == 1)?;
        let v = s.machine_pos()[i];
        return Some(if super::state::State::is_linear(i) {
            s.to_prog(v)
        } else {
            v
        });
    }
    match lower.as_str() {
        // G5.3 leaves rs274's motion mode at -1 (no G code).
        "_motion_mode" if s.motion == ModalMotion::None && it.splines.no_motion_code => Some(-1.0),
        "_motion_mode" => Some(motion_code(s.motion)),
        "_ccomp" => Some(match s.comp_side {
            CompSide::Off => 400.0,
            CompSide::Left => 410.0,
            CompSide::Right => 420.0,
        }),
        "_inverse_time" => b(s.feed_mode == FeedMode::InverseTime),
        "_units_per_minute" => b(s.feed_mode == FeedMode::PerMinute),
        "_units_per_rev" => b(s.feed_mode == FeedMode::PerRevolution),
        "_tool_offset" => b(s.tool_offset.iter().any(|v| *v != 0.0)),
        "_retract_r_plane" => b(!s.retract_initial),
        "_retract_old_z" => b(s.retract_initial),
        "_spindle_rpm_mode" => b(s.css_max == 0.0),
        "_spindle_css_mode" => b(s.css_max != 0.0),
        "_ijk_absolute_mode" => b(s.arc_absolute),
        "_lathe_diameter_mode" => b(s.lathe_diameter),
        "_lathe_radius_mode" => b(!s.lathe_diameter),
        "_spindle_on" => b(s.spindle != SpindleDir::Stopped),
        "_spindle_cw" => b(s.spindle == SpindleDir::Cw),
        _ => None,
    }
}

/// `#<_motion_mode>`: the G code of the modal motion times ten (G80: 800).
fn motion_code(m: ModalMotion) -> f64 {
    match m {
        ModalMotion::None => 800.0,
        ModalMotion::Move(k) => match k {
            MotionKind::Rapid => 0.0,
            MotionKind::Linear => 10.0,
            MotionKind::Arc(ArcDir::Cw) => 20.0,
            MotionKind::Arc(ArcDir::Ccw) => 30.0,
            MotionKind::Probe {
                toward: true,
                error: true,
            } => 382.0,
            MotionKind::Probe {
                toward: true,
                error: false,
            } => 383.0,
            MotionKind::Probe {
                toward: false,
                error: true,
            } => 384.0,
            MotionKind::Probe {
                toward: false,
                error: false,
            } => 385.0,
            MotionKind::Other(d) => (d.to_f64() * 10.0).round(),
            MotionKind::Implicit | MotionKind::ArcThrough | MotionKind::ArcTangent => 800.0,
        },
        ModalMotion::Cycle(c) => match c {
            CycleKind::Drill => 810.0,
            CycleKind::DrillDwell => 820.0,
            CycleKind::Peck => 830.0,
            CycleKind::ChipBreak => 730.0,
            CycleKind::Tap => 840.0,
            CycleKind::TapLeft => 740.0,
            CycleKind::BoreFeedOut => 850.0,
            CycleKind::BoreStopRapidOut => 860.0,
            CycleKind::BackBore => 870.0,
            CycleKind::BoreManual => 880.0,
            CycleKind::BoreDwellFeedOut => 890.0,
            CycleKind::FineBore => 760.0,
        },
    }
}

/// A numbered system parameter that mirrors the machine state, if `n` is
/// one (LinuxCNC numbering; Fanuc's #5221.. work offsets use the same
/// stride). Others (#5161 G28, #5181 G30, probe results) are stored
/// parameters: the core writes them with `params.set_numbered`.
pub fn numbered(it: &Interp<'_, '_>, n: u32) -> Option<f64> {
    let s = &it.state;
    let machine = it
        .spec
        .has(crate::dialect::Capability::OffsetParametersInMachineUnits);
    let scale = match it.opts.machine_units {
        crate::ir::LengthUnit::Inch => super::state::MM_PER_INCH,
        crate::ir::LengthUnit::Mm => 1.0,
    };
    let len = |i: usize, v: f64| {
        if !super::state::State::is_linear(i) {
            v
        } else if machine {
            v / scale
        } else {
            s.to_prog(v)
        }
    };
    match n {
        5210 => Some(s.g92_flag),
        // G92.2 suspends the offset and keeps its values (rs274 2.9).
        5211..=5219 => {
            let i = (n - 5211) as usize;
            Some(len(i, s.g92[i]))
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
        // #5400..#5410 are stored parameters written by M6 (see tools.rs).
        5420..=5428 => named(
            it,
            ["_x", "_y", "_z", "_a", "_b", "_c", "_u", "_v", "_w"][(n - 5420) as usize],
        ),
        _ => None,
    }
}
