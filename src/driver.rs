//! The reading pipeline: text → lines → front end → lowering → checks.
//!
//! [`Reader`] takes one line at a time, so a program can be checked as a
//! stream in memory that does not grow with its length
//! ([`check_stream`]), or read whole into a [`Program`] ([`read_program`]).

use crate::check::structure::StructureChecker;
use crate::diag::Diagnostic;
use crate::dialect::{DialectSpec, Family};
use crate::ir::{Arena, Block, Expr, Program};
use crate::lower::lower_line;
use crate::source::KeptLine;
use crate::span::FileId;
use crate::syntax::sinumerik::SinumerikFrontEnd;
use crate::syntax::word::WordFrontEnd;
use crate::syntax::{FrontEnd, LineInput};
use std::io::BufRead;

/// The front end for a dialect's syntax family.
pub fn front_end_for(spec: &DialectSpec) -> Box<dyn FrontEnd> {
    match spec.family {
        Family::WordAddress => Box::new(WordFrontEnd::new()),
        Family::Sinumerik => Box::new(SinumerikFrontEnd::new()),
        // Klartext has no front end yet; the registry refuses the dialect.
        Family::Klartext => Box::new(WordFrontEnd::new()),
    }
}

/// Reads lines into blocks, running the per-line and structure checks.
pub struct Reader<'s> {
    spec: &'s DialectSpec,
    file: FileId,
    front: Box<dyn FrontEnd>,
    structure: StructureChecker,
    index: usize,
}

impl<'s> Reader<'s> {
    pub fn new(spec: &'s DialectSpec, file: FileId) -> Self {
        Reader { spec, file, front: front_end_for(spec), structure: StructureChecker::new(spec), index: 0 }
    }

    /// Reads one line (without its ending) that starts at byte `offset`.
    pub fn line(
        &mut self,
        text: &str,
        offset: u32,
        exprs: &mut Arena<Expr>,
        diags: &mut Vec<Diagnostic>,
    ) -> Option<Block> {
        let input = LineInput { text, file: self.file, offset, spec: self.spec };
        let syntax = self.front.parse_line(&input, exprs, diags)?;
        let block = lower_line(syntax, self.spec, exprs, diags);
        self.structure.block(self.index, &block, exprs);
        self.index += 1;
        Some(block)
    }

    /// Ends the program: the checks that need all of it.
    pub fn finish(self) -> Vec<Diagnostic> {
        self.structure.finish()
    }
}

/// Splits text into lines without their endings (`\n` or `\r\n`), with the
/// byte offset of each line's start.
pub fn lines(text: &str) -> impl Iterator<Item = (&str, u32)> {
    let mut offset = 0usize;
    text.split_inclusive('\n').map(move |raw| {
        let start = offset;
        offset += raw.len();
        let line = raw.strip_suffix('\n').unwrap_or(raw);
        let line = line.strip_suffix('\r').unwrap_or(line);
        (line, start as u32)
    })
}

/// Reads a whole program.
pub fn read_program(text: &str, file: FileId, spec: &DialectSpec) -> (Program, Vec<Diagnostic>) {
    let mut program = Program::new(file, spec.id.clone());
    let mut diags = Vec::new();
    let mut reader = Reader::new(spec, file);
    for (line, offset) in lines(text) {
        if let Some(b) = reader.line(line, offset, &mut program.exprs, &mut diags) {
            program.blocks.push(b);
        }
    }
    diags.extend(reader.finish());
    (program, diags)
}

/// Decodes a file's bytes: UTF-8 when valid, otherwise each line that is
/// not valid UTF-8 as Latin-1 (old controllers' files), so that no byte is
/// lost. Offsets in the result are offsets in the decoded text.
pub fn decode(bytes: &[u8]) -> String {
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_owned(),
        Err(_) => {
            let mut out = String::with_capacity(bytes.len());
            for line in bytes.split_inclusive(|&b| b == b'\n') {
                decode_line_into(line, &mut out);
            }
            out
        }
    }
}

fn decode_line_into(line: &[u8], out: &mut String) {
    match std::str::from_utf8(line) {
        Ok(s) => out.push_str(s),
        Err(_) => out.extend(line.iter().map(|&b| b as char)),
    }
}

