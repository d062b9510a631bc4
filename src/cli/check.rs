//! `cncc check`: read programs, report every problem, exit 1 on errors.
//! A clean program prints nothing.
//!
//! A program that reads cleanly is also run (calls discarded), so run-time
//! errors show too: arcs that do not close, moves with no feed, unknown
//! tools, division by zero, loops past their limit... A program with no
//! control flow runs block by block while it is read, so memory stays flat
//! on large CAM files; one with control flow (jumps, loops, calls,
//! parameters) is read whole and run by the program walker.

use crate::cli::args::Format;
use crate::cli::context::{detection_note, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::output::summary_line;
use crate::diag::{Code, Diagnostic, Severity};
use crate::dialect::DialectSpec;
use crate::driver::{check_stream, read_program, FsLoader};
use crate::interp::{stream::StreamRun, tooltable::ToolTable, Interp, Options};
use crate::sim::report::StockFrom;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

pub struct CheckArgs<'a> {
    pub files: &'a [std::path::PathBuf],
    pub dialect: Option<&'a str>,
    pub format: Format,
    pub verbose: bool,
    pub tool_table: Option<&'a Path>,
    /// Run the program after reading it (run-time checks).
    pub run: bool,
    /// `--stock`: simulate the material and probe the rapids (E1001).
    pub stock: Option<&'a str>,
    /// Lint the run, with these command-line selectors (None: `--no-lint`).
    pub lint: Option<crate::lint::CliSelect>,
    pub options: Options,
    /// `--ini`, `--var-file`: a LinuxCNC configuration (read, not written).
    pub config: crate::cli::rs274_config::ConfigFiles<'a>,
}

