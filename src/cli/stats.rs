//! `cncc stats`: machining statistics per tool and in total (see
//! [`crate::stats`]). Also home of [`stream_events`], how `stats`, `diff`
//! and `plot` run a program file into resolved events while it is read
//! (a STEP-NC file: its plan posted and run, see
//! [`crate::cli::stepnc_input`]).

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::diag::Diagnostic;
use crate::interp::{file::run_file, tooltable::ToolTable, Options};
use crate::span::{FileId, Span};
use crate::stats::{report, StatsBuilder, StatsOptions};
use crate::toolpath::{Event, Tracker};
use std::io::IsTerminal;
use std::path::Path;

/// Files at least this large get a progress bar (on a terminal).
const PROGRESS_FROM: u64 = 8 << 20;

pub struct StatsArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub rapid_rate: f64,
    pub tool_change_time: f64,
    pub format: Format,
    pub options: Options,
}

/// Loads `--tool-table` into the run options; its diagnostics.
pub(crate) fn load_tool_table(
    ctx: &mut Context,
    table: Option<&Path>,
    options: &mut Options,
) -> Result<Vec<Diagnostic>, Failure> {
    let Some(t) = table else {
        return Ok(Vec::new());
    };
    let (tid, ttext) = ctx.add_side_file(t)?;
    let (table, d) = ToolTable::parse(&ttext, tid);
    options.tool_table = table;
    Ok(d)
}

/// Millimetres per machine unit (tool table numbers).
pub(crate) fn machine_mm(options: &Options) -> f64 {
    match options.machine_units {
        crate::ir::LengthUnit::Inch => 25.4,
        crate::ir::LengthUnit::Mm => 1.0,
    }
}

/// Runs a program file, handing every resolved event to `on_event` as the
/// file is read (memory stays flat). Shows a progress bar for large files
/// when stderr is a terminal; says which dialect was detected when
/// `say_dialect`. The file is registered sparse: call
/// [`keep_lines_at`] for the lines a report shows. A STEP-NC file is
/// posted (to `dialect`, LinuxCNC by default) and the posted program run;
/// the id is then the posted program's (or the Part 21 file's, when the
/// post refused the plan), both held whole.
pub(crate) fn stream_events(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    options: &Options,
    say_dialect: bool,
    mut on_event: impl FnMut(&Event),
) -> Result<(FileId, Vec<Diagnostic>), Failure> {
    let head = crate::cli::check::read_head(path)?;
    if crate::stepnc::is_part21(path, &head) {
        let mut tracker = Tracker::new();
        let mut sink = |call: crate::canon::Canon, span: Span| {
            tracker.push(&call, span, |e| on_event(&e));
        };
        let (id, diags) =
            crate::cli::stepnc_input::post_and_run(ctx, path, dialect, options, &mut sink)?;
        let id = id.unwrap_or_else(|| ctx.files.add(path.display().to_string(), String::new()));
        return Ok((id, diags));
    }
    let (spec, reason) = ctx.spec_for(dialect, path, &head)?;
    if let (Some(r), true) = (reason, say_dialect) {
        report_detection(path, &spec, &r);
    }
    let id = ctx.files.add_sparse(path.display().to_string(), Vec::new());
    let size = std::fs::metadata(path).map(|m| m.len()).unwrap_or(0);
    let bar = (size >= PROGRESS_FROM && std::io::stderr().is_terminal()).then(|| {
        let b = indicatif::ProgressBar::new(size);
        b.set_style(
            indicatif::ProgressStyle::with_template("{bar:40} {bytes}/{total_bytes} {eta}")
                .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
        b
    });
    let mut tracker = Tracker::new();
    let mut count = 0u64;
    let mut sink = |call: crate::canon::Canon, span: Span| {
        tracker.push(&call, span, |e| on_event(&e));
        count += 1;
        if let Some(b) = &bar {
            if count.is_multiple_of(4096) && span.file == id {
                b.set_position(span.start as u64);
            }
        }
    };
    let diags = run_file(path, id, &spec, options, &mut ctx.files, &mut sink)
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    Ok((id, diags))
}

/// Keeps the lines of a streamed file that diagnostics and `spans` show.
pub(crate) fn keep_lines_at(
    ctx: &mut Context,
    path: &Path,
    id: FileId,
    diags: &[Diagnostic],
    spans: &[Span],
) -> Result<(), Failure> {
    if !ctx.files.is_sparse(id) {
        return Ok(());
    }
    let offsets: Vec<u32> = diags
        .iter()
        .flat_map(|d| d.labels.iter().map(|l| l.span))
        .chain(spans.iter().copied())
        .filter(|s| s.file == id)
        .flat_map(|s| [s.start, s.end.saturating_sub(1).max(s.start)])
        .collect();
    let file =
        std::fs::File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let lines = crate::driver::lines_at(std::io::BufReader::new(file), &offsets)?;
    ctx.files.set_sparse(id, lines);
    Ok(())
}

pub fn run(ctx: &mut Context, mut a: StatsArgs<'_>) -> Result<i32, Failure> {
    if !(a.rapid_rate > 0.0 && a.rapid_rate.is_finite()) {
        return Err(Failure(
            "--rapid-rate must be a positive number of mm/min".into(),
        ));
    }
    if !(a.tool_change_time >= 0.0 && a.tool_change_time.is_finite()) {
        return Err(Failure(
            "--tool-change-time must be zero or more seconds".into(),
        ));
    }
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    let head = crate::cli::check::read_head(a.file)?;
    let (spec, _) = ctx.spec_for(a.dialect, a.file, &head)?;
    a.options = crate::cli::check::program_tools(&a.options, &head, &spec);
    a.options = crate::cli::stepnc_input::with_plan_tools(a.file, &a.options);
    let mut builder = StatsBuilder::new(StatsOptions {
        rapid_rate: a.rapid_rate,
        tool_change_s: a.tool_change_time,
    });
    let (id, run) = stream_events(ctx, a.file, a.dialect, &a.options, true, |e| {
        builder.push(e)
    })?;
    diags.extend(run);
    keep_lines_at(ctx, a.file, id, &diags, &[])?;
    ctx.print(&diags, a.format);
    if diags.iter().any(|d| d.is_error()) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    let stats = builder.finish(&a.options.tool_table, machine_mm(&a.options));
    let text = match a.format {
        Format::Human => report::human(&stats),
        Format::Json | Format::Sarif => report::json(&stats),
    };
    crate::cli::output::emit_output(None, &text)?;
    Ok(EXIT_OK)
}
