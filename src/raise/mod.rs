//! Raising a program to STEP-NC (ISO 14649): the run's toolpath events
//! ([`crate::toolpath`]) become a [`Project`]. CC1 ([`cc1`]): explicit
//! toolpaths, with drilling cycles as hole features; CC2 ([`cc2`]):
//! machining features recognised from the toolpaths.
//!
//! [`raise_file`] streams the run: for CC1 no event is held longer than
//! the statement it belongs to, only the model grows. CC2 needs the whole
//! event list (its recognisers look back and ahead).

pub mod blank;
pub mod cc1;
pub mod cc2;
mod curves;
pub mod holes;
pub mod ops;
pub mod project;
mod report;
pub mod stock;
pub mod summary;

use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::tooltable::ToolTable;
use crate::ir::LengthUnit;
use crate::source::SourceMap;
use crate::span::FileId;
use crate::stepnc::model::{Project, ToolId};
use crate::toolpath::{Event, Tracker};
pub use stock::Stock;

/// Which conformance class to raise to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    /// Explicit toolpaths.
    Cc1,
    /// Machining features.
    Cc2,
}

#[derive(Clone, Debug)]
pub struct RaiseOptions {
    pub stock: Option<Stock>,
    /// The table tool geometry comes from (the one the run used).
    pub tool_table: ToolTable,
    /// The unit of the table's numbers.
    pub table_units: LengthUnit,
    pub level: Level,
    /// The project's name.
    pub name: String,
}

impl RaiseOptions {
    pub fn new(level: Level, name: impl Into<String>) -> Self {
        RaiseOptions {
            stock: None,
            tool_table: ToolTable::builtin(),
            table_units: LengthUnit::Inch,
            level,
            name: name.into(),
        }
    }

    fn tools(&self) -> project::ToolRegistry {
        let scale = match self.table_units {
            LengthUnit::Inch => 25.4,
            LengthUnit::Mm => 1.0,
        };
        project::ToolRegistry::new(self.tool_table.clone(), scale)
    }
}

/// A raised project with what raising reports (missing tool geometry,
/// what could not be carried exactly).
pub struct Raised {
    pub project: Project,
    pub diagnostics: Vec<Diagnostic>,
}

/// CC1, event by event: [`cc1::Cc1Builder`] set up for `opts`.
pub fn cc1_builder(opts: &RaiseOptions) -> cc1::Cc1Builder {
    let project = project::skeleton(&opts.name, opts.stock.as_ref());
    cc1::Cc1Builder::new(project, opts.tools(), opts.stock)
}

fn finish_cc1(b: cc1::Cc1Builder) -> Raised {
    let (mut project, tools, losses, rapid_z, max_z) = b.finish();
    project::set_security_plane(&mut project, rapid_z.or(max_z).unwrap_or(0.0));
    let mut diagnostics = tools.diagnostics;
    diagnostics.extend(losses.diagnostics());
    Raised {
        project,
        diagnostics,
    }
}

/// Raises a run's events.
pub fn raise_events(events: &[Event], opts: &RaiseOptions) -> Raised {
    match opts.level {
        Level::Cc1 => {
            let mut b = cc1_builder(opts);
            for e in events {
                b.push(e.clone());
            }
            finish_cc1(b)
        }
        Level::Cc2 => raise_cc2(events, opts),
    }
}