/// What a streamed check found.
pub struct StreamResult {
    pub diagnostics: Vec<Diagnostic>,
    /// The lines the diagnostics point at, for rendering.
    pub kept_lines: Vec<KeptLine>,
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
    let mut input = input;
    let mut reader = Reader::new(spec, file);
    let mut exprs = Arena::new();
    let mut diags = Vec::new();
    let mut kept = Vec::new();
    let mut raw = Vec::new();
    let mut text = String::new();
    let (mut offset, mut line_no) = (0u64, 0u64);
    loop {
        raw.clear();
        if input.read_until(b'\n', &mut raw)? == 0 {
            break;
        }
        text.clear();
        decode_line_into(&raw, &mut text);
        let line = text.strip_suffix('\n').unwrap_or(&text);
        let line = line.strip_suffix('\r').unwrap_or(line);
        let off = u32::try_from(offset).map_err(|_| too_large())?;
        let before = diags.len();
        if let Some(b) = reader.line(line, off, &mut exprs, &mut diags) {
            on_block(&b, &exprs);
        }
        if diags.len() > before && kept.len() < crate::diag::MAX_KEPT {
            kept.push(KeptLine { line: line_no as usize, start: offset as usize, text: line.to_owned() });
        }
        if diags.len() > crate::diag::MAX_KEPT {
            diags.truncate(crate::diag::MAX_KEPT);
        }
        exprs.clear();
        offset += text.len() as u64;
        line_no += 1;
    }
    diags.extend(reader.finish());
    Ok(StreamResult { diagnostics: diags, kept_lines: kept, bytes: offset, lines: line_no })
}

fn too_large() -> std::io::Error {
    std::io::Error::new(std::io::ErrorKind::InvalidData, "file larger than 4 GiB")
}

/// Loads subprograms from files beside the main program:
/// `o<name> call` → `name.ngc`; `M98 P1000` → `O1000.nc`, `1000.nc`, ...
/// (any extension the dialect claims), read with the same dialect.
pub struct FsLoader<'a> {
    dir: std::path::PathBuf,
    spec: std::sync::Arc<DialectSpec>,
    files: &'a mut crate::source::SourceMap,
    /// Diagnostics from reading the loaded files.
    pub diags: Vec<Diagnostic>,
}

impl<'a> FsLoader<'a> {
    pub fn new(dir: std::path::PathBuf, spec: std::sync::Arc<DialectSpec>, files: &'a mut crate::source::SourceMap) -> Self {
        FsLoader { dir, spec, files, diags: Vec::new() }
    }

    fn candidates(&self, target: &crate::ir::CallTarget) -> Vec<std::path::PathBuf> {
        use crate::ir::CallTarget;
        let stems: Vec<String> = match target {
            CallTarget::Name(n) => {
                let n = n.trim_matches(|c| c == '<' || c == '>');
                vec![n.to_string(), n.to_ascii_lowercase(), n.to_ascii_uppercase()]
            }
            CallTarget::Number(n) => vec![format!("O{n}"), format!("O{n:04}"), format!("o{n}"), n.to_string(), format!("L{n}")],
            CallTarget::Computed(_) => Vec::new(),
        };
        let mut exts: Vec<String> = self.spec.extensions.clone();
        exts.extend(["ngc", "nc", "NC", "spf", "SPF", "mpf", "MPF"].map(String::from));
        let mut out = Vec::new();
        for s in &stems {
            out.push(self.dir.join(s));
            for e in &exts {
                out.push(self.dir.join(format!("{s}.{e}")));
            }
        }
        out
    }
}

impl crate::interp::flow::ProgramLoader for FsLoader<'_> {
    fn load(&mut self, target: &crate::ir::CallTarget) -> Option<std::rc::Rc<Program>> {
        let path = self.candidates(target).into_iter().find(|p| p.is_file())?;
        let text = decode(&std::fs::read(&path).ok()?);
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
    let mut input = input;
    let (mut raw, mut text) = (Vec::new(), String::new());
    let (mut offset, mut line_no, mut next) = (0u64, 0usize, 0usize);
    let mut out = Vec::new();
    while next < wanted.len() {
        raw.clear();
        if input.read_until(b'\n', &mut raw)? == 0 {
            break;
        }
        text.clear();
        decode_line_into(&raw, &mut text);
        let end = offset + text.len() as u64;
        if wanted[next] < end || (wanted[next] == end && !text.ends_with('\n')) {
            let line = text.strip_suffix('\n').unwrap_or(&text);
            let line = line.strip_suffix('\r').unwrap_or(line);
            out.push(KeptLine { line: line_no, start: offset as usize, text: line.to_owned() });
            while next < wanted.len() && wanted[next] <= end {
                next += 1;
            }
        }
        offset = end;
        line_no += 1;
    }
    Ok(out)
}
