//! Lint: the mistakes that crash machines, found on the interpreter's run.
//!
//! `check` runs each program; a [`Linter`] watches the run block by block
//! ([`crate::interp::watch`]) and reads what the interpreter computed (the
//! canonical calls, the modal state after each block, cycle values, tool
//! data). It also sees every block the reader hands over (for inline
//! `cncc: ignore[...]` directives and for moves written after the end).
//! Rules ([`rules::RULES`]) have stable codes W07xx with names, run where
//! the dialect's spec says they apply, and are chosen by the shop's
//! `cncc.toml` and the command line ([`config`]). Findings are warnings
//! unless the shop lists them under `error`.

pub mod config;
pub mod directive;
pub mod rules;
mod values;

pub use config::{CliSelect, LintConfig};

use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::{Block, LengthUnit, StmtKind, StopKind};
use crate::span::Span;
use std::collections::HashMap;

/// Most findings of one rule kept per file.
pub const MAX_PER_RULE: usize = 100;

/// A subprogram call in force (W0707).
#[derive(Debug)]
struct Frame {
    call: Span,
    entered_incremental: bool,
    sets_mode: bool,
    reported: bool,
}

/// What the reader saw, in the order of the file (W0704, W0705).
#[derive(Debug, Default)]
struct Source {
    /// A top-level M2/M30 was read; the first move after it.
    end: Option<Span>,
    move_after_end: Option<Span>,
    /// Jumps or calls: code after an end may be reached.
    flow: bool,
    /// Some end of any kind (M2/M30, M99, END PGM, a closing `%`).
    any_end: bool,
    content: bool,
    last: Option<Span>,
    /// The last block with content had a comment or message (W0714).
    told: bool,
}

/// The lint of one program's run.
pub struct Linter {
    cfg: LintConfig,
    enabled: Vec<Code>,
    /// mm per machine unit (tool-table sizes).
    machine_scale: f64,
    found: Vec<Diagnostic>,
    counts: HashMap<Code, usize>,
    directives: directive::Directives,
    src: Source,
    // Run state read from the interpreter's steps.
    length_pending: Option<Span>,
    after_change: Option<Span>,
    ref_return: Option<Span>,
    min_cut_mm: Option<f64>,
    /// x0 y0 x1 y1 (mm) round the feed moves of this tool.
    cut_box: Option<[f64; 4]>,
    last_pose: Option<[f64; 6]>,
    /// Feed, speed, units and spindle after the last block.
    last_values: values::CutValues,
    last_z_mm: f64,
    spindle_reported: bool,
    speed_reported: bool,
    speed_programmed: bool,
    had_coolant: bool,
    coolant_reported: bool,
    below_reported: bool,
    units_set: bool,
    work_offset_set: bool,
    first_motion: Option<Span>,
    ended: bool,
    frames: Vec<Frame>,
    last_block: (Span, bool),
    last_absolute: bool,
    rates: values::RateReported,
    units: values::UnitSurvey,
    /// Address letters the spec gives the role `length-offset` (H).
    length_letters: Vec<char>,
}

/// How a run ended, as `check` saw it.
#[derive(Clone, Copy, Debug)]
pub struct RunEnd {
    /// The run reached the end of the program (no error, nothing unknown
    /// stopped it).
    pub complete: bool,
    /// The file is a subprogram or library checked alone: rules about the
    /// whole program (end, units, work offset) do not apply.
    pub fragment: bool,
}

impl Linter {
    pub fn new(spec: &DialectSpec, cfg: LintConfig, machine_units: LengthUnit) -> Linter {
        let enabled = rules::RULES
            .iter()
            .filter(|r| cfg.is_enabled(r.code) && (r.applies)(spec))
            .map(|r| r.code)
            .collect();
        Linter {
            cfg,
            enabled,
            machine_scale: match machine_units {
                LengthUnit::Mm => 1.0,
                LengthUnit::Inch => crate::interp::state::MM_PER_INCH,
            },
            found: Vec::new(),
            counts: HashMap::new(),
            directives: directive::Directives::default(),
            src: Source::default(),
            length_pending: None,
            after_change: None,
            ref_return: None,
            min_cut_mm: None,
            cut_box: None,
            last_pose: None,
            last_values: Default::default(),
            last_z_mm: 0.0,
            spindle_reported: false,
            speed_reported: false,
            speed_programmed: false,
            had_coolant: false,
            coolant_reported: false,
            below_reported: false,
            units_set: false,
            work_offset_set: false,
            first_motion: None,
            ended: false,
            frames: Vec::new(),
            last_block: (Span::default(), false),
            last_absolute: true,
            rates: Default::default(),
            units: Default::default(),
            length_letters: spec
                .addresses
                .iter()
                .filter(|a| a.role == "length-offset")
                .map(|a| a.letter)
                .collect(),
        }
    }

    /// Whether any rule runs at all (none: the run need not be watched).
    pub fn is_active(&self) -> bool {
        !self.enabled.is_empty()
    }