/// CC2: the skeleton and the tools, then the recognisers.
fn raise_cc2(events: &[Event], opts: &RaiseOptions) -> Raised {
    let mut project = project::skeleton(&opts.name, opts.stock.as_ref());
    let mut tools = opts.tools();
    let mut ids = std::collections::HashMap::new();
    let mut run: Vec<holes::Item> = Vec::new();
    let mut rapid_z: Option<f64> = None;
    let mut flush =
        |run: &mut Vec<holes::Item>, tools: &mut project::ToolRegistry, p: &mut Project| {
            let drilling = matches!(holes::classify(run), holes::Pattern::Hole(_));
            for it in run.drain(..) {
                if let holes::Item::Move(m) = it {
                    let id = tools.id(p, m.tool, m.span);
                    ids.insert(m.tool, id);
                    if m.is_feed() {
                        tools.used(id, drilling);
                    }
                }
            }
        };
    for e in events {
        if let Event::Move(m) = e {
            if run
                .first()
                .is_some_and(|i| !matches!(i, holes::Item::Move(f) if f.span == m.span))
            {
                flush(&mut run, &mut tools, &mut project);
            }
            if m.kind == crate::toolpath::MoveKind::Rapid {
                rapid_z = Some(rapid_z.map_or(m.to[2], |z: f64| z.max(m.to[2])));
            }
            run.push(holes::Item::Move(m.clone()));
        }
    }
    flush(&mut run, &mut tools, &mut project);
    tools.settle_kinds(&mut project);
    let secplane_z = rapid_z.unwrap_or(0.0);
    project::set_security_plane(&mut project, secplane_z);
    let table = opts.tools();
    let ctx = cc2::Cc2Context {
        tool_diameter: Box::new(move |n| table.diameter(n)),
        stock: opts.stock.map(|s| (s.corner, s.max())),
        secplane_z,
    };
    let tool = |n: i64| ids.get(&n).copied().unwrap_or(ToolId(0));
    let mut diagnostics = tools.diagnostics;
    diagnostics.extend(cc2::recognise_report(events, &mut project, &tool, &ctx));
    project::set_security_plane(&mut project, secplane_z);
    Raised {
        project,
        diagnostics,
    }
}

/// Runs the program in `path` (registered as `id` in `files`) and raises
/// it. Returns the project with the run's and the raiser's diagnostics.
pub fn raise_file(
    path: &std::path::Path,
    id: FileId,
    spec: &std::sync::Arc<DialectSpec>,
    run: &crate::interp::Options,
    opts: &RaiseOptions,
    files: &mut SourceMap,
) -> std::io::Result<Raised> {
    let (opts, mut blank_diags) = with_program_stock(path, id, spec, opts)?;
    let opts = &opts;
    let mut raised = raise_run(path, id, spec, run, opts, files)?;
    raised.diagnostics.append(&mut blank_diags);
    Ok(raised)
}

/// `opts`, with the program's own blank (`BLK FORM`) as the stock when
/// `--stock` is absent ([`Stock::from_program`]).
fn with_program_stock(
    path: &std::path::Path,
    id: FileId,
    spec: &DialectSpec,
    opts: &RaiseOptions,
) -> std::io::Result<(RaiseOptions, Vec<Diagnostic>)> {
    let mut opts = opts.clone();
    if opts.stock.is_some() {
        return Ok((opts, Vec::new()));
    }
    let (stock, diags) = Stock::from_program(std::fs::File::open(path)?, id, spec);
    opts.stock = stock;
    Ok((opts, diags))
}

fn raise_run(
    path: &std::path::Path,
    id: FileId,
    spec: &std::sync::Arc<DialectSpec>,
    run: &crate::interp::Options,
    opts: &RaiseOptions,
    files: &mut SourceMap,
) -> std::io::Result<Raised> {
    match opts.level {
        Level::Cc1 => {
            let mut tracker = Tracker::new();
            let mut b = cc1_builder(opts);
            let mut sink = |call: crate::canon::Canon, span| {
                tracker.push(&call, span, |e| b.push(e));
            };
            let run_diags = crate::interp::file::run_file(path, id, spec, run, files, &mut sink)?;
            let mut raised = finish_cc1(b);
            let mut diags = run_diags;
            diags.append(&mut raised.diagnostics);
            raised.diagnostics = diags;
            Ok(raised)
        }
        Level::Cc2 => {
            let (events, mut diags) = crate::toolpath::events_of_file(path, id, spec, run, files)?;
            let mut raised = raise_cc2(&events, opts);
            diags.append(&mut raised.diagnostics);
            raised.diagnostics = diags;
            Ok(raised)
        }
    }
}
