//! `cncc check`: read programs, report every problem, exit 1 on errors.
//! A clean program prints nothing.

use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::args::Format;
use crate::cli::output::summary_line;
use crate::diag::{Diagnostic, Severity};
use crate::driver::check_stream;
use std::fs::File;
use std::io::BufReader;
use std::path::Path;

pub fn run(ctx: &mut Context, files: &[std::path::PathBuf], dialect: Option<&str>, format: Format, verbose: bool) -> Result<i32, Failure> {
    let mut all = Vec::new();
    for path in files {
        all.extend(check_file(ctx, path, dialect, verbose)?);
    }
    ctx.print(&all, format);
    let errors = all.iter().filter(|d| d.severity == Severity::Error).count();
    let warnings = all.iter().filter(|d| d.severity == Severity::Warning).count();
    if format == Format::Human {
        if let Some(s) = summary_line(errors, warnings, 0) {
            eprintln!("{s}");
        }
    }
    Ok(if errors > 0 { EXIT_INPUT_ERRORS } else { EXIT_OK })
}

/// Streams one file through the reader; keeps only the lines diagnostics
/// point at, so memory does not grow with the file.
fn check_file(ctx: &mut Context, path: &Path, dialect: Option<&str>, verbose: bool) -> Result<Vec<Diagnostic>, Failure> {
    let head = read_head(path)?;
    let (spec, reason) = ctx.spec_for(dialect, path, &head)?;
    let input = BufReader::with_capacity(1 << 16, File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?);
    let id = ctx.files.add_sparse(path.display().to_string(), Vec::new());
    let result = check_stream(input, id, &spec, |_, _| {}).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let offsets: Vec<u32> = result
        .diagnostics
        .iter()
        .flat_map(|d| d.labels.iter())
        .filter(|l| l.span.file == id)
        .flat_map(|l| [l.span.start, l.span.end.saturating_sub(1).max(l.span.start)])
        .collect();
    let file = File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let lines = crate::driver::lines_at(BufReader::new(file), &offsets)?;
    ctx.files.set_sparse(id, lines);
    if let Some(r) = reason {
        if verbose || !result.diagnostics.is_empty() {
            report_detection(path, &spec, &r);
        }
    }
    Ok(result.diagnostics)
}

/// The first 64 KiB of a file, for dialect detection.
fn read_head(path: &Path) -> Result<String, Failure> {
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
