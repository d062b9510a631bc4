//! Running a STEP-NC plan: `canon`, `plot`, `stats` (and `interpolate`)
//! take a Part 21 file (`.stp`, `.step`, `.p21`, `.stpnc`, or any file
//! that starts with `ISO-10303-21;`) as they take a program.
//!
//! The plan is posted in memory with the same post as `cncc post` (to
//! LinuxCNC unless `--dialect` names another target) and the posted
//! program is run by cncc's interpreter. The canonical calls of a plan
//! are therefore by construction those of its post: what rs274 prints
//! for `cncc post FILE.stp --to linuxcnc`. A plan the post refuses gives
//! the post's diagnostics, located in the Part 21 file; the posted text is
//! registered in the source map (named `FILE.stp (posted for D)`) so that
//! a diagnostic of the run points into it.

use crate::cli::context::{Context, Failure};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::{file::run_text, Options, Sink};
use crate::span::FileId;
use std::path::Path;
use std::sync::Arc;

/// The target a plan is posted to for running, unless `--dialect` says.
pub const RUN_TARGET: &str = "linuxcnc";

/// Whether `path` is a STEP-NC Part 21 file (by extension or first word).
pub fn is_stepnc(path: &Path) -> Result<bool, Failure> {
    let head = crate::cli::check::read_head(path)?;
    Ok(crate::stepnc::is_part21(path, &head))
}

/// A plan posted for running.
pub struct PostedPlan {
    /// The posted program, registered whole in the source map.
    pub id: FileId,
    pub text: String,
    pub spec: Arc<DialectSpec>,
}

/// `options` with the tool sizes of the plan in `path` (when it is a
/// STEP-NC file) in its tool table, where the table does not give the
/// tool or is cncc's built-in one: what plots and statistics draw and
/// report with. The plan is read once more for this (quietly).
pub fn with_plan_tools(path: &Path, options: &Options) -> Options {
    let mut o = options.clone();
    if !is_stepnc(path).unwrap_or(false) {
        return o;
    }
    let Ok(text) = crate::cli::context::read_text(path) else {
        return o;
    };
    let Some(project) = crate::stepnc::read_text(&text, FileId(0)).project else {
        return o;
    };
    let per_mm = 1.0 / crate::cli::stats::machine_mm(options);
    let table = &mut o.tool_table;
    for (number, diameter, name) in plan_tools(&project) {
        if table.get(number).is_some() && !table.invented {
            continue;
        }
        table.tools.retain(|t| t.number != number);
        let mut t = crate::interp::tooltable::Tool::blank(number, name);
        t.diameter = diameter * per_mm;
        table.tools.push(t);
        table.from_program.insert(number);
    }
    o
}

/// The tools of a plan as the post numbers them.
fn plan_tools(project: &crate::stepnc::model::Project) -> Vec<(i64, f64, String)> {
    let mut out: Vec<(i64, f64, String)> = Vec::new();
    for item in crate::post::plan::plan(project).unwrap_or_default() {
        if let crate::post::plan::Item::Step(s) = item {
            let n = s.tool_no as i64;
            if !out.iter().any(|t| t.0 == n) {
                out.push((n, s.tool.body.dimension.diameter, s.tool.id.clone()));
            }
        }
    }
    out
}

/// What posting a plan gave: the program to run, or nothing (the
/// diagnostics say why). The diagnostics are the reader's and the post's,
/// located in the Part 21 file.
pub struct Prepared {
    pub plan: Option<PostedPlan>,
    pub diagnostics: Vec<Diagnostic>,
}

/// Reads and posts the plan in `path` for `target` (default
/// [`RUN_TARGET`]).
pub fn post_plan(
    ctx: &mut Context,
    path: &Path,
    target: Option<&str>,
) -> Result<Prepared, Failure> {
    let spec = ctx.spec(target.unwrap_or(RUN_TARGET))?;
    let read = crate::stepnc::read_file(path, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let mut diagnostics = read.diagnostics;
    let project = match read.project {
        Some(p) if !diagnostics.iter().any(Diagnostic::is_error) => p,
        _ => {
            return Ok(Prepared {
                plan: None,
                diagnostics,
            })
        }
    };
    let posted = crate::post::post_with(&project, &spec, ctx.post_dir.as_ref());
    drop(project);
    let (text, mut more) = match posted {
        Ok(p) => (Some(p.text), p.warnings),
        Err(d) => (None, d),
    };
    crate::stepnc::query::locate_diagnostics(&read.graph, &mut more);
    diagnostics.extend(more);
    let plan = text.map(|text| {
        let name = format!("{} (posted for {})", path.display(), spec.id);
        let id = ctx.files.add(name, text.clone());
        PostedPlan { id, text, spec }
    });
    Ok(Prepared { plan, diagnostics })
}

/// Runs a posted plan, every call to `sink`; the run's diagnostics.
/// Subprograms (none are posted today) would be looked for beside `path`.
pub fn run_plan(
    ctx: &mut Context,
    path: &Path,
    plan: &PostedPlan,
    options: &Options,
    sink: &mut Sink<'_>,
) -> Result<Vec<Diagnostic>, Failure> {
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    run_text(
        &plan.text,
        plan.id,
        &dir,
        &plan.spec,
        options,
        &mut ctx.files,
        sink,
    )
    .map_err(|e| Failure(format!("{}: {e}", path.display())))
}

/// Posts and runs the plan in `path`: the posted program's id (None when
/// the post refused the plan) and every diagnostic.
pub fn post_and_run(
    ctx: &mut Context,
    path: &Path,
    target: Option<&str>,
    options: &Options,
    sink: &mut Sink<'_>,
) -> Result<(Option<FileId>, Vec<Diagnostic>), Failure> {
    let Prepared {
        plan,
        mut diagnostics,
    } = post_plan(ctx, path, target)?;
    let Some(plan) = plan else {
        return Ok((None, diagnostics));
    };
    diagnostics.extend(run_plan(ctx, path, &plan, options, sink)?);
    Ok((Some(plan.id), diagnostics))
}
