//! `cncc stepnc PROGRAM`: run a program and raise it to STEP-NC (CC1
//! explicit toolpaths by default, `--cc2` machining features). With
//! `--summary` the readable listing of the project is printed instead of
//! Part 21 ([`crate::stepnc::write_project`]).

use crate::cli::args::Format;
use crate::cli::check::{keep_lines, read_head};
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::output::{emit_output, emit_output_with};
use crate::cli::tool_table;
use crate::interp::Options;
use crate::raise::{raise_file, summary::summary, Level, RaiseOptions, Stock};
use std::path::Path;

pub struct RaiseArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub stock: Option<&'a str>,
    pub cc2: bool,
    pub summary: bool,
    pub output: Option<&'a Path>,
    pub format: Format,
    pub options: Options,
}

pub fn run(ctx: &mut Context, mut a: RaiseArgs<'_>) -> Result<i32, Failure> {
    let stock = match a.stock {
        Some(s) => Some(Stock::parse(s).map_err(|e| Failure(format!("--stock: {e}")))?),
        None => None,
    };
    let head = read_head(a.file)?;
    let (spec, reason) = ctx.spec_for(a.dialect, a.file, &head)?;
    if let Some(r) = reason {
        report_detection(a.file, &spec, &r);
    }
    let mut diags = Vec::new();
    if let Some(t) = a.tool_table {
        let (table, d) = tool_table::load(ctx, t, a.options.machine_units)?;
        diags.extend(d);
        a.options.tool_table = table;
    }
    a.options = crate::cli::check::program_tools(&a.options, &head, &spec);
    let name = a
        .file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "PROGRAM".into());
    let opts = RaiseOptions {
        stock,
        tool_table: a.options.tool_table.clone(),
        table_units: a.options.machine_units,
        level: if a.cc2 { Level::Cc2 } else { Level::Cc1 },
        name,
    };
    let id = ctx
        .files
        .add_sparse(a.file.display().to_string(), Vec::new());
    let raised = raise_file(a.file, id, &spec, &a.options, &opts, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", a.file.display())))?;
    diags.extend(raised.diagnostics);
    keep_lines(ctx, a.file, id, &diags)?;
    ctx.print(&diags, a.format);
    if diags.iter().any(|d| d.is_error()) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    let written = if a.summary {
        emit_output(a.output, &summary(&raised.project))
    } else {
        // Streamed: the Part 21 text of a large program is never held whole.
        emit_output_with(a.output, |out| {
            crate::stepnc::write_owned_project_to(raised.project, &[], out)
        })
    };
    written.map_err(|e| Failure(format!("writing the output: {e}")))?;
    Ok(EXIT_OK)
}
