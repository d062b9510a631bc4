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
pub mod cycle_io;
pub mod cycles;
pub mod eval;
pub mod exec;
pub mod fanuc_xform;
pub mod file;
pub mod flow;
pub mod haas_g150;
pub mod haas_pocket;
pub mod heidenhain;
pub mod host;
pub mod index;
pub mod machine;
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
pub mod target;
pub mod threading;
pub mod tools;
pub mod tooltable;

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
}

impl<'a, 's> Interp<'a, 's> {
    pub fn new(spec: &'s DialectSpec, opts: &'s Options, sink: &'a mut Sink<'a>) -> Self {
        let mut state = State::new();
        if spec.has(crate::dialect::Capability::PowerOnRapid) {
            state.motion = state::ModalMotion::Move(crate::ir::MotionKind::Rapid);
        }
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
            },
            diags: Vec::new(),
            span: Span::default(),
            ended: false,
            params: params::Params::new(),
            cycles: cycles::CycleMemory::new(),
            comp: comp::RadiusComp::new(),
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

    /// The calls every run starts with.
    pub fn start(&mut self) {
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
}

impl Output<'_> {
    /// One call, tagged with the span of its statement.
    pub fn call(&mut self, call: Canon, span: Span) {
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
    let mut diags = std::mem::take(&mut it.diags);
    match result {
        Err(Stop::Error(d)) => {
            diags.push(d);
            machine::abort_sequence(&mut it);
        }
        Err(Stop::End) => {}
        Ok(()) => machine::fell_off_end(&mut it, &mut diags),
    }
    diags
}
