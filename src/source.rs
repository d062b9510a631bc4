//! The files a run has read, for rendering diagnostics with codespan.
//!
//! A file is either held whole ([`SourceMap::add`]) or, for streamed inputs,
//! only as the lines that diagnostics point at ([`SourceMap::add_sparse`]).
//! A sparse file is rendered from a text made of its kept lines: spans keep
//! real-file offsets and are mapped with [`SourceMap::to_view`].

use crate::span::FileId;
use codespan_reporting::files::{self, Files};
use std::ops::Range;

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
    view: String,
    /// Byte offset in `view` of each line start.
    view_starts: Vec<usize>,
    /// For a sparse file: (real line index, real start offset) per view line.
    sparse: Option<Vec<(usize, usize)>>,
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
        let empty = || SourceFile {
            name: String::new(),
            view: String::new(),
            view_starts: vec![0],
            sparse: None,
        };
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
        let view = text.into();
        let view_starts = line_starts(&view);
        self.files.push(SourceFile {
            name: name.into(),
            view,
            view_starts,
            sparse: None,
        });
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
        f.view.clear();
        f.view_starts.clear();
        let mut map = Vec::with_capacity(lines.len());
        for l in lines {
            f.view_starts.push(f.view.len());
            f.view.push_str(&l.text);
            f.view.push('\n');
            map.push((l.line, l.start));
        }
        if f.view_starts.is_empty() {
            f.view_starts.push(0);
        }
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
        f.view_starts = line_starts("");
        std::mem::take(&mut f.view)
    }

    pub fn text(&self, id: FileId) -> &str {
        &self.files[id.0 as usize].view
    }

    /// Maps a real-file byte offset to an offset in the rendered text.
    pub fn to_view(&self, id: FileId, offset: usize) -> usize {
        let f = &self.files[id.0 as usize];
        match &f.sparse {
            None => offset.min(f.view.len()),
            Some(map) => {
                let i = map
                    .partition_point(|&(_, start)| start <= offset)
                    .saturating_sub(1);
                match map.get(i) {
                    Some(&(_, start)) => {
                        let vs = f.view_starts[i];
                        let ve = f
                            .view_starts
                            .get(i + 1)
                            .map(|e| e - 1)
                            .unwrap_or(f.view.len());
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
        let li = f.view_starts.partition_point(|&s| s <= v).saturating_sub(1);
        let start = f.view_starts[li];
        let col = f
            .view
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
            .map(|f| f.view.as_str())
            .ok_or(files::Error::FileMissing)
    }

    fn line_index(&'a self, id: usize, byte_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        Ok(f.view_starts
            .partition_point(|&s| s <= byte_index)
            .saturating_sub(1))
    }

    fn line_number(&'a self, id: usize, line_index: usize) -> Result<usize, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        Ok(self.real_line(f, line_index) + 1)
    }

    fn line_range(&'a self, id: usize, line_index: usize) -> Result<Range<usize>, files::Error> {
        let f = self.files.get(id).ok_or(files::Error::FileMissing)?;
        let start = *f
            .view_starts
            .get(line_index)
            .ok_or(files::Error::LineTooLarge {
                given: line_index,
                max: f.view_starts.len() - 1,
            })?;
        let end = f
            .view_starts
            .get(line_index + 1)
            .copied()
            .unwrap_or(f.view.len());
        Ok(start..end)
    }
}
