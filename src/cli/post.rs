//! `cncc post FILE.stp --to D [-o OUT]`: a STEP-NC feature file becomes a
//! program for the target, with its canned cycles. Nothing is written
//! unless the whole program could be posted and read back cleanly.

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::diag::Diagnostic;
use crate::span::FileId;
use crate::stepnc::model::Project;
use std::path::Path;

pub fn run(
    ctx: &mut Context,
    file: &Path,
    to: &str,
    output: Option<&Path>,
    format: Format,
) -> Result<i32, Failure> {
    let target = ctx.spec(to)?;
    let (id, text) = ctx.add_file(file)?;
    let project = match read_project(&text, id)? {
        Ok(p) => p,
        Err(diags) => {
            ctx.print(&diags, format);
            return Ok(EXIT_INPUT_ERRORS);
        }
    };
    match crate::post::post(&project, &target) {
        Ok(posted) => {
            ctx.print(&posted.warnings, format);
            crate::cli::output::emit_output(output, &posted.text)
                .map_err(|e| Failure(format!("cannot write the program: {e}")))?;
            Ok(EXIT_OK)
        }
        Err(diags) => {
            ctx.print(&diags, format);
            Ok(EXIT_INPUT_ERRORS)
        }
    }
}

/// Reads a Part 21 file into the model. The reader is being written on
/// another branch (`stepio`); until it is merged, this is a usage error
/// that says so rather than a guess.
fn read_project(_text: &str, _file: FileId) -> Result<Result<Project, Vec<Diagnostic>>, Failure> {
    Err(Failure(
        "reading STEP-NC (Part 21) files is not available in this build yet: the reader is not merged".into(),
    ))
}
