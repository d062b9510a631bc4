//! The files a run has read, for rendering diagnostics with codespan.
//!
//! A file is either held whole ([`SourceMap::add`]) or, for streamed inputs,
//! only as the lines that diagnostics point at ([`SourceMap::add_sparse`]).
//! A sparse file is rendered from a text made of its kept lines: spans keep
//! real-file offsets and are mapped with [`SourceMap::to_view`].

use crate::span::FileId;
use codespan_reporting::files::{self, Files};
use std::ops::Range;
use std::sync::{Arc, OnceLock};

/// One line of a file kept for rendering a streamed file's diagnostics.
#[derive(Clone, Debug)]
pub struct KeptLine {
    /// Zero-based line index in the real file.
    pub line: usize,
    /// Byte offset of the line's start in the real file.
    pub start: usize,
    /// The line's text, without its line ending.
    pub text: String,
}

struct SourceFile {
    name: String,
    /// The text codespan sees: the whole file, or the kept lines joined.
    view: Text,
    /// Byte offset in `view` of each line start, found when a diagnostic
    /// first needs them (a large file without one never pays for them).
    view_starts: OnceLock<Vec<usize>>,
    /// For a sparse file: (real line index, real start offset) per view line.
    sparse: Option<Vec<(usize, usize)>>,
}

/// A file's text: owned by the map, or shared with the command that
/// reads it (a large input is held once, not copied into the map).
enum Text {
    Owned(String),
    Shared(Arc<String>),
}

impl Text {
    fn as_str(&self) -> &str {
        match self {
            Text::Owned(s) => s,
            Text::Shared(s) => s.as_str(),
        }
    }
}

impl SourceFile {
    fn new(name: String, view: Text) -> Self {
        SourceFile {
            name,
            view,
            view_starts: OnceLock::new(),
            sparse: None,
        }
    }

    fn text(&self) -> &str {
        self.view.as_str()
    }

    fn starts(&self) -> &[usize] {
        self.view_starts.get_or_init(|| line_starts(self.text()))
    }
}

/// Every source file of a run, by [`FileId`].
#[derive(Default)]
pub struct SourceMap {
    files: Vec<SourceFile>,
}

/// Line starts: after each LF, and after each lone CR past the last LF
/// (a CR-only file), as the driver reads lines.
fn line_starts(text: &str) -> Vec<usize> {
    let b = text.as_bytes();
    let last_lf = b.iter().rposition(|&c| c == b'\n');
    std::iter::once(0)
        .chain(b.iter().enumerate().filter_map(|(i, &c)| {
            let lone_cr = c == b'\r' && last_lf.is_none_or(|l| i > l);
            (c == b'\n' || (lone_cr && b.get(i + 1) != Some(&b'\n'))).then_some(i + 1)
        }))
        .collect()
}

impl SourceMap {
    pub fn new() -> Self {
        Self::default()
    }

