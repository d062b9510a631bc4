//! `cncc ir`: the meta-model of a program as stable readable text.

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::driver::read_blocks;
use crate::ir::print::print_block;
use std::path::Path;

pub fn run(
    ctx: &mut Context,
    path: &Path,
    dialect: Option<&str>,
    format: Format,
) -> Result<i32, Failure> {
    // The text is kept once, in the file map (for the diagnostics).
    let text = crate::cli::context::read_text_limited(path, crate::cli::context::MAX_INPUT)?;
    let id = ctx.files.add(path.display().to_string(), text);
    let text = ctx.files.text(id);
    let (spec, reason) = ctx.spec_for(dialect, path, text)?;
    if let Some(r) = reason {
        report_detection(path, &spec, &r);
    }
    // Two reads, neither holding the program: the first finds the
    // diagnostics (nothing is printed when one is an error), the second
    // prints each block as it is read.
    let diags = read_blocks(text, id, &spec, |_, _| {});
    ctx.print(&diags, format);
    if diags.iter().any(|d| d.is_error()) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    crate::cli::output::emit_output_with(None, |out| {
        let mut result = Ok(());
        read_blocks(text, id, &spec, |b, exprs| {
            if result.is_ok() {
                result = writeln!(out, "{}", print_block(b, exprs));
            }
        });
        result
    })?;
    Ok(EXIT_OK)
}
