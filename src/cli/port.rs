//! `cncc port`: read a program in one dialect, write it in another (or the
//! same one). Nothing is written unless the whole program could be.

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::driver::read_program;
use crate::emit::write_program;
use std::path::Path;

pub struct PortArgs<'a> {
    pub file: &'a Path,
    pub to: &'a str,
    pub from: Option<&'a str>,
    pub output: Option<&'a Path>,
    pub format: Format,
}

pub fn run(ctx: &mut Context, a: PortArgs<'_>) -> Result<i32, Failure> {
    let target = ctx.spec(a.to)?;
    let (id, text) = ctx.add_file(a.file)?;
    let (spec, reason) = ctx.spec_for(a.from, a.file, &text)?;
    if let Some(r) = reason {
        report_detection(a.file, &spec, &r);
    }
    let (program, diags) = read_program(&text, id, &spec);
    if diags.iter().any(|d| d.is_error()) {
        ctx.print(&diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    match write_program(&program, &target) {
        Ok(out) => {
            ctx.print(&diags, a.format);
            crate::cli::output::emit_output(a.output, &out)?;
            Ok(EXIT_OK)
        }
        Err(errs) => {
            let mut all = diags;
            all.extend(errs);
            ctx.print(&all, a.format);
            Ok(EXIT_INPUT_ERRORS)
        }
    }
}