    fn report(&mut self, d: Diagnostic) {
        if !self.enabled.contains(&d.code) {
            return;
        }
        let n = self.counts.entry(d.code).or_default();
        *n += 1;
        if *n <= MAX_PER_RULE {
            let sev = self.cfg.severity(d.code);
            self.found.push(d.with_severity(sev));
        }
    }

    /// A block as the reader hands it over, in file order.
    pub fn read_block(&mut self, b: &Block) {
        self.directives.read(b);
        if b.skip.is_some() || b.stmts.is_empty() {
            return;
        }
        let comments_only = b
            .stmts
            .iter()
            .all(|s| matches!(s.kind, StmtKind::Comment { .. } | StmtKind::Message(_)));
        for s in &b.stmts {
            self.read_stmt(&s.kind, b.span);
        }
        self.stop_message(b);
        if !comments_only {
            self.src.content = true;
            self.src.last = Some(b.span);
        }
    }

    /// W0714: an M0/M1 with no comment or message in its block or the
    /// block before.
    fn stop_message(&mut self, b: &Block) {
        let said = b
            .stmts
            .iter()
            .any(|s| matches!(s.kind, StmtKind::Comment { .. } | StmtKind::Message(_)));
        let stop = b.stmts.iter().any(|s| {
            matches!(
                s.kind,
                StmtKind::Stop(StopKind::Program | StopKind::Optional)
            )
        });
        if stop && !said && !self.src.told {
            self.report(
                Diagnostic::new(
                    Code::LintStopWithoutMessage,
                    "the program stops with no message to the operator",
                )
                .primary(b.span, "stop")
                .help("say why in a comment or message in this block or the one before"),
            );
        }
        self.src.told = said;
    }

    fn read_stmt(&mut self, k: &StmtKind, block: Span) {
        use StmtKind::*;
        let src = &mut self.src;
        match k {
            Stop(StopKind::End | StopKind::EndRewind) => {
                src.any_end = true;
                src.end.get_or_insert(block);
            }
            ProgramEnd { .. } | SubReturn { .. } | Return { .. } | SubEnd { .. } => {
                src.any_end = true
            }
            Tape if src.content => src.any_end = true,
            ProgramStart { .. } | SubStart { .. } | Tape => src.end = None,
            Goto { .. } | Call { .. } | Case { .. } | SectionRepeat { .. } | IfThen { .. } => {
                src.flow = true
            }
            Motion(_) | Cycle(_) | CycleCall(_) if src.end.is_some() => {
                src.move_after_end.get_or_insert(block);
            }
            _ => {}
        }
    }

    /// The findings of the whole run, the directives applied.
    pub fn finish(mut self, end: RunEnd) -> Vec<Diagnostic> {
        if end.fragment {
            return Vec::new();
        }
        self.whole_program(end);
        let found = std::mem::take(&mut self.found);
        let dropped: Vec<(Code, usize)> = self
            .counts
            .iter()
            .filter(|(_, n)| **n > MAX_PER_RULE)
            .map(|(c, n)| (*c, *n))
            .collect();
        let mut kept: Vec<Diagnostic> = found
            .into_iter()
            .filter(|d| !self.directives.suppresses(d))
            .collect();
        for (code, n) in dropped {
            if let Some(d) = kept.iter_mut().find(|d| d.code == code) {
                d.notes.push(format!(
                    "{n} {} findings in all; the first {MAX_PER_RULE} are kept",
                    code.code()
                ));
            }
        }
        kept
    }

    /// Rules about the program as a whole.
    fn whole_program(&mut self, end: RunEnd) {
        let Some(first) = self.first_motion else {
            return;
        };
        let looks_inch = self.metric_looks_inch(end);
        if !self.units_set {
            let mut d = Diagnostic::new(Code::LintNoUnits, "the program never sets its units")
                .primary(first, "first move, in whatever units the control is in")
                .help("set the units at the top (G20/G21, G70/G71, MM/INCH)");
            if let Some(what) = looks_inch {
                d.notes.push(format!(
                    "{what}: it is right only on a control left in inch"
                ));
            }
            self.report(d);
        }
        if !self.work_offset_set {
            self.report(
                Diagnostic::new(
                    Code::LintNoWorkOffset,
                    "the program never selects a work offset",
                )
                .primary(first, "first move, in whichever work offset is active")
                .help("select the work offset at the top (G54..)"),
            );
        }
        if let (Some(end), Some(mv), false) = (self.src.end, self.src.move_after_end, self.src.flow)
        {
            self.report(
                Diagnostic::new(
                    Code::LintMoveAfterEnd,
                    "moves after the program end are never run",
                )
                .primary(mv, "never run")
                .secondary(end, "the program ends here"),
            );
        }
        if end.complete && !self.ended && !self.src.any_end {
            if let Some(last) = self.src.last {
                self.report(
                    Diagnostic::new(
                        Code::LintNoProgramEnd,
                        "the program runs off its last block without a program end",
                    )
                    .primary(last, "last block")
                    .help("end the program with M30 (or M2)"),
                );
            }
        }
    }
}
