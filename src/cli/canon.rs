//! `cncc canon`: run a program and print its canonical machining calls,
//! one per line, in the text form of LinuxCNC's `rs274`.
//!
//! The file is read twice as a stream: first for the reader's diagnostics
//! (a program with errors is not run), then to run it block by block while
//! it is read. A program with control flow is read whole from its first
//! such block and the walker goes on from there (see
//! [`crate::interp::stream`]), so memory stays flat on large CAM files.
//! A STEP-NC file is posted in memory and the posted program run (see
//! [`crate::cli::stepnc_input`]).

use crate::canon::write_call;
use crate::cli::args::Format;
use crate::cli::check::{keep_lines, read_head};
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::rs274_config::{self, ConfigFiles};
use crate::cli::stepnc_input::post_and_run;
use crate::interp::{file::run_file, tooltable::ToolTable, Options};
use std::io::Write;
use std::path::Path;

/// How many bytes of calls are gathered before they are written out.
const OUT_CHUNK: usize = 1 << 16;

/// Writes the gathered calls out (keeping the first write error; after
/// one, calls are dropped).
fn flush_to(out: &mut impl Write, buf: &mut Vec<u8>, io_error: &mut Option<std::io::Error>) {
    if io_error.is_none() {
        if let Err(e) = out.write_all(buf) {
            *io_error = Some(e);
        }
    }
    buf.clear();
}

pub struct CanonArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub format: Format,
    /// `--ini`, `--var-file`: a LinuxCNC configuration.
    pub config: ConfigFiles<'a>,
    pub options: Options,
}

pub fn run(ctx: &mut Context, mut a: CanonArgs<'_>) -> Result<i32, Failure> {
    let fail = |e: std::io::Error| Failure(format!("{}: {e}", a.file.display()));
    let head = read_head(a.file)?;
    let stepnc = crate::stepnc::is_part21(a.file, &head);
    if stepnc && a.config.any() {
        return Err(Failure(
            "--ini and --var-file apply to a part program, not a STEP-NC plan".into(),
        ));
    }
    let spec = if stepnc {
        None
    } else {
        let (spec, reason) = ctx.spec_for(a.dialect, a.file, &head)?;
        if let Some(r) = reason {
            report_detection(a.file, &spec, &r);
        }
        Some(spec)
    };
    let mut diags = Vec::new();
    if let Some(t) = a.tool_table {
        let (tid, ttext) = ctx.add_side_file(t)?;
        let (table, d) = ToolTable::parse(&ttext, tid);
        diags.extend(d);
        a.options.tool_table = table;
    }
    if let Some(spec) = &spec {
        rs274_config::require(spec, a.config)?;
    }
    let config = rs274_config::read(ctx, a.config, &mut a.options)?;
    if config.diags.iter().any(|d| d.is_error()) {
        // rs274 does not start with a parameter file it cannot read.
        ctx.print(&config.diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    diags.extend(config.diags.iter().cloned());
    let mut out = std::io::stdout().lock();
    let mut io_error = None;
    // Calls are written into a buffer, handed to stdout in large chunks.
    let mut buf: Vec<u8> = Vec::with_capacity(OUT_CHUNK + 4096);
    let mut sink = |call: crate::canon::Canon, _span| {
        write_call(&mut buf, &call);
        buf.push(b'\n');
        if buf.len() >= OUT_CHUNK {
            flush_to(&mut out, &mut buf, &mut io_error);
        }
    };
    match spec {
        Some(spec) => {
            let id = ctx
                .files
                .add_sparse(a.file.display().to_string(), Vec::new());
            let run =
                run_file(a.file, id, &spec, &a.options, &mut ctx.files, &mut sink).map_err(fail)?;
            diags.extend(run);
            rs274_config::write_back(&config, &a.options)?;
            flush_to(&mut out, &mut buf, &mut io_error);
            keep_lines(ctx, a.file, id, &diags)?;
        }
        None => {
            let (_, run) = post_and_run(ctx, a.file, a.dialect, &a.options, &mut sink)?;
            diags.extend(run);
            flush_to(&mut out, &mut buf, &mut io_error);
        }
    }
    out.flush()?;
    if let Some(e) = io_error {
        return Err(e.into());
    }
    ctx.print(&diags, a.format);
    Ok(if diags.iter().any(|d| d.is_error()) {
        EXIT_INPUT_ERRORS
    } else {
        EXIT_OK
    })
}
