//! Machine functions kept by code (`StmtKind::Aux`): LinuxCNC's override
//! switches M48..M53, M61, the I/O codes M62..M68, lathe G7/G8, the
//! spindle-synchronised motions G33/G33.1 and M70..M73 (modal state). They have no neutral
//! meaning in the dialect specs yet, so they are told apart by number
//! here: [`AUX`] is the one table to extend.

use super::{Interp, Stop};
use crate::canon::Canon;
use crate::diag::{Code, Diagnostic};
use crate::ir::{Arena, Block, Expr, StmtKind, Word};

/// What an M code does, by meaning.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum AuxFn {
    /// M48 / M49: both overrides on / off.
    Overrides(bool),
    /// M50 P: feed override (P0 off, else on).
    FeedOverride,
    /// M51 P: spindle speed override.
    SpeedOverride,
    /// M52 P: adaptive feed.
    AdaptiveFeed,
    /// M53 P: feed stop (hold).
    FeedHold,
    /// M61 Q: set the tool number without a change.
    SetToolNumber,
    /// M62..M65 P: digital output bit (motion-synchronised?, on?).
    DigitalOut { motion: bool, on: bool },
    /// M67/M68 E Q: analog output (motion-synchronised?).
    AnalogOut { motion: bool },
    /// M66: wait for an input; rs274's simulated machine prints nothing.
    WaitInput,
    /// M70 / M73 (true: restore on return).
    SaveModal { auto: bool },
    /// M71.
    InvalidateModal,
    /// M72.
    RestoreModal,
    /// G7 (true) / G8: lathe diameter / radius mode for X.
    LatheDiameter(bool),
    /// G33 K (false) / G33.1 K (true, rigid tapping): spindle-synchronised
    /// motion, modal; the block's axis words give the end point.
    SpindleSync { rigid: bool },
}

/// The codes run here: letter, code times ten, meaning.
const AUX: &[(char, i64, AuxFn)] = &[
    ('M', 480, AuxFn::Overrides(true)),
    ('M', 490, AuxFn::Overrides(false)),
    ('M', 500, AuxFn::FeedOverride),
    ('M', 510, AuxFn::SpeedOverride),
    ('M', 520, AuxFn::AdaptiveFeed),
    ('M', 530, AuxFn::FeedHold),
    ('M', 610, AuxFn::SetToolNumber),
    (
        'M',
        620,
        AuxFn::DigitalOut {
            motion: true,
            on: true,
        },
    ),
    (
        'M',
        630,
        AuxFn::DigitalOut {
            motion: true,
            on: false,
        },
    ),
    (
        'M',
        640,
        AuxFn::DigitalOut {
            motion: false,
            on: true,
        },
    ),
    (
        'M',
        650,
        AuxFn::DigitalOut {
            motion: false,
            on: false,
        },
    ),
    ('M', 670, AuxFn::AnalogOut { motion: true }),
    ('M', 680, AuxFn::AnalogOut { motion: false }),
    ('M', 660, AuxFn::WaitInput),
    ('M', 700, AuxFn::SaveModal { auto: false }),
    ('M', 710, AuxFn::InvalidateModal),
    ('M', 720, AuxFn::RestoreModal),
    ('M', 730, AuxFn::SaveModal { auto: true }),
    ('G', 70, AuxFn::LatheDiameter(true)),
    ('G', 80, AuxFn::LatheDiameter(false)),
    ('G', 330, AuxFn::SpindleSync { rigid: false }),
    ('G', 331, AuxFn::SpindleSync { rigid: true }),
];

