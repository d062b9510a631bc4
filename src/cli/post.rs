//! `cncc post FILE.stp --to D [-o OUT]`: a STEP-NC feature file becomes a
//! program for the target, with its canned cycles. Nothing is written
//! unless the whole program could be posted and read back cleanly.

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::diag::Diagnostic;
use crate::span::FileId;
use crate::stepnc::model::Project;
use crate::stepnc::part21::P21File;
use crate::stepnc::query::locate_diagnostics;
use std::path::Path;

/// What `post` is asked besides the file and target.
pub struct Options {
    /// `--profiles-absolute`.
    pub profiles_absolute: bool,
    /// `--summary`: list what each workingstep became.
    pub summary: bool,
}

pub fn run(
    ctx: &mut Context,
    file: &Path,
    to: &str,
    output: Option<&Path>,
    format: Format,
    opts: Options,
) -> Result<i32, Failure> {
    let target = ctx.spec(to)?;
    let (id, text) = ctx.add_file(file)?;
    let (mut project, graph) = match read_project(ctx, &text, id, format) {
        Ok(p) => p,
        Err(diags) => {
            ctx.print(&diags, format);
            return Ok(EXIT_INPUT_ERRORS);
        }
    };
    if opts.profiles_absolute {
        crate::post::validate::profiles_absolute(&mut project);
    }
    match crate::post::post_with(&project, &target, ctx.post_dir.as_ref()) {
        Ok(mut posted) => {
            locate_diagnostics(&graph, &mut posted.warnings);
            ctx.print(&posted.warnings, format);
            if opts.summary {
                print_summary(&posted.summary, &target.name);
                if output.is_none() {
                    return Ok(EXIT_OK);
                }
            }
            crate::cli::output::emit_output(output, &posted.text)
                .map_err(|e| Failure(format!("cannot write the program: {e}")))?;
            Ok(EXIT_OK)
        }
        Err(mut diags) => {
            locate_diagnostics(&graph, &mut diags);
            ctx.print(&diags, format);
            Ok(EXIT_INPUT_ERRORS)
        }
    }
}

/// `--summary`: a line per workingstep.
fn print_summary(steps: &[crate::post::summary::PostedStep], target: &str) {
    println!("posted for {target}:");
    for s in steps {
        println!("  {}", s.line());
    }
}

/// Reads a Part 21 file into the model: warnings are printed, errors
/// end the command.
fn read_project(
    ctx: &Context,
    text: &str,
    file: FileId,
    format: Format,
) -> Result<(Project, P21File), Vec<Diagnostic>> {
    let read = crate::stepnc::read_text(text, file);
    match read.project {
        Some(p) if !read.diagnostics.iter().any(Diagnostic::is_error) => {
            ctx.print(&read.diagnostics, format);
            Ok((p, read.graph))
        }
        _ => Err(read.diagnostics),
    }
}
