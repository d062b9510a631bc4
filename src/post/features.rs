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
//! numbers the post gave them; tools are compared under those numbers.
//!
//! Compared (a difference fails): every feature (kind, placement, depth,
//! profile, sizes, bottom), every tool's diameter, and the order in which
//! the features are machined. Names (features are compared as `F1`, `F2`
//! in machining order, tools as the post numbers them) and tolerances are
//! not: a program does not carry them.
//! Not compared, but counted as notes: operations, workingsteps, the
//! workpiece and the rest of the tool data (teeth, hand of cut, taper,
//! material, clamping: nothing a program says). The target's cycle
//! legitimately machines a feature its own way: POCKET1 roughs and then
//! finishes what the source cut in one pass (one operation becomes two),
//! a cycle's technology (retract distances, first peck depth) is raised
//! from the cycle's own moves.

use super::plan::{self, Item};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::interp::tooltable::{Tool as TableTool, ToolTable};
use crate::ir::LengthUnit;
use crate::raise::{raise_events, RaiseOptions};
use crate::span::FileId;
use crate::stepnc::diff::{diff_projects, DiffReport};
use crate::stepnc::model::Project;
use crate::toolpath::{Event, Tracker};
use std::rc::Rc;

/// The outcome of comparing the features of the source and the port.
#[derive(Debug)]
pub struct FeatureVerdict {
    /// The port raises to the same features.
    pub same: bool,
    /// Number of features compared.
    pub features: usize,
    /// The differences (`- only in source`, `+ only in port`, `~ changed`).
    pub lines: Vec<String>,
    /// Differences in what is not compared (operations, workingsteps).
    pub notes: Vec<String>,
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
    let (events, table) = run_posted(source, posted, id, target, run)?;
    Ok(verify_events(source, &events, table, opts))
}

/// Runs `posted` (posted from `source`) with the tool table the post
/// numbered: its moves and that table.
pub fn run_posted(
    source: &Project,
    posted: &str,
    id: FileId,
    target: &DialectSpec,
    run: &crate::interp::Options,
) -> Result<(Vec<Event>, ToolTable), Vec<Diagnostic>> {
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
    Ok((events, table))
}

/// Raises the posted program's moves (`events`, run with `table`) to CC2
/// again and compares the features with `source`'s.
pub fn verify_events(
    source: &Project,
    events: &[Event],
    table: ToolTable,
    opts: &RaiseOptions,
) -> FeatureVerdict {
    let again = RaiseOptions {
        tool_table: table,
        table_units: LengthUnit::Mm,
        ..opts.clone()
    };
    let raised = raise_events(events, &again);
    compare_features(source, &raised.project)
}

/// The source tool number of each tool the post numbered (`T<n>` of the
/// raised tool's name), by the post's number.
pub fn source_tools(project: &Project) -> Vec<(i64, Option<i64>)> {
    let Ok(items) = plan::plan(project) else {
        return Vec::new();
    };
    let mut out: Vec<(i64, Option<i64>)> = Vec::new();
    for it in &items {
        let Item::Step(s) = it else { continue };
        let n = s.tool_no as i64;
        if out.iter().any(|(p, _)| *p == n) {
            continue;
        }
        let source = s
            .tool
            .id
            .split(' ')
            .next()
            .and_then(|t| t.strip_prefix('T'))
            .and_then(|t| t.parse().ok());
        out.push((n, source));
    }
    out
}

/// Compares the features of `a` (the source) and `b` (raised from its
/// post): see the module doc for what is compared.
pub fn compare_features(a: &Project, b: &Project) -> FeatureVerdict {
    let (a, order_a) = canonical(a);
    let (b, order_b) = canonical(b);
    let report: DiffReport = diff_projects(&a, &b);
    let (mut lines, notes): (Vec<String>, Vec<String>) =
        report.lines.into_iter().partition(|l| is_compared(l));
    if order_a != order_b {
        lines.push(format!(
            "~ the features are machined in another order: {} → {}",
            order_a.join(", "),
            order_b.join(", ")
        ));
    }
    FeatureVerdict {
        same: lines.is_empty(),
        features: order_a.len(),
        lines,
        notes,
    }
}

/// Whether a difference line (`± section / path ...`) is one that fails
/// the comparison: a feature's geometry (not its name, tolerances, owner
/// or list of operations) or a tool's diameter. Operations, workingsteps,
/// the workplan, the workpiece (material, clamping) and the rest of the
/// tools (teeth, hand of cut, taper) are not carried by a program: not
/// compared.
fn is_compared(line: &str) -> bool {
    let body = line.get(2..).unwrap_or("");
    let path_has = |p: &str| body.contains(p);
    let feature = body.starts_with("feature '")
        && !(path_has("/ its_operations")
            || path_has("/ its_workpiece")
            || path_has("/ name = ")
            || path_has("/ name: ")
            || path_has("/ its_id")
            || path_has("implicit_tolerance /"));
    let tool_size = body.starts_with("tool '") && path_has("/ dimension / diameter");
    feature || tool_size
}

/// A copy of `project` with its features named `F<k>` in the order they
/// are machined and its tools `T<n>` by the number the post gives them
/// (names and the source's tool numbers are not carried by a program),
/// with the features' original names in that order.
fn canonical(project: &Project) -> (Project, Vec<String>) {
    let mut named = project.clone();
    let Ok(items) = plan::plan(project) else {
        return (named, Vec::new());
    };
    let mut order: Vec<String> = Vec::new();
    for it in &items {
        let Item::Step(s) = it else { continue };
        if !order.contains(&s.feature.id) {
            order.push(s.feature.id.clone());
            let k = order.len();
            if let Some(f) = named.features.iter_mut().find(|f| f.id == s.feature.id) {
                f.id = format!("F{k}");
            }
        }
        if let Some(t) = named.tools.get_mut(s.op.tool.index()) {
            t.id = format!("T{}", s.tool_no);
        }
    }
    let kinds = order
        .iter()
        .enumerate()
        .map(|(k, _)| {
            let f = &named.features;
            let name = format!("F{}", k + 1);
            f.iter()
                .find(|x| x.id == name)
                .map(|x| format!("{name} {}", super::names::feature_kind(&x.kind)))
                .unwrap_or(name)
        })
        .collect();
    (named, kinds)
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

/// Posts `project` for `target` and raises the posted program to CC2
/// again (what `cncc post` then `cncc stepnc --cc2` do, with the tools of
/// `project` as the table): the posted text and how its features compare.
pub fn round_trip(
    project: &Project,
    target: &DialectSpec,
) -> Result<(String, FeatureVerdict), Vec<Diagnostic>> {
    let posted = super::post(project, target)?;
    let opts = RaiseOptions::new(crate::raise::Level::Cc2, project.id.clone());
    let run = crate::interp::Options::default();
    let v = verify_features(project, &posted.text, FileId(0), target, &run, &opts)?;
    Ok((posted.text, v))
}
