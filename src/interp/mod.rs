//! The interpreter: runs the meta-model as a controller would and emits
//! canonical machining calls ([`crate::canon`]), with every modal state
//! explicit.
//!
//! [`Interp`] holds the machine [`state::State`]; `exec` runs one block's
//! statements in the order NIST's Table 8 (and LinuxCNC) gives them;
//! the program loop walks the blocks.

pub mod arcs;
pub mod aux;
pub mod comp;
pub mod config;
pub mod cycle_io;
pub mod cycles;
pub mod eval;
pub mod exec;
pub mod fanuc_xform;
pub mod file;
pub mod flow;
pub mod fragment;
pub mod haas_g150;
pub mod haas_pocket;
pub mod heidenhain;
pub mod host;
pub mod index;
pub mod lathe_cycles;
pub mod lathe_profile;
pub mod lazy;
pub mod machine;
pub mod machine_desc;
pub mod modal_save;
pub mod modes;
pub mod motion;
pub mod offsets;
pub mod options;
pub mod params;
pub mod polar;
pub mod predefined;
pub mod siemens;
pub mod splines;
pub mod state;
pub mod stream;
pub mod sub_styles;
pub mod target;
pub mod threading;
pub mod tool_header;
pub mod tools;
pub mod tooltable;
pub mod watch;

#[cfg(test)]
mod hold_tests;

pub use options::{Limits, Options};

use crate::canon::Canon;
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::ir::{Arena, Block, Expr, Program};

use crate::span::Span;
use state::State;

/// Where the calls go, each with the span of the statement it came from.
pub type Sink<'a> = dyn FnMut(Canon, Span) + 'a;

/// Why a run stopped before the program's end.
#[derive(Debug)]
pub enum Stop {
    /// An error: the controller would alarm here.
    Error(Diagnostic),
    /// M2/M30 or a closing `%`: the program ended.
    End,
    /// A value the program gets from outside (its caller's arguments, the
    /// machine's variables) is needed and cannot be known when the file is
    /// checked alone: the run stops here with this warning (W0590).
    Unknown(Diagnostic),
}

pub struct Interp<'a, 's> {
    pub spec: &'s DialectSpec,
    pub opts: &'s Options,
    pub state: State,
    pub sink: Output<'a>,
    /// Non-fatal findings (warnings) collected while running.
    pub diags: Vec<Diagnostic>,
    /// The span of the statement being executed (calls are tagged with it).
    pub span: Span,
    pub ended: bool,
    pub params: params::Params,
    /// Siemens programmable frame and modal cycle call.
    pub siemens: siemens::SiemensState,
    /// Fanuc G68/G51/G51.1 transforms (mapped through `siemens.frame`).
    pub fanuc: fanuc_xform::FanucXform,
    /// Heidenhain pole, cycle definitions, held line for corners.
    pub heidenhain: heidenhain::HeidenhainState,
    /// Canned-cycle values that carry over between blocks.
    pub cycles: cycles::CycleMemory,
    /// A lathe profile cycle (G70/G71/G72) reading its contour.
    pub lathe: lathe_cycles::LatheCycles,
    /// Cutter radius compensation (every move goes through it).
    pub comp: comp::RadiusComp,
    /// Recent blocks' spans by compensation tag (errors name them).
    pub comp_tags: std::collections::VecDeque<(u64, Span)>,
    /// The tool table as the program changes it (G10 L1/L10/L11).
    pub tool_table: tooltable::ToolTable,
    /// The span of the block being run.
    pub block_span: Span,
    /// The block's line in its file, from 1 (`#<_line>`): the readers keep
    /// one block per source line, blank lines included, so it is the
    /// block's index plus one. Set by the walker and the streamed run.
    pub line: u32,
    /// M70's saved modal state; M73's, with the call level that restores it.
    pub saved_modal: Option<Box<State>>,
    pub auto_restore: Vec<(usize, Box<State>)>,
    /// G5.2's gathered NURBS points and G5's default I J.
    pub splines: splines::Splines,
    /// The last conditional jump taken (an error the program raises names
    /// the test that led to it).
    pub last_jump: Option<Span>,
    /// The file is a subprogram, macro, PROC or subroutine library checked
    /// alone: values it never sets come from outside, unknown here
    /// ([`Stop::Unknown`]).
    pub from_outside: bool,
    /// Tools whose sizes no tool table gave: the first block that used
    /// each, and whether cncc's built-in table invented them (W0592).
    pub tools_without_data: std::collections::BTreeMap<i64, (Span, bool)>,
    /// Radius compensation ran with a radius no tool table gave.
    pub comp_without_size: bool,
    /// Run-time mistakes reported so far while going on after them.
    pub recovered: u32,
    /// What was reported once per run already (W0517, W0518, W0519).
    reported: std::collections::HashSet<String>,
    /// Told of every block before it runs (see [`BlockObserver`]).
    pub observer: Option<Box<BlockObserver>>,
    /// Shown every block after it ran ([`watch::Watcher`]: the lint layer).
    pub watcher: Option<Box<watch::Watcher>>,
}

