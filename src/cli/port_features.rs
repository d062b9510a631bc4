//! `cncc port FILE --to D --features`: run the program, raise it to
//! STEP-NC CC2 (machining features) and post the features with the
//! target's own cycles ([`crate::post::post`]). With `--verify` the posted
//! program is raised again and its features compared with the source's
//! ([`crate::post::features::verify_features`]); the port is written only
//! when they are the same. Tool numbers follow the post (first use = T1).

use crate::cli::check::{keep_lines, read_head};
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::cli::port::PortArgs;
use crate::cli::tool_table;
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::Options;
use crate::post::features::{mismatch, run_posted, source_tools, verify_events};
use crate::raise::{raise_file, Level, RaiseOptions, Stock};
use crate::sim::material::{self, MaterialVerdict, Side};
use crate::sim::{Cutter, Cutters};
use crate::span::FileId;
use crate::stepnc::model::Project;
use std::path::Path;

/// How many feature differences `--verify` prints.
const SHOWN: usize = 400;

/// The options only `--features` has.
pub struct FeatureArgs<'a> {
    pub tool_table: Option<&'a Path>,
    pub stock: Option<&'a str>,
    pub options: Options,
}

pub fn run(ctx: &mut Context, a: PortArgs<'_>) -> Result<i32, Failure> {
    let Some(mut f) = a.features else {
        return Err(Failure("port --features without its options".into()));
    };
    if a.tool_map.is_some() {
        return Err(Failure(
            "--tool-map does not apply to --features: the post numbers tools in order of use"
                .into(),
        ));
    }
    let target = ctx.spec(a.to)?;
    let stock = match f.stock {
        Some(s) => Some(Stock::parse(s).map_err(|e| Failure(format!("--stock: {e}")))?),
        None => None,
    };
    let head = read_head(a.file)?;
    let (spec, reason) = ctx.spec_for(a.from, a.file, &head)?;
    if let Some(r) = reason {
        report_detection(a.file, &spec, &r);
    }
    let mut diags = Vec::new();
    if let Some(t) = f.tool_table {
        let (table, d) = tool_table::load(ctx, t, f.options.machine_units)?;
        diags.extend(d);
        f.options.tool_table = table;
    }
    let opts = RaiseOptions {
        stock,
        tool_table: f.options.tool_table.clone(),
        table_units: f.options.machine_units,
        level: Level::Cc2,
        name: a
            .file
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| "PROGRAM".into()),
    };
    let id = ctx
        .files
        .add_sparse(a.file.display().to_string(), Vec::new());
    let raised = raise_file(a.file, id, &spec, &f.options, &opts, &mut ctx.files)
        .map_err(|e| Failure(format!("{}: {e}", a.file.display())))?;
    diags.extend(raised.diagnostics);
    keep_lines(ctx, a.file, id, &diags)?;
    if diags.iter().any(Diagnostic::is_error) {
        ctx.print(&diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    let posted = match crate::post::post_with(&raised.project, &target, ctx.post_dir.as_ref()) {
        Ok(p) => p,
        Err(errs) => {
            diags.extend(errs);
            ctx.print(&diags, a.format);
            return Ok(EXIT_INPUT_ERRORS);
        }
    };
    diags.extend(posted.warnings);
    if a.verify {
        let name = match a.output {
            Some(p) => p.display().to_string(),
            None => format!("{} (ported to {} by features)", a.file.display(), target.id),
        };
        let out_id = ctx.files.add(name, posted.text.clone());
        let ran = run_posted(&raised.project, &posted.text, out_id, &target, &f.options);
        let verdict = ran.map(|(events, table)| {
            let v = verify_events(&raised.project, &events, table.clone(), &opts);
            (v, table)
        });
        let verdict = match verdict {
            Ok((v, table)) => {
                let posted = (&raised.project, posted.text.as_str(), out_id, &*target);
                let m = by_material(ctx, (a.file, a.from), &f, posted, &head, &table)?;
                Ok((v, m))
            }
            Err(e) => Err(e),
        };
        let ok = match verdict {
            Err(errs) => {
                diags.extend(errs);
                eprintln!("verify: FAILED: the posted program does not read back or run");
                false
            }
            Ok((v, m)) if v.same => {
                eprintln!(
                    "verify: OK: the same {} feature(s) and tools, machined in the same order; {} difference(s) in operations and workingsteps (not compared)",
                    v.features,
                    v.notes.len()
                );
                material_verdict(&m, &mut diags)
            }
            Ok((v, m)) => {
                material_verdict(&m, &mut diags);
                eprintln!("verify: DIFFERENT: {} difference(s):", v.lines.len());
                for l in v.lines.iter().take(SHOWN) {
                    eprintln!("  {l}");
                }
                if v.lines.len() > SHOWN {
                    eprintln!("  ... and {} more", v.lines.len() - SHOWN);
                }
                diags.push(mismatch(&v));
                false
            }
        };
        ctx.print(&diags, a.format);
        if !ok {
            return Ok(EXIT_INPUT_ERRORS);
        }
    } else {
        ctx.print(&diags, a.format);
    }
    crate::cli::output::emit_output(a.output, &posted.text)?;
    Ok(EXIT_OK)
}

/// Prints the material comparison's outcome; true when the parts agree.
fn material_verdict(m: &MaterialVerdict, diags: &mut Vec<Diagnostic>) -> bool {
    if m.same() {
        eprintln!("verify: material: {}", material::summary(m));
        return true;
    }
    eprintln!(
        "verify: DIFFERENT by material: the port cuts another part (E1002: {} mm off)",
        crate::ir::num::short_text(m.comparison.largest, 3)
    );
    diags.push(material::diagnostic(m));
    false
}

/// The posted program: the project it was posted from, its text, its
/// file and its dialect.
type Posted<'a> = (&'a Project, &'a str, FileId, &'a DialectSpec);

