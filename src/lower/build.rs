//! One statement per G/M code, by the meaning its spec entry gives, taking
//! the words the code uses.

use super::checks::{check_index, check_not_negative};
use super::codes::CodeWord;
use super::motion::{cycle, motion};
use super::words::Words;
use super::Ctx;
use crate::dialect::{Capability, Meaning, SpindleFn};
use crate::ir::{
    CallArgs, CallKind, CallTarget, Decimal, DwellUnit, SpindleState, StmtKind, Transform, Value,
    Word,
};
use crate::syntax::WordSyntax;

/// The words a code's spec entry says it uses, as addresses.
fn uses<'s>(cw: &CodeWord<'s>) -> &'s [char] {
    cw.def.map(|d| d.uses.as_slice()).unwrap_or_default()
}

/// The value of the first `uses` word present (a register, a limit, an angle).
fn first_used(cw: &CodeWord<'_>, words: &mut Words) -> Option<Value> {
    uses(cw).iter().find_map(|c| words.value(*c))
}

/// The `uses` words present, in the order the spec lists them.
fn used_words(cw: &CodeWord<'_>, words: &mut Words) -> Vec<Word> {
    uses(cw)
        .iter()
        .filter_map(|&c| words.take(c).map(|w| Word::new(c, w.value, w.span)))
        .collect()
}

/// The code kept by number (no neutral meaning, or not understood).
pub(super) fn aux(cw: &CodeWord<'_>, words: &mut Words) -> StmtKind {
    StmtKind::Aux {
        letter: cw.letter,
        code: cw.code,
        words: used_words(cw, words),
    }
}

/// The statement for a code with a meaning.
pub(super) fn code_stmt(
    cw: &CodeWord<'_>,
    meaning: Meaning,
    words: &mut Words,
    ctx: &mut Ctx<'_>,
) -> StmtKind {
    use Meaning as M;
    match meaning {
        M::Motion(kind) => StmtKind::Motion(motion(kind, uses(cw), words, ctx)),
        M::Cycle(kind) => StmtKind::Cycle(Box::new(cycle(kind, words, ctx))),
        M::CycleCancel => StmtKind::CycleCancel,
        M::Dwell => dwell(cw, words, ctx),
        M::Plane(p) => StmtKind::Plane(p),
        M::Units { unit, with_feeds } => StmtKind::Units { unit, with_feeds },
        M::Distance(d) => StmtKind::Distance(d),
        M::ArcDistance(d) => StmtKind::ArcDistance(d),
        M::FeedMode(f) => StmtKind::FeedMode(f),
        M::RadiusComp(side) => StmtKind::RadiusComp {
            side,
            register: first_used(cw, words),
            diameter: false,
        },
        M::RadiusCompDiameter(side) => StmtKind::RadiusComp {
            side,
            register: first_used(cw, words),
            diameter: true,
        },
        M::LengthComp(mode) => length_comp(cw, mode, words),
        M::WorkOffset(index) => StmtKind::WorkOffset {
            index,
            extended: None,
        },
        M::WorkOffsetExtended => StmtKind::WorkOffset {
            index: 1,
            extended: words.value("P"),
        },
        M::MachineCoords => StmtKind::MachineCoords,
        M::CoordShift(kind) => StmtKind::CoordShift {
            kind,
            axes: Box::new(words.take_axes()),
        },
        M::SetData => set_data(cw, words, ctx),
        M::RefReturn {
            index,
            store,
            direct,
        } => StmtKind::RefReturn {
            index,
            store,
            direct,
            axes: Box::new(if direct {
                words.take_machine_axes()
            } else {
                words.take_axes()
            }),
        },
        M::PathMode(mode) => StmtKind::PathMode {
            mode,
            words: used_words(cw, words),
        },
        M::ReturnMode(initial) => StmtKind::ReturnToInitial(initial),
        M::Rotate(on) => StmtKind::Transform(Box::new(rotate(on, words))),
        M::Scale(on) => StmtKind::Transform(Box::new(scale(on, words))),
        M::Mirror(true) => StmtKind::Transform(Box::new(Transform::MirrorOn {
            axes: words.take_axes(),
        })),
        M::Mirror(false) => StmtKind::Transform(Box::new(Transform::MirrorOff)),
        M::Css(on) => StmtKind::SpindleCss {
            on,
            max_rpm: if on { first_used(cw, words) } else { None },
        },
        M::MacroCall => macro_call(CallKind::Macro, cw, words, ctx),
        M::ModalMacroCall => macro_call(CallKind::ModalMacro, cw, words, ctx),
        M::ModalMacroCancel => StmtKind::ModalMacroCancel,
        M::Stop(kind) => StmtKind::Stop(kind),
        M::Spindle(f) => StmtKind::Spindle(spindle(cw, f, words)),
        M::ToolChange => StmtKind::ToolChange,
        M::Coolant(c) => StmtKind::Coolant(c),
        M::SubCall => sub_call(CallKind::Subprogram, cw, words, ctx),
        M::LocalCall if ctx.spec.has(Capability::LocalSubprogramCall) => {
            sub_call(CallKind::Local, cw, words, ctx)
        }
        M::LocalCall | M::PathSmoothing | M::Machine(_) | M::Aux => aux(cw, words),
        M::SubReturn => StmtKind::SubReturn {
            to: words.value("P"),
        },
    }
}

fn length_comp(cw: &CodeWord<'_>, mode: crate::ir::LengthComp, words: &mut Words) -> StmtKind {
    let register = first_used(cw, words);
    let axes = if mode == crate::ir::LengthComp::Dynamic {
        words.take_axes()
    } else {
        Default::default()
    };
    StmtKind::LengthComp {
        mode,
        register,
        axes: Box::new(axes),
    }
}

