//! The reading pipeline: text → lines → front end → lowering → checks.
//!
//! [`Reader`] takes one line at a time, so a program can be checked as a
//! stream in memory that does not grow with its length
//! ([`check_stream`]), or read whole into a [`Program`] ([`read_program`]).

use crate::check::structure::StructureChecker;
use crate::diag::Diagnostic;
use crate::dialect::{DialectSpec, Family};
use crate::ir::{Arena, Block, Expr, Program};
use crate::lower::Lowering;
use crate::source::KeptLine;
use crate::span::FileId;
use crate::span::Span;
use crate::syntax::klartext::KlartextFrontEnd;
use crate::syntax::sinumerik::SinumerikFrontEnd;
use crate::syntax::word::WordFrontEnd;
use crate::syntax::{FrontEnd, LineInput};
use std::io::BufRead;

/// The front end for a dialect's syntax family.
pub fn front_end_for(spec: &DialectSpec) -> Box<dyn FrontEnd> {
    match spec.family {
        Family::WordAddress => Box::new(WordFrontEnd::new()),
        Family::Sinumerik => Box::new(SinumerikFrontEnd::new()),
        Family::Klartext => Box::new(KlartextFrontEnd::new()),
    }
}

/// Reads lines into blocks, running the per-line and structure checks.
pub struct Reader<'s> {
    spec: &'s DialectSpec,
    file: FileId,
    front: Box<dyn FrontEnd>,
    lowering: Lowering<'s>,
    structure: StructureChecker,
    index: usize,
    /// `%` lines read so far.
    percents: u32,
    /// Whether the lines after the closing `%` were reported (W0007).
    after_end_noted: bool,
}

impl<'s> Reader<'s> {
    pub fn new(spec: &'s DialectSpec, file: FileId) -> Self {
        Reader {
            spec,
            file,
            front: front_end_for(spec),
            lowering: Lowering::new(spec),
            structure: StructureChecker::new(spec),
            index: 0,
            percents: 0,
            after_end_noted: false,
        }
    }

