//! `cncc port --features` and the post → raise round trip: a program's
//! explicit toolpaths become the target's feature cycles, and a posted
//! program raised again to CC2 gives back the same features (compared by
//! meaning with `stepnc::diff::diff_projects`; operations, names and
//! tolerances are not compared: see `cncc::post::features`).

mod common;

use cncc::dialect::builtin;
use cncc::post::features::round_trip;
use std::path::Path;

fn shared(rel: &str) -> Option<std::path::PathBuf> {
    let p = common::root().join("../shared").join(rel);
    if p.exists() {
        Some(p)
    } else {
        eprintln!("note: ../shared/{rel} is absent; skipped");
        None
    }
}

fn read_stp(path: &Path) -> cncc::stepnc::model::Project {
    let mut files = cncc::source::SourceMap::new();
    let r = cncc::stepnc::read_file(path, &mut files).unwrap();
    assert!(
        !r.diagnostics.iter().any(|d| d.is_error()),
        "{:#?}",
        r.diagnostics
    );
    r.project.expect("a project")
}

fn assert_round_trip(p: &cncc::stepnc::model::Project, id: &str) {
    let spec = builtin(id).unwrap();
    let (text, v) = round_trip(p, &spec).unwrap_or_else(|e| panic!("{id}: {e:#?}"));
    assert!(v.same, "{id}: {:#?}\n{text}", v.lines);
    assert!(v.features > 0);
}

#[test]
fn ex1_posted_and_raised_again_gives_the_same_features() {
    let Some(ex1) = shared("stepnc-samples/ex1.stp") else {
        return;
    };
    let p = read_stp(&ex1);
    for id in ["fanuc", "siemens840d"] {
        assert_round_trip(&p, id);
    }
}
