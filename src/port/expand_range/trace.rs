//! One recorded run of the source program: which block of the main
//! program ran at each top-level step, the canonical calls each step made
//! (its subprogram calls included), and the state in force before it.

use crate::canon::Canon;
use crate::dialect::DialectSpec;
use crate::interp::flow::{ProgramLoader, Walker};
use crate::interp::params::OuterVar;
use crate::interp::state::{ModalMotion, State};
use crate::interp::{BlockEvent, Interp, Options, Stop};
use crate::ir::{CompSide, Program};
use crate::span::Span;
use std::cell::RefCell;
use std::collections::HashMap;
use std::rc::Rc;

/// The modal state a replaced part of the program must start and end in.
#[derive(Clone, Debug)]
pub struct Modes {
    pub absolute: bool,
    pub arc_absolute: bool,
    pub plane: crate::canon::CanonPlane,
    pub inch: bool,
    pub motion: ModalMotion,
    pub comp: CompSide,
    /// A modal cycle call (`MCALL`, `M89`) is in force.
    pub modal_call: bool,
    /// A move of an earlier block is still held back (see
    /// [`BlockEvent::held`]): its calls would fall on the wrong side.
    pub held: bool,
    /// The G92/G52 offset (mm): a part must give back the one it got.
    pub g92: [f64; 9],
    pub vars: HashMap<OuterVar, f64>,
}

impl Modes {
    fn of(s: &State, modal_call: bool, held: bool, vars: HashMap<OuterVar, f64>) -> Modes {
        Modes {
            absolute: s.absolute,
            arc_absolute: s.arc_absolute,
            plane: s.plane,
            inch: s.units == crate::ir::LengthUnit::Inch,
            motion: s.motion,
            comp: s.comp_side,
            modal_call,
            held,
            g92: if s.g92_applied { s.g92 } else { [0.0; 9] },
            vars,
        }
    }

    /// A state a run of plain moves can start or end in: no cutter
    /// compensation (the recorded moves are already offset), no modal
    /// cycle or modal call (the blocks after would no longer drill), and
    /// no move held back (its calls come out after the boundary).
    pub fn is_plain(&self) -> bool {
        self.comp == CompSide::Off
            && !matches!(self.motion, ModalMotion::Cycle(_))
            && !self.modal_call
            && !self.held
    }
}

/// One block of the main program run at the top level.
pub struct Step {
    pub pc: usize,
    /// Its place in [`Trace::visits`].
    pub visit: usize,
    /// Its calls: `calls[first..next step's first]`.
    pub first: usize,
    pub before: Modes,
}

#[derive(Default)]
pub struct Trace {
    pub steps: Vec<Step>,
    pub calls: Vec<(Canon, Span)>,
    /// Blocks of the main program's file run inside a call: the top-level
    /// steps during which they ran.
    pub deep: HashMap<usize, Vec<usize>>,
    /// Every block of the main program's file that ran, in order, with the
    /// number of calls made before it (comments are written from these).
    pub visits: Vec<(usize, usize)>,
    /// The state after the last step.
    pub end: Option<Modes>,
    /// The run ended on an error or an unknown value at this step.
    pub stopped: Option<usize>,
    /// The block running is in the main program's file (calls made in
    /// another file keep no span: its statements are not this program's).
    in_main: bool,
    /// More calls than [`MAX_CALLS`]: the rest was not recorded.
    overflow: bool,
}

/// The most canonical calls one recorded run keeps (about 100 bytes
/// each): a program that makes more is not written as its moves.
pub const MAX_CALLS: usize = 2_000_000;

impl Trace {
    /// The state after step `i`.
    pub fn after(&self, i: usize) -> Option<&Modes> {
        match self.steps.get(i + 1) {
            Some(s) => Some(&s.before),
            None => self.end.as_ref(),
        }
    }
}

/// Runs `p` and records it.
pub fn record(
    p: &Program,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
) -> Trace {
    let trace = Rc::new(RefCell::new(Trace {
        in_main: true,
        ..Trace::default()
    }));
    let t = trace.clone();
    let mut sink = move |c: Canon, s: Span| {
        let mut t = t.borrow_mut();
        if t.calls.len() >= MAX_CALLS {
            t.overflow = true;
            return;
        }
        let s = if t.in_main { s } else { elsewhere() };
        t.calls.push((c, s));
    };
    let mut sink_ref: &mut dyn FnMut(Canon, Span) = &mut sink;
    let (end, stopped) = run(p, spec, opts, loader, &mut sink_ref, &trace);
    drop(sink);
    let mut t = Rc::try_unwrap(trace)
        .map(RefCell::into_inner)
        .unwrap_or_default();
    t.end = Some(end);
    if stopped || t.overflow {
        t.stopped = t.steps.len().checked_sub(1);
    }
    t
}

fn run<'a>(
    p: &Program,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
    sink: &'a mut &'a mut dyn FnMut(Canon, Span),
    trace: &Rc<RefCell<Trace>>,
) -> (Modes, bool) {
    let mut it = Interp::new(spec, opts, sink);
    // A subprogram ported alone runs from its top with its caller's
    // values unknown, as `check` runs it.
    it.from_outside = crate::interp::fragment::detect(p).is_some();
    let t = trace.clone();
    it.observer = Some(Box::new(move |e: &BlockEvent, s: &State, params| {
        let mut t = t.borrow_mut();
        t.in_main = e.prog == 0;
        if e.prog != 0 {
            return;
        }
        let first = t.calls.len();
        let visit = t.visits.len();
        t.visits.push((first, e.pc));
        if e.depth == 0 {
            let before = Modes::of(s, e.modal_call, e.held, params.outer_values());
            t.steps.push(Step {
                pc: e.pc,
                visit,
                first,
                before,
            });
        } else if let Some(step) = t.steps.len().checked_sub(1) {
            t.deep.entry(e.pc).or_default().push(step);
        }
    }));
    it.start();
    let result = Walker::new(Rc::new(p.clone()), loader).run(&mut it);
    it.observer = None;
    let end = Modes::of(
        &it.state,
        it.modal_call_active(),
        it.heidenhain.held.is_some(),
        it.params.outer_values(),
    );
    let stopped = matches!(result, Err(Stop::Error(_)) | Err(Stop::Unknown(_)));
    (end, stopped)
}

/// The span given to calls made by another file's statements.
fn elsewhere() -> Span {
    Span {
        file: crate::span::FileId(u32::MAX),
        start: 0,
        end: 0,
    }
}
