//! STEP-NC (ISO 14649 ARM, Part 21): the typed model ([`model`]) that
//! programs are raised into, Part 21 files are read into and written
//! from, and post-processors read.
//!
//! Reading: text → [`part21`] generic instance graph (with spans) →
//! [`schema`] validation (entities, argument counts and kinds, references)
//! → [`read`] typed model in internal units. Writing: model → [`write`]
//! generic graph (shared value objects, depth-first numbering) → text.
//! [`query`] answers attribute paths over the generic graph; [`diff`]
//! compares two files' models.

pub mod ap238;
pub mod diff;
pub mod model;
pub mod model_geom;
pub mod part21;
pub mod query;
pub mod read;
pub mod schema;
pub mod units;
pub mod write;

use crate::diag::{Code, Diagnostic};
use crate::source::SourceMap;
use crate::span::{FileId, Span};
use part21::P21File;
use std::path::Path;

pub use write::{
    write_owned_project_to, write_project, write_project_to, write_project_with_header,
};

/// FILE_SCHEMA names of ISO 14649 ARM files (read).
const ARM_SCHEMAS: &[&str] = &["MACHINING_SCHEMA", "MILLING_SCHEMA", "COMBINED_SCHEMA"];

/// What reading a Part 21 text gives: the generic graph, the model when
/// the file makes one without errors, and every diagnostic.
pub struct ReadResult {
    pub graph: P21File,
    pub project: Option<model::Project>,
    pub diagnostics: Vec<Diagnostic>,
}

/// Whether a file is Part 21: by its extension (.stp, .step, .p21,
/// .stpnc) or its first word `ISO-10303-21;`.
pub fn is_part21(path: &Path, head: &str) -> bool {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if matches!(ext.as_deref(), Some("stp" | "step" | "p21" | "stpnc")) {
        return true;
    }
    head.trim_start_matches('\u{feff}')
        .trim_start()
        .starts_with("ISO-10303-21")
}

/// Reads a Part 21 text (already registered as `file` in a SourceMap).
pub fn read_text(text: &str, file: FileId) -> ReadResult {
    let (graph, mut diagnostics) = part21::parse::parse(text, file);
    if let Some(d) = unsupported_schema(&graph, file) {
        diagnostics.push(d);
        return ReadResult {
            graph,
            project: None,
            diagnostics,
        };
    }
    if graph.schemas().iter().any(|s| ap238::is_aim_schema(s)) {
        let (project, d) = ap238::read_project(&graph);
        diagnostics.extend(d);
        return ReadResult {
            graph,
            project,
            diagnostics,
        };
    }
    diagnostics.extend(schema::validate(&graph));
    let mut project = None;
    if !diagnostics.iter().any(Diagnostic::is_error) {
        let (p, d) = read::read_project(&graph);
        project = p;
        diagnostics.extend(d);
    }
    ReadResult {
        graph,
        project,
        diagnostics,
    }
}

/// Reads a Part 21 file, registering it in `files` for the diagnostics'
/// spans.
pub fn read_file(path: &Path, files: &mut SourceMap) -> std::io::Result<ReadResult> {
    let bytes = crate::cli::context::read_limited(path, crate::cli::context::MAX_INPUT)?;
    let text = crate::driver::decode(&bytes);
    drop(bytes);
    let id = files.add(path.display().to_string(), text);
    Ok(read_text(files.text(id), id))
}

/// E0806 for a FILE_SCHEMA that is not ISO 14649 ARM.
fn unsupported_schema(graph: &P21File, file: FileId) -> Option<Diagnostic> {
    let schemas = graph.schemas();
    let span = graph
        .header_record("FILE_SCHEMA")
        .map_or(Span::new(file, 0, 0), |r| r.span);
    if schemas.is_empty() {
        return Some(
            Diagnostic::new(Code::UnsupportedSchema, "the file names no FILE_SCHEMA")
                .primary(span, "no schema")
                .help("an ISO 14649 file has FILE_SCHEMA(('MACHINING_SCHEMA','MILLING_SCHEMA'));"),
        );
    }
    let foreign: Vec<&String> = schemas
        .iter()
        .filter(|s| !ARM_SCHEMAS.contains(&s.split_whitespace().next().unwrap_or("")))
        .filter(|s| !(schemas.len() == 1 && ap238::is_aim_schema(s)))
        .collect();
    if foreign.is_empty() {
        return None;
    }
    let aim = foreign.iter().any(|s| {
        s.starts_with("INTEGRATED_CNC_SCHEMA")
            || s.starts_with("MODEL_BASED_INTEGRATED_MANUFACTURING")
    });
    let mut d = Diagnostic::new(
        Code::UnsupportedSchema,
        format!("unsupported schema {}", foreign[0]),
    )
    .primary(span, "not an ISO 14649 ARM schema");
    d = if aim {
        d.note("this is an AP238 ed.2+ AIM file: the same concepts mapped onto generic STEP resources; cncc reads the toolpaths of AP238 ed.1 (INTEGRATED_CNC_SCHEMA) files only")
            .help("export the ISO 14649 ARM form (MACHINING_SCHEMA, MILLING_SCHEMA) or AP238 ed.1 instead")
    } else {
        d.help(
            "cncc reads ISO 14649 ARM files: MACHINING_SCHEMA, MILLING_SCHEMA or COMBINED_SCHEMA",
        )
    };
    Some(d)
}

/// For fuzz targets: whatever the bytes, reading (and writing what reads,
/// and reading that again, and querying) must not panic, hang or blow up.
pub fn fuzz_read_write(data: &[u8]) {
    let text = crate::driver::decode(data);
    let r = read_text(&text, FileId(0));
    let _ = query::query(&r.graph, "/project/main_workplan/its_elements[*]/its_id");
    if let Some(p) = r.project {
        let out = write_project(&p);
        let again = read_text(&out, FileId(1));
        assert!(
            !again.diagnostics.iter().any(Diagnostic::is_error),
            "cncc's own output does not read back"
        );
    }
}