fn lookup(letter: char, code: f64) -> Option<AuxFn> {
    let tenths = (code * 10.0).round();
    if (code * 10.0 - tenths).abs() > 1e-6 {
        return None;
    }
    let letter = letter.to_ascii_uppercase();
    AUX.iter()
        .find(|(l, n, _)| *l == letter && *n as f64 == tenths)
        .map(|(_, _, f)| *f)
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

/// Aux codes that are motions run in the motion phase (splines, G76,
/// Haas G12/G13).
pub fn is_motion_aux(letter: char, code: crate::ir::Decimal) -> bool {
    super::splines::is_spline(letter, code)
        || super::threading::is_threading(letter, code)
        || super::haas_pocket::is_circular_pocket(letter, code)
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
    let Some(f) = lookup(letter, code) else {
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
    match f {
        AuxFn::Overrides(on) => {
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
        AuxFn::FeedOverride => {
            it.state.feed_override = on;
            it.out(if on {
                Canon::EnableFeedOverride
            } else {
                Canon::DisableFeedOverride
            });
        }
        AuxFn::SpeedOverride => {
            it.state.speed_override = on;
            it.out(if on {
                Canon::EnableSpeedOverride
            } else {
                Canon::DisableSpeedOverride
            });
        }
        AuxFn::AdaptiveFeed => it.out(if on {
            Canon::EnableAdaptiveFeed
        } else {
            Canon::DisableAdaptiveFeed
        }),
        AuxFn::FeedHold => it.out(if on {
            Canon::EnableFeedHold
        } else {
            Canon::DisableFeedHold
        }),
        AuxFn::SetToolNumber => {
            let q = word(it, words, 'Q', exprs)?.unwrap_or(0.0) as i64;
            let row = super::tools::row_of(it, q)?;
            it.state.tool_number = q;
            it.state.spindle_row = row;
            it.state.m61_block = Some(it.block_span);
            it.out(Canon::ChangeToolNumber(row));
        }
        AuxFn::DigitalOut { motion, on } => {
            let n = p.unwrap_or(0.0) as i64;
            let what = match (on, motion) {
                (true, true) => "SET_MOTION_OUTPUT_BIT",
                (false, true) => "CLEAR_MOTION_OUTPUT_BIT",
                (true, false) => "SET_AUX_OUTPUT_BIT",
                (false, false) => "CLEAR_AUX_OUTPUT_BIT",
            };
            it.out(Canon::Io(format!("{what}({n})")));
        }
        AuxFn::AnalogOut { motion } => {
            let e = word(it, words, 'E', exprs)?.unwrap_or(0.0) as i64;
            let q = word(it, words, 'Q', exprs)?.unwrap_or(0.0);
            let what = if motion {
                "SET_MOTION_OUTPUT_VALUE"
            } else {
                "SET_AUX_OUTPUT_VALUE"
            };
            it.out(Canon::Io(format!("{what}({e},{q:.6})")));
        }
        AuxFn::WaitInput => {}
        AuxFn::SaveModal { auto } => super::modal_save::save(it, auto),
        AuxFn::InvalidateModal => super::modal_save::invalidate(it),
        AuxFn::RestoreModal => {
            if !super::modal_save::restore_saved(it) {
                return Err(it.error_at(
                    it.span,
                    Code::BadWordValue,
                    "Cannot restore context: no valid context saved by M70",
                ));
            }
        }
        AuxFn::LatheDiameter(on) => {
            if on != it.state.lathe_diameter {
                let what = if on { "diameter" } else { "radius" };
                it.out(Canon::Comment(format!(
                    "interpreter: Lathe diameter mode changed to {what}"
                )));
            }
            it.state.lathe_diameter = on;
        }
        AuxFn::SpindleSync { rigid } => {
            let k = word(it, words, 'K', exprs)?.unwrap_or(0.0);
            it.cycles.cancel();
            it.state.sync_pitch = k;
            let code = crate::ir::Decimal::from_f64(if rigid { 33.1 } else { 33.0 }, 1);
            it.state.motion = super::state::ModalMotion::Move(crate::ir::MotionKind::Other(code));
        }
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
    let _ = block;
    exec(it, letter, code, words, exprs)
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
