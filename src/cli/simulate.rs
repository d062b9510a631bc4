//! `cncc simulate FILE [--stock ..] [--resolution MM] [-o part.png|part.stl]`:
//! runs the program twice as a stream (memory stays the grid's): once to
//! learn the tools it cuts with and where it cuts (for the grid and, with
//! no stock given, a guessed stock), once through [`crate::sim`] to cut
//! the stock. Prints the removed volume per tool and the machining time;
//! writes the cut part as a shaded top view (PNG) or a mesh (STL).
//! A rapid through the material is an error (E1001), after the part is
//! written.

use crate::cli::args::Format;
use crate::cli::atomic::AtomicFile;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::output::write_bytes_atomically;
use crate::cli::stats::{keep_lines_at, load_tool_table, machine_mm, stream_events};
use crate::diag::Diagnostic;
use crate::interp::Options;
use crate::sim::material::guess_stock;
use crate::sim::report::{safety_diagnostics, StockFrom, Summary};
use crate::sim::{Cutters, HeightField, Simulation};
use crate::toolpath::{Event, Stock, P3};
use std::collections::BTreeSet;
use std::path::Path;

pub struct SimulateArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub stock: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub resolution: Option<f64>,
    pub output: Option<&'a Path>,
    pub ascii: bool,
    pub width: u32,
    /// mm/min; 0: rapids left out of the time.
    pub rapid_rate: f64,
    pub format: Format,
    pub options: Options,
}

/// What a first pass over a program learns.
pub(crate) struct Survey {
    pub diags: Vec<Diagnostic>,
    /// Tools that feed.
    pub tools: BTreeSet<i64>,
    /// The box round the feed moves, if any.
    pub feed_box: Option<[P3; 2]>,
    pub blank: Option<Stock>,
    pub head: String,
}

/// The first pass: diagnostics, tools, the box of the feed moves, the
/// program's own blank.
pub(crate) fn survey(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    options: &Options,
) -> Result<Survey, Failure> {
    let mut tools = BTreeSet::new();
    let mut feed_box: Option<[P3; 2]> = None;
    let (id, diags) = stream_events(ctx, path, dialect, options, true, |e| {
        note_feed(&mut tools, &mut feed_box, e)
    })?;
    let s = finish_survey(ctx, path, dialect, id, diags, tools, feed_box)?;
    keep_lines_at(ctx, path, id, &s.diags, &[])?;
    Ok(s)
}

/// Notes the tool and the ends of a feed move.
fn note_feed(tools: &mut BTreeSet<i64>, feed_box: &mut Option<[P3; 2]>, e: &Event) {
    let Event::Move(m) = e else { return };
    if !m.is_feed() {
        return;
    }
    tools.insert(m.tool);
    for p in [m.from, m.to] {
        let b = feed_box.get_or_insert([p, p]);
        for k in 0..3 {
            b[0][k] = b[0][k].min(p[k]);
            b[1][k] = b[1][k].max(p[k]);
        }
    }
}

/// A survey from what a pass over file `id` gathered, with the
/// program's own blank read.
fn finish_survey(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    id: crate::span::FileId,
    mut diags: Vec<Diagnostic>,
    tools: BTreeSet<i64>,
    feed_box: Option<[P3; 2]>,
) -> Result<Survey, Failure> {
    let head = crate::cli::check::read_head(path)?;
    let (spec, _) = ctx.spec_for(dialect, path, &head)?;
    let file =
        std::fs::File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let (blank, d) = Stock::from_program(file, id, &spec);
    diags.extend(d);
    Ok(Survey {
        diags,
        tools,
        feed_box,
        blank,
        head,
    })
}