/// Where the walker is about to run a block: which program (0: the main
/// one), which block, how many calls deep. The port's expansion fallback
/// records its run with it.
#[derive(Clone, Copy, Debug)]
pub struct BlockEvent {
    pub prog: usize,
    pub pc: usize,
    pub depth: usize,
    /// A modal call (840D `MCALL`, TNC `M89`) runs after each positioning
    /// block: the blocks from here on do more than move.
    pub modal_call: bool,
    /// A move of an earlier block is still held back (a Klartext line
    /// waiting for a `RND`/`CHF`, an `APPR` waiting for its element): its
    /// calls come out while a later block runs.
    pub held: bool,
}

/// Called before each block with the state in force before it.
pub type BlockObserver = dyn FnMut(&BlockEvent, &State, &params::Params);

impl<'a, 's> Interp<'a, 's> {
    /// A modal cycle call (840D `MCALL`, TNC `M89`) is in force.
    pub fn modal_call_active(&self) -> bool {
        self.siemens.modal.is_some() || self.heidenhain.modal_call
    }

    /// True the first time `what` is asked in a run: report it then.
    pub fn once(&mut self, what: impl Into<String>) -> bool {
        self.reported.insert(what.into())
    }

    pub fn new(spec: &'s DialectSpec, opts: &'s Options, sink: &'a mut Sink<'a>) -> Self {
        let mut state = State::new();
        if spec.has(crate::dialect::Capability::PowerOnRapid) {
            state.motion = state::ModalMotion::Move(crate::ir::MotionKind::Rapid);
        }
        let mut comp = comp::RadiusComp::new();
        comp.rules = comp::CompRules {
            entry_longer_than_radius: spec
                .has(crate::dialect::Capability::CompEntryLongerThanRadius),
            on_when_on_error: spec.has(crate::dialect::Capability::CompOnWhenOnError),
        };
        if spec.has(crate::dialect::Capability::PowerOnLinear) {
            state.motion = state::ModalMotion::Move(crate::ir::MotionKind::Linear);
        }
        Interp {
            spec,
            opts,
            state,
            sink: Output {
                sink,
                held: Vec::new(),
                holding: false,
                unread: false,
                axes_left_by_operator: true,
            },
            diags: Vec::new(),
            span: Span::default(),
            ended: false,
            params: params::Params::new(),
            cycles: cycles::CycleMemory::new(),
            lathe: Default::default(),
            comp,
            comp_tags: std::collections::VecDeque::new(),
            tool_table: opts.tool_table.clone(),
            block_span: Span::default(),
            line: 0,
            saved_modal: None,
            auto_restore: Vec::new(),
            splines: splines::Splines::default(),
            siemens: siemens::SiemensState::default(),
            fanuc: fanuc_xform::FanucXform::default(),
            heidenhain: heidenhain::HeidenhainState::default(),
            last_jump: None,
            from_outside: false,
            tools_without_data: Default::default(),
            comp_without_size: false,
            recovered: 0,
            reported: Default::default(),
            observer: None,
            watcher: None,
        }
    }

    /// Emits one call, tagged with the current statement's span.
    pub fn emit(&mut self, call: Canon) {
        self.sink.call(call, self.span);
    }

    /// Holds the calls that follow until [`Self::settle`]: a block whose
    /// words rs274 cannot even read (an expression that fails) prints
    /// nothing of its own, while one that fails when it runs keeps the
    /// calls it made before the failure.
    pub fn hold(&mut self) {
        self.sink.holding = true;
    }

    /// An error rs274 reports while reading the block (its word checks),
    /// before it runs any of it: the block's own calls are dropped.
    pub fn read_error(
        &mut self,
        span: Span,
        code: crate::diag::Code,
        msg: impl Into<String>,
    ) -> Stop {
        self.sink.unread = true;
        self.error_at(span, code, msg)
    }

    /// Ends [`Self::hold`]: the held calls go out, unless `result` is an
    /// error rs274 finds while reading the block.
    pub fn settle<T>(&mut self, result: Result<T, Stop>) -> Result<T, Stop> {
        self.sink.holding = false;
        let flagged = std::mem::take(&mut self.sink.unread);
        let unread = matches!(&result, Err(Stop::Error(d)) if flagged || read_time_error(d));
        if unread {
            self.sink.held.clear();
        } else {
            self.sink.release();
        }
        result
    }

    /// The run's findings so far, with the note of tools whose sizes were
    /// invented or unknown (said once per run).
    pub fn take_diags(&mut self) -> Vec<Diagnostic> {
        let mut d = std::mem::take(&mut self.diags);
        d.extend(tools::tools_without_data(self));
        d
    }

