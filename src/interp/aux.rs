//! Machine functions kept by code (`StmtKind::Aux`), run by the meaning
//! the dialect spec gives the code ([`MachineFn`]: LinuxCNC's override
//! switches, M61, I/O, modal-state save and restore, lathe diameter mode,
//! spindle-synchronised motion), or by its `run` attribute.

use super::{Interp, Stop};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::dialect::{DialectSpec, MachineFn, Meaning};
use crate::ir::{Arena, Block, Decimal, Expr, StmtKind, Word};

/// What a kept code means on this control, if it is one of the machine
/// functions the interpreter runs (the spec says; never the number).
pub fn machine_fn(spec: &DialectSpec, letter: char, code: Decimal) -> Option<MachineFn> {
    match spec.code(letter.to_ascii_uppercase(), code)?.meaning {
        Meaning::Machine(f) => Some(f),
        _ => None,
    }
}

fn lookup(spec: &DialectSpec, letter: char, code: f64) -> Option<MachineFn> {
    let d = Decimal::parse(&format!("{code}")).ok()?;
    machine_fn(spec, letter, d)
}

/// The value of a word among `words`, if written.
fn word(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match words
        .iter()
        .find(|w| w.letter.eq_ignore_ascii_case(&letter))
    {
        Some(w) => Ok(Some(it.value(&w.value, exprs)?)),
        None => Ok(None),
    }
}

/// The value of a word among a statement's own `words`, else among the
/// block's loose words.
pub fn word_or_loose(
    it: &mut Interp<'_, '_>,
    words: &[Word],
    block: &Block,
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    match word(it, words, letter, exprs)? {
        Some(v) => Ok(Some(v)),
        None => block_word(it, block, letter, exprs),
    }
}

/// Aux codes that are motions run in the motion phase (splines, lathe
/// threading, circular pockets), by their meaning in `spec`.
pub fn is_motion_aux(spec: &DialectSpec, letter: char, code: Decimal) -> bool {
    machine_fn(spec, letter, code).is_some_and(MachineFn::is_motion)
}

/// Runs a kept code that is a motion (in the motion phase of its block).
pub fn exec_motion(
    it: &mut Interp<'_, '_>,
    letter: char,
    code: Decimal,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    it.begin_block(block);
    match machine_fn(it.spec, letter, code) {
        Some(MachineFn::Spline(kind)) => super::splines::exec(it, kind, words, block, exprs),
        Some(MachineFn::LatheThread) => super::threading::exec(it, words, block, exprs),
        Some(MachineFn::LatheProfile(kind)) => {
            super::lathe_cycles::exec(it, kind, code, words, block, exprs)
        }
        Some(MachineFn::CircularPocket { clockwise }) => {
            super::haas_pocket::exec(it, letter, code, clockwise, words, block, exprs)
        }
        _ => Ok(()),
    }
}

/// The value of a loose word (`StmtKind::Word`) of the block, if written.
pub fn block_word(
    it: &mut Interp<'_, '_>,
    block: &Block,
    letter: char,
    exprs: &Arena<Expr>,
) -> Result<Option<f64>, Stop> {
    for s in &block.stmts {
        if let StmtKind::Word(w) = &s.kind {
            if w.letter.eq_ignore_ascii_case(&letter) {
                return Ok(Some(it.value(&w.value, exprs)?));
            }
        }
    }
    Ok(None)
}

/// A code the spec calls `path.smoothing` (high-speed contouring, look-
/// ahead): the programmed path stands, so it is run as nothing.
fn smoothing(it: &Interp<'_, '_>, letter: char, code: f64) -> bool {
    let Ok(d) = crate::ir::Decimal::parse(&code.to_string()) else {
        return false;
    };
    it.spec
        .code(letter.to_ascii_uppercase(), d)
        .is_some_and(|c| c.meaning == crate::dialect::Meaning::PathSmoothing)
}