/// Cuts the stock with the source (run again, as a stream) and with the
/// posted program (run with the post's `table`) and compares the parts
/// ([`crate::sim::material`]). Both run on the machine (`--machine`, else
/// the default one, as `simulate` does), so that reference returns stay
/// above the work. The posted tools cut with the source tools' shapes
/// (the post numbers them in order of use).
fn by_material(
    ctx: &mut Context,
    (file, from): (&Path, Option<&str>),
    f: &FeatureArgs<'_>,
    (project, text, out_id, target): Posted<'_>,
    head: &str,
    table: &crate::interp::tooltable::ToolTable,
) -> Result<MaterialVerdict, Failure> {
    let mut run = f.options.clone();
    run.machine.get_or_insert_with(Default::default);
    let posted = match run_posted(project, text, out_id, target, &run) {
        Ok((events, _)) => events,
        Err(_) => Vec::new(),
    };
    let posted = posted.as_slice();
    let mut events = Vec::new();
    let (id, _) =
        crate::cli::stats::stream_events(ctx, file, from, &run, false, |e| events.push(e.clone()))?;
    let mm = crate::cli::stats::machine_mm(&f.options);
    let source = Cutters::from_table(&f.options.tool_table, head, mm, false);
    let mut port = Cutters::default();
    for (n, from) in source_tools(project) {
        let c = match from {
            Some(s) => source.get(s),
            None => Cutter::from_tool(table.get(n), None, 1.0),
        };
        port.by_tool.insert(n, c);
    }
    let given = match f.stock {
        Some(s) => Some(s.parse().map_err(Failure)?),
        None => blank(ctx, file, from, head)?,
    };
    let sides = [
        Side {
            events: &events,
            cutters: source,
        },
        Side {
            events: posted,
            cutters: port,
        },
    ];
    let (stock, cell) = material::grid_for(&sides, given, None).map_err(Failure)?;
    let m = material::compare_runs(sides, &stock, cell, crate::sim::compare::TOLERANCE)
        .map_err(Failure)?;
    let spans: Vec<_> = m.made.iter().flatten().map(|(s, _)| *s).collect();
    crate::cli::stats::keep_lines_at(ctx, file, id, &[], &spans)?;
    Ok(m)
}

/// The source's own blank (`BLK FORM`), if it has one.
fn blank(
    ctx: &mut Context,
    path: &Path,
    from: Option<&str>,
    head: &str,
) -> Result<Option<crate::toolpath::Stock>, Failure> {
    let (spec, _) = ctx.spec_for(from, path, head)?;
    let file =
        std::fs::File::open(path).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    let id = ctx.files.add(String::new(), String::new());
    Ok(crate::toolpath::Stock::from_program(file, id, &spec).0)
}