    /// The calls every run starts with.
    pub fn start(&mut self) {
        if let Some(m) = self.opts.machine.clone() {
            m.apply(self);
        }
        let opts = self.opts;
        opts.rs274.apply(self);
        machine::init_sequence(self);
    }

    /// Runs one block.
    pub fn block(&mut self, block: &Block, exprs: &Arena<Expr>) -> Result<(), Stop> {
        if block.skip.is_some() && self.opts.block_delete {
            return Ok(());
        }
        exec::exec_block(self, block, exprs)
    }
}

/// Most run-time mistakes one `check` reports before it stops running.
pub const MAX_RECOVERED: u32 = 50;

impl Interp<'_, '_> {
    /// With [`Options::keep_going`], a run-time mistake that leaves the
    /// program's values sound is kept as a finding and the run goes on
    /// with the next block (`Ok`); anything else stops the run (`Err`).
    /// Cutter compensation is switched off after a mistake, so that one
    /// bad corner does not report every corner after it.
    pub fn recover(&mut self, stop: Stop) -> Result<(), Stop> {
        let Stop::Error(d) = stop else {
            return Err(stop);
        };
        if !self.opts.keep_going || !recoverable(&d) || self.recovered >= MAX_RECOVERED {
            return Err(Stop::Error(d));
        }
        self.recovered += 1;
        let rules = self.comp.rules;
        self.comp = comp::RadiusComp::new();
        self.comp.rules = rules;
        self.state.comp_side = crate::ir::CompSide::Off;
        self.diags
            .push(d.note("the run went on with the next block, as if this one had not been given"));
        Ok(())
    }
}

/// Mistakes after which the run's values are still what the program
/// meant: geometry, words, feeds, tools. Not: loops past their limit, the
/// program's own alarms, or values that could not be computed.
fn recoverable(d: &Diagnostic) -> bool {
    use crate::diag::Code;
    d.code.code().starts_with("E05")
        && !matches!(
            d.code,
            Code::LimitExceeded
                | Code::KlartextProgramError
                | Code::UndefinedVariable
                | Code::DivisionByZero
                | Code::DomainError
                | Code::UnsupportedHere
                | Code::TiltNeedsRotaryAxes
        )
}

/// Errors rs274 meets while reading a block, before it runs any of it:
/// the block's words are evaluated as they are read.
fn read_time_error(d: &Diagnostic) -> bool {
    use crate::diag::Code;
    matches!(
        d.code,
        Code::DivisionByZero | Code::UndefinedVariable | Code::DomainError
    )
}

/// Where calls go: to the sink, or held while a block may still turn out
/// unreadable (see [`Interp::hold`]).
pub struct Output<'a> {
    sink: &'a mut Sink<'a>,
    held: Vec<(Canon, Span)>,
    holding: bool,
    /// The block failed a check rs274 makes while reading it.
    unread: bool,
    /// No move has gone out since the start or the last program stop: the
    /// axes stand where the machine was, or where the operator jogged them
    /// during the stop (a touch-off program reads them with FN 18
    /// ID270), which only the running machine knows. [?] Coarse: one move
    /// of any axis counts as knowing them all.
    axes_left_by_operator: bool,
}

impl Output<'_> {
    /// One call, tagged with the span of its statement.
    pub fn call(&mut self, call: Canon, span: Span) {
        match call {
            Canon::ProgramStop | Canon::OptionalProgramStop => self.axes_left_by_operator = true,
            Canon::StraightTraverse(_)
            | Canon::StraightFeed(_)
            | Canon::StraightProbe(_)
            | Canon::ArcFeed { .. } => self.axes_left_by_operator = false,
            _ => {}
        }
        if self.holding {
            self.held.push((call, span));
        } else {
            (self.sink)(call, span);
        }
    }

    fn release(&mut self) {
        for (c, s) in self.held.drain(..) {
            (self.sink)(c, s);
        }
    }
}

/// Runs a whole program; returns every diagnostic (the first error ends it).
pub fn run(
    program: std::rc::Rc<Program>,
    spec: &DialectSpec,
    opts: &Options,
    loader: &mut dyn flow::ProgramLoader,
    sink: &mut Sink<'_>,
) -> Vec<Diagnostic> {
    let mut sink = sink;
    let mut it = Interp::new(spec, opts, &mut sink);
    it.start();
    let result = flow::Walker::new(program, loader).run(&mut it);
    let mut diags = it.take_diags();
    match result {
        Err(Stop::Error(d)) => {
            diags.push(d);
            machine::abort_sequence(&mut it);
        }
        Err(Stop::End) => {}
        Err(Stop::Unknown(d)) => diags.push(d),
        Ok(()) => machine::fell_off_end(&mut it, &mut diags),
    }
    opts.rs274.keep_final(&it);
    diags
}
