//! `cncc diff A B`: what two programs (any dialects) cut differently, by
//! [`crate::compare`]: cutting moves, holes, tools, feeds and speeds,
//! grouped by operation (tool), with the source line on both sides.
//! Exit 0 when they cut the same, 1 when not (or when one cannot be run).
//!
//! Two STEP-NC files are compared by the STEP-NC diff (see
//! [`is_stepnc`]). A STEP-NC file and a program are compared by what they
//! cut: the plan is posted and run (see [`crate::cli::stepnc_input`]),
//! `--dialect-a`/`--dialect-b` naming the post's target for it.

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::diff_side_by_side;
use crate::cli::stats::{keep_lines_at, load_tool_table, stream_events};
use crate::compare::{compare_ops, CompareOptions, Comparison, DiffKind, Difference, OpBuilder};
use crate::interp::Options;
use crate::source::SourceMap;
use crate::span::Span;
use std::fmt::Write;
use std::path::Path;

pub struct DiffArgs<'a> {
    pub a: &'a Path,
    pub b: &'a Path,
    pub dialect_a: Option<&'a str>,
    pub dialect_b: Option<&'a str>,
    pub tolerance: f64,
    pub feeds: bool,
    pub rapids: bool,
    pub tool_table: Option<&'a Path>,
    pub format: Format,
    pub options: Options,
}

/// Is this file STEP-NC (Part 21): by extension or its first line?
pub fn is_stepnc(path: &Path) -> bool {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase());
    if matches!(ext.as_deref(), Some("stp" | "p21" | "stpnc" | "step")) {
        return true;
    }
    let mut head = [0u8; 64];
    let n = std::fs::File::open(path)
        .and_then(|mut f| std::io::Read::read(&mut f, &mut head))
        .unwrap_or(0);
    String::from_utf8_lossy(&head[..n])
        .trim_start()
        .starts_with("ISO-10303-21;")
}

pub fn run(ctx: &mut Context, mut a: DiffArgs<'_>) -> Result<i32, Failure> {
    match (is_stepnc(a.a), is_stepnc(a.b)) {
        (true, true) => return stepnc_diff(ctx, a.a, a.b, a.format),
        (true, false) | (false, true) | (false, false) => {}
    }
    if !(a.tolerance > 0.0 && a.tolerance.is_finite()) {
        return Err(Failure(
            "--tolerance must be a positive number of mm".into(),
        ));
    }
    let opts = CompareOptions {
        tolerance_mm: a.tolerance,
        compare_feeds: a.feeds,
        compare_rapids: a.rapids,
    };
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    let builder = || match opts.compare_rapids {
        true => OpBuilder::new(opts.tolerance_mm),
        false => OpBuilder::without_rapids(opts.tolerance_mm),
    };
    let (ida, idb, c, da, db) = if is_stepnc(a.a) || is_stepnc(a.b) {
        // A plan is posted first, and held whole.
        let mut ba = builder();
        let (ida, da) = stream_events(ctx, a.a, a.dialect_a, &a.options, true, |e| ba.push(e))?;
        let mut bb = builder();
        let (idb, db) = stream_events(ctx, a.b, a.dialect_b, &a.options, true, |e| bb.push(e))?;
        let (oa, ob) = (ba.finish(), bb.finish());
        (ida, idb, compare_ops(&oa, &ob, &opts), da, db)
    } else {
        let pa = program(ctx, a.a, a.dialect_a)?;
        let pb = program(ctx, a.b, a.dialect_b)?;
        let (ida, idb) = (pa.id, pb.id);
        let r = diff_side_by_side::compare(ctx, (pa, pb), &a.options, &opts)?;
        (ida, idb, r.comparison, r.a, r.b)
    };
    let spans = |pick: fn(&Difference) -> Option<Span>| -> Vec<Span> {
        c.differences
            .iter()
            .chain(&c.rapid_differences)
            .filter_map(pick)
            .collect()
    };
    keep_lines_at(ctx, a.a, ida, &da, &spans(|d| d.a))?;
    keep_lines_at(ctx, a.b, idb, &db, &spans(|d| d.b))?;
    diags.extend(da);
    diags.extend(db);
    ctx.print(&diags, a.format);
    if diags.iter().any(|d| d.is_error()) {
        eprintln!("error: the programs could not be run to the end; not compared");
        return Ok(EXIT_INPUT_ERRORS);
    }
    let text = match a.format {
        Format::Human => human(&ctx.files, &c, [a.a, a.b]),
        Format::Json | Format::Sarif => json(&ctx.files, &c),
    };
    crate::cli::output::emit_output(None, &text)?;
    Ok(if c.same { EXIT_OK } else { EXIT_INPUT_ERRORS })
}

/// A program file to run side by side: its dialect (detected and said
/// where not given) and its id, registered sparse as `stream_events` does.
fn program<'p>(
    ctx: &mut Context,
    path: &'p Path,
    dialect: Option<&str>,
) -> Result<diff_side_by_side::Program<'p>, Failure> {
    let head = crate::cli::check::read_head(path)?;
    let (spec, reason) = ctx.spec_for(dialect, path, &head)?;
    if let Some(r) = reason {
        crate::cli::context::report_detection(path, &spec, &r);
    }
    let id = ctx.files.add_sparse(path.display().to_string(), Vec::new());
    Ok(diff_side_by_side::Program { path, id, spec })
}