fn spindle(cw: &CodeWord<'_>, f: SpindleFn, words: &mut Words) -> SpindleState {
    match f {
        SpindleFn::Cw => SpindleState::Cw,
        SpindleFn::Ccw => SpindleState::Ccw,
        SpindleFn::Stop => SpindleState::Stop,
        // The angle is the first `uses` word (LinuxCNC R); the others
        // (LinuxCNC P direction, Q timeout) stay words of the block.
        SpindleFn::Orient => SpindleState::Orient(uses(cw).first().and_then(|c| words.value(*c))),
    }
}

fn rotate(on: bool, words: &mut Words) -> Transform {
    if !on {
        return Transform::RotateOff;
    }
    Transform::RotateOn {
        center: words.take_axes(),
        angle: words.value("R"),
    }
}

fn scale(on: bool, words: &mut Words) -> Transform {
    if !on {
        return Transform::ScaleOff;
    }
    let center = words.take_axes();
    let factor = words.value("P");
    let per_axis = ['I', 'J', 'K']
        .iter()
        .filter_map(|c| words.value(*c).map(|v| (*c, v)))
        .collect();
    Transform::ScaleOn {
        center,
        factor,
        per_axis,
    }
}

/// G4: the first word its `dwell_units` name gives the time and unit.
fn dwell(cw: &CodeWord<'_>, words: &mut Words, ctx: &mut Ctx<'_>) -> StmtKind {
    let units: Vec<(char, DwellUnit)> = cw.def.map(|d| d.dwell_units.clone()).unwrap_or_default();
    for (letter, unit) in units {
        if let Some(w) = words.take(letter) {
            check_not_negative(&w.value, w.span, "dwell time", ctx.diags);
            return StmtKind::Dwell {
                value: w.value,
                unit,
            };
        }
    }
    // Missing time: reported by the required-word check; kept by code.
    aux(cw, words)
}

/// G10: L, and the words it uses (the spec's `uses`, and axes) as
/// written. Other words (F, S, T...) stay the block's own: in
/// `F200 S1000 G10 L1 P1 R1` rs274 sets the feed and the speed.
fn set_data(cw: &CodeWord<'_>, words: &mut Words, ctx: &mut Ctx<'_>) -> StmtKind {
    let l = words.take("L");
    let is_l2 = l
        .as_ref()
        .and_then(|w| w.value.number())
        .map(|d| d == Decimal::from_int(2))
        .unwrap_or(false);
    if is_l2 {
        if let Some(p) = words.get("P").cloned() {
            check_index(&p, "work offset number for G10 L2", Some(9), ctx.diags);
        }
    }
    let l = l.map(|w| w.value).unwrap_or(Value::Number(Decimal::ZERO));
    StmtKind::SetData {
        l,
        words: words.take_all_letters(&not_used(cw)),
    }
}

/// The letters that are neither axes nor among the code's `uses`.
fn not_used(cw: &CodeWord<'_>) -> Vec<char> {
    let uses = uses(cw);
    ('A'..='Z')
        .filter(|c| !uses.contains(c) && !crate::ir::AXIS_LETTERS.contains(c))
        .collect()
}

/// M98 / M97: target P (a number, packed `P00031234`, or computed), repeats L.
fn sub_call(kind: CallKind, cw: &CodeWord<'_>, words: &mut Words, ctx: &mut Ctx<'_>) -> StmtKind {
    let Some(p) = words.take("P") else {
        return aux(cw, words);
    };
    let mut repeat = words.take("L");
    if let Some(l) = &repeat {
        check_index(l, "repeat count", None, ctx.diags);
    }
    let target = match &p.value {
        Value::Expr(e) => CallTarget::Computed(*e),
        Value::Number(_) => {
            let n =
                check_index(&p, "program number", Some(u32::MAX as i64), ctx.diags).unwrap_or(0);
            let (count, program) = unpack(&p, n, repeat.is_some());
            if count > 0 {
                repeat = Some(WordSyntax {
                    value: Value::Number(Decimal::from_int(count)),
                    ..p.clone()
                });
            }
            CallTarget::Number(program as u32)
        }
    };
    StmtKind::Call {
        kind,
        target,
        args: CallArgs::None,
        repeat: repeat.map(|w| w.value),
    }
}

/// Fanuc's packed `P00031234`: eight digits written, the first four the
/// count, the last four the program. Only read so when written with all
/// eight digits and no `L`, so that long program numbers stay intact.
fn unpack(p: &WordSyntax, n: i64, has_l: bool) -> (i64, i64) {
    let digits = p.span.end.saturating_sub(p.address_span.end);
    if has_l || digits != 8 || n >= 10_000_000 {
        return (0, n);
    }
    (n / 10_000, n % 10_000)
}

/// G65 / G66: P the program, L the repeats, every other letter an argument.
fn macro_call(kind: CallKind, cw: &CodeWord<'_>, words: &mut Words, ctx: &mut Ctx<'_>) -> StmtKind {
    let Some(p) = words.take("P") else {
        return aux(cw, words);
    };
    let target = match &p.value {
        Value::Expr(e) => CallTarget::Computed(*e),
        Value::Number(_) => CallTarget::Number(
            check_index(&p, "program number", Some(u32::MAX as i64), ctx.diags).unwrap_or(0) as u32,
        ),
    };
    let repeat = words.value("L");
    let args = words.take_all_letters(&['L', 'N', 'O', 'P']);
    let args = CallArgs::Letters(args.into_iter().map(|w| (w.letter, w.value)).collect());
    StmtKind::Call {
        kind,
        target,
        args,
        repeat,
    }
}
