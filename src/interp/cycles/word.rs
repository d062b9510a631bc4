//! Resolving one word-address cycle block (sticky values, G90/G91, G98/G99,
//! repeats) and running it, in the order LinuxCNC 2.9 does: checks, the
//! raise to R when the initial level is below it, exact-path mode, the
//! positioning moves and the cycle body per repeat, then the old path mode.

use super::body::{run_body, Levels};
use super::frame::Frame;
use super::memory::CycleMemory;
use crate::canon::{Canon, CanonUnits, MotionMode};
use crate::diag::{Code, Diagnostic};
use crate::interp::cycle_io::CycleBlock;
use crate::interp::host::MotionHost;
use crate::ir::{CycleKind, DwellUnit};

/// Runs one canned-cycle block. Problems are reported through
/// `host.report`; the block then stops where LinuxCNC stops (moves already
/// made stay made, the path mode is not restored, memory is not updated).
pub fn run_cycle(host: &mut dyn MotionHost, mem: &mut CycleMemory, block: &CycleBlock) {
    if let Err(d) = try_run(host, mem, block) {
        host.report(d);
    }
}

fn err(code: Code, block: &CycleBlock, msg: &str, label: &str, help: &str) -> Diagnostic {
    Diagnostic::new(code, msg)
        .primary(block.span, label)
        .help(help)
}

/// The resolved geometry of one block.
struct Plan {
    start: (f64, f64),
    step: (f64, f64),
    /// G91 polar words: distance and angle (degrees) added per repeat.
    polar_step: Option<(f64, f64)>,
    r: f64,
    bottom: f64,
    bottom_word: f64,
    r_word: f64,
    old: f64,
    repeats: u64,
}

fn try_run(
    host: &mut dyn MotionHost,
    mem: &mut CycleMemory,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let same = mem.active == Some(block.kind);
    if block.rotary_refused {
        if let Some(i) = (3..6).find(|i| block.axes[*i].is_some()) {
            let letter = ["a", "b", "c"][i - 3];
            return Err(err(
                Code::WordNotAllowed,
                block,
                &format!("Cannot put an {letter} in canned cycle"),
                "rotary axis word in a cycle block",
                "move the rotary axis in a block of its own, after G80",
            ));
        }
    }
    if host.feed_rate() == 0.0 {
        return Err(err(
            Code::CycleZeroFeed,
            block,
            "cannot feed with zero feed rate",
            "canned cycle with F0",
            "program a feed rate (F) before the cycle",
        ));
    }
    let r_word = match (block.r, same) {
        (Some(r), _) => r,
        (None, true) => mem.r,
        (None, false) if block.words_required => {
            return Err(err(
                Code::CycleMissingWord,
                block,
                "R clearance plane unspecified in cycle",
                "no R word",
                "give the retract plane with R in the first block of a cycle",
            ))
        }
        // [?] Fanuc/Haas: no R in the first block leaves point R at the
        // initial level (the cycle feeds from where the tool is).
        (None, false) if block.incremental => 0.0,
        (None, false) => Frame::of(host).here(host).1,
    };
    let repeats = repeats(block, mem)?;
    let frame = Frame::of(host);
    let plan = plan(host, mem, block, frame, r_word, same, repeats)?;
    if plan.repeats == 0 {
        remember(mem, block, &plan);
        return Ok(());
    }
    let below = enters_below(block);
    if below {
        super::oriented::downward_note(host, plan.r, plan.bottom, block);
    }
    let s = toward(plan.r, plan.bottom);
    let mut old = plan.old;
    if s * (old - plan.r) > 0.0 && !below {
        let (at, _) = frame.here(host);
        frame.rapid(host, at, plan.r);
        old = plan.r;
    }
    // [?] Fanuc back boring returns to the initial level only ("G99 is
    // not used" in its figure); the run takes G99 there as G98.
    let clear = if block.return_initial || below {
        old
    } else {
        plan.r
    };
    let (mode, naive) = host.path_mode();
    let wrap = mode != MotionMode::ExactPath;
    if wrap {
        host.emit(Canon::SetMotionControlMode(MotionMode::ExactPath));
    }
    let params = params(host, mem, block, same, plan.bottom, frame)?;
    super::oriented::no_shift_note(host, &params, block);
    positions_and_bodies(host, frame, &plan, clear, &params, block)?;
    if wrap {
        host.emit(Canon::SetMotionControlMode(mode));
        if let MotionMode::Continuous(_) = mode {
            host.emit(Canon::SetNaivecamTolerance(naive));
        }
    }
    remember(mem, block, &plan);
    mem.q = params.q.unwrap_or(mem.q);
    mem.dwell = params.dwell;
    if let Some(ijk) = params.ijk_words {
        mem.ijk = ijk;
    }
    if let Some(s) = &params.shift {
        super::oriented::remember(mem, s);
    }
    Ok(())
}

/// Fanuc back boring (a `shift` code): the tool enters below the part at R
/// from the initial level, oriented and shifted, so positioning stays on
/// the initial level.
fn enters_below(block: &CycleBlock) -> bool {
    block.kind == CycleKind::BackBore && block.shift.is_some()
}