/// `file:line: text` of the line a span starts on.
pub fn source_line(files: &SourceMap, s: Span) -> String {
    let (line, _) = files.line_col(s.file, s.start as usize);
    format!("{}:{line}: {}", files.name(s.file), line_text(files, s))
}

fn line_text(files: &SourceMap, s: Span) -> String {
    let view = files.text(s.file);
    let v = files.to_view(s.file, s.start as usize).min(view.len());
    let start = view[..v].rfind('\n').map(|i| i + 1).unwrap_or(0);
    let end = view[v..].find('\n').map(|i| v + i).unwrap_or(view.len());
    view[start..end].trim_end_matches('\r').to_string()
}

fn kind_name(k: DiffKind) -> &'static str {
    match k {
        DiffKind::Cuts => "cuts differ",
        DiffKind::Tool => "tool differs",
        DiffKind::Feed => "feed differs",
        DiffKind::Spindle => "spindle differs",
        DiffKind::Dwell => "dwell differs",
        DiffKind::Rapids => "rapids differ",
    }
}

fn side(out: &mut String, files: &SourceMap, label: &str, s: Option<Span>) {
    let _ = match s {
        Some(s) => writeln!(out, "    {label} {}", source_line(files, s)),
        None => writeln!(out, "    {label} (nothing here)"),
    };
}

/// The report for people, grouped by operation (tool).
fn human(files: &SourceMap, c: &Comparison, paths: [&Path; 2]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "A: {} ({} operations)\nB: {} ({} operations)",
        paths[0].display(),
        c.ops_a,
        paths[1].display(),
        c.ops_b
    );
    let mut all: Vec<&Difference> = c.differences.iter().chain(&c.rapid_differences).collect();
    all.sort_by_key(|d| (d.a_ops.start, d.b_ops.start, d.kind == DiffKind::Rapids));
    let mut group = None;
    for d in all {
        let g = (d.group_a, d.tool_a, d.group_b, d.tool_b);
        if group != Some(g) {
            group = Some(g);
            let _ = writeln!(
                out,
                "\noperation {} (T{}) in A, operation {} (T{}) in B:",
                d.group_a, d.tool_a, d.group_b, d.tool_b
            );
        }
        let note = if d.kind == DiffKind::Rapids {
            " (not counted)"
        } else {
            ""
        };
        let _ = writeln!(out, "  {}{note}: {}", kind_name(d.kind), d.what);
        side(&mut out, files, "A", d.a);
        side(&mut out, files, "B", d.b);
    }
    let n = c.differences.len();
    let _ = writeln!(
        out,
        "\n{}{}{}",
        if c.same {
            "same: the programs cut the same".to_string()
        } else {
            format!("different: {n} difference{}", if n == 1 { "" } else { "s" })
        },
        if c.rapid_differences.is_empty() {
            String::new()
        } else {
            let n = c.rapid_differences.len();
            format!(
                "; {n} rapid difference{} listed",
                if n == 1 { "" } else { "s" }
            )
        },
        if c.truncated {
            " (stopped early: too many differences)"
        } else {
            ""
        }
    );
    out
}

fn json(files: &SourceMap, c: &Comparison) -> String {
    let place = |s: Option<Span>| {
        s.map(|s| {
            let (line, col) = files.line_col(s.file, s.start as usize);
            serde_json::json!({"file": files.name(s.file), "line": line, "column": col, "text": line_text(files, s)})
        })
    };
    let one = |d: &Difference| {
        serde_json::json!({
            "kind": kind_name(d.kind),
            "what": d.what,
            "a": place(d.a),
            "b": place(d.b),
            "operation_a": d.group_a, "tool_a": d.tool_a,
            "operation_b": d.group_b, "tool_b": d.tool_b,
        })
    };
    let v = serde_json::json!({
        "same": c.same,
        "operations_a": c.ops_a,
        "operations_b": c.ops_b,
        "truncated": c.truncated,
        "differences": c.differences.iter().map(one).collect::<Vec<_>>(),
        "rapid_differences": c.rapid_differences.iter().map(one).collect::<Vec<_>>(),
    });
    let mut s = serde_json::to_string_pretty(&v).unwrap_or_default();
    s.push('\n');
    s
}

/// Two STEP-NC files: the semantic difference of their models
/// ([`crate::stepnc::diff`]), one line a difference; exit 0 same, 1 not.
fn stepnc_diff(
    ctx: &mut Context,
    a: &std::path::Path,
    b: &std::path::Path,
    format: Format,
) -> Result<i32, Failure> {
    match crate::stepnc::diff::diff_files(a, b) {
        Ok(report) => {
            for l in &report.lines {
                println!("{l}");
            }
            if report.same {
                println!("same: {} and {} say the same", a.display(), b.display());
                Ok(EXIT_OK)
            } else {
                println!("{} difference(s)", report.lines.len());
                Ok(EXIT_INPUT_ERRORS)
            }
        }
        Err(e) => {
            if let Some(io) = e.io {
                return Err(Failure(io));
            }
            ctx.files = e.files;
            ctx.print(&e.diagnostics, format);
            Ok(EXIT_INPUT_ERRORS)
        }
    }
}