/// One pass that both surveys and cuts, when the grid is known before
/// the run (`--stock` and `--resolution` given): the survey's
/// diagnostics come after the cut, so a program with errors is cut for
/// nothing, but a good one is run once instead of twice.
fn survey_and_cut(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    options: &Options,
    mut sim: Simulation,
) -> Result<(Survey, Simulation), Failure> {
    let mut tools = BTreeSet::new();
    let mut feed_box: Option<[P3; 2]> = None;
    let (id, diags) = stream_events(ctx, path, dialect, options, true, |e| {
        note_feed(&mut tools, &mut feed_box, e);
        sim.push(e);
    })?;
    let s = finish_survey(ctx, path, dialect, id, diags, tools, feed_box)?;
    keep_lines_at(ctx, path, id, &s.diags, &kept_spans(&sim))?;
    Ok((s, sim))
}

/// The second pass: the program cuts `field`; the spans of rapid hits
/// are kept for the report.
pub(crate) fn cut(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    options: &Options,
    mut sim: Simulation,
) -> Result<Simulation, Failure> {
    let (id, _) = stream_events(ctx, path, dialect, options, false, |e| sim.push(e))?;
    keep_lines_at(ctx, path, id, &[], &kept_spans(&sim))?;
    Ok(sim)
}

/// The tool table with the program's own tool definitions, and its cutters.
fn tools_of(
    options: &Options,
    head: &str,
    spec: &crate::dialect::DialectSpec,
) -> (crate::interp::tooltable::ToolTable, Cutters) {
    let mm = machine_mm(options);
    let table = crate::sim::tool_defs::with_tool_defs(&options.tool_table, head, spec, mm);
    let cutters = Cutters::from_table(&table, head, mm, false);
    (table, cutters)
}

/// A simulation of `stock` on cells of `cell`, checking rapids.
fn simulation(stock: &Stock, cell: f64, cutters: Cutters) -> Result<Simulation, Failure> {
    let field = HeightField::new(stock, cell).map_err(Failure)?;
    let mut sim = Simulation::new(field, cutters);
    sim.check_rapids = true;
    Ok(sim)
}

/// The spans a simulation's report shows.
fn kept_spans(sim: &Simulation) -> Vec<crate::span::Span> {
    let mut spans: Vec<_> = sim.rapid_hits.iter().map(|h| h.span).collect();
    spans.extend(sim.plunges.iter().map(|p| p.span));
    spans.extend(sim.probe_stopped.map(|(s, _)| s));
    spans.extend(sim.watch.and_then(|w| w.last).map(|(s, _)| s));
    spans
}

/// The stock to cut and where it came from.
pub(crate) fn stock_for(
    given: Option<&str>,
    s: &Survey,
    cutters: &Cutters,
) -> Result<(Stock, StockFrom), Failure> {
    if let Some(t) = given {
        return Ok((t.parse::<Stock>().map_err(Failure)?, StockFrom::Option));
    }
    if let Some(b) = s.blank {
        return Ok((b, StockFrom::Blank));
    }
    let b = s
        .feed_box
        .ok_or_else(|| Failure("the program cuts nothing and no --stock is given".into()))?;
    let r = s
        .tools
        .iter()
        .map(|t| cutters.get(*t).radius)
        .fold(0.0, f64::max);
    Ok((guess_stock(b, r), StockFrom::Guessed))
}

/// The grid cell: `--resolution`, else from the smallest tool that feeds.
pub(crate) fn cell_for(
    resolution: Option<f64>,
    stock: &Stock,
    tools: &BTreeSet<i64>,
    cutters: &Cutters,
) -> f64 {
    resolution.unwrap_or_else(|| {
        let smallest = tools
            .iter()
            .map(|t| 2.0 * cutters.get(*t).radius)
            .filter(|d| *d > 0.0)
            .reduce(f64::min);
        HeightField::auto_cell(stock, smallest)
    })
}