/// The way the cycle drills along its axis from R: -1 down (R above the
/// bottom, the usual), +1 up (a right-angle head in G18, where the dialect
/// allows R below the bottom).
pub(super) fn toward(r: f64, bottom: f64) -> f64 {
    if bottom > r {
        1.0
    } else {
        -1.0
    }
}

fn remember(mem: &mut CycleMemory, block: &CycleBlock, plan: &Plan) {
    mem.active = Some(block.kind);
    mem.r_below_part = enters_below(block);
    mem.bottom = plan.bottom_word;
    mem.r = plan.r_word;
}

fn repeats(block: &CycleBlock, mem: &CycleMemory) -> Result<u64, Diagnostic> {
    let Some(l) = block.repeat else { return Ok(1) };
    if l < 0.0 || l.fract() != 0.0 || l > 1.0e6 {
        return Err(err(
            Code::CycleBadRepeat,
            block,
            "negative l word used",
            "repeat count",
            "the repeat count must be a whole number of at least 1",
        ));
    }
    if l == 0.0 && !mem.allow_zero_repeats {
        return Err(err(
            Code::CycleBadRepeat,
            block,
            "cannot do zero repeats of cycle",
            "L0",
            "leave L out to drill once",
        ));
    }
    Ok(l as u64)
}

fn plan(
    host: &dyn MotionHost,
    mem: &mut CycleMemory,
    block: &CycleBlock,
    f: Frame,
    r_word: f64,
    same: bool,
    repeats: u64,
) -> Result<Plan, Diagnostic> {
    let bottom_word = match (block.axes[f.n], same) {
        (Some(z), _) => z,
        (None, true) => mem.bottom,
        (None, false) => {
            let msg = format!(
                "{} value unspecified in {} plane canned cycle",
                axis_name(f.n),
                plane_name(f)
            );
            return Err(err(
                Code::CycleMissingWord,
                block,
                &msg,
                "no hole bottom",
                "give the bottom of the hole in the first block of a cycle",
            ));
        }
    };
    let (here, cur_n) = f.here(host);
    let old = *mem.initial_level.get_or_insert(cur_n);
    let (start, step, r, bottom);
    if block.incremental {
        step = (
            block.axes[f.a].unwrap_or(0.0),
            block.axes[f.b].unwrap_or(0.0),
        );
        start = here;
        r = r_word + old;
        bottom = r + bottom_word;
    } else {
        step = (0.0, 0.0);
        start = (
            block.axes[f.a].unwrap_or(here.0),
            block.axes[f.b].unwrap_or(here.1),
        );
        r = r_word;
        bottom = bottom_word;
    }
    if r < bottom && !enters_below(block) && block.r_above_bottom {
        let msg = format!(
            "R less than {} in cycle in {} plane",
            axis_name(f.n).to_lowercase(),
            plane_name(f).to_lowercase()
        );
        return Err(err(
            Code::CycleRBelowBottom,
            block,
            &msg,
            "R plane below the bottom",
            "R must lie between the initial level and the hole bottom",
        ));
    }
    Ok(Plan {
        start,
        step,
        polar_step: block.polar_step,
        r,
        bottom,
        bottom_word,
        r_word,
        old,
        repeats,
    })
}

fn axis_name(i: usize) -> &'static str {
    ["X", "Y", "Z", "A", "B", "C"][i]
}

fn plane_name(f: Frame) -> &'static str {
    match f.n {
        2 => "XY",
        1 => "XZ",
        _ => "YZ",
    }
}

/// The words the body needs, resolved against the memory.
pub(super) struct Params {
    pub q: Option<f64>,
    pub dwell: f64,
    pub ijk_words: Option<[f64; 3]>,
    /// G87: the top of the back bore, absolute along the drilling axis.
    pub middle: f64,
    pub rapid_delta: f64,
    pub kind: CycleKind,
    /// Fanuc/Haas oriented boring: the resolved shift.
    pub shift: Option<super::oriented::Shift>,
}

fn params(
    host: &dyn MotionHost,
    mem: &CycleMemory,
    block: &CycleBlock,
    same: bool,
    bottom: f64,
    f: Frame,
) -> Result<Params, Diagnostic> {
    use CycleKind::*;
    let need_p = matches!(
        block.kind,
        DrillDwell | BoreStopRapidOut | BoreManual | BoreDwellFeedOut
    );
    // Fanuc/Haas: no P is no dwell; LinuxCNC refuses it.
    if need_p && block.p.is_none() && !same && block.words_required {
        let msg = format!("dwell time P word missing with {}", gcode(block.kind));
        return Err(err(
            Code::CycleMissingWord,
            block,
            &msg,
            "no P word",
            "give the dwell time with P",
        ));
    }
    let dwell = block
        .p
        .map(|p| to_seconds(p, block.p_unit, host.spindle_speed()))
        .unwrap_or(mem.dwell);
    let shift = super::oriented::resolve(mem, block, f);
    let q = match block.kind {
        _ if shift.is_some() => shift.and_then(|s| s.q),
        Peck | ChipBreak | FineBore => Some(q_word(mem, block, same)?),
        _ => None,
    };
    let (ijk_words, middle) = if block.kind == BackBore && shift.is_none() {
        g87_words(mem, block, same, bottom, f)?
    } else {
        (None, 0.0)
    };
    let rapid_delta = match host.units() {
        CanonUnits::Inches => 0.010,
        CanonUnits::Mm => 0.254,
    };
    Ok(Params {
        q,
        dwell,
        ijk_words,
        middle,
        rapid_delta,
        kind: block.kind,
        shift,
    })
}

