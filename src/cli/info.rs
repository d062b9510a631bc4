//! `cncc dialects` and `cncc explain`.

use crate::cli::context::{Context, Failure, EXIT_OK, EXIT_USAGE};
use crate::diag::Code;

/// Lists the known dialects, or with `spec` prints that built-in spec's
/// XML text exactly as it is built in.
pub fn dialects(ctx: &Context, spec: Option<&str>) -> Result<i32, Failure> {
    let text = match spec {
        None => crate::dialect::describe_all(&ctx.registry),
        Some(name) => match crate::dialect::builtin_source(name) {
            Some(text) => text.to_string(),
            None => {
                eprintln!(
                    "error: `{name}` is not a built-in dialect; built in: {}",
                    crate::dialect::BUILTIN_SOURCES
                        .iter()
                        .map(|(id, _, _)| *id)
                        .collect::<Vec<_>>()
                        .join(", ")
                );
                return Ok(EXIT_USAGE);
            }
        },
    };
    crate::cli::output::emit_output(None, &text)?;
    Ok(EXIT_OK)
}

/// Writes the post templates of dialect `name` (as `--post-dir`, if
/// given, and the built-in folders make them) into `dir`, keeping any file
/// already there.
pub fn copy_templates(ctx: &Context, name: &str, dir: &std::path::Path) -> Result<i32, Failure> {
    let spec = ctx.spec(name)?;
    let sources = match crate::post::templates_of(&spec, ctx.post_dir.as_ref()) {
        Ok(s) => s,
        Err(diags) => {
            ctx.print(&diags, crate::cli::args::Format::Human);
            return Ok(crate::cli::context::EXIT_INPUT_ERRORS);
        }
    };
    std::fs::create_dir_all(dir).map_err(|e| Failure(format!("{}: {e}", dir.display())))?;
    let (mut written, mut kept) = (0, 0);
    for s in sources {
        let path = dir.join(&s.file);
        if path.exists() {
            kept += 1;
            continue;
        }
        std::fs::write(&path, s.text.as_bytes())
            .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
        written += 1;
    }
    eprintln!(
        "{written} post templates of `{}` written to {}{}",
        spec.id,
        dir.display(),
        if kept > 0 {
            format!(" ({kept} already there kept)")
        } else {
            String::new()
        }
    );
    Ok(EXIT_OK)
}

pub fn explain(code: Option<&str>) -> Result<i32, Failure> {
    let text = match code {
        None => Code::ALL
            .iter()
            .map(|c| format!("{} {:<32} {}\n", c.code(), c.name(), c.summary()))
            .collect(),
        Some(c) => match Code::lookup(c) {
            Some(c) => format!(
                "{} {} ({})\n\n{}\n\n{}\n",
                c.code(),
                c.name(),
                severity_word(c),
                c.summary(),
                c.explanation()
            ),
            // A prefix (`W07`: the lint rules) lists the codes under it.
            None if Code::ALL.iter().any(|k| starts(k, c)) => Code::ALL
                .iter()
                .filter(|k| starts(k, c))
                .map(|k| {
                    format!(
                        "{} {:<36} {}{}\n",
                        k.code(),
                        k.name(),
                        k.summary(),
                        lint_default(*k)
                    )
                })
                .collect(),
            None => {
                eprintln!("error: no diagnostic code `{c}`; `cncc explain` lists them all");
                return Ok(EXIT_USAGE);
            }
        },
    };
    crate::cli::output::emit_output(None, &text)?;
    Ok(EXIT_OK)
}

fn starts(k: &Code, prefix: &str) -> bool {
    !prefix.is_empty() && k.code().starts_with(&prefix.trim().to_ascii_uppercase())
}

/// For a lint rule, whether it runs by default.
fn lint_default(c: Code) -> &'static str {
    match crate::lint::rules::rule(c) {
        Some(r) if r.default => " [lint, on by default]",
        Some(_) => " [lint, off by default]",
        None => "",
    }
}

fn severity_word(c: Code) -> &'static str {
    match c.severity() {
        crate::diag::Severity::Error => "error",
        crate::diag::Severity::Warning => "warning",
        crate::diag::Severity::Note => "note",
    }
}