    /// The number of files.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    pub fn is_empty(&self) -> bool {
        self.files.is_empty()
    }

    /// A map for a task that runs beside others: the ids below `self`'s
    /// length stand for `self`'s files (they hold nothing there), new
    /// files get the ids after them; [`SourceMap::absorb`] takes them back.
    pub fn branch(&self) -> SourceMap {
        let empty = || SourceFile::new(String::new(), Text::Owned(String::new()));
        SourceMap {
            files: (0..self.files.len()).map(|_| empty()).collect(),
        }
    }

    /// Takes the files a [`SourceMap::branch`] of this map added; gives
    /// the id each of the branch's ids now has.
    pub fn absorb(&mut self, branch: SourceMap, shared: usize) -> impl Fn(FileId) -> FileId {
        let base = self.files.len() as u32;
        self.files.extend(branch.files.into_iter().skip(shared));
        let shared = shared as u32;
        move |id: FileId| {
            if id.0 < shared {
                id
            } else {
                FileId(base + id.0 - shared)
            }
        }
    }

    /// Adds a file held whole.
    pub fn add(&mut self, name: impl Into<String>, text: impl Into<String>) -> FileId {
        self.push(SourceFile::new(name.into(), Text::Owned(text.into())))
    }

    /// Adds a file held whole whose text the caller keeps too (shared,
    /// not copied).
    pub fn add_shared(&mut self, name: impl Into<String>, text: Arc<String>) -> FileId {
        self.push(SourceFile::new(name.into(), Text::Shared(text)))
    }

    fn push(&mut self, f: SourceFile) -> FileId {
        self.files.push(f);
        FileId(self.files.len() as u32 - 1)
    }

    /// Adds a file known only by some of its lines.
    pub fn add_sparse(&mut self, name: impl Into<String>, lines: Vec<KeptLine>) -> FileId {
        let id = self.add(name, String::new());
        self.set_sparse(id, lines);
        id
    }

    /// Replaces the text of a file by some of its lines.
    pub fn set_sparse(&mut self, id: FileId, mut lines: Vec<KeptLine>) {
        lines.sort_by_key(|l| l.line);
        lines.dedup_by_key(|l| l.line);
        let f = &mut self.files[id.0 as usize];
        let mut view = String::new();
        let mut starts = Vec::with_capacity(lines.len().max(1));
        let mut map = Vec::with_capacity(lines.len());
        for l in lines {
            starts.push(view.len());
            view.push_str(&l.text);
            view.push('\n');
            map.push((l.line, l.start));
        }
        if starts.is_empty() {
            starts.push(0);
        }
        f.view = Text::Owned(view);
        f.view_starts = OnceLock::from(starts);
        f.sparse = Some(map);
    }

    /// Whether the file is known only by some of its lines.
    pub fn is_sparse(&self, id: FileId) -> bool {
        self.files[id.0 as usize].sparse.is_some()
    }

    pub fn name(&self, id: FileId) -> &str {
        &self.files[id.0 as usize].name
    }

    /// The text of a file held whole (the kept lines of a sparse one).
    /// Takes a file's text back (its spans then show nothing): a large
    /// output is read back and reported on without being held twice.
    pub fn take_text(&mut self, id: FileId) -> String {
        let f = &mut self.files[id.0 as usize];
        f.view_starts = OnceLock::new();
        match std::mem::replace(&mut f.view, Text::Owned(String::new())) {
            Text::Owned(s) => s,
            Text::Shared(s) => Arc::unwrap_or_clone(s),
        }
    }

    pub fn text(&self, id: FileId) -> &str {
        self.files[id.0 as usize].text()
    }

    /// Maps a real-file byte offset to an offset in the rendered text.
    pub fn to_view(&self, id: FileId, offset: usize) -> usize {
        let f = &self.files[id.0 as usize];
        match &f.sparse {
            None => offset.min(f.text().len()),
            Some(map) => {
                let i = map
                    .partition_point(|&(_, start)| start <= offset)
                    .saturating_sub(1);
                match map.get(i) {
                    Some(&(_, start)) => {
                        let vs = f.starts()[i];
                        let ve = f
                            .starts()
                            .get(i + 1)
                            .map(|e| e - 1)
                            .unwrap_or(f.text().len());
                        (vs + offset.saturating_sub(start)).min(ve)
                    }
                    None => 0,
                }
            }
        }
    }

    /// One-based line and column (in characters) of a real-file byte offset.
    pub fn line_col(&self, id: FileId, offset: usize) -> (usize, usize) {
        let f = &self.files[id.0 as usize];
        let v = self.to_view(id, offset);
        let li = f.starts().partition_point(|&s| s <= v).saturating_sub(1);
        let start = f.starts()[li];
        let col = f
            .text()
            .get(start..v)
            .map(|s| s.chars().count())
            .unwrap_or(v - start);
        (self.real_line(f, li) + 1, col + 1)
    }

    fn real_line(&self, f: &SourceFile, view_line: usize) -> usize {
        match &f.sparse {
            None => view_line,
            Some(map) => map.get(view_line).map(|&(l, _)| l).unwrap_or(view_line),
        }
    }
}

impl<'a> Files<'a> for SourceMap {
    type FileId = usize;
    type Name = &'a str;
    type Source = &'a str;

    fn name(&'a self, id: usize) -> Result<&'a str, files::Error> {
        self.files
            .get(id)
            .map(|f| f.name.as_str())
            .ok_or(files::Error::FileMissing)
    }

    fn source(&'a self, id: usize) -> Result<&'a str, files::Error> {
        self.files
            .get(id)
            .map(|f| f.text())
            .ok_or(files::Error::FileMissing)
    }

    fn line_index(&'a self, id: usize, byte_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        Ok(f.starts()
            .partition_point(|&s| s <= byte_index)
            .saturating_sub(1))
    }

    fn line_number(&'a self, id: usize, line_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        Ok(self.real_line(f, line_index) + 1)
    }

    fn line_range(&'a self, id: usize, line_index: usize) -> Result<Range<usize>, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        let starts = f.starts();
        let start = *starts.get(line_index).ok_or(files::Error::LineTooLarge {
            given: line_index,
            max: starts.len() - 1,
        })?;
        let end = starts
            .get(line_index + 1)
            .copied()
            .unwrap_or(f.text().len());
        Ok(start..end)
    }
}
