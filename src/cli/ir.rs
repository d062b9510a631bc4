//! `cncc ir`: the meta-model of a program as stable readable text.

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::driver::read_program;
use crate::ir::print::print_program;
use std::path::Path;

pub fn run(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    format: Format,
) -> Result<i32, Failure> {
    let (id, text) = ctx.add_file(path)?;
    let (spec, reason) = ctx.spec_for(dialect, path, &text)?;
    if let Some(r) = reason {
        report_detection(path, &spec, &r);
    }
    let (program, diags) = read_program(&text, id, &spec);
    ctx.print(&diags, format);
    if diags.iter().any(|d| d.is_error()) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    crate::cli::output::emit_output(None, &print_program(&program))?;
    Ok(EXIT_OK)
}
