//! Raising a program to STEP-NC (ISO 14649): the run's toolpath events
//! ([`crate::toolpath`]) become a [`Project`]. CC1 ([`cc1`]): explicit
//! toolpaths, with drilling cycles as hole features; CC2 ([`cc2`]):
//! machining features recognised from the toolpaths.
//!
//! [`raise_file`] streams the run: for CC1 no event is held longer than
//! the statement it belongs to, only the model grows. CC2's recognisers
//! look back and ahead, but only at the cuts (a cut's moves, and every
//! cut's envelope): the run is made into cuts as it comes and no event
//! list is held; finished cuts are kept packed until the run ends, then
//! unpacked, raised and dropped one at a time.

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

/// CC2 on a run's events: [`Cc2Pass`] over them.
fn raise_cc2(events: &[Event], opts: &RaiseOptions) -> Raised {
    let mut pass = Cc2Pass::new(opts);
    for e in events {
        pass.push(e.clone());
    }
    pass.finish(opts)
}

/// CC2, event by event: the skeleton, the tools as the run first uses
/// them, the highest rapid and the run's cuts ([`cc2::CutStream`]); then,
/// once the run has ended (the security plane and the tools' kinds need
/// all of it), the recognisers over the cuts.
struct Cc2Pass {
    project: Project,
    tools: project::ToolRegistry,
    ids: std::collections::HashMap<i64, ToolId>,
    /// The moves of the statement being run (one drilling cycle or not).
    run: Vec<holes::Item>,
    rapid_z: Option<f64>,
    cuts: cc2::CutStream,
}

impl Cc2Pass {
    fn new(opts: &RaiseOptions) -> Self {
        Cc2Pass {
            project: project::skeleton(&opts.name, opts.stock.as_ref()),
            tools: opts.tools(),
            ids: std::collections::HashMap::new(),
            run: Vec::new(),
            rapid_z: None,
            cuts: cc2::CutStream::default(),
        }
    }

    fn push(&mut self, e: Event) {
        if let Event::Move(m) = &e {
            if self
                .run
                .first()
                .is_some_and(|i| !matches!(i, holes::Item::Move(f) if f.span == m.span))
            {
                self.flush();
            }
            if m.kind == crate::toolpath::MoveKind::Rapid {
                self.rapid_z = Some(self.rapid_z.map_or(m.to[2], |z: f64| z.max(m.to[2])));
            }
            self.run.push(holes::Item::Move(m.clone()));
        }
        // The project's tools have the table's diameters: the radius
        // recognition uses (`cc2::recognise_report`) is the table's.
        let tools = &self.tools;
        self.cuts.push(e, &|t| cc2::radius_of(tools.diameter(t)));
    }

    /// Registers the tools of the statement's moves, counting its cuts as
    /// drilling when the statement is a drilling cycle.
    fn flush(&mut self) {
        let drilling = matches!(holes::classify(&self.run), holes::Pattern::Hole(_));
        for it in self.run.drain(..) {
            if let holes::Item::Move(m) = it {
                let id = self.tools.id(&mut self.project, m.tool, m.span);
                self.ids.insert(m.tool, id);
                if m.is_feed() {
                    self.tools.used(id, drilling);
                }
            }
        }
    }

    fn finish(mut self, opts: &RaiseOptions) -> Raised {
        self.flush();
        let tools = &self.tools;
        let cuts = self.cuts.finish(&|t| cc2::radius_of(tools.diameter(t)));
        let mut project = self.project;
        self.tools.settle_kinds(&mut project);
        let secplane_z = self.rapid_z.unwrap_or(0.0);
        project::set_security_plane(&mut project, secplane_z);
        let table = opts.tools();
        let ctx = cc2::Cc2Context {
            tool_diameter: Box::new(move |n| table.diameter(n)),
            stock: opts.stock.map(|s| (s.corner, s.max())),
            secplane_z,
        };
        let ids = self.ids;
        let tool = |n: i64| ids.get(&n).copied().unwrap_or(ToolId(0));
        let mut diagnostics = self.tools.diagnostics;
        diagnostics.extend(cc2::recognise_cuts(cuts, &mut project, &tool, &ctx));
        project::set_security_plane(&mut project, secplane_z);
        Raised {
            project,
            diagnostics,
        }
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
            let mut tracker = Tracker::new();
            let mut pass = Cc2Pass::new(opts);
            let mut sink = |call: crate::canon::Canon, span| {
                tracker.push(&call, span, |e| pass.push(e));
            };
            let mut diags = crate::interp::file::run_file(path, id, spec, run, files, &mut sink)?;
            let mut raised = pass.finish(opts);
            diags.append(&mut raised.diagnostics);
            raised.diagnostics = diags;
            Ok(raised)
        }
    }
}
