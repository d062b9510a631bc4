//! Running a program file as a stream: each block runs as it is read; a
//! program with control flow is read whole from its first such block and
//! the walker goes on from there (see [`super::stream`]), its plain moves
//! held as text ([`super::lazy`]). Memory stays
//! flat on large CAM files. `cncc canon` and everything that reads the
//! canonical stream (toolpaths, plots, STEP-NC raising) run files this way.
//! [`run_text`] runs a program held in memory the same way (a STEP-NC
//! plan posted for running, see `crate::cli::stepnc_input`).

use super::lazy::read_program_lazy;
use super::{flow::ProgramLoader, stream::StreamRun, Interp, Options, Sink};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::driver::{check_stream_while, decode, FsLoader};
use crate::source::SourceMap;
use crate::span::FileId;
use std::borrow::Cow;
use std::fs::File;
use std::io::{BufRead, BufReader};
use std::path::Path;
use std::sync::Arc;

/// Runs the program in `path` (already registered as `id`, sparse or
/// whole, in `files`), sending every call to `sink`. Returns the reader's
/// and the run's diagnostics. The first block that does not read cleanly
/// stops the run there, as rs274 stops at a bad block; subprograms are
/// loaded from files beside the program.
pub fn run_file(
    path: &Path,
    id: FileId,
    spec: &Arc<DialectSpec>,
    opts: &Options,
    files: &mut SourceMap,
    sink: &mut Sink<'_>,
) -> std::io::Result<Vec<Diagnostic>> {
    let input = BufReader::with_capacity(1 << 16, File::open(path)?);
    let whole = || {
        crate::cli::context::read_limited(path, crate::cli::context::MAX_INPUT)
            .map(|b| Cow::Owned(decode(&b)))
    };
    let dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
    let mut loader =
        FsLoader::new(dir, spec.clone(), files).with_search(&opts.rs274.subroutine_path);
    let mut diags = Run { id, spec, opts }.go(input, whole, &mut loader, sink)?;
    diags.append(&mut loader.diags);
    Ok(diags)
}

/// [`run_file`] for a program held in memory (registered as `id`);
/// subprograms are looked for in `dir`.
pub fn run_text(
    text: &str,
    id: FileId,
    dir: &Path,
    spec: &Arc<DialectSpec>,
    opts: &Options,
    files: &mut SourceMap,
    sink: &mut Sink<'_>,
) -> std::io::Result<Vec<Diagnostic>> {
    let mut loader = FsLoader::new(dir.to_path_buf(), spec.clone(), files);
    let mut diags = run_text_loading(text, id, spec, opts, &mut loader, sink);
    diags.append(&mut loader.diags);
    Ok(diags)
}

/// [`run_text`] with the caller's loader for the programs it calls (the
/// port's proof loads the source's subprograms as ported).
pub fn run_text_loading(
    text: &str,
    id: FileId,
    spec: &Arc<DialectSpec>,
    opts: &Options,
    loader: &mut dyn ProgramLoader,
    sink: &mut Sink<'_>,
) -> Vec<Diagnostic> {
    let run = Run { id, spec, opts };
    // Reading from memory cannot fail.
    run.go(text.as_bytes(), || Ok(Cow::Borrowed(text)), loader, sink)
        .unwrap_or_default()
}

/// What a run needs besides its input.
struct Run<'r> {
    id: FileId,
    spec: &'r Arc<DialectSpec>,
    opts: &'r Options,
}

impl Run<'_> {
    /// Streams `input`; `whole` gives the whole text when the walker takes
    /// over (control flow), which loads called programs with `loader`.
    fn go<'t>(
        self,
        input: impl BufRead,
        whole: impl FnOnce() -> std::io::Result<Cow<'t, str>>,
        loader: &mut dyn ProgramLoader,
        sink: &mut Sink<'_>,
    ) -> std::io::Result<Vec<Diagnostic>> {
        let Run { id, spec, opts } = self;
        let mut sink = sink;
        let mut it = Interp::new(spec, opts, &mut sink);
        it.start();
        let mut stream = StreamRun::default();
        let mut stopped = false;
        // Reading stops at the hand-over: the walker's reading of the
        // whole text gives the diagnostics of every line.
        let read = check_stream_while(input, id, spec, |b, e, bad| {
            stopped |= bad;
            if !stopped {
                stream.block(&mut it, b, e);
            }
            stream.handover.is_none()
        })?;
        let mut diags = read.diagnostics;
        let mut whole_read = None;
        if stream.handover.is_some() {
            let (program, lazy, read) = read_program_lazy(whole()?, id, spec);
            diags = read;
            whole_read = Some((program, lazy));
        }
        let read_errors = diags.iter().any(|d| d.is_error());
        let run = match whole_read {
            _ if read_errors => stream.abandon(&mut it),
            None => stream.finish(&mut it),
            Some((program, lazy)) => {
                stream.continue_with(&mut it, std::rc::Rc::new(program), Some(lazy), loader)
            }
        };
        diags.extend(run);
        opts.rs274.keep_final(&it);
        Ok(diags)
    }
}
