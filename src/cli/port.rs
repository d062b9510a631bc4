//! `cncc port`: read a program in one dialect, turn it into the target's
//! forms ([`crate::port`]), write it with the target's writer and, with
//! `--verify`, prove that it cuts the same. Nothing is written unless the
//! whole program could be (and, with `--verify`, was proved the same).
//! `--features` ports through STEP-NC features ([`crate::cli::port_features`]).

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::driver::{read_program, FsLoader};
use crate::emit::write_program_warned;
use crate::ir::Program;
use crate::port::stream::{self, Chunking};
use crate::port::subload::PortingLoader;
use crate::port::verify::{self, Difference, Verdict};
use crate::port::verify_lockstep::{self, Side};
use crate::port::verify_text;
use crate::port::{port_owned, PortOptions, ToolMap};
use crate::span::Span;
use std::path::Path;
use std::rc::Rc;
use std::sync::Arc;

pub struct PortArgs<'a> {
    pub file: &'a Path,
    pub to: &'a str,
    pub from: Option<&'a str>,
    pub output: Option<&'a Path>,
    pub tool_map: Option<&'a str>,
    pub expand_cycles: bool,
    /// Refuse instead of writing a construct as the moves it makes.
    pub strict: bool,
    /// How programs run for the expansion and the proof.
    pub options: crate::interp::Options,
    pub verify: bool,
    /// `--verify --material` (without `--features`): compare the parts too.
    pub material: Option<crate::cli::port_material::MaterialArgs<'a>>,
    /// `--stock` or `--tool-table` given without `--features`/`--material`.
    pub side_options: bool,
    pub format: Format,
    /// `--features`: port through STEP-NC features instead.
    pub features: Option<crate::cli::port_features::FeatureArgs<'a>>,
}

