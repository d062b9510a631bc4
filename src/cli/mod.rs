//! The `cncc` command line: argument parsing and one module per command.

pub mod args;
pub mod atomic;
pub mod canon;
pub mod check;
pub mod context;
pub mod diff;
pub mod diff_material;
pub mod diff_side_by_side;
pub mod info;
pub mod interpolate;
pub mod ir;
pub mod memory;
pub mod output;
pub mod plot;
pub mod port;
pub mod port_features;
pub mod port_material;
pub mod post;
pub mod query;
pub mod raise;
pub mod rs274_config;
pub mod simulate;
pub mod stats;
pub mod stepnc;
pub mod stepnc_input;
pub mod tool_table;

use args::{Cli, Command, Format};
use context::{Context, Failure, EXIT_USAGE};

/// Runs a parsed command line; returns the exit code.
pub fn run(cli: Cli) -> i32 {
    let format = match &cli.command {
        Command::Check { format, .. }
        | Command::Ir { format, .. }
        | Command::Port { format, .. }
        | Command::Post { format, .. }
        | Command::Canon { format, .. }
        | Command::Stepnc { format, .. }
        | Command::Query { format, .. }
        | Command::Stats { format, .. }
        | Command::Diff { format, .. }
        | Command::Plot { format, .. }
        | Command::Simulate { format, .. } => *format,
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
            stock,
            lint,
            config,
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
                stock: stock.as_deref(),
                lint: (!lint.no_lint).then(|| lint.selection()),
                options: run.analysis_options(),
                config: config.files(),
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
            tool_map,
            expand_cycles,
            strict,
            verify,
            material,
            features,
            tool_table,
            stock,
            format,
            run,
        } => port::run(
            &mut ctx,
            port::PortArgs {
                file,
                to,
                from: from.as_deref(),
                output: output.as_deref(),
                tool_map: tool_map.as_deref(),
                expand_cycles: *expand_cycles,
                strict: *strict,
                options: run.analysis_options(),
                verify: *verify,
                material: (*material && !*features).then(|| port_material::MaterialArgs {
                    tool_table: tool_table.as_deref(),
                    stock: stock.as_deref(),
                }),
                side_options: !*features && !*material && (tool_table.is_some() || stock.is_some()),
                format: *format,
                features: features.then(|| port_features::FeatureArgs {
                    tool_table: tool_table.as_deref(),
                    stock: stock.as_deref(),
                    options: run.options(),
                }),
            },
        ),
        Command::Post {
            file,
            to,
            output,
            format,
            profiles_absolute,
            summary,
        } => post::run(
            &mut ctx,
            file,
            to,
            output.as_deref(),
            *format,
            post::Options {
                profiles_absolute: *profiles_absolute,
                summary: *summary,
            },
        ),
        Command::Canon {
            file,
            dialect,
            tool_table,
            format,
            config,
            run,
        } => canon::run(
            &mut ctx,
            canon::CanonArgs {
                file,
                dialect: dialect.as_deref(),
                tool_table: tool_table.as_deref(),
                format: *format,
                config: config.files(),
                options: run.options(),
            },
        ),
        Command::Stepnc {
            file,
            dialect,
            tool_table,
            stock,
            cc1: _,
            cc2,
            summary,
            output,
            format,
            run,
        } if !is_step_file(file) => raise::run(
            &mut ctx,
            raise::RaiseArgs {
                file,
                dialect: dialect.as_deref(),
                tool_table: tool_table.as_deref(),
                stock: stock.as_deref(),
                cc2: *cc2,
                summary: *summary,
                output: output.as_deref(),
                format: *format,
                options: run.analysis_options(),
            },
        ),
        Command::Stats {
            file,
            dialect,
            tool_table,
            rapid_rate,
            tool_change_time,
            format,
            run,
        } => stats::run(
            &mut ctx,
            stats::StatsArgs {
                file,
                dialect: dialect.as_deref(),
                tool_table: tool_table.as_deref(),
                rapid_rate: *rapid_rate,
                tool_change_time: *tool_change_time,
                format: *format,
                options: run.analysis_options(),
            },
        ),
        Command::Diff {
            a,
            b,
            dialect_a,
            dialect_b,
            material: true,
            stock,
            resolution,
            material_tolerance,
            tool_table,
            format,
            run,
            ..
        } => diff_material::run(
            &mut ctx,
            diff_material::MaterialArgs {
                files: [a, b],
                dialects: [dialect_a.as_deref(), dialect_b.as_deref()],
                stock: stock.as_deref(),
                resolution: *resolution,
                tolerance: *material_tolerance,
                tool_table: tool_table.as_deref(),
                format: *format,
                options: run.analysis_options(),
            },
        ),
        Command::Diff {
            a,
            b,
            dialect_a,
            dialect_b,
            tolerance,
            no_feeds,
            rapids,
            tool_table,
            format,
            run,
            ..
        } => diff::run(
            &mut ctx,
            diff::DiffArgs {
                a,
                b,
                dialect_a: dialect_a.as_deref(),
                dialect_b: dialect_b.as_deref(),
                tolerance: *tolerance,
                feeds: !*no_feeds,
                rapids: *rapids,
                tool_table: tool_table.as_deref(),
                format: *format,
                options: run.analysis_options(),
            },
        ),
        Command::Plot {
            files,
            output,
            dialect,
            views,
            stock,
            tool_table,
            width,
            format,
            run,
        } => plot::run(
            &mut ctx,
            plot::PlotArgs {
                files,
                output,
                dialect: dialect.as_deref(),
                views,
                stock: stock.as_deref(),
                tool_table: tool_table.as_deref(),
                width: *width,
                format: *format,
                options: run.analysis_options(),
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
            summary,
            ..
        } => stepnc::run(
            &mut ctx,
            stepnc::StepncArgs {
                file,
                output: output.as_deref(),
                format: *format,
                summary: *summary,
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
        Command::Interpolate {
            file,
            dialect,
            tool_table,
            period,
            blu,
            accel,
            jerk,
            rapid_rate,
            lookahead,
            corner_tolerance,
            format,
            output,
            run,
        } => interpolate::run(
            &mut ctx,
            interpolate::InterpolateArgs {
                file,
                dialect: dialect.as_deref(),
                tool_table: tool_table.as_deref(),
                output: output.as_deref(),
                period,
                settings: crate::interpolate::Settings {
                    period: 0.001,
                    blu: *blu,
                    accel: *accel,
                    jerk: *jerk,
                    rapid_rate: *rapid_rate,
                    lookahead: *lookahead,
                    corner_tolerance: *corner_tolerance,
                },
                form: *format,
                options: run.options(),
            },
        ),
        Command::Simulate {
            file,
            dialect,
            stock,
            tool_table,
            resolution,
            output,
            ascii,
            width,
            rapid_rate,
            format,
            run,
        } => simulate::run(
            &mut ctx,
            simulate::SimulateArgs {
                file,
                dialect: dialect.as_deref(),
                stock: stock.as_deref(),
                tool_table: tool_table.as_deref(),
                resolution: *resolution,
                output: output.as_deref(),
                ascii: *ascii,
                width: *width,
                rapid_rate: *rapid_rate,
                format: *format,
                options: run.analysis_options(),
            },
        ),
        Command::Query { file, path, format } => query::run(&mut ctx, file, path, *format),
        Command::Dialects {
            spec,
            templates,
            output,
        } => match (templates, output) {
            (Some(id), Some(dir)) => info::copy_templates(&ctx, id, dir),
            _ => info::dialects(&ctx, spec.as_deref()),
        },
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

/// Is this file STEP-NC Part 21 (by extension or its first line), rather
/// than a program?
fn is_step_file(path: &std::path::Path) -> bool {
    let head = check::read_head(path).unwrap_or_default();
    crate::stepnc::is_part21(path, &head)
}
