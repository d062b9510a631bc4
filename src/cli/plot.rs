//! `cncc plot FILE... -o OUT.svg|OUT.png`: draws one program, or two
//! overlaid with their differences marked (see [`crate::plot`]). Each
//! file is run once as a stream, so memory holds only the simplified
//! picture (and, for an overlay, the operations being
//! compared).

use crate::cli::args::Format;
use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::output::write_bytes_atomically;
use crate::cli::stats::{keep_lines_at, load_tool_table, machine_mm, stream_events};
use crate::compare::{compare_ops, CompareOptions, OpBuilder};
use crate::interp::Options;
use crate::plot::{legend, png, svg, Picture, Scene, View};
use crate::stats::Bounds;
use crate::toolpath::Stock;
use std::path::{Path, PathBuf};

pub struct PlotArgs<'a> {
    pub files: &'a [PathBuf],
    pub output: &'a Path,
    pub dialect: Option<&'a str>,
    pub views: &'a [String],
    pub stock: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub width: u32,
    pub format: Format,
    pub options: Options,
}

enum Kind {
    Svg,
    Png,
}

fn parse_args(a: &PlotArgs<'_>) -> Result<(Kind, Vec<View>, Option<Stock>), Failure> {
    let ext = a
        .output
        .extension()
        .and_then(|e| e.to_str())
        .map(|e| e.to_ascii_lowercase());
    let kind = match ext.as_deref() {
        Some("svg") => Kind::Svg,
        Some("png") => Kind::Png,
        _ => return Err(Failure("-o must name a .svg or .png file".into())),
    };
    let views = a
        .views
        .iter()
        .map(|v| {
            View::parse(v).ok_or_else(|| Failure(format!("unknown view `{v}`: use top, side, iso")))
        })
        .collect::<Result<Vec<_>, _>>()?;
    if views.is_empty() {
        return Err(Failure(
            "--views needs at least one of top, side, iso".into(),
        ));
    }
    if !(200..=16_000).contains(&a.width) {
        return Err(Failure(
            "--width must be between 200 and 16000 pixels".into(),
        ));
    }
    let stock = a
        .stock
        .map(str::parse::<Stock>)
        .transpose()
        .map_err(Failure)?;
    Ok((kind, views, stock))
}

pub fn run(ctx: &mut Context, mut a: PlotArgs<'_>) -> Result<i32, Failure> {
    let (kind, views, stock) = parse_args(&a)?;
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    if let Some(first) = a.files.first() {
        let head = crate::cli::check::read_head(first)?;
        let (spec, _) = ctx.spec_for(a.dialect, first, &head)?;
        a.options = crate::cli::check::program_tools(&a.options, &head, &spec);
        a.options = crate::cli::stepnc_input::with_plan_tools(first, &a.options);
    }
    let mut bounds = Bounds::default();
    if let Some(s) = stock {
        bounds.add(s.corner);
        bounds.add(s.max());
    }
    let overlay = a.files.len() > 1;
    let mut scene = Scene::new(views, a.width as f64, bounds);
    let mm = machine_mm(&a.options);
    let table = &a.options.tool_table;
    scene.diameters = table
        .tools
        .iter()
        .map(|t| (t.number, t.diameter * mm))
        .collect();
    // One pass per file: draw, and gather operations to compare an overlay.
    let copts = CompareOptions {
        compare_rapids: false,
        ..CompareOptions::default()
    };
    let mut ops = Vec::new();
    for (i, path) in a.files.iter().enumerate() {
        let mut builder = OpBuilder::without_rapids(copts.tolerance_mm);
        let (id, d) = stream_events(ctx, path, a.dialect, &a.options, true, |e| {
            scene.push(i, e);
            if overlay {
                builder.push(e);
            }
        })?;
        keep_lines_at(ctx, path, id, &d, &[])?;
        diags.extend(d);
        ops.push(builder.finish());
    }
    ctx.print(&diags, a.format);
    if diags.iter().any(|d| d.is_error()) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    scene.finish();
    let mut differences = None;
    if overlay {
        let c = compare_ops(&ops[0], &ops[1], &copts);
        scene.marks = c.differences.iter().filter_map(|d| d.region).collect();
        differences = Some(c.differences.len());
        eprintln!(
            "{}: {} difference{} marked",
            a.output.display(),
            c.differences.len(),
            if c.differences.len() == 1 { "" } else { "s" }
        );
    }
    drop(ops);
    let names: Vec<String> = a
        .files
        .iter()
        .map(|p| {
            p.file_name()
                .unwrap_or(p.as_os_str())
                .to_string_lossy()
                .into_owned()
        })
        .collect();
    let legend = legend::entries(
        &scene,
        &names,
        |t| table.get(t).map(|x| x.diameter * mm),
        differences,
    );
    let picture = Picture {
        layout: scene.layout(),
        scene,
        stock,
        legend,
        overlay,
    };
    let bytes = match kind {
        Kind::Svg => svg::render(&picture).into_bytes(),
        Kind::Png => png::render(&picture).map_err(Failure)?,
    };
    write_bytes_atomically(a.output, &bytes)
        .map_err(|e| Failure(format!("{}: {e}", a.output.display())))?;
    Ok(EXIT_OK)
}
