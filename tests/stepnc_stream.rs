//! `cncc stepnc` streams: the run is raised as it comes (CC1 event by
//! event; CC2 made into cuts as it comes, kept packed) and the writer
//! drops each toolpath once written. The Part 21 text must be the one the
//! whole event list and a borrowed project give, on the test programs,
//! for both conformance classes.

use cncc::dialect::builtin::builtin;
use cncc::interp::{tooltable::ToolTable, Options};
use cncc::ir::LengthUnit;
use cncc::raise::{raise_events, raise_file, Level, RaiseOptions, Raised, Stock};
use cncc::source::SourceMap;
use cncc::stepnc::{write_owned_project_to, write_project};
use std::path::Path;

/// The programs, their dialect, tool table and stock.
const PROGRAMS: &[(&str, &str, &str, Option<&str>)] = &[
    (
        "raise/part.nc",
        "fanuc",
        "raise/part.tbl",
        Some("120x80x30"),
    ),
    (
        "raise/part.mpf",
        "siemens840d",
        "raise/part.tbl",
        Some("120x80x30"),
    ),
    ("raise/part.nc", "fanuc", "raise/part.tbl", None),
    ("raise2/cc2part.nc", "fanuc", "raise2/cc2part.tbl", None),
    (
        "raise2/cc2part.mpf",
        "siemens840d",
        "raise2/cc2part.tbl",
        Some("120x80x21"),
    ),
    ("raise2/camlike.nc", "fanuc", "raise2/cc2part.tbl", None),
];

struct Setup {
    run: Options,
    opts: RaiseOptions,
    files: SourceMap,
}

fn setup(table: &str, stock: Option<&str>, level: Level) -> Setup {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/programs");
    let text = std::fs::read_to_string(root.join(table)).unwrap();
    let mut files = SourceMap::default();
    let tid = files.add(table, text.clone());
    let (table, _) = ToolTable::parse(&text, tid);
    let mut run = Options::default();
    run.tool_table = table.clone();
    run.machine_units = LengthUnit::Mm;
    let mut opts = RaiseOptions::new(level, "part");
    opts.stock = stock.map(|s| Stock::parse(s).unwrap());
    opts.tool_table = table;
    opts.table_units = LengthUnit::Mm;
    Setup { run, opts, files }
}

/// Raised as `cncc stepnc` does: streamed from the file.
fn streamed(file: &str, dialect: &str, s: &mut Setup) -> Raised {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/programs")
        .join(file);
    let id = s.files.add_sparse(file.to_string(), Vec::new());
    let spec = builtin(dialect).unwrap();
    raise_file(&path, id, &spec, &s.run, &s.opts, &mut s.files).unwrap()
}

/// Raised from the run's whole event list, with the run's diagnostics
/// first (as [`raise_file`] gives them).
fn whole(file: &str, dialect: &str, s: &mut Setup) -> Raised {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/programs")
        .join(file);
    let id = s.files.add_sparse(file.to_string(), Vec::new());
    let spec = builtin(dialect).unwrap();
    let (events, mut diags) =
        cncc::toolpath::events_of_file(&path, id, &spec, &s.run, &mut s.files).unwrap();
    let mut raised = raise_events(&events, &s.opts);
    diags.append(&mut raised.diagnostics);
    raised.diagnostics = diags;
    raised
}

#[test]
fn streamed_raising_and_writing_give_the_whole_paths_text() {
    for level in [Level::Cc1, Level::Cc2] {
        for &(file, dialect, table, stock) in PROGRAMS {
            let what = format!("{file} {dialect} {level:?} stock {stock:?}");
            // Each from a fresh source map: the spans name the same files.
            let a = streamed(file, dialect, &mut setup(table, stock, level));
            let b = whole(file, dialect, &mut setup(table, stock, level));
            let text = write_project(&b.project);
            assert!(
                text.contains("MACHINING_WORKINGSTEP"),
                "{what}: no workingstep"
            );
            assert_eq!(
                write_project(&a.project),
                text,
                "{what}: raised differently"
            );
            let codes = |r: &Raised| -> Vec<String> {
                r.diagnostics.iter().map(|d| format!("{d:?}")).collect()
            };
            assert_eq!(codes(&a), codes(&b), "{what}: other diagnostics");
            let mut owned = Vec::new();
            write_owned_project_to(a.project, &[], &mut owned).unwrap();
            assert_eq!(
                String::from_utf8(owned).unwrap(),
                text,
                "{what}: written differently"
            );
        }
    }
}
