//! `cncc canon`: run a program and print its canonical machining calls,
//! one per line, in the text form of LinuxCNC's `rs274`.

use crate::cli::args::Format;
use crate::cli::context::{report_detection, Context, Failure, EXIT_INPUT_ERRORS, EXIT_OK};
use crate::canon::format_call;
use crate::driver::{read_program, FsLoader};
use crate::interp::{self, tooltable::ToolTable, Options};
use std::io::Write;
use std::path::Path;

pub struct CanonArgs<'a> {
    pub file: &'a Path,
    pub dialect: Option<&'a str>,
    pub tool_table: Option<&'a Path>,
    pub format: Format,
    pub options: Options,
}

pub fn run(ctx: &mut Context, mut a: CanonArgs<'_>) -> Result<i32, Failure> {
    let (id, text) = ctx.add_file(a.file)?;
    let (spec, reason) = ctx.spec_for(a.dialect, a.file, &text)?;
    if let Some(r) = reason {
        report_detection(a.file, &spec, &r);
    }
    let mut diags = Vec::new();
    if let Some(t) = a.tool_table {
        let (tid, ttext) = ctx.add_file(t)?;
        let (table, d) = ToolTable::parse(&ttext, tid);
        diags.extend(d);
        a.options.tool_table = table;
    }
    let (program, d) = read_program(&text, id, &spec);
    diags.extend(d);
    if diags.iter().any(|d| d.is_error()) {
        ctx.print(&diags, a.format);
        return Ok(EXIT_INPUT_ERRORS);
    }
    let out = std::io::stdout();
    let mut out = std::io::BufWriter::new(out.lock());
    let mut io_error = None;
    let mut sink = |call: crate::canon::Canon, _span| {
        if io_error.is_none() {
            if let Err(e) = writeln!(out, "{}", format_call(&call)) {
                io_error = Some(e);
            }
        }
    };
    let dir = a.file.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut loader = FsLoader::new(dir, spec.clone(), &mut ctx.files);
    diags.extend(interp::run(std::rc::Rc::new(program), &spec, &a.options, &mut loader, &mut sink));
    diags.append(&mut loader.diags);
    drop(sink);
    out.flush()?;
    if let Some(e) = io_error {
        return Err(e.into());
    }
    ctx.print(&diags, a.format);
    Ok(if diags.iter().any(|d| d.is_error()) { EXIT_INPUT_ERRORS } else { EXIT_OK })
}