/// An M code the spec does not know (a machine builder's): run as a
/// switch that moves nothing (W0519, once per run) [?: the code may do
/// more on its machine; a dialect file says what].
fn assumed_static(it: &mut Interp<'_, '_>, letter: char, code: f64) {
    if !it.once("assumed machine function") {
        return;
    }
    let span = it.span;
    it.diags.push(
        crate::diag::Diagnostic::new(
            Code::MachineFunctionAssumed,
            format!("{letter}{code} and the other M codes this dialect does not know are run as machine functions that do not move the axes"),
        )
        .primary(span, "run as a switch of the machine")
        .help("if it moves the machine or changes a mode, describe it in a dialect file (see `cncc explain W0519`)"),
    );
}

/// Runs an Aux statement.
pub fn exec(
    it: &mut Interp<'_, '_>,
    letter: char,
    code: f64,
    words: &[Word],
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    let Some(f) = lookup(it.spec, letter, code) else {
        use crate::dialect::spec::AuxRun;
        let known = crate::ir::Decimal::parse(&format!("{code}"))
            .ok()
            .and_then(|d| it.spec.code(letter, d));
        if known.is_none() && letter.eq_ignore_ascii_case(&'M') {
            assumed_static(it, letter, code);
            return Ok(());
        }
        let run = known.map(|c| c.run).unwrap_or_default();
        match run {
            AuxRun::Pass => return Ok(()),
            AuxRun::Kinematics => {
                let what = format!("{letter}{code} is a function of the machine's kinematics");
                let span = it.span;
                super::heidenhain::kinematics_not_run(it, &what, span);
                return Ok(());
            }
            AuxRun::MachineDatum => {
                machine_datum_note(it, letter, code);
                return Ok(());
            }
            AuxRun::Stop | AuxRun::UserProgram => {}
        }
        if smoothing(it, letter, code) {
            return Ok(());
        }
        return Err(it.error_at(
            it.span,
            Code::UnsupportedHere,
            format!("{letter}{code} is not run by the interpreter"),
        ));
    };
    let p = word(it, words, 'P', exprs)?;
    let on = p.map(|v| v != 0.0).unwrap_or(true);
    use MachineFn as F;
    match f {
        F::Overrides(on) => {
            it.state.feed_override = on;
            it.state.speed_override = on;
            it.out(if on {
                Canon::EnableFeedOverride
            } else {
                Canon::DisableFeedOverride
            });
            it.out(if on {
                Canon::EnableSpeedOverride
            } else {
                Canon::DisableSpeedOverride
            });
        }
        F::FeedOverride => {
            it.state.feed_override = on;
            it.out(if on {
                Canon::EnableFeedOverride
            } else {
                Canon::DisableFeedOverride
            });
        }
        F::SpeedOverride => {
            it.state.speed_override = on;
            it.out(if on {
                Canon::EnableSpeedOverride
            } else {
                Canon::DisableSpeedOverride
            });
        }
        F::AdaptiveFeed => it.out(if on {
            Canon::EnableAdaptiveFeed
        } else {
            Canon::DisableAdaptiveFeed
        }),
        F::FeedHold => it.out(if on {
            Canon::EnableFeedHold
        } else {
            Canon::DisableFeedHold
        }),
        F::SetToolNumber => {
            let q = word(it, words, 'Q', exprs)?.unwrap_or(0.0) as i64;
            let row = super::tools::row_of(it, q)?;
            it.state.tool_number = q;
            it.state.spindle_row = row;
            it.state.m61_block = Some(it.block_span);
            it.out(Canon::ChangeToolNumber(row));
        }
        F::DigitalOut { motion, on } => {
            let n = p.unwrap_or(0.0) as i64;
            let what = match (on, motion) {
                (true, true) => "SET_MOTION_OUTPUT_BIT",
                (false, true) => "CLEAR_MOTION_OUTPUT_BIT",
                (true, false) => "SET_AUX_OUTPUT_BIT",
                (false, false) => "CLEAR_AUX_OUTPUT_BIT",
            };
            it.out(Canon::Io(format!("{what}({n})")));
        }
        F::AnalogOut { motion } => {
            let e = word(it, words, 'E', exprs)?.unwrap_or(0.0) as i64;
            let q = word(it, words, 'Q', exprs)?.unwrap_or(0.0);
            let what = if motion {
                "SET_MOTION_OUTPUT_VALUE"
            } else {
                "SET_AUX_OUTPUT_VALUE"
            };
            it.out(Canon::Io(format!("{what}({e},{q:.6})")));
        }
        F::WaitInput => {}
        F::SaveModal { auto } => super::modal_save::save(it, auto),
        F::InvalidateModal => super::modal_save::invalidate(it),
        F::RestoreModal => {
            if !super::modal_save::restore_saved(it) {
                return Err(it.error_at(
                    it.span,
                    Code::BadWordValue,
                    "Cannot restore context: no valid context saved by M70",
                ));
            }
        }
        F::LatheDiameter(on) => {
            if on != it.state.lathe_diameter {
                let what = if on { "diameter" } else { "radius" };
                it.out(Canon::Comment(format!(
                    "interpreter: Lathe diameter mode changed to {what}"
                )));
            }
            it.state.lathe_diameter = on;
        }
        F::SpindleSync { rigid } => {
            let k = word(it, words, 'K', exprs)?.unwrap_or(0.0);
            it.cycles.cancel();
            it.state.sync_pitch = k;
            let _ = rigid;
            let code = Decimal::from_f64(code, 1);
            it.state.motion = super::state::ModalMotion::Move(crate::ir::MotionKind::Other(code));
        }
        // Motions run in the motion phase; a dynamic one is not run.
        F::Spline(_) | F::LatheThread | F::LatheProfile(_) | F::CircularPocket { .. } => {
            return Err(it.error_at(
                it.span,
                Code::UnsupportedHere,
                format!("{letter}{code} is not run by the interpreter when its number is computed"),
            ))
        }
        F::GeneralPocket => super::haas_g150::exec(it, &format!("{letter}{code}"))?,
    }
    Ok(())
}

