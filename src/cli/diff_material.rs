//! `cncc diff --material A B`: both programs cut the same stock on the
//! same grid ([`crate::sim`]); the parts are compared cell by cell
//! ([`crate::sim::compare`]): the largest deviation and where, the box of
//! the cells that differ, the volume each removed. Exit 0 when no cell
//! differs by more than the tolerance (default 0.01 mm), 1 otherwise.

use crate::cli::context::{Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::simulate::{cell_for, cut, survey};
use crate::cli::stats::{load_tool_table, machine_mm};
use crate::diag::Diagnostic;
use crate::interp::Options;
use crate::sim::compare::compare;
use crate::sim::material::guess_stock;
use crate::sim::{Cutters, HeightField, Simulation, Watch};
use crate::toolpath::Stock;
use std::path::Path;

pub struct MaterialArgs<'a> {
    pub files: [&'a Path; 2],
    pub dialects: [Option<&'a str>; 2],
    pub stock: Option<&'a str>,
    pub resolution: Option<f64>,
    pub tolerance: f64,
    pub tool_table: Option<&'a Path>,
    pub format: crate::cli::args::Format,
    pub options: Options,
}

pub fn run(ctx: &mut Context, mut a: MaterialArgs<'_>) -> Result<i32, Failure> {
    if !(a.tolerance >= 0.0 && a.tolerance.is_finite()) {
        return Err(Failure("--material-tolerance must be mm, 0 or more".into()));
    }
    let mut diags = load_tool_table(ctx, a.tool_table, &mut a.options)?;
    let mut runs = Vec::new();
    for k in 0..2 {
        let head = crate::cli::check::read_head(a.files[k])?;
        let (spec, _) = ctx.spec_for(a.dialects[k], a.files[k], &head)?;
        let opts = crate::cli::check::program_tools(&a.options, &head, &spec);
        let s = survey(ctx, a.files[k], a.dialects[k], &opts)?;
        diags.extend(s.diags.iter().cloned());
        let mm = machine_mm(&opts);
        let table = crate::sim::tool_defs::with_tool_defs(&opts.tool_table, &s.head, &spec, mm);
        let cutters = Cutters::from_table(&table, &s.head, mm, false);
        runs.push((opts, s, cutters));
    }
    ctx.print(&diags, a.format);
    if diags.iter().any(Diagnostic::is_error) {
        return Ok(EXIT_INPUT_ERRORS);
    }
    let stock = match a.stock {
        Some(t) => t.parse::<Stock>().map_err(Failure)?,
        None => match runs.iter().find_map(|r| r.1.blank) {
            Some(b) => b,
            None => {
                let mut bx: Option<[[f64; 3]; 2]> = None;
                let mut r = 0.0f64;
                for (_, s, c) in &runs {
                    for t in &s.tools {
                        r = r.max(c.get(*t).radius);
                    }
                    if let Some(b) = s.feed_box {
                        let u = bx.get_or_insert(b);
                        for k in 0..3 {
                            u[0][k] = u[0][k].min(b[0][k]);
                            u[1][k] = u[1][k].max(b[1][k]);
                        }
                    }
                }
                let b = bx.ok_or_else(|| Failure("neither program cuts: give --stock".into()))?;
                guess_stock(b, r)
            }
        },
    };
    let cell = (0..2)
        .map(|k| cell_for(a.resolution, &stock, &runs[k].1.tools, &runs[k].2))
        .fold(f64::MAX, f64::min);
    let mut fields = Vec::new();
    for (k, (opts, _, cutters)) in runs.iter().enumerate() {
        let sim = Simulation::new(
            HeightField::new(&stock, cell).map_err(Failure)?,
            cutters.clone(),
        );
        let sim = cut(ctx, a.files[k], a.dialects[k], opts, sim)?;
        fields.push(sim.field);
    }
    let c = compare(&fields[0], &fields[1], a.tolerance).map_err(Failure)?;
    let f = &fields[0];
    println!(
        "material: grid {} x {} cells of {:.4} x {:.4} mm, tolerance {} mm",
        f.nx, f.ny, f.dx, f.dy, a.tolerance
    );
    println!(
        "removed: A {:.1} mm3, B {:.1} mm3; A only {:.1} mm3, B only {:.1} mm3",
        c.removed[0], c.removed[1], c.only[0], c.only[1]
    );
    if c.same(a.tolerance) {
        println!(
            "the parts are the same (largest deviation {:.4} mm)",
            c.largest
        );
        return Ok(EXIT_OK);
    }
    println!(
        "the parts differ: largest deviation {:.3} mm at X{:.3} Y{:.3} (A at Z{:.3}, B at Z{:.3})",
        c.largest, c.at[0], c.at[1], c.heights[0], c.heights[1]
    );
    if let Some(r) = c.region {
        println!(
            "{} cells differ, within X{:.3}..{:.3} Y{:.3}..{:.3}",
            c.cells, r[0], r[2], r[1], r[3]
        );
    }
    let Some(cell_at) = f.cell_at(c.at[0], c.at[1]) else {
        return Ok(EXIT_INPUT_ERRORS);
    };
    for (k, (opts, _, cutters)) in runs.iter().enumerate() {
        let mut sim = Simulation::new(
            HeightField::new(&stock, cell).map_err(Failure)?,
            cutters.clone(),
        );
        sim.watch = Some(Watch {
            cell: cell_at,
            last: None,
        });
        let sim = cut(ctx, a.files[k], a.dialects[k], opts, sim)?;
        let who = ["A", "B"][k];
        match sim.watch.and_then(|w| w.last) {
            Some((span, z)) => {
                let (line, text) = line_of(ctx, span);
                println!("{who}: line {line} cut there last, to Z{z:.3}: {text}");
            }
            None => println!("{who}: no move cuts there"),
        }
    }
    Ok(EXIT_INPUT_ERRORS)
}

/// The line number and text of a span's first line.
fn line_of(ctx: &Context, span: crate::span::Span) -> (usize, String) {
    let (line, _) = ctx.files.line_col(span.file, span.start as usize);
    let text = ctx.files.text(span.file);
    let v = ctx
        .files
        .to_view(span.file, span.start as usize)
        .min(text.len());
    let start = text[..v].rfind('\n').map_or(0, |k| k + 1);
    let end = text[v..].find('\n').map_or(text.len(), |k| v + k);
    (line, text[start..end].trim().to_string())
}
