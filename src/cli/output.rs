//! Writing results: whole or not at all, and diagnostics to stderr.

use crate::cli::args::{ColorChoice, Format};
use crate::cli::atomic::AtomicFile;
use crate::diag::{render, Diagnostic};
use crate::source::SourceMap;
use std::io::{IsTerminal, Write};
use std::path::Path;

/// Writes `text` to `path` through a temporary file in the same folder,
/// renamed into place, so a failed run never leaves half a program.
pub fn write_atomically(path: &Path, text: &str) -> std::io::Result<()> {
    write_bytes_atomically(path, text.as_bytes())
}

/// [`write_atomically`] for bytes (pictures).
pub fn write_bytes_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let mut tmp = AtomicFile::create(path)?;
    tmp.file().write_all(bytes).map_err(|e| named(path, e))?;
    tmp.commit()
}

/// The error with the output's path in it.
fn named(path: &Path, e: std::io::Error) -> std::io::Error {
    std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
}

/// Writes the result to the output file, or to stdout.
pub fn emit_output(output: Option<&Path>, text: &str) -> std::io::Result<()> {
    match output {
        Some(p) => write_atomically(p, text),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(text.as_bytes())?;
            out.flush()
        }
    }
}

/// [`emit_output`] for bytes already encoded.
pub fn emit_output_bytes(output: Option<&Path>, bytes: &[u8]) -> std::io::Result<()> {
    match output {
        Some(p) => write_bytes_atomically(p, bytes),
        None => {
            let mut out = std::io::stdout().lock();
            out.write_all(bytes)?;
            out.flush()
        }
    }
}

/// Like [`emit_output`], for output written piece by piece by `write`
/// (into a temporary file renamed at the end, or stdout).
pub fn emit_output_with(
    output: Option<&Path>,
    write: impl FnOnce(&mut dyn Write) -> std::io::Result<()>,
) -> std::io::Result<()> {
    match output {
        Some(path) => {
            let mut tmp = AtomicFile::create(path)?;
            let mut out = std::io::BufWriter::new(tmp.file());
            write(&mut out)
                .and_then(|()| out.flush())
                .map_err(|e| named(path, e))?;
            drop(out);
            tmp.commit()
        }
        None => {
            let mut out = std::io::BufWriter::new(std::io::stdout().lock());
            write(&mut out)?;
            out.flush()
        }
    }
}

/// Prints diagnostics on stderr in the chosen format.
pub fn print_diagnostics(
    diags: &[Diagnostic],
    files: &SourceMap,
    format: Format,
    color: ColorChoice,
) {
    if diags.is_empty() {
        return;
    }
    let text = match format {
        Format::Json => render::json(diags, files),
        Format::Sarif => crate::diag::sarif::sarif(diags, files),
        Format::Human => {
            let use_color = match color {
                ColorChoice::Always => true,
                ColorChoice::Never => false,
                ColorChoice::Auto => std::io::stderr().is_terminal(),
            };
            render::human(diags, files, use_color)
        }
    };
    let _ = std::io::stderr().lock().write_all(text.as_bytes());
}

/// The one-line summary after human diagnostics.
pub fn summary_line(errors: usize, warnings: usize, dropped: usize) -> Option<String> {
    if errors == 0 && warnings == 0 {
        return None;
    }
    let mut s = format!(
        "{errors} error{}, {warnings} warning{}",
        plural(errors),
        plural(warnings)
    );
    if dropped > 0 {
        s.push_str(&format!(" ({dropped} more not shown)"));
    }
    Some(s)
}

fn plural(n: usize) -> &'static str {
    if n == 1 {
        ""
    } else {
        "s"
    }
}