    /// Reads one line (without its ending) that starts at byte `offset`.
    pub fn line(
        &mut self,
        text: &str,
        offset: u32,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<Block> {
        let mut block = empty_block();
        self.line_into(text, offset, exprs, diags, &mut block)
            .then_some(block)
    }

    /// [`Reader::line`] into `block`, whose statements vector is reused;
    /// `false` (and `block` unspecified) when the line gives no block.
    pub fn line_into(
        &mut self,
        text: &str,
        offset: u32,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
        block: &mut Block,
    ) -> bool {
        let input = LineInput {
            text,
            file: self.file,
            offset,
            spec: self.spec,
        };
        if self.past_closing_percent(text, offset, diags) {
            return false;
        }
        if text.len() > MAX_LINE {
            diags.push(too_long(Span::new(
                self.file,
                offset as usize,
                offset as usize + 80.min(text.len()),
            )));
            return false;
        }
        let first_expr = exprs.len();
        let Some(mut syntax) = self.front.parse_line(&input, exprs, diags) else {
            return false;
        };
        if let Some(deep) = crate::ir::depth::first_too_deep(exprs, first_expr) {
            diags.push(too_deep(exprs[deep].span));
            return false;
        }
        self.lowering.recycle(&mut block.stmts);
        self.lowering
            .lower(&mut syntax.items, exprs, diags, &mut block.stmts);
        self.front.recycle(syntax.items);
        block.span = syntax.span;
        block.skip = syntax.skip;
        block.number = syntax.number;
        block.label = syntax.label.map(Box::new);
        self.structure.block(self.index, block, exprs);
        self.index += 1;
        if block
            .stmts
            .iter()
            .any(|s| matches!(s.kind, crate::ir::StmtKind::Tape))
        {
            self.percents += 1;
        }
        true
    }

    /// Where the dialect has `stop-at-closing-percent` (LinuxCNC): a line
    /// after the second `%` is not read; the first such line with text gets
    /// a note (W0007).
    fn past_closing_percent(
        &mut self,
        text: &str,
        offset: u32,
        diags: &mut Vec<Diagnostic>,
    ) -> bool {
        if self.percents < 2
            || !self
                .spec
                .has(crate::dialect::Capability::StopAtClosingPercent)
        {
            return false;
        }
        if !self.after_end_noted && !text.trim().is_empty() {
            self.after_end_noted = true;
            let end = offset as usize + text.len().min(80);
            diags.push(
                Diagnostic::new(
                    crate::diag::Code::AfterClosingPercent,
                    "text after the closing `%` is not read",
                )
                .primary(Span::new(self.file, offset as usize, end), "from here on")
                .help("move what should run before the closing `%`"),
            );
        }
        true
    }

    /// Ends the program: the checks that need all of it.
    pub fn finish(mut self) -> Vec<Diagnostic> {
        let mut diags = Vec::new();
        self.front.finish(self.file, &mut diags);
        diags.extend(self.structure.finish());
        diags
    }
}

/// The longest line read as a block: no controller takes one near it,
/// and reading a longer one would hold far more memory than the file.
pub const MAX_LINE: usize = 1 << 20;

/// E0191 for a line over [`MAX_LINE`].
fn too_long(span: Span) -> Diagnostic {
    Diagnostic::new(
        crate::diag::Code::BlockTooLong,
        format!("a line longer than {MAX_LINE} bytes"),
    )
    .primary(span, "this line is not read")
    .help("split it into several blocks")
}

/// E0190 at the part of an expression that crosses the depth limit.
fn too_deep(span: Span) -> Diagnostic {
    Diagnostic::new(
        crate::diag::Code::ExpressionTooDeep,
        format!(
            "expression nested more than {} levels deep",
            crate::ir::depth::MAX_EXPR_DEPTH
        ),
    )
    .primary(span, "too deep from here on; this block is not run")
    .help("split the expression into several assignments")
}

fn empty_block() -> Block {
    Block {
        span: Span::default(),
        skip: None,
        number: None,
        label: None,
        stmts: Vec::new(),
    }
}

/// Splits text into lines without their endings (`\n`, `\r\n` or a lone
/// `\r`), with the byte offset of each line's start.
pub fn lines(text: &str) -> impl Iterator<Item = (&str, u32)> {
    let mut offset = 0usize;
    text.split_inclusive('\n').flat_map(move |raw| {
        // Only a piece without LF (a CR-only file, the last line) can hold
        // lone CRs; every other line is one line, with no allocation.
        let mut pieces = Vec::new();
        let mut one = None;
        if raw.ends_with('\n') {
            one = Some((strip_ending(raw), offset as u32));
            offset += raw.len();
        } else {
            let _ = crate::encoding::split_lone_cr::<()>(raw, |p, _| {
                pieces.push((strip_ending(p), offset as u32));
                offset += p.len();
                Ok(true)
            });
        }
        one.into_iter().chain(pieces)
    })
}

/// The note for a file whose lines end with a lone CR, at the first one.
fn cr_note(file: FileId, at: Option<u64>) -> Option<Diagnostic> {
    let at = u32::try_from(at?).ok()?;
    Some(
        Diagnostic::new(
            crate::diag::Code::CrLineEnds,
            "lines end with a lone carriage return (CR): read as line ends",
        )
        .primary(Span::new(file, at as usize, at as usize + 1), "a CR without LF")
        .help("CR-only line ends come from old Mac or DNC software; most controllers want LF or CR LF"),
    )
}

/// Reads a whole program.
pub fn read_program(text: &str, file: FileId, spec: &DialectSpec) -> (Program, Vec<Diagnostic>) {
    let mut program = Program::new(file, spec.id.clone());
    let mut blocks = Vec::new();
    let diags = read_each(text, file, spec, &mut program.exprs, |b, _| blocks.push(b));
    program.blocks = blocks;
    (program, diags)
}

/// [`read_program`] block by block: each block is handed to `on_block`
/// with its expressions and dropped, so memory does not grow with the
/// program. Gives the same blocks and diagnostics.
pub fn read_blocks(
    text: &str,
    file: FileId,
    spec: &DialectSpec,
    mut on_block: impl FnMut(&Block, &Arena<Expr>),
) -> Vec<Diagnostic> {
    let mut exprs = Arena::new();
    read_each(text, file, spec, &mut exprs, |b, exprs| {
        on_block(&b, exprs);
        exprs.clear();
    })
}

/// Reads `text` line by line into `exprs`, handing each block to
/// `on_block`; the reader's closing diagnostics and the CR-only note
/// come last.
pub(crate) fn read_each(
    text: &str,
    file: FileId,
    spec: &DialectSpec,
    exprs: &mut Arena<Expr>,
    mut on_block: impl FnMut(Block, &mut Arena<Expr>),
) -> Vec<Diagnostic> {
    let mut diags = Vec::new();
    let mut reader = Reader::new(spec, file);
    let mut first_cr = None;
    for (line, offset) in lines(text) {
        let end = offset as usize + line.len();
        if first_cr.is_none()
            && text.as_bytes().get(end) == Some(&b'\r')
            && text.as_bytes().get(end + 1) != Some(&b'\n')
        {
            first_cr = Some(end as u64);
        }
        if let Some(b) = reader.line(line, offset, exprs, &mut diags) {
            on_block(b, exprs);
        }
        // As a streamed reading keeps them.
        if diags.len() > crate::diag::MAX_KEPT {
            diags.truncate(crate::diag::MAX_KEPT);
        }
    }
    diags.extend(reader.finish());
    diags.extend(cr_note(file, first_cr));
    diags
}

pub use crate::encoding::decode;

/// What a streamed check found.
pub struct StreamResult {
    /// The lines they point at are read again with [`lines_at`].
    pub diagnostics: Vec<Diagnostic>,
    pub bytes: u64,
    pub lines: u64,
}

/// Checks a program as a stream: memory stays flat whatever its length.
/// `on_block` sees every block (with the expressions it refers to).
pub fn check_stream(
    input: impl BufRead,
    file: FileId,
    spec: &DialectSpec,
    mut on_block: impl FnMut(&Block, &Arena<Expr>),
) -> std::io::Result<StreamResult> {
    check_stream_flagged(input, file, spec, |b, e, _| on_block(b, e))
}

/// [`check_stream`], telling `on_block` whether reading its line found an
/// error (a run stops there, as a controller stops at a bad block).
pub fn check_stream_flagged(
    input: impl BufRead,
    file: FileId,
    spec: &DialectSpec,
    mut on_block: impl FnMut(&Block, &Arena<Expr>, bool),
) -> std::io::Result<StreamResult> {
    check_stream_while(input, file, spec, |b, e, bad| {
        on_block(b, e, bad);
        true
    })
}

/// [`check_stream_flagged`] until `on_block` says `false`: the lines after
/// that block are not read (the caller reads them otherwise), and the
/// result has the diagnostics of the lines read.
pub fn check_stream_while(
    input: impl BufRead,
    file: FileId,
    spec: &DialectSpec,
    mut on_block: impl FnMut(&Block, &Arena<Expr>, bool) -> bool,
) -> std::io::Result<StreamResult> {
    let mut reader = Reader::new(spec, file);
    let mut exprs = Arena::new();
    let mut diags = Vec::new();
    let mut block = empty_block();
    let (mut offset, mut line_no) = (0u64, 0u64);
    let mut first_cr = None;
    for_each_line(input, |text| {
        if first_cr.is_none() && text.ends_with('\r') {
            first_cr = Some(offset + text.len() as u64 - 1);
        }
        let line = strip_ending(text);
        let off = u32::try_from(offset).map_err(|_| too_large())?;
        let before = diags.len();
        let mut more = true;
        if reader.line_into(line, off, &mut exprs, &mut diags, &mut block) {
            let bad = diags[before..].iter().any(|d| d.is_error());
            more = on_block(&block, &exprs, bad);
        }
        if diags.len() > crate::diag::MAX_KEPT {
            diags.truncate(crate::diag::MAX_KEPT);
        }
        exprs.clear();
        offset += text.len() as u64;
        line_no += 1;
        Ok(more)
    })?;
    diags.extend(reader.finish());
    diags.extend(cr_note(file, first_cr));
    Ok(StreamResult {
        diagnostics: diags,
        bytes: offset,
        lines: line_no,
    })
}

/// A line without its ending (`\n`, `\r\n`).
fn strip_ending(text: &str) -> &str {
    let line = text.strip_suffix('\n').unwrap_or(text);
    line.strip_suffix('\r').unwrap_or(line)
}

/// Calls `f` with each line of the input, with its ending, decoded as
/// [`decode`] does (no BOM; UTF-8, or Latin-1 for a line that is not; a
/// lone CR ends a line), until `f` says `false`. Reads the input's buffer in place: whole buffers of lines
/// are checked as UTF-8 at once; only a line across two reads is copied.
pub fn for_each_line<F>(mut input: impl BufRead, mut f: F) -> std::io::Result<()>
where
    F: FnMut(&str) -> std::io::Result<bool>,
{
    // Bytes that began like a BOM but were not one are the first line's.
    let mut carry: Vec<u8> = skip_bom(&mut input)?;
    let mut f = |text: &str| crate::encoding::split_lone_cr(text, |p, _| f(p));
    let mut latin = String::new();
    loop {
        let chunk = match input.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        if chunk.is_empty() {
            break;
        }
        let (used, go_on) = if carry.is_empty() {
            match chunk.iter().rposition(|&b| b == b'\n') {
                Some(last) => (last + 1, lines_in(&chunk[..=last], &mut latin, &mut f)?),
                None => {
                    carry.extend_from_slice(chunk);
                    (chunk.len(), true)
                }
            }
        } else {
            match chunk.iter().position(|&b| b == b'\n') {
                Some(i) => {
                    carry.extend_from_slice(&chunk[..=i]);
                    let go_on = one_line(&carry, &mut latin, &mut f)?;
                    carry.clear();
                    (i + 1, go_on)
                }
                None => {
                    carry.extend_from_slice(chunk);
                    (chunk.len(), true)
                }
            }
        };
        input.consume(used);
        if !go_on {
            return Ok(());
        }
    }
    if !carry.is_empty() {
        one_line(&carry, &mut latin, &mut f)?;
    }
    Ok(())
}

/// Consumes a UTF-8 byte order mark at the start of the input; gives back
/// the bytes consumed that turned out not to be one.
fn skip_bom(input: &mut impl BufRead) -> std::io::Result<Vec<u8>> {
    let bom = crate::encoding::BOM;
    let mut seen = 0;
    while seen < bom.len() {
        let chunk = match input.fill_buf() {
            Ok(c) => c,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(e),
        };
        let n = chunk.len().min(bom.len() - seen);
        if n == 0 || chunk[..n] != bom[seen..seen + n] {
            return Ok(bom[..seen].to_vec());
        }
        input.consume(n);
        seen += n;
    }
    Ok(Vec::new())
}

/// Whole lines (the last one ends with `\n`).
fn lines_in<F>(bytes: &[u8], latin: &mut String, f: &mut F) -> std::io::Result<bool>
where
    F: FnMut(&str) -> std::io::Result<bool>,
{
    if let Ok(text) = std::str::from_utf8(bytes) {
        // Lines are short: a plain scan beats a vectorised search here.
        let mut start = 0;
        for (i, _) in text.bytes().enumerate().filter(|&(_, b)| b == b'\n') {
            if !f(&text[start..=i])? {
                return Ok(false);
            }
            start = i + 1;
        }
        return Ok(true);
    }
    for raw in bytes.split_inclusive(|&b| b == b'\n') {
        if !one_line(raw, latin, f)? {
            return Ok(false);
        }
    }
    Ok(true)
}

fn one_line<F>(raw: &[u8], latin: &mut String, f: &mut F) -> std::io::Result<bool>
where
    F: FnMut(&str) -> std::io::Result<bool>,
{
    match std::str::from_utf8(raw) {
        Ok(s) => f(s),
        Err(_) => {
            latin.clear();
            latin.extend(raw.iter().map(|&b| b as char));
            f(latin)
        }
    }
}

fn too_large() -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, "file larger than 4 GiB")
}

