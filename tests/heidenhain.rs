//! Heidenhain Klartext: the meta-model of our own programs (one per group of
//! constructs), the writer's round trip to a fixpoint, canonical calls of
//! the programs that run, and the diagnostics of programs with mistakes.
//! Read each snapshot: it is the spec of what the front end understands.

mod common;
use cncc::dialect::builtin::builtin;
use cncc::driver::read_program;
use cncc::emit::write_program;
use cncc::source::SourceMap;
use common::*;

const PROGRAMS: &[&str] = &[
    "tests/programs/heidenhain/paths.h",
    "tests/programs/heidenhain/approach.h",
    "tests/programs/heidenhain/params.h",
    "tests/programs/heidenhain/cycles.h",
    "tests/programs/heidenhain/run.h",
    "tests/programs/heidenhain/apprrun.h",
    "tests/programs/heidenhain/millrun.h",
    "tests/programs/samepart/part.h",
];

fn ir(file: &str) -> String {
    let o = cncc(&["ir", "--dialect", "heidenhain", file]);
    assert_eq!(o.status.code(), Some(0), "{file}: {}", stderr(&o));
    stdout(&o)
}

fn name(file: &str) -> String {
    std::path::Path::new(file)
        .file_stem()
        .unwrap()
        .to_string_lossy()
        .into_owned()
}

#[test]
fn meta_model_of_each_construct_group() {
    for f in PROGRAMS {
        insta::assert_snapshot!(format!("ir_{}", name(f)), ir(f));
    }
}

#[test]
fn written_klartext_of_each_program() {
    let spec = builtin("heidenhain").unwrap();
    for f in PROGRAMS {
        let text = std::fs::read_to_string(root().join(f)).unwrap();
        let mut sm = SourceMap::new();
        let id = sm.add(*f, text.clone());
        let (p, _) = read_program(&text, id, &spec);
        let out = write_program(&p, &spec)
            .unwrap_or_else(|d| panic!("{f}: {}", cncc::diag::render::human(&d, &sm, false)));
        insta::assert_snapshot!(format!("written_{}", name(f)), out);
    }
}

/// A fingerprint without the block numbers (the writer renumbers).
fn unnumbered(p: &cncc::ir::Program) -> String {
    model_fingerprint(p)
        .lines()
        .map(|l| match l.strip_prefix('N') {
            Some(r) if r.starts_with(|c: char| c.is_ascii_digit()) => r
                .trim_start_matches(|c: char| c.is_ascii_digit())
                .trim_start(),
            _ => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

#[test]
fn writer_round_trips_to_a_fixpoint() {
    let spec = builtin("heidenhain").unwrap();
    for f in PROGRAMS {
        let text = std::fs::read_to_string(root().join(f)).unwrap();
        let mut sm = SourceMap::new();
        let id = sm.add(*f, text.clone());
        let (p1, _) = read_program(&text, id, &spec);
        let out1 = write_program(&p1, &spec).expect("writes");
        let id2 = sm.add("written", out1.clone());
        let (p2, d2) = read_program(&out1, id2, &spec);
        let errors: Vec<_> = d2.into_iter().filter(|d| d.is_error()).collect();
        assert!(
            errors.is_empty(),
            "{f}: written text has errors:\n{}",
            cncc::diag::render::human(&errors, &sm, false)
        );
        if let Some(d) = first_difference(&unnumbered(&p1), &unnumbered(&p2)) {
            panic!("{f}: meta-model changed at {d}\n{out1}");
        }
        let out2 = write_program(&p2, &spec).expect("writes again");
        assert_eq!(out1, out2, "{f}: not a fixpoint");
    }
}

#[test]
fn canonical_calls_of_running_programs() {
    for f in [
        "tests/programs/heidenhain/paths.h",
        "tests/programs/heidenhain/run.h",
        "tests/programs/heidenhain/apprrun.h",
        "tests/programs/heidenhain/millrun.h",
        "tests/programs/heidenhain/tooldef.h",
    ] {
        // The sizes these programs were written for: cncc's built-in
        // table given as the shop's (without a table, a TNC's tools run
        // with no radius, W0592).
        let o = cncc(&[
            "canon",
            "--dialect",
            "heidenhain",
            "--tool-table",
            "tests/programs/builtin.tbl",
            f,
        ]);
        assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
        assert_eq!(stderr(&o), "", "{f}");
        insta::assert_snapshot!(format!("canon_{}", name(f)), stdout(&o));
    }
}

#[test]
fn mistakes_are_reported_in_heidenhain_terms() {
    for f in [
        "tests/programs/heidenhain/mistakes.h",
        "tests/programs/heidenhain/nocentre.h",
        "tests/programs/heidenhain/badcorner.h",
        "tests/programs/heidenhain/notangent.h",
    ] {
        let o = cncc(&["check", "--dialect", "heidenhain", f]);
        assert_eq!(o.status.code(), Some(1), "{f}: {}", stderr(&o));
        insta::assert_snapshot!(format!("check_{}", name(f)), stderr(&o));
    }
}

#[test]
fn clean_programs_check_silently() {
    for f in [
        "tests/programs/heidenhain/paths.h",
        "tests/programs/heidenhain/run.h",
        "tests/programs/samepart/part.h",
    ] {
        let o = cncc(&["check", "--dialect", "heidenhain", f]);
        assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
        assert_eq!(stderr(&o), "", "{f}");
    }
}

#[test]
fn detected_from_extension_and_begin_pgm() {
    let o = cncc(&["ir", "tests/programs/heidenhain/run.h"]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(
        stdout(&o).contains("program-start name=\"RUN\""),
        "{}",
        stdout(&o)
    );
    let dir = std::env::temp_dir().join(format!("cncc-tnc-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let f = dir.join("noext.txt");
    std::fs::write(&f, "0 BEGIN PGM X MM\n1 L X+1 FMAX\n2 END PGM X MM\n").unwrap();
    let o = cncc(&["ir", f.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).contains("program-end"), "{}", stdout(&o));
    let _ = std::fs::remove_dir_all(&dir);
}