/// `M[#1]`, `G#2`: a code known only at run time.
pub fn dynamic(
    it: &mut Interp<'_, '_>,
    letter: char,
    code: f64,
    words: &[Word],
    block: &Block,
    exprs: &Arena<Expr>,
) -> Result<(), Stop> {
    // A computed spindle or coolant code (`M[#1]`, Siemens `M=R1`,
    // `M1=DIR`) runs as the code it turns out to be.
    let def = Decimal::parse(&format!("{code}"))
        .ok()
        .and_then(|d| it.spec.code(letter, d));
    match def.map(|d| d.meaning) {
        Some(Meaning::Spindle(f)) => {
            use crate::dialect::SpindleFn as F;
            use crate::ir::SpindleState as S;
            let st = match f {
                F::Cw => S::Cw,
                F::Ccw => S::Ccw,
                F::Stop => S::Stop,
                F::Orient => S::Orient(None),
            };
            super::modes::spindle(it, &st, block, exprs)
        }
        Some(Meaning::Coolant(c)) => super::modes::coolant(it, c),
        _ => exec(it, letter, code, words, exprs),
    }
}

/// `M92`: the block moved in machine coordinates (see
/// [`crate::dialect::spec::AuxRun::MachineDatum`]); said once a run.
fn machine_datum_note(it: &mut Interp<'_, '_>, letter: char, code: f64) {
    if !it.once("machine datum") {
        return;
    }
    let span = it.span;
    it.diags.push(
        Diagnostic::new(
            Code::UnknownAtCheckTime,
            format!("{letter}{code} positions are measured from a datum the machine builder sets: not known at check time"),
        )
        .primary(span, "run as machine coordinates")
        .help("the run takes the machine datum (as M91) for it; with --machine, the machine description's reference point and travel apply (see `cncc explain W0517`)"),
    );
}