fn q_word(mem: &CycleMemory, block: &CycleBlock, same: bool) -> Result<f64, Diagnostic> {
    match (block.q, same) {
        (Some(q), _) => Ok(q),
        (None, true) => Ok(mem.q),
        (None, false) => {
            let msg = format!("Q word missing with {}", gcode(block.kind));
            Err(err(
                Code::CycleMissingWord,
                block,
                &msg,
                "no Q word",
                "give the peck depth (or shift) with Q",
            ))
        }
    }
}

fn g87_words(
    mem: &CycleMemory,
    block: &CycleBlock,
    same: bool,
    bottom: f64,
    f: Frame,
) -> Result<(Option<[f64; 3]>, f64), Diagnostic> {
    let words = [block.i, block.j, block.k];
    let mut ijk = mem.ijk;
    for (n, w) in words.iter().enumerate() {
        match (w, same) {
            (Some(v), _) => ijk[n] = *v,
            (None, true) => {}
            (None, false) => {
                let msg = format!("{} word missing with G87", ["I", "J", "K"][n]);
                return Err(err(
                    Code::CycleMissingWord,
                    block,
                    &msg,
                    "back boring needs I, J and K",
                    "give the shift (I, J) and the top of the back bore (K)",
                ));
            }
        }
    }
    // The top of the back bore is the drilling-axis word of I J K (K in
    // G17, J in G18, I in G19): absolute in G90, from the bottom in G91.
    let word = ijk[f.n];
    let middle = if block.incremental {
        bottom + word
    } else {
        word
    };
    Ok((Some(ijk), middle))
}

fn to_seconds(p: f64, unit: DwellUnit, speed: f64) -> f64 {
    match unit {
        DwellUnit::Seconds => p,
        DwellUnit::Milliseconds => p / 1000.0,
        DwellUnit::Revolutions => {
            if speed > 0.0 {
                p * 60.0 / speed
            } else {
                0.0
            }
        }
    }
}

pub(super) fn gcode(kind: CycleKind) -> &'static str {
    use CycleKind::*;
    match kind {
        Drill => "G81",
        DrillDwell => "G82",
        Peck => "G83",
        ChipBreak => "G73",
        Tap => "G84",
        TapLeft => "G74",
        BoreFeedOut => "G85",
        BoreStopRapidOut => "G86",
        BackBore => "G87",
        BoreManual => "G88",
        BoreDwellFeedOut => "G89",
        FineBore => "G76",
    }
}

/// LinuxCNC's positioning per repeat: the first at the current level when
/// that is above R (then down to R), later ones at the clear level.
fn positions_and_bodies(
    host: &mut dyn MotionHost,
    f: Frame,
    plan: &Plan,
    clear: f64,
    params: &Params,
    block: &CycleBlock,
) -> Result<(), Diagnostic> {
    let below = enters_below(block);
    let s = toward(plan.r, plan.bottom);
    let mut at = plan.start;
    for n in 0..plan.repeats {
        at = match plan.polar_step {
            Some(step) => polar_step(at, step, block)?,
            None => (at.0 + plan.step.0, at.1 + plan.step.1),
        };
        let (_, cur) = f.here(host);
        // "Above R": on the side of R away from the bottom.
        if n == 0 && s * (cur - plan.r) < 0.0 {
            f.rapid(host, at, cur);
            if !below {
                f.rapid(host, at, plan.r);
            }
        } else {
            f.rapid(host, at, clear);
            if s * (clear - plan.r) < 0.0 && !below {
                f.rapid(host, at, plan.r);
            }
        }
        let levels = Levels {
            at,
            r: plan.r,
            clear,
            bottom: plan.bottom,
        };
        run_body(host, f, &levels, params, block)?;
    }
    Ok(())
}

/// The next hole of a G91 polar repeat: `at` turned by the angle step and
/// moved out by the distance step, about the program origin.
fn polar_step(
    at: (f64, f64),
    (dr, da): (f64, f64),
    block: &CycleBlock,
) -> Result<(f64, f64), Diagnostic> {
    if at == (0.0, 0.0) {
        return Err(err(
            Code::PolarAtOrigin,
            block,
            "Incremental motion with polar coordinates is indeterminate when at the origin",
            "G91 polar words at the origin",
            "move off the program origin before an incremental polar cycle",
        ));
    }
    let r = at.0.hypot(at.1) + dr;
    let a = at.1.atan2(at.0) + da.to_radians();
    Ok((r * a.cos(), r * a.sin()))
}