/// Loads subprograms from files beside the main program:
/// `o<name> call` → `name.ngc`; `M98 P1000` → `O1000.nc`, `1000.nc`, ...
/// (any extension the dialect claims), read with the same dialect.
pub struct FsLoader<'a> {
    dir: std::path::PathBuf,
    /// Folders searched after `dir` (LinuxCNC's `SUBROUTINE_PATH`).
    search: Vec<std::path::PathBuf>,
    spec: std::sync::Arc<DialectSpec>,
    files: &'a mut crate::source::SourceMap,
    /// Diagnostics from reading the loaded files.
    pub diags: Vec<Diagnostic>,
}

impl<'a> FsLoader<'a> {
    pub fn new(
        dir: std::path::PathBuf,
        spec: std::sync::Arc<DialectSpec>,
        files: &'a mut crate::source::SourceMap,
    ) -> Self {
        FsLoader {
            dir,
            search: Vec::new(),
            spec,
            files,
            diags: Vec::new(),
        }
    }

    /// Also looks for called programs in `dirs`, in order, after the
    /// program's own folder.
    pub fn with_search(mut self, dirs: &[std::path::PathBuf]) -> Self {
        self.search = dirs.to_vec();
        self
    }

    fn candidates(&self, target: &crate::ir::CallTarget) -> Vec<std::path::PathBuf> {
        use crate::ir::CallTarget;
        let stems: Vec<String> = match target {
            CallTarget::Name(n) => {
                let n = n.trim_matches(|c| c == '<' || c == '>');
                // Heidenhain `CALL PGM TNC:\DIR\NAME.H`: the file name.
                let n = n.rsplit(['\\', '/', ':']).next().unwrap_or(n);
                vec![
                    n.to_string(),
                    n.to_ascii_lowercase(),
                    n.to_ascii_uppercase(),
                ]
            }
            CallTarget::Number(n) => vec![
                format!("O{n}"),
                format!("O{n:04}"),
                format!("o{n}"),
                n.to_string(),
                format!("L{n}"),
            ],
            CallTarget::Computed(_) => Vec::new(),
        };
        let mut exts: Vec<String> = self.spec.extensions.clone();
        exts.extend(["ngc", "nc", "NC", "spf", "SPF", "mpf", "MPF"].map(String::from));
        let mut out = Vec::new();
        for dir in std::iter::once(&self.dir).chain(&self.search) {
            for s in &stems {
                out.push(dir.join(s));
                for e in &exts {
                    out.push(dir.join(format!("{s}.{e}")));
                }
            }
        }
        out
    }
}