pub fn run(ctx: &mut Context, mut a: SimulateArgs<'_>) -> Result<i32, Failure> {
    if !(a.rapid_rate >= 0.0 && a.rapid_rate.is_finite()) {
        return Err(Failure(
            "--rapid-rate must be a number of mm/min (0: leave rapids out)".into(),
        ));
    }
    let kind = output_kind(a.output)?;
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    let head = crate::cli::check::read_head(a.file)?;
    let (spec, _) = ctx.spec_for(a.dialect, a.file, &head)?;
    a.options = crate::cli::check::program_tools(&a.options, &head, &spec);
    let (survey, sim, from, table) = match (a.stock, a.resolution) {
        (Some(given), Some(cell)) => {
            // The grid is known: one pass surveys and cuts.
            let stock = given.parse::<Stock>().map_err(Failure)?;
            let (table, cutters) = tools_of(&a.options, &head, &spec);
            let sim = simulation(&stock, cell, cutters)?;
            let (survey, sim) = survey_and_cut(ctx, a.file, a.dialect, &a.options, sim)?;
            (survey, sim, StockFrom::Option, table)
        }
        _ => {
            let survey = survey(ctx, a.file, a.dialect, &a.options)?;
            if survey.diags.iter().any(Diagnostic::is_error) {
                diags.extend(survey.diags);
                ctx.print(&diags, a.format);
                return Ok(EXIT_INPUT_ERRORS);
            }
            let (table, cutters) = tools_of(&a.options, &survey.head, &spec);
            let (stock, from) = stock_for(a.stock, &survey, &cutters)?;
            let cell = cell_for(a.resolution, &stock, &survey.tools, &cutters);
            let sim = simulation(&stock, cell, cutters)?;
            let sim = cut(ctx, a.file, a.dialect, &a.options, sim)?;
            (survey, sim, from, table)
        }
    };
    diags.extend(survey.diags.iter().cloned());
    if diags.iter().any(Diagnostic::is_error) {
        ctx.print(&diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    let table = &table;
    diags.extend(safety_diagnostics(&sim, from));
    ctx.print(&diags, a.format);
    let invented = table.invented
        && survey
            .tools
            .iter()
            .any(|t| *t != 0 && !table.from_program.contains(t));
    let summary = Summary {
        sim: &sim,
        stock_from: from,
        rapid_rate: (a.rapid_rate > 0.0).then_some(a.rapid_rate),
        invented,
    };
    let text = match a.format {
        Format::Human => summary.human(),
        Format::Json | Format::Sarif => summary.json(),
    };
    print!("{text}");
    if let (Some(out), Some(kind)) = (a.output, kind) {
        write_part(&sim.field, out, kind, a.ascii, a.width, a.file)?;
    }
    Ok(if sim.rapid_hits.is_empty() {
        EXIT_OK
    } else {
        EXIT_INPUT_ERRORS
    })
}

#[derive(Clone, Copy)]
enum Kind {
    Png,
    Stl,
}

fn output_kind(out: Option<&Path>) -> Result<Option<Kind>, Failure> {
    let Some(out) = out else { return Ok(None) };
    let ext = out
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase());
    match ext.as_deref() {
        Some("png") => Ok(Some(Kind::Png)),
        Some("stl") => Ok(Some(Kind::Stl)),
        _ => Err(Failure("-o must name a .png or .stl file".into())),
    }
}

fn write_part(
    field: &HeightField,
    out: &Path,
    kind: Kind,
    ascii: bool,
    width: u32,
    program: &Path,
) -> Result<(), Failure> {
    let fail = |e: std::io::Error| Failure(format!("{}: {e}", out.display()));
    match kind {
        Kind::Png => {
            if !(200..=8000).contains(&width) {
                return Err(Failure(
                    "--width must be between 200 and 8000 pixels".into(),
                ));
            }
            let name = program
                .file_name()
                .map(|n| n.to_string_lossy().into_owned())
                .unwrap_or_default();
            let title = format!("{name}: the cut part, top view");
            let bytes = crate::sim::image::render(field, width, &title).map_err(Failure)?;
            write_bytes_atomically(out, &bytes).map_err(fail)
        }
        Kind::Stl => {
            let mut tmp = AtomicFile::create(out).map_err(fail)?;
            {
                let mut w = std::io::BufWriter::new(tmp.file());
                crate::sim::stl::write(field, ascii, &mut w).map_err(fail)?;
            }
            tmp.commit().map_err(fail)
        }
    }
}
