//! `cncc dialects` and `cncc explain`.

use crate::cli::context::{Context, Failure, EXIT_OK, EXIT_USAGE};
use crate::diag::Code;

pub fn dialects(ctx: &Context) -> Result<i32, Failure> {
    crate::cli::output::emit_output(None, &crate::dialect::describe_all(&ctx.registry))?;
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
            None => {
                eprintln!("error: no diagnostic code `{c}`; `cncc explain` lists them all");
                return Ok(EXIT_USAGE);
            }
        },
    };
    crate::cli::output::emit_output(None, &text)?;
    Ok(EXIT_OK)
}

fn severity_word(c: Code) -> &'static str {
    match c.severity() {
        crate::diag::Severity::Error => "error",
        crate::diag::Severity::Warning => "warning",
        crate::diag::Severity::Note => "note",
    }
}
