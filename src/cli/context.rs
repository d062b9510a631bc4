//! What every command needs: the dialect registry (built-ins plus
//! `--dialect-file` specs), the source map, and choosing a file's dialect.

use crate::cli::args::{Cli, ColorChoice, Format};
use crate::cli::output::print_diagnostics;
use crate::diag::Diagnostic;
use crate::dialect::{detect, DialectSpec, Registry};
use crate::source::SourceMap;
use crate::span::FileId;
use std::path::Path;
use std::sync::Arc;

/// Exit codes of the command-line contract.
pub const EXIT_OK: i32 = 0;
pub const EXIT_INPUT_ERRORS: i32 = 1;
pub const EXIT_USAGE: i32 = 2;

pub struct Context {
    pub registry: Registry,
    pub files: SourceMap,
    pub color: ColorChoice,
    /// Notes for stderr that a multi-file command prints in input order,
    /// before the diagnostics (the dialect each file was read as).
    pub notes: Vec<String>,
    /// The user's post templates (`--post-dir`).
    pub post_dir: Option<crate::post::PostDir>,
}

/// A usage or I/O failure: message for stderr, exit 2.
#[derive(Debug)]
pub struct Failure(pub String);

impl From<std::io::Error> for Failure {
    fn from(e: std::io::Error) -> Self {
        Failure(e.to_string())
    }
}

impl From<Diagnostic> for Failure {
    /// A diagnostic about the command line itself (no place in a file).
    fn from(d: Diagnostic) -> Self {
        let mut s = format!("{} [{} {}]", d.message, d.code.code(), d.code.name());
        for n in &d.notes {
            s.push_str(&format!("\n  = note: {n}"));
        }
        if let Some(h) = &d.help {
            s.push_str(&format!("\n  = help: {h}"));
        }
        Failure(s)
    }
}

impl Context {
    /// Loads the built-in dialects and the user's spec files. A broken spec
    /// is reported like a program error (exit 1).
    pub fn new(cli: &Cli, format: Format) -> Result<Context, i32> {
        let mut ctx = Context {
            registry: Registry::with_builtins(),
            files: SourceMap::new(),
            color: cli.color,
            notes: Vec::new(),
            post_dir: None,
        };
        if let Some(dir) = &cli.post_dir {
            match crate::post::PostDir::read(dir) {
                Ok(d) => ctx.post_dir = Some(d),
                Err(m) => {
                    eprintln!("error: cannot read the post templates: {m}");
                    return Err(EXIT_USAGE);
                }
            }
        }
        for path in &cli.dialect_files {
            let text = match read_text_limited(path, MAX_SIDE_FILE) {
                Ok(t) => t,
                Err(Failure(m)) => {
                    eprintln!("error: cannot read dialect spec {}: {m}", path.display());
                    return Err(EXIT_USAGE);
                }
            };
            let id = ctx.files.add(path.display().to_string(), text.clone());
            if let Err(diags) = ctx.registry.load(&text, id) {
                print_diagnostics(&diags, &ctx.files, format, ctx.color);
                return Err(EXIT_INPUT_ERRORS);
            }
        }
        Ok(ctx)
    }

    /// The spec for a dialect name (id or alias).
    pub fn spec(&self, name: &str) -> Result<Arc<DialectSpec>, Failure> {
        Ok(self.registry.resolve(name)?)
    }

    /// The spec for a file: the one asked for, or one chosen from the file's
    /// name and content (with the reason).
    pub fn spec_for(
        &self,
        asked: Option<&str>,
        path: &Path,
        text: &str,
    ) -> Result<(Arc<DialectSpec>, Option<String>), Failure> {
        match asked {
            Some(name) => Ok((self.spec(name)?, None)),
            None => {
                let d = detect(&self.registry, Some(path), text);
                Ok((self.spec(&d.id)?, Some(d.reason)))
            }
        }
    }

    /// Reads a source file and adds it to the source map.
    pub fn add_file(&mut self, path: &Path) -> Result<(FileId, String), Failure> {
        self.add_file_limited(path, MAX_INPUT)
    }

    /// A side file (tool table...): at most [`MAX_SIDE_FILE`] bytes.
    pub fn add_side_file(&mut self, path: &Path) -> Result<(FileId, String), Failure> {
        self.add_file_limited(path, MAX_SIDE_FILE)
    }

    fn add_file_limited(&mut self, path: &Path, limit: u64) -> Result<(FileId, String), Failure> {
        let text = read_text_limited(path, limit)?;
        let id = self.files.add(path.display().to_string(), text.clone());
        Ok((id, text))
    }

    /// [`Context::add_file`], with what the file's bytes were (for writing
    /// a result the same way).
    pub fn add_file_encoded(
        &mut self,
        path: &Path,
    ) -> Result<(FileId, Arc<String>, crate::encoding::SourceEncoding), Failure> {
        let bytes = read_limited(path, MAX_INPUT)
            .map_err(|e| Failure(format!("{}: {e}", path.display())))?;
        let encoding = crate::encoding::sniff(&bytes);
        let text = crate::driver::decode(&bytes);
        drop(bytes);
        let text = Arc::new(text);
        let id = self
            .files
            .add_shared(path.display().to_string(), text.clone());
        Ok((id, text, encoding))
    }

    pub fn print(&self, diags: &[Diagnostic], format: Format) {
        print_diagnostics(diags, &self.files, format, self.color);
    }
}

/// The largest program or STEP-NC file read whole.
pub const MAX_INPUT: u64 = 256 << 20;
/// The largest side file (tool table, dialect spec, tool map, stock).
pub const MAX_SIDE_FILE: u64 = 16 << 20;

/// Reads a file as text (Latin-1 for lines that are not UTF-8), up to
/// [`MAX_INPUT`] bytes.
pub fn read_text(path: &Path) -> Result<String, Failure> {
    read_text_limited(path, MAX_INPUT)
}

/// [`read_text`] with a size limit: a larger file (or an endless one such
/// as `/dev/zero`) is a clear error, never memory exhausted.
pub fn read_text_limited(path: &Path, limit: u64) -> Result<String, Failure> {
    let bytes =
        read_limited(path, limit).map_err(|e| Failure(format!("{}: {e}", path.display())))?;
    Ok(crate::driver::decode(&bytes))
}

/// A file's bytes, refused past `limit`.
pub fn read_limited(path: &Path, limit: u64) -> std::io::Result<Vec<u8>> {
    use std::io::Read;
    let mut bytes = Vec::new();
    std::fs::File::open(path)?
        .take(limit + 1)
        .read_to_end(&mut bytes)?;
    if bytes.len() as u64 > limit {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!("larger than {} MiB, the most cncc reads here", limit >> 20),
        ));
    }
    Ok(bytes)
}

/// Says which dialect was chosen and why, on stderr.
pub fn report_detection(path: &Path, spec: &DialectSpec, reason: &str) {
    eprintln!("{}", detection_note(path, spec, reason));
}

/// The note saying which dialect a file was read as, and why.
pub fn detection_note(path: &Path, spec: &DialectSpec, reason: &str) -> String {
    format!(
        "note: reading {} as {} ({reason}); use --dialect to choose",
        path.display(),
        spec.id
    )
}