pub fn run(ctx: &mut Context, mut a: CheckArgs<'_>) -> Result<i32, Failure> {
    let mut all = Vec::new();
    if let Some(t) = a.tool_table {
        let (tid, ttext) = ctx.add_side_file(t)?;
        let (table, d) = ToolTable::parse(&ttext, tid);
        all.extend(d);
        a.options.tool_table = table;
    }
    let config = crate::cli::rs274_config::read(ctx, a.config, &mut a.options)?;
    if config.diags.iter().any(|d| d.is_error()) {
        ctx.print(&config.diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    all.extend(config.diags);
    a.options.missing_calls_warn = true;
    a.options.keep_going = true;
    // A check names invented tool sizes only where they mattered (W0592).
    a.options.report_tool_sizes = false;
    let mut failed = false;
    let results = check_all(ctx, &a);
    for note in ctx.notes.drain(..) {
        eprintln!("{note}");
    }
    for result in results {
        match result {
            Ok(d) => all.extend(d),
            Err(Failure(msg)) => {
                // Each file is independent: the others are still checked.
                eprintln!("error: {msg}");
                failed = true;
            }
        }
    }
    if a.format == Format::Sarif {
        // One document, on stdout, even when there is nothing to say.
        let doc = crate::diag::sarif::sarif(&all, &ctx.files);
        print!("{doc}");
    } else {
        ctx.print(&all, a.format);
    }
    let errors = all.iter().filter(|d| d.severity == Severity::Error).count();
    let warnings = all
        .iter()
        .filter(|d| d.severity == Severity::Warning)
        .count();
    if a.format == Format::Human {
        if let Some(s) = summary_line(errors, warnings, 0) {
            eprintln!("{s}");
        }
    }
    // A file that could not be checked at all is the status an I/O
    // failure always had (2), once every other file is checked.
    Ok(if failed {
        crate::cli::context::EXIT_USAGE
    } else if errors > 0 {
        EXIT_INPUT_ERRORS
    } else {
        EXIT_OK
    })
}

/// Checks every file, in input order. Several files are checked on every
/// core, each with its own source map, merged back in input order.
fn check_all(ctx: &mut Context, a: &CheckArgs<'_>) -> Vec<Result<Vec<Diagnostic>, Failure>> {
    if a.files.len() < 2 {
        return a.files.iter().map(|p| check_one(ctx, p, a)).collect();
    }
    use rayon::prelude::*;
    let (registry, color, shared) = (&ctx.registry, ctx.color, &ctx.files);
    let done: Vec<_> = a
        .files
        .par_iter()
        .map(|path| {
            let mut local = Context {
                registry: registry.clone(),
                files: shared.branch(),
                color,
                notes: Vec::new(),
                post_dir: None,
            };
            (check_one(&mut local, path, a), local.files, local.notes)
        })
        .collect();
    let shared = ctx.files.len();
    done.into_iter()
        .map(|(result, files, mut notes)| {
            ctx.notes.append(&mut notes);
            let id = ctx.files.absorb(files, shared);
            result.map(|mut diags| {
                for l in diags.iter_mut().flat_map(|d| d.labels.iter_mut()) {
                    l.span.file = id(l.span.file);
                }
                diags
            })
        })
        .collect()
}

/// Checks one file (a program or STEP-NC); a panic in cncc while checking
/// it is reported as a failure of that file alone.
fn check_one(
    ctx: &mut Context,
    path: &Path,
    a: &CheckArgs<'_>,
) -> Result<Vec<Diagnostic>, Failure> {
    let run = std::panic::AssertUnwindSafe(|| {
        if crate::stepnc::is_part21(path, &read_head(path)?) {
            return crate::cli::stepnc::check_file(ctx, path);
        }
        check_file(ctx, path, a)
    });
    std::panic::catch_unwind(run).unwrap_or_else(|p| {
        let what = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_default();
        Err(Failure(format!(
            "{}: internal error in cncc while checking this file ({what}); please report it",
            path.display()
        )))
    })
}

/// Streams one file through the reader (and the interpreter, until the
/// program shows control flow); keeps only the lines diagnostics point at.
fn check_file(
    ctx: &mut Context,
    path: &Path,
    a: &CheckArgs<'_>,
) -> Result<Vec<Diagnostic>, Failure> {
    let fail = |e: std::io::Error| Failure(format!("{}: {e}", path.display()));
    let head = read_head(path)?;
    let (spec, reason) = ctx.spec_for(a.dialect, path, &head)?;
    crate::cli::rs274_config::require(&spec, a.config)?;
    let input = BufReader::with_capacity(1 << 16, File::open(path).map_err(fail)?);
    let id = ctx.files.add_sparse(path.display().to_string(), Vec::new());
    let options = program_tools(&a.options, &head, &spec);
    let (mut sim, stock_from) = rapid_checker(a.stock, &options, &head, path, id, &spec)?;
    let has_blank = sim.is_some();
    let mut tracker = crate::toolpath::Tracker::new();
    // The statements that move in machine coordinates (see
    // `Simulation::push_in_frame`), marked as their blocks are read.
    let machine = std::cell::RefCell::new(std::collections::HashSet::new());
    let mut discard = |c: crate::canon::Canon, span: crate::span::Span| {
        if let Some(s) = sim.as_mut() {
            let framed = machine.borrow().contains(&span);
            tracker.push(&c, span, |e| s.push_in_frame(&e, framed));
        }
    };
    let linter = lint_for(path, a, &spec, &options)?;
    let mut it = Interp::new(&spec, &options, &mut discard);
    if let Some(l) = &linter {
        let l = l.clone();
        it.watcher = Some(Box::new(move |step| l.borrow_mut().step(step)));
    }
    it.start();
    let mut stream = StreamRun::default();
    // Whether the file may be a subprogram, known without reading it whole.
    let mut top_level = crate::interp::fragment::Detector::default();
    let result = check_stream(input, id, &spec, |b, e| {
        top_level.block(b);
        if a.stock.is_some() || has_blank {
            mark_machine_frame(&mut machine.borrow_mut(), b, &spec);
        }
        if let Some(l) = &linter {
            l.borrow_mut().read_block(b);
        }
        if a.run {
            stream.block(&mut it, b, e)
        }
    })
    .map_err(fail)?;
    let mut diags = result.diagnostics;
    if a.run && !diags.iter().any(Diagnostic::is_error) {
        // A main program is walked with its plain moves held as text
        // (every block was marked as it was read); a file that may be a
        // subprogram is read whole, to find where it starts.
        let program = match stream.handover {
            Some(_) if top_level.is_fragment() => Some(read_whole(path, id, &spec)?),
            _ => None,
        };
        for b in program.iter().flat_map(|p| &p.blocks) {
            mark_machine_frame(&mut machine.borrow_mut(), b, &spec);
        }
        let fragment = program.as_deref().and_then(crate::interp::fragment::detect);
        let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
        let mut loader = FsLoader::new(dir, spec.clone(), &mut ctx.files)
            .with_search(&a.options.rs274.subroutine_path);
        let mut run = match (&program, &fragment) {
            (None, _) if stream.handover.is_none() => stream.finish(&mut it),
            (None, _) => {
                let (main, lazy, _) =
                    crate::interp::lazy::read_program_lazy(read_text(path)?, id, &spec);
                stream.continue_with(&mut it, std::rc::Rc::new(main), Some(lazy), &mut loader)
            }
            (Some(_), Some(_)) => Vec::new(),
            (Some(program), None) => {
                stream.continue_with(&mut it, program.clone(), None, &mut loader)
            }
        };
        run.append(&mut loader.diags);
        drop(loader);
        drop(it);
        if let Some(mut s) = sim.take() {
            // A tilt the run does not make (W0518) moves the tool where
            // the run does not: the stock is not checked after it.
            let tilt = run
                .iter()
                .filter(|d| d.code == Code::KinematicsNotRun)
                .filter_map(Diagnostic::span)
                .min_by_key(|s| s.start);
            let mut d = Vec::new();
            if let Some(at) = tilt {
                if crate::sim::report::stop_at_tilt(&mut s, at) {
                    d.push(crate::sim::report::tilt_stopped_diagnostic(at));
                }
            }
            d.extend(crate::sim::report::safety_diagnostics(&s, stock_from));
            // Where the checks stopped is said when the stock was asked
            // for; a program's own blank is checked as far as it can be.
            if stock_from != crate::sim::report::StockFrom::Option {
                d.retain(|d| d.code != Code::MaterialCheckStopped);
            }
            run.extend(d);
        }
        // A subprogram or library checked alone runs again from its top
        // with its caller's values unknown: at once when it has control
        // flow (read whole already), after a failed run when it has none
        // (a feed from the caller; only then is it read whole).
        let fragment = match (program, fragment) {
            (Some(p), Some(f)) => Some((p, f)),
            (None, None) if run.iter().any(Diagnostic::is_error) && top_level.is_fragment() => {
                let p = read_whole(path, id, &spec)?;
                crate::interp::fragment::detect(&p).map(|f| (p, f))
            }
            _ => None,
        };
        let is_fragment = fragment.is_some();
        if let Some((program, fragment)) = fragment {
            run = run_as_fragment(ctx, path, &spec, &options, program, &fragment);
        }
        // A statement cncc cannot run yet is our limit, not the program's
        // mistake: said as a warning that the run-time checks stop there.
        for d in run.iter_mut().filter(|d| d.code == Code::UnsupportedHere) {
            d.code = Code::RunStoppedEarly;
            d.severity = crate::diag::Severity::Warning;
            d.help = Some(
                "cncc cannot run this yet; run-time checks of the blocks after it were not made"
                    .into(),
            );
        }
        let end = crate::lint::RunEnd {
            complete: !run.iter().any(stopped_the_run),
            fragment: is_fragment,
        };
        diags.extend(run);
        if let Some(l) = linter.and_then(|l| std::rc::Rc::try_unwrap(l).ok()) {
            diags.extend(l.into_inner().finish(end));
        }
    }
    keep_lines(ctx, path, id, &diags)?;
    if let Some(r) = reason {
        if a.verbose || !diags.is_empty() {
            ctx.notes.push(detection_note(path, &spec, &r));
        }
    }
    Ok(diags)
}

/// With a stock (`--stock`, else the program's own blank: Heidenhain
/// `BLK FORM`): the material simulation that probes every rapid (tools
/// of invented size are checked along their axis only; a grid of about
/// 1000 cells along the stock's longest side).
fn rapid_checker(
    stock: Option<&str>,
    options: &Options,
    head: &str,
    path: &Path,
    id: crate::span::FileId,
    spec: &DialectSpec,
) -> Result<(Option<crate::sim::Simulation>, StockFrom), Failure> {
    let (stock, from) = match stock {
        Some(text) => (
            text.parse::<crate::toolpath::Stock>().map_err(Failure)?,
            StockFrom::Option,
        ),
        None => {
            let file = File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
            match crate::toolpath::Stock::from_program(file, id, spec).0 {
                Some(b) => (b, StockFrom::Blank),
                None => return Ok((None, StockFrom::Blank)),
            }
        }
    };
    let longest = stock.size[0].max(stock.size[1]);
    let cell = crate::sim::HeightField::auto_cell(&stock, Some(longest / 10.0));
    let field = crate::sim::HeightField::new(&stock, cell).map_err(Failure)?;
    let mm = crate::cli::stats::machine_mm(options);
    let table = crate::sim::tool_defs::with_tool_defs(&options.tool_table, head, spec, mm);
    let cutters = crate::sim::Cutters::from_table(&table, head, mm, true);
    let mut sim = crate::sim::Simulation::new(field, cutters);
    sim.check_rapids = true;
    Ok((Some(sim), from))
}

/// Adds the statements of `b` when the block moves in machine coordinates.
fn mark_machine_frame(
    spans: &mut std::collections::HashSet<crate::span::Span>,
    b: &crate::ir::Block,
    spec: &DialectSpec,
) {
    let machine = b.stmts.iter().any(|s| spec.in_machine_coords(&s.kind));
    if machine {
        spans.extend(b.stmts.iter().map(|s| s.span));
    }
}

/// The lint of one program (None with `--no-lint`, `--no-run`, or when
/// no rule runs): its `cncc.toml` found beside or above it.
type SharedLinter = std::rc::Rc<std::cell::RefCell<crate::lint::Linter>>;

fn lint_for(
    path: &Path,
    a: &CheckArgs<'_>,
    spec: &DialectSpec,
    options: &Options,
) -> Result<Option<SharedLinter>, Failure> {
    let Some(sel) = a.lint.as_ref().filter(|_| a.run) else {
        return Ok(None);
    };
    let cfg = crate::lint::LintConfig::for_program(path, sel).map_err(Failure)?;
    let l = crate::lint::Linter::new(spec, cfg, options.machine_units);
    Ok(l.is_active()
        .then(|| std::rc::Rc::new(std::cell::RefCell::new(l))))
}

/// A diagnostic after which the run did not reach the program's end.
fn stopped_the_run(d: &Diagnostic) -> bool {
    d.is_error()
        || matches!(
            d.code,
            Code::ValueFromOutside | Code::RunStoppedEarly | Code::LimitExceeded
        )
}

/// Runs a subprogram or library checked alone with its caller's values
/// unknown ([`crate::interp::fragment`]).
fn run_as_fragment(
    ctx: &mut Context,
    path: &Path,
    spec: &std::sync::Arc<DialectSpec>,
    options: &Options,
    program: std::rc::Rc<crate::ir::Program>,
    fragment: &crate::interp::fragment::Fragment,
) -> Vec<Diagnostic> {
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut loader = FsLoader::new(dir, spec.clone(), &mut ctx.files)
        .with_search(&options.rs274.subroutine_path);
    let mut discard = |_: crate::canon::Canon, _: crate::span::Span| {};
    let mut d =
        crate::interp::fragment::run(program, fragment, spec, options, &mut loader, &mut discard);
    d.append(&mut loader.diags);
    d
}

/// The run options for one program: the tools its header comments list
/// join the tool table where no real table gives them.
pub(crate) fn program_tools(options: &Options, head: &str, spec: &DialectSpec) -> Options {
    let mut o = options.clone();
    crate::interp::tool_header::merge_header(&mut o.tool_table, head, o.machine_units, spec);
    o
}

/// Keeps, for a file read as a stream, the lines the diagnostics show.
pub(crate) fn keep_lines(
    ctx: &mut Context,
    path: &Path,
    id: crate::span::FileId,
    diags: &[Diagnostic],
) -> Result<(), Failure> {
    let offsets: Vec<u32> = diags
        .iter()
        .flat_map(|d| d.labels.iter())
        .filter(|l| l.span.file == id)
        .flat_map(|l| [l.span.start, l.span.end.saturating_sub(1).max(l.span.start)])
        .collect();
    let file = File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let lines = crate::driver::lines_at(BufReader::new(file), &offsets)?;
    ctx.files.set_sparse(id, lines);
    Ok(())
}

/// Reads a whole program (for the walker), with spans in file `id`.
pub(crate) fn read_whole(
    path: &Path,
    id: crate::span::FileId,
    spec: &DialectSpec,
) -> Result<std::rc::Rc<crate::ir::Program>, Failure> {
    let text = read_text(path)?;
    Ok(std::rc::Rc::new(read_program(&text, id, spec).0))
}

/// The file's text, decoded, within the input limit.
fn read_text(path: &Path) -> Result<String, Failure> {
    let bytes = crate::cli::context::read_limited(path, crate::cli::context::MAX_INPUT)
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    Ok(crate::driver::decode(&bytes))
}

/// The first 64 KiB of a file, for dialect detection.
pub(crate) fn read_head(path: &Path) -> Result<String, Failure> {
    use std::io::Read;
    let mut buf = vec![0u8; 1 << 16];
    let mut f = File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let mut n = 0;
    while n < buf.len() {
        let k = f.read(&mut buf[n..])?;
        if k == 0 {
            break;
        }
        n += k;
    }
    buf.truncate(n);
    Ok(crate::driver::decode(&buf))
}
