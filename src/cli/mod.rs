//! The `cncc` command line: argument parsing and one module per command.

pub mod args;
pub mod canon;
pub mod check;
pub mod context;
pub mod info;
pub mod ir;
pub mod output;
pub mod port;
pub mod query;
pub mod stepnc;

use args::{Cli, Command, Format};
use context::{Context, Failure, EXIT_USAGE};

/// Runs a parsed command line; returns the exit code.
pub fn run(cli: Cli) -> i32 {
    let format = match &cli.command {
        Command::Check { format, .. }
        | Command::Ir { format, .. }
        | Command::Port { format, .. }
        | Command::Canon { format, .. }
        | Command::Stepnc { format, .. }
        | Command::Query { format, .. } => *format,
        _ => Format::Human,
    };
    let mut ctx = match Context::new(&cli, format) {
        Ok(c) => c,
        Err(code) => return code,
    };
    let result = match &cli.command {
        Command::Check {
            files,
            dialect,
            format,
            verbose,
            tool_table,
            no_run,
            run,
        } => check::run(
            &mut ctx,
            check::CheckArgs {
                files,
                dialect: dialect.as_deref(),
                format: *format,
                verbose: *verbose,
                tool_table: tool_table.as_deref(),
                run: !*no_run,
                options: run.options(),
            },
        ),
        Command::Ir {
            file,
            dialect,
            format,
        } => ir::run(&mut ctx, file, dialect.as_deref(), *format),
        Command::Port {
            file,
            to,
            from,
            output,
            format,
        } => port::run(
            &mut ctx,
            port::PortArgs {
                file,
                to,
                from: from.as_deref(),
                output: output.as_deref(),
                format: *format,
            },
        ),
        Command::Canon {
            file,
            dialect,
            tool_table,
            format,
            run,
        } => canon::run(
            &mut ctx,
            canon::CanonArgs {
                file,
                dialect: dialect.as_deref(),
                tool_table: tool_table.as_deref(),
                format: *format,
                options: run.options(),
            },
        ),
        Command::Stepnc {
            file,
            output,
            format,
            cc1,
            cc2,
            stock,
            dialect,
            tool_table,
        } => stepnc::run(
            &mut ctx,
            stepnc::StepncArgs {
                file,
                output: output.as_deref(),
                format: *format,
                raising_options: [
                    (*cc1, "--cc1"),
                    (*cc2, "--cc2"),
                    (stock.is_some(), "--stock"),
                    (dialect.is_some(), "--dialect"),
                    (tool_table.is_some(), "--tool-table"),
                ]
                .into_iter()
                .filter_map(|(given, name)| given.then_some(name))
                .collect(),
            },
        ),
        Command::Query { file, path, format } => query::run(&mut ctx, file, path, *format),
        Command::Dialects => info::dialects(&ctx),
        Command::Explain { code } => info::explain(code.as_deref()),
    };
    match result {
        Ok(code) => code,
        Err(Failure(msg)) => {
            eprintln!("error: {msg}");
            EXIT_USAGE
        }
    }
}
