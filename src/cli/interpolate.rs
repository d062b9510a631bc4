//! `cncc interpolate FILE`: the set-points of a program or STEP-NC plan at
//! a fixed sampling period (CSV: time, position, path speed) or its
//! reference pulses per axis and period at the BLU resolution (see
//! [`crate::interpolate`]). Written while the program runs.

use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::stats::{keep_lines_at, load_tool_table, stream_events};
use crate::diag::{Code, Diagnostic};
use crate::interp::Options;
use crate::interpolate::{Interpolator, Sample, Settings};
use std::io::Write;
use std::path::Path;

/// What is written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Form {
    /// `t,x,y,z,speed`: seconds, mm, mm/min.
    Csv,
    /// `period,x,y,z`: pulses per axis in each period.
    Pulses,
}

pub struct InterpolateArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub output: Option<&'a Path>,
    pub period: &'a str,
    pub settings: Settings,
    pub form: Form,
    pub options: Options,
}

/// `1ms`, `250us`, `0.002s` as seconds.
pub fn parse_period(text: &str) -> Result<f64, Failure> {
    let t = text.trim();
    let (num, scale) = if let Some(n) = t.strip_suffix("ms") {
        (n, 1e-3)
    } else if let Some(n) = t.strip_suffix("us") {
        (n, 1e-6)
    } else if let Some(n) = t.strip_suffix('s') {
        (n, 1.0)
    } else {
        return Err(Failure(format!(
            "--period {text}: give a unit, as in 1ms, 250us or 0.002s"
        )));
    };
    match num.trim().parse::<f64>() {
        Ok(v) if v > 0.0 && v.is_finite() && v * scale >= 1e-6 => Ok(v * scale),
        _ => Err(Failure(format!(
            "--period {text}: a period of at least 1us"
        ))),
    }
}

fn check_settings(s: &Settings) -> Result<(), Failure> {
    if !(s.blu > 0.0 && s.blu.is_finite()) {
        return Err(Failure("--blu must be a positive number of mm".into()));
    }
    if !(s.accel >= 0.0 && s.accel.is_finite()) {
        return Err(Failure(
            "--accel must be zero (no limit) or a positive number of mm/s²".into(),
        ));
    }
    if !(s.jerk >= 0.0 && s.jerk.is_finite()) {
        return Err(Failure(
            "--jerk must be zero (no limit) or a positive number of mm/s³".into(),
        ));
    }
    if !(s.corner_tolerance >= 0.0 && s.corner_tolerance.is_finite()) {
        return Err(Failure(
            "--corner-tolerance must be zero (stop at corners) or a positive number of mm".into(),
        ));
    }
    if s.lookahead > 100_000 {
        return Err(Failure(
            "--lookahead: at most 100000 moves (the window is held in memory)".into(),
        ));
    }
    if !(s.rapid_rate > 0.0 && s.rapid_rate.is_finite()) {
        return Err(Failure(
            "--rapid-rate must be a positive number of mm/min".into(),
        ));
    }
    Ok(())
}

fn write_sample(out: &mut dyn Write, form: Form, s: &Sample) -> std::io::Result<()> {
    match form {
        Form::Csv => writeln!(
            out,
            "{:.6},{:.6},{:.6},{:.6},{:.3}",
            s.time, s.position[0], s.position[1], s.position[2], s.speed
        ),
        Form::Pulses => writeln!(
            out,
            "{},{},{},{}",
            s.index, s.pulses[0], s.pulses[1], s.pulses[2]
        ),
    }
}

pub fn run(ctx: &mut Context, mut a: InterpolateArgs<'_>) -> Result<i32, Failure> {
    a.settings.period = parse_period(a.period)?;
    check_settings(&a.settings)?;
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    let mut failure = None;
    let mut summary = None;
    let written = crate::cli::output::emit_output_with(a.output, |out| {
        let header = match a.form {
            Form::Csv => "t,x,y,z,speed",
            Form::Pulses => "period,x,y,z",
        };
        writeln!(out, "{header}")?;
        let mut io_error = None;
        let mut interp = Interpolator::new(a.settings, |s: &Sample| {
            if io_error.is_none() {
                if let Err(e) = write_sample(out, a.form, s) {
                    io_error = Some(e);
                }
            }
        });
        let streamed = stream_events(ctx, a.file, a.dialect, &a.options, true, |e| interp.push(e));
        let error = interp.error.take();
        let moves = interp.moves;
        let time = interp.finish();
        if let Some(e) = io_error {
            return Err(e);
        }
        match streamed {
            Ok((id, d)) => {
                let stops = d.iter().any(Diagnostic::is_error) || error.is_some();
                if let Some(e) = error {
                    diags.push(
                        Diagnostic::new(
                            Code::NoFeedRate,
                            format!("cannot interpolate {}: no speed to move at", e.why),
                        )
                        .primary(e.span, "this move"),
                    );
                }
                keep_lines_at(ctx, a.file, id, &d, &[])
                    .map_err(|Failure(m)| std::io::Error::other(m))?;
                diags.extend(d);
                summary = Some((moves, time));
                if stops {
                    return Err(std::io::Error::other("the run stopped"));
                }
                Ok(())
            }
            Err(f) => {
                failure = Some(f);
                Err(std::io::Error::other("not run"))
            }
        }
    });
    if let Some(f) = failure {
        return Err(f);
    }
    ctx.print(&diags, crate::cli::args::Format::Human);
    if diags.iter().any(Diagnostic::is_error) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    written.map_err(|e| Failure(format!("cannot write: {e}")))?;
    if let Some((moves, time)) = summary {
        eprintln!(
            "interpolated {moves} moves: {time:.3} s at {} s a period",
            a.settings.period
        );
    }
    Ok(EXIT_OK)
}
