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
use crate::interp::Options;
use crate::post::features::{mismatch, verify_features};
use crate::raise::{raise_file, Level, RaiseOptions, Stock};
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
    let posted = match crate::post::post(&raised.project, &target) {
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
        let verdict = verify_features(
            &raised.project,
            &posted.text,
            out_id,
            &target,
            &f.options,
            &opts,
        );
        let ok = match verdict {
            Err(errs) => {
                diags.extend(errs);
                eprintln!("verify: FAILED: the posted program does not read back or run");
                false
            }
            Ok(v) if v.same => {
                eprintln!(
                    "verify: OK: the same {} feature(s) and tools, machined in the same order; {} difference(s) in operations and workingsteps (not compared)",
                    v.features,
                    v.notes.len()
                );
                true
            }
            Ok(v) => {
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
