//! `cncc query FILE.stp PATH`: prints the values an attribute path
//! reaches in a STEP-NC file, one a line (see `crate::stepnc::query`).
//! A path that names no attribute is a usage error (exit 2, E0810).

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::diag::{Code, Diagnostic};
use crate::stepnc;
use std::path::Path;

pub fn run(ctx: &mut Context, file: &Path, path: &str, format: Format) -> Result<i32, Failure> {
    let r = stepnc::read_file(file, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", file.display())))?;
    // A query reads the instance graph: syntax and reference errors stop
    // it, model warnings do not.
    let blocking: Vec<Diagnostic> = r
        .diagnostics
        .iter()
        .filter(|d| {
            d.is_error()
                && matches!(
                    d.code,
                    Code::P21Syntax
                        | Code::P21UnreadableText
                        | Code::DanglingReference
                        | Code::P21Structure
                        | Code::DuplicateInstance
                )
        })
        .cloned()
        .collect();
    if !blocking.is_empty() {
        ctx.print(&blocking, format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    match stepnc::query::query(&r.graph, path) {
        Ok(lines) => {
            let mut text = lines.join("\n");
            if !text.is_empty() {
                text.push('\n');
            }
            crate::cli::output::emit_output(None, &text)?;
            Ok(EXIT_OK)
        }
        Err(msg) => Err(
            Diagnostic::new(Code::BadQueryPath, format!("bad path `{path}`: {msg}"))
                .help("a path is /ENTITY or /#n, then /attribute, [index] or [*] steps")
                .into(),
        ),
    }
}