impl crate::interp::flow::ProgramLoader for FsLoader<'_> {
    fn load(&mut self, target: &crate::ir::CallTarget) -> Option<std::rc::Rc<Program>> {
        let path = self.candidates(target).into_iter().find(|p| p.is_file())?;
        let text =
            decode(&crate::cli::context::read_limited(&path, crate::cli::context::MAX_INPUT).ok()?);
        let id = self.files.add(path.display().to_string(), text.clone());
        let (p, d) = read_program(&text, id, &self.spec);
        self.diags.extend(d);
        Some(std::rc::Rc::new(p))
    }
}

/// Reads, in one pass, the lines of a file that contain any of the given
/// byte offsets (offsets in the decoded text, as spans are): what a
/// streamed file's diagnostics need to be rendered.
pub fn lines_at(input: impl BufRead, offsets: &[u32]) -> std::io::Result<Vec<KeptLine>> {
    let mut wanted: Vec<u64> = offsets.iter().map(|&o| o as u64).collect();
    wanted.sort_unstable();
    wanted.dedup();
    let (mut offset, mut line_no, mut next) = (0u64, 0usize, 0usize);
    let mut out = Vec::new();
    if wanted.is_empty() {
        return Ok(out);
    }
    for_each_line(input, |text| {
        let end = offset + text.len() as u64;
        if wanted[next] < end || (wanted[next] == end && !text.ends_with('\n')) {
            out.push(KeptLine {
                line: line_no,
                start: offset as usize,
                text: strip_ending(text).to_owned(),
            });
            while next < wanted.len() && wanted[next] <= end {
                next += 1;
            }
        }
        offset = end;
        line_no += 1;
        Ok(next < wanted.len())
    })?;
    Ok(out)
}

#[cfg(test)]
#[path = "driver_tests.rs"]
mod tests;
