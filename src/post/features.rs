//! `cncc port --features`: a program is run, raised to STEP-NC CC2
//! (machining features) and posted for the target with the target's own
//! feature cycles ([`super::post`]): a Fanuc program's explicit pocket
//! moves become one POCKET1/POCKET3 call on the 840D.
//!
//! Verification is on the features, not on the moves: the posted program
//! is run and raised to CC2 again and the two projects are compared with
//! [`crate::stepnc::diff::diff_projects`] (by meaning: instance numbers
//! aside). Both sides are raised with the same project name, and the
//! second with a tool table made from the first project's tools under the
//! numbers the post gave them (so tool names and sizes agree). What is
//! compared: every feature (kind, placement, depth, profile, sizes), every
//! operation (kind, technology, planes, strategy), every tool and the
//! workplan's workingsteps. Nothing is ignored: a difference, however
//! small, is reported.

use super::plan::{self, Item};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::tooltable::{Tool as TableTool, ToolTable};
use crate::ir::LengthUnit;
use crate::raise::{raise_events, RaiseOptions};
use crate::span::FileId;
use crate::stepnc::diff::{diff_projects, DiffReport};
use crate::stepnc::model::Project;
use crate::toolpath::Tracker;
use std::rc::Rc;

/// The outcome of comparing the features of the source and the port.
#[derive(Debug)]
pub struct FeatureVerdict {
    /// The port raises to the same features.
    pub same: bool,
    /// Number of workingsteps compared.
    pub workingsteps: usize,
    /// The differences (`- only in source`, `+ only in port`, `~ changed`).
    pub lines: Vec<String>,
}

/// Raises `posted` (a program in `target`, registered as `id`) to CC2
/// again and compares it with `source`, the project it was posted from.
/// `run` are the run options of the source (limits, units).
pub fn verify_features(
    source: &Project,
    posted: &str,
    id: FileId,
    target: &DialectSpec,
    run: &crate::interp::Options,
    opts: &RaiseOptions,
) -> Result<FeatureVerdict, Vec<Diagnostic>> {
    let (program, read) = crate::driver::read_program(posted, id, target);
    let mut errors: Vec<Diagnostic> = read.into_iter().filter(Diagnostic::is_error).collect();
    if !errors.is_empty() {
        return Err(errors);
    }
    let table = tool_table_of(source).map_err(|e| vec![e.into_diagnostic()])?;
    let mut run = run.clone();
    run.tool_table = table.clone();
    run.machine_units = LengthUnit::Mm;
    let mut tracker = Tracker::new();
    let mut events = Vec::new();
    let mut sink = |call: crate::canon::Canon, span| tracker.push(&call, span, |e| events.push(e));
    let mut loader = crate::interp::flow::NoLoader;
    let diags = crate::interp::run(Rc::new(program), target, &run, &mut loader, &mut sink);
    errors.extend(diags.into_iter().filter(Diagnostic::is_error));
    if !errors.is_empty() {
        return Err(errors);
    }
    let again = RaiseOptions {
        tool_table: table,
        table_units: LengthUnit::Mm,
        ..opts.clone()
    };
    let raised = raise_events(&events, &again);
    let (a, steps) = tools_by_number(source);
    let (b, _) = tools_by_number(&raised.project);
    let report: DiffReport = diff_projects(&a, &b);
    Ok(FeatureVerdict {
        same: report.same,
        workingsteps: steps,
        lines: report.lines,
    })
}

/// A copy of `project` whose tools are named `T<n>` by the number the
/// post gives them (the source's own numbers are not carried), with the
/// number of workingsteps posted.
fn tools_by_number(project: &Project) -> (Project, usize) {
    let mut named = project.clone();
    let Ok(items) = plan::plan(project) else {
        return (named, 0);
    };
    let mut steps = 0;
    for it in &items {
        let Item::Step(s) = it else { continue };
        steps += 1;
        if let Some(t) = named.tools.get_mut(s.op.tool.index()) {
            t.id = format!("T{}", s.tool_no);
        }
    }
    (named, steps)
}

/// The tools of `project` as a table (mm) under the numbers the post
/// gives them (order of first use), named as in the project.
pub fn tool_table_of(project: &Project) -> Result<ToolTable, super::PostError> {
    let items = plan::plan(project).map_err(|mut e| e.remove(0))?;
    let mut table = ToolTable::default();
    for it in &items {
        let Item::Step(s) = it else { continue };
        if table.get(s.tool_no as i64).is_some() {
            continue;
        }
        let mut offset = [0.0; 9];
        offset[2] = super::step::tool_length(s.tool);
        table.tools.push(TableTool {
            number: s.tool_no as i64,
            pocket: s.tool_no as i64,
            offset,
            diameter: s.tool.body.dimension.diameter,
            front_angle: 0.0,
            back_angle: 0.0,
            orientation: 0,
            comment: table_comment(&s.tool.id, s.tool_no),
        });
    }
    Ok(table)
}

/// The raiser names a tool `T<n> <comment>`: give back the source's
/// comment so the names agree.
fn table_comment(id: &str, n: u32) -> String {
    match id.split_once(' ') {
        Some((t, rest)) if t.starts_with('T') => rest.to_string(),
        _ => format!("{id} (T{n})"),
    }
}

/// The diagnostic for a port whose features differ.
pub fn mismatch(v: &FeatureVerdict) -> Diagnostic {
    let first = v.lines.first().cloned().unwrap_or_default();
    Diagnostic::new(
        Code::FeaturesMismatch,
        format!("the port raises to other features: {first}"),
    )
    .help("the port is not written; port without --features, or report the program")
}