pub fn run(ctx: &mut Context, mut a: PortArgs<'_>) -> Result<i32, Failure> {
    if a.side_options {
        return Err(Failure(
            "--stock and --tool-table need --features or --verify --material".into(),
        ));
    }
    if a.features.is_some() {
        return crate::cli::port_features::run(ctx, a);
    }
    let target = ctx.spec(a.to)?;
    let mut table_diags = Vec::new();
    if let Some(m) = &a.material {
        table_diags = crate::cli::port_material::load_table(ctx, m, &mut a.options)?;
    }
    let tool_map = match a.tool_map {
        Some(m) => ToolMap::from_arg(m).map_err(|why| {
            Failure::from(
                Diagnostic::new(Code::BadToolMap, format!("--tool-map: {why}"))
                    .help("write pairs OLD=NEW separated by commas, e.g. 1=5,2=7"),
            )
        })?,
        None => ToolMap::default(),
    };
    let opts = PortOptions {
        tool_map,
        expand_cycles: a.expand_cycles,
        tool_names: tool_names(&a.options),
    };
    let (id, text, encoding) = ctx.add_file_encoded(a.file)?;
    let (spec, reason) = ctx.spec_for(a.from, a.file, &text)?;
    if let Some(r) = reason {
        report_detection(a.file, &spec, &r);
    }
    let mut diags = table_diags;
    let proof = match &a.material {
        Some(m) => Some(crate::cli::port_material::Proof::new(
            m, &a.options, &text, id, &spec, &mut diags,
        )?),
        None => None,
    };
    if diags.iter().any(|d| d.is_error()) {
        ctx.print(&diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    let streamed = (text.len() >= STREAM_FROM_BYTES)
        .then(|| stream::port_text(&text, id, &spec, &target, &opts, Chunking::default()))
        .flatten();
    let mut scan = None;
    let (out, expanded) = match streamed {
        Some(s) => {
            diags.extend(s.read);
            diags.extend(s.port);
            scan = Some(s.scan);
            (s.text, false)
        }
        None => match whole(ctx, &a, (&text, id, &spec), &target, &opts, &mut diags) {
            Ok(done) => done,
            Err(code) => return Ok(code),
        },
    };
    finish(
        ctx,
        &a,
        (&text, id, &spec, scan),
        &target,
        &opts,
        proof.as_ref(),
        out,
        expanded,
        diags,
        encoding,
    )
}

/// Programs from this size (bytes) are ported as a stream where they can
/// be ([`stream`]); below it the whole port is as cheap.
const STREAM_FROM_BYTES: usize = 1 << 20;

/// The port of the program held whole: the text and whether cycles were
/// expanded, or the exit code (the diagnostics printed).
fn whole(
    ctx: &mut Context,
    a: &PortArgs<'_>,
    source: (&str, crate::span::FileId, &Arc<DialectSpec>),
    target: &Arc<DialectSpec>,
    opts: &PortOptions,
    diags: &mut Vec<Diagnostic>,
) -> Result<(String, bool), i32> {
    let (text, id, spec) = source;
    let (program, read) = read_program(text, id, spec);
    diags.extend(read);
    if diags.iter().any(|d| d.is_error()) {
        ctx.print(diags, a.format);
        return Err(EXIT_INPUT_ERRORS);
    }
    let dir = a.file.parent().map(Path::to_path_buf).unwrap_or_default();
    // The port works on the program in place; where it is needed again
    // (the fallback, the proof) it is read again from the source text,
    // so a large program is never held twice.
    let reread = || read_program(text, id, spec).0;
    let first = attempt(ctx, &dir, program, spec, target, opts);
    match first {
        Ok((out, d)) => {
            diags.extend(d);
            Ok((out, false))
        }
        Err(errors) if a.strict => {
            diags.extend(errors);
            ctx.print(diags, a.format);
            Err(EXIT_INPUT_ERRORS)
        }
        Err(errors) => {
            let mut scratch = crate::source::SourceMap::new();
            let mut loader = FsLoader::new(dir.clone(), spec.clone(), &mut scratch);
            let tried = crate::port::expand_range::legalize(
                &reread(),
                text,
                spec,
                target,
                &a.options,
                &mut loader,
                errors,
                |p| attempt(ctx, &dir, p.clone(), spec, target, opts),
            );
            match tried {
                Ok(((out, d), notes)) => {
                    diags.extend(notes);
                    diags.extend(d);
                    Ok((out, true))
                }
                Err(errors) => {
                    diags.extend(errors);
                    ctx.print(diags, a.format);
                    Err(EXIT_INPUT_ERRORS)
                }
            }
        }
    }
}

/// Proves the port where asked (or where cycles were expanded), prints
/// the diagnostics and writes the output.
#[allow(clippy::too_many_arguments)]
fn finish(
    ctx: &mut Context,
    a: &PortArgs<'_>,
    source: (
        &str,
        crate::span::FileId,
        &Arc<DialectSpec>,
        Option<verify_text::Scan>,
    ),
    target: &Arc<DialectSpec>,
    opts: &PortOptions,
    proof: Option<&crate::cli::port_material::Proof>,
    mut out: String,
    expanded: bool,
    mut diags: Vec<Diagnostic>,
    encoding: crate::encoding::SourceEncoding,
) -> Result<i32, Failure> {
    let (text, id, spec, scan) = source;
    if a.verify || expanded {
        let name = match a.output {
            Some(p) => p.display().to_string(),
            None => format!("{} (ported to {})", a.file.display(), target.id),
        };
        let dir = a.file.parent().map(Path::to_path_buf).unwrap_or_default();
        let sides = Sides {
            dir: &dir,
            run: &a.options,
            source: (text, id, spec),
            source_scan: scan,
            target,
            opts,
            material: proof,
        };
        // The output is read back from the source map (its diagnostics
        // point there), not held twice.
        let out_id = ctx.files.add(name, std::mem::take(&mut out));
        crate::cli::memory::release_freed();
        let ok = verify_port(ctx, sides, out_id, &mut diags);
        if std::env::var_os("CNCC_DEBUG_PORT").is_some() {
            eprintln!("{}", ctx.files.text(out_id));
        }
        ctx.print(&diags, a.format);
        if !ok {
            return Ok(EXIT_INPUT_ERRORS);
        }
        out = ctx.files.take_text(out_id);
    } else {
        ctx.print(&diags, a.format);
    }
    // Written as the source was: comment bytes, BOM, line ends.
    let bytes = crate::encoding::encode_cow(&out, encoding);
    crate::cli::output::emit_output_bytes(a.output, &bytes)?;
    Ok(EXIT_OK)
}

struct Sides<'a> {
    dir: &'a Path,
    /// How both programs run (the analysis commands' machine).
    run: &'a crate::interp::Options,
    /// The source's text, its file and dialect.
    source: (&'a str, crate::span::FileId, &'a Arc<DialectSpec>),
    /// The source's scan where the port made it while reading.
    source_scan: Option<verify_text::Scan>,
    target: &'a Arc<DialectSpec>,
    opts: &'a PortOptions,
    /// `--material`: the parts are compared too.
    material: Option<&'a crate::cli::port_material::Proof>,
}

/// Reads the output back, runs both and compares; prints the verdict.
/// Both sides run as streams ([`verify_text`]) and only their events
/// are held; a subprogram ported alone runs whole, as `check` runs it.
fn verify_port(
    ctx: &mut Context,
    mut s: Sides<'_>,
    out_id: crate::span::FileId,
    diags: &mut Vec<Diagnostic>,
) -> bool {
    let back = verify_text::scan(ctx.files.text(out_id), out_id, s.target);
    if back.has_errors() {
        diags.extend(back.diags);
        eprintln!(
            "verify: FAILED: the ported program does not read back as {}",
            s.target.id
        );
        return false;
    }
    let (src_text, src_id, src_spec) = s.source;
    let opts = same_tool_sizes(s.run, src_spec, s.target);
    // The tools a CAM header lists join the table, as `check` runs it.
    let head = crate::cli::port_material::head_of(src_text);
    let opts = crate::cli::check::program_tools(&opts, head, src_spec);
    let front = match s.source_scan.take() {
        Some(scan) => scan,
        None => verify_text::scan(src_text, src_id, src_spec),
    };
    let tolerance = verify::tolerance_for(s.target);
    let source = Side {
        text: src_text,
        id: src_id,
        scan: front,
        spec: src_spec,
        opts: &opts,
    };
    let side_by_side = s.material.is_none() && source.streams() && !back.fragment;
    let walker = source.scan.walker || back.walker;
    let mut proved = None;
    if side_by_side {
        let port = (ctx.files.text(out_id), out_id, back.clone());
        let mut notes = Vec::new();
        let (proof, called_out) =
            side_by_side_proof(&s, source.clone(), port, tolerance, &mut notes);
        // A program that calls another file is proved with it loaded.
        if !(walker && called_out) {
            diags.append(&mut notes);
            proved = Some(proof);
        }
    }
    let (proof, da, mut db) = match proved {
        Some(p) => p,
        None => {
            // The loaders add the files the program calls.
            let out = ctx.files.text(out_id).to_string();
            whole_proof(ctx, &s, source, (&out, out_id, back), tolerance, diags)
        }
    };
    db.retain(|d| d.is_error());
    let run_errors = |d: &[Diagnostic]| d.iter().filter(|d| d.is_error()).count();
    if run_errors(&da) > 0 {
        diags.extend(da.into_iter().filter(|d| d.is_error()));
        eprintln!("verify: FAILED: the source program stops with an error, so there is nothing to compare");
        return false;
    }
    if run_errors(&db) > run_errors(&da) {
        diags.extend(db.into_iter().filter(|d| d.is_error()));
        eprintln!(
            "verify: FAILED: the ported program stops with an error the source does not have"
        );
        return false;
    }
    let (v, runs) = proof;
    report(ctx, &v, tolerance);
    for r in &v.rapids {
        let mut d = Diagnostic::new(Code::VerifyRapids, r.what.clone());
        if let Some(sp) = r.b.or(r.a) {
            d = d.primary(sp, "here");
        }
        diags.push(d);
    }
    if let Some(first) = v.cutting.as_ref().or(v.low_rapid.as_ref()) {
        diags.push(mismatch(first));
    }
    let by_material = match (s.material, &runs) {
        (Some(p), Some((ea, eb))) => p.verify(ea, eb, &s.opts.tool_map, diags),
        _ => true,
    };
    v.same() && by_material
}

/// A proof's verdict, the two runs' events where the material proof
/// needs them, and each run's diagnostics.
type Proof = (
    (
        Verdict,
        Option<(Vec<crate::toolpath::Event>, Vec<crate::toolpath::Event>)>,
    ),
    Vec<Diagnostic>,
    Vec<Diagnostic>,
);

/// Both programs run side by side ([`verify_lockstep`]): the memory of
/// two streamed runs.
fn side_by_side_proof(
    s: &Sides<'_>,
    source: Side<'_>,
    (out, out_id, back): (&str, crate::span::FileId, verify_text::Scan),
    tolerance: f64,
    diags: &mut Vec<Diagnostic>,
) -> (Proof, bool) {
    let holds = crate::dialect::Capability::ControlHoldsTools;
    let changes = match s.target.has(holds) {
        true => Vec::new(),
        false => verify_lockstep::tool_changes(source.text, source.id, source.spec, source.opts),
    };
    let topts = with_source_tools(source.opts, (source.spec, s.target), &changes, diags);
    let port = Side {
        text: out,
        id: out_id,
        scan: back,
        spec: s.target,
        opts: &topts,
    };
    let o = verify_lockstep::compare(source, port, &s.opts.tool_map, tolerance);
    (((o.verdict, None), o.source, o.port), o.called_out)
}

/// Each program run in turn and its events held: a subprogram ported
/// alone, a program with control flow (which loads others), or the
/// material proof (which needs the runs after the comparison).
fn whole_proof(
    ctx: &mut Context,
    s: &Sides<'_>,
    source: Side<'_>,
    (out, out_id, back): (&str, crate::span::FileId, verify_text::Scan),
    tolerance: f64,
    diags: &mut Vec<Diagnostic>,
) -> Proof {
    let (src_text, src_id, src_spec, opts) = (source.text, source.id, source.spec, source.opts);
    let fragment = source.scan.fragment;
    let (ea, da) = {
        let mut loader = FsLoader::new(s.dir.to_path_buf(), src_spec.clone(), &mut ctx.files);
        if fragment {
            let p = read_program(src_text, src_id, src_spec).0;
            run_fragment(Rc::new(p), src_spec, opts, &mut loader)
        } else {
            verify_text::events(src_text, src_id, source.scan, src_spec, opts, &mut loader)
        }
    };
    let (eb, db) = {
        let source = FsLoader::new(s.dir.to_path_buf(), src_spec.clone(), &mut ctx.files);
        let mut loader = PortingLoader {
            source,
            from: src_spec,
            to: s.target,
            opts: s.opts,
            diags: Vec::new(),
        };
        let changes: Vec<(i64, Span)> = ea
            .iter()
            .filter_map(|e| match e {
                crate::toolpath::Event::ToolChange { tool, span } => Some((*tool, *span)),
                _ => None,
            })
            .collect();
        let topts = with_source_tools(opts, (src_spec, s.target), &changes, diags);
        let (e, mut d) = if fragment {
            let p = read_program(out, out_id, s.target).0;
            run_fragment(Rc::new(p), s.target, &topts, &mut loader)
        } else {
            verify_text::events(out, out_id, back, s.target, &topts, &mut loader)
        };
        d.extend(loader.diags.into_iter().filter(Diagnostic::is_error));
        (e, d)
    };
    let errors = |d: &[Diagnostic]| d.iter().any(|d| d.is_error());
    if errors(&da) || errors(&db) {
        // Not compared: the caller reports the run's errors.
        return ((Verdict::default(), None), da, db);
    }
    // The material proof needs the runs after the comparison; otherwise
    // they go as they are reduced.
    let proof = match s.material {
        Some(_) => (
            verify::compare_within(&ea, &eb, &s.opts.tool_map, tolerance),
            Some((ea, eb)),
        ),
        None => (
            verify::compare_owned(ea, eb, &s.opts.tool_map, tolerance),
            None,
        ),
    };
    (proof, da, db)
}

fn place(ctx: &Context, sp: Option<Span>) -> String {
    match sp {
        Some(sp) => {
            let (line, _) = ctx.files.line_col(sp.file, sp.start as usize);
            format!("{}:{line}", ctx.files.name(sp.file))
        }
        None => "(nothing)".into(),
    }
}

fn report(ctx: &Context, v: &Verdict, tolerance: f64) {
    match v.cutting.as_ref().or(v.low_rapid.as_ref()) {
        None => eprintln!(
            "verify: OK: the same {} operations (within {} mm); {} rapid(s) differ",
            v.cutting_moves,
            (tolerance * 1e5).round() / 1e5,
            v.rapids.len()
        ),
        Some(d) => eprintln!(
            "verify: DIFFERENT: {}\n  source: {}\n  port:   {}",
            d.what,
            place(ctx, d.a),
            place(ctx, d.b)
        ),
    }
}

fn mismatch(d: &Difference) -> Diagnostic {
    let mut diag = Diagnostic::new(
        Code::VerifyMismatch,
        format!("the port cuts differently: {}", d.what),
    );
    if let Some(a) = d.a {
        diag = diag.primary(a, "the source cuts this");
    }
    if let Some(b) = d.b {
        diag = if d.a.is_some() {
            diag.secondary(b, "the port cuts this")
        } else {
            diag.primary(b, "the port cuts this")
        };
    }
    diag.help("the port is not written; report the construct, or use --expand-cycles for cycles")
}

/// Ports, writes and (for Heidenhain) appends the label subprograms:
/// the target's text with its warnings, or every error.
fn attempt(
    ctx: &mut Context,
    dir: &Path,
    program: Program,
    spec: &Arc<DialectSpec>,
    target: &Arc<DialectSpec>,
    opts: &PortOptions,
) -> Result<(String, Vec<Diagnostic>), Vec<Diagnostic>> {
    let (ported, mut diags) = port_owned(program, spec, target, opts);
    if diags.iter().any(|d| d.is_error()) {
        return Err(diags.into_iter().filter(|d| d.is_error()).collect());
    }
    let out = match write_program_warned(&ported, target) {
        Ok((out, warnings)) => {
            diags.extend(warnings);
            out
        }
        Err(errs) => return Err(errs),
    };
    // Subprograms the target keeps in the same file (Heidenhain `LBL`).
    let mut loader = FsLoader::new(dir.to_path_buf(), spec.clone(), &mut ctx.files);
    let out = crate::port::to_tnc::sub_text::append(
        &ported,
        out,
        spec,
        target,
        opts,
        &mut loader,
        &mut diags,
    );
    diags.append(&mut loader.diags);
    if diags.iter().any(|d| d.is_error()) {
        return Err(diags.into_iter().filter(|d| d.is_error()).collect());
    }
    Ok((out, diags))
}

/// The moves of a subprogram or macro ported alone, as `--verify`
/// compares them: it runs as `check` runs it, from its first block, with
/// the values it gets from its caller unknown.
fn run_fragment(
    p: Rc<Program>,
    spec: &DialectSpec,
    opts: &crate::interp::Options,
    loader: &mut dyn crate::interp::flow::ProgramLoader,
) -> (Vec<crate::toolpath::Event>, Vec<Diagnostic>) {
    let kind =
        crate::interp::fragment::detect(&p).unwrap_or(crate::interp::fragment::Fragment::Called);
    let mut tracker = crate::toolpath::Tracker::new();
    let mut out = Vec::new();
    let mut sink = |call: crate::canon::Canon, span: Span| {
        tracker.push(&call, span, |e| out.push(e));
    };
    let diags = crate::interp::fragment::run(p, &kind, spec, opts, loader, &mut sink);
    (out, diags)
}

/// Both sides cut with the same physical tools. A control that holds its
/// own tool data compensates by no size where the table is cncc's
/// invention; one that reads the table, by the table's sizes. So where
/// the source reads the table and the target holds its tools, both take
/// the table's sizes; where the source holds its tools (its radii are not
/// known) and the target reads the table, both compensate by none: the
/// comparison is of the programmed paths, as for the tools
/// [`with_source_tools`] adds (it clears the target's radii).
fn same_tool_sizes(
    run: &crate::interp::Options,
    from: &DialectSpec,
    to: &DialectSpec,
) -> crate::interp::Options {
    let mut o = run.clone();
    let holds = crate::dialect::Capability::ControlHoldsTools;
    if !from.has(holds) && to.has(holds) {
        o.tool_table.invented = false;
    }
    o
}

/// The options of the ported program's run: a target that needs every
/// tool in its tool table (no capability `control-holds-tools`: LinuxCNC)
/// gets the tools the source's run changed to that the table lacks, as
/// tools of no size (what the source's control held for them is not
/// known either), so the comparison is of the paths. Each is reported:
/// the target machine's table must list it.
fn with_source_tools(
    opts: &crate::interp::Options,
    (from, target): (&DialectSpec, &DialectSpec),
    source: &[(i64, Span)],
    diags: &mut Vec<Diagnostic>,
) -> crate::interp::Options {
    let mut o = opts.clone();
    let holds = crate::dialect::Capability::ControlHoldsTools;
    if target.has(holds) {
        return o;
    }
    if from.has(holds) && o.tool_table.invented {
        // The source compensated by no size (see [`same_tool_sizes`]),
        // but by the sizes its header comments give.
        let given = &o.tool_table.from_program;
        o.tool_table
            .tools
            .iter_mut()
            .filter(|t| !given.contains(&t.number))
            .for_each(|t| t.diameter = 0.0);
    }
    for (tool, span) in source {
        if *tool <= 0 || o.tool_table.get(*tool).is_some() {
            continue;
        }
        o.tool_table
            .tools
            .push(crate::interp::tooltable::Tool::blank(*tool, String::new()));
        diags.push(
            Diagnostic::new(
                Code::PortApproximate,
                format!("{} needs tool {tool} in its tool table; the proof ran it as a tool of no size", target.name),
            )
            .primary(*span, "the source changes to this tool")
            .help("add the tool to the machine's tool table (`--tool-table` gives the proof its sizes)"),
        );
    }
    o
}

/// The tools of the run's tool table by name (a row's comment), when a
/// table was given.
fn tool_names(o: &crate::interp::Options) -> Vec<(String, i64)> {
    if o.tool_table == crate::interp::tooltable::ToolTable::builtin() {
        return Vec::new();
    }
    o.tool_table
        .tools
        .iter()
        .filter(|t| !t.comment.trim().is_empty())
        .map(|t| (t.comment.trim().to_string(), t.number))
        .collect()
}
