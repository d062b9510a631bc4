//! `cncc stepnc FILE`: a Part 21 file is re-written normalised (one
//! instance a line, depth-first numbering from the project, shared value
//! objects, canonical spellings); a program would be raised into STEP-NC
//! (not built in this tree). Also the Part 21 side of `cncc check`.

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK, EXIT_USAGE};
use crate::cli::output::{emit_output_with, summary_line};
use crate::diag::{Diagnostic, Severity};
use crate::stepnc;
use std::path::Path;

pub struct StepncArgs<'a> {
    pub file: &'a Path,
    pub output: Option<&'a Path>,
    pub format: Format,
    /// Print the readable listing (`--summary`) instead of Part 21.
    pub summary: bool,
    /// Options given that only apply to raising a program (named, for a
    /// note when the file is Part 21).
    pub raising_options: Vec<&'static str>,
}

pub fn run(ctx: &mut Context, a: StepncArgs<'_>) -> Result<i32, Failure> {
    let head = crate::cli::check::read_head(a.file)?;
    if !stepnc::is_part21(a.file, &head) {
        // RAISE: the lead wires `crate::raise::raise_file(...)` here.
        eprintln!(
            "error: {}: raising programs into STEP-NC is not built in this tree; \
             `cncc stepnc` re-writes Part 21 files (.stp, .p21, .stpnc, .step)",
            a.file.display()
        );
        return Ok(EXIT_USAGE);
    }
    if !a.raising_options.is_empty() {
        eprintln!(
            "note: ignored for a Part 21 file (they apply when raising a program): {}",
            a.raising_options.join(", ")
        );
    }
    let mut r = stepnc::read_file(a.file, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", a.file.display())))?;
    ctx.print(&r.diagnostics, a.format);
    // Only the header is needed from here on.
    let header = std::mem::take(&mut r.graph.header);
    drop(r.graph);
    let Some(project) = r.project else {
        summary(&r.diagnostics, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    };
    if a.summary {
        crate::cli::output::emit_output(a.output, &crate::raise::summary::summary(&project))
            .map_err(|e| Failure(format!("cannot write: {e}")))?;
        return Ok(EXIT_OK);
    }
    emit_output_with(a.output, |out| {
        stepnc::write_project_to(&project, &header, out)
    })
    .map_err(|e| Failure(format!("cannot write: {e}")))?;
    Ok(EXIT_OK)
}

/// `cncc check FILE.stp`: every diagnostic of reading the file.
pub fn check_file(ctx: &mut Context, path: &Path) -> Result<Vec<Diagnostic>, Failure> {
    let r = stepnc::read_file(path, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    Ok(r.diagnostics)
}

fn summary(diags: &[Diagnostic], format: Format) {
    if format != Format::Human {
        return;
    }
    let errors = diags
        .iter()
        .filter(|d| d.severity == Severity::Error)
        .count();
    let warnings = diags
        .iter()
        .filter(|d| d.severity == Severity::Warning)
        .count();
    if let Some(s) = summary_line(errors, warnings, 0) {
        eprintln!("{s}");
    }
}
