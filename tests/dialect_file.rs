//! `--dialect-file`: a user's own spec, loaded at run time, extends a
//! built-in dialect; a spec with mistakes is reported like a program.

mod common;
use common::*;

const PROGRAM: &str = "tests/programs/haas/probe-corner.nc";

#[test]
fn the_built_in_haas_does_not_know_the_shop_code() {
    let o = cncc(&["check", "--dialect", "haas", PROGRAM]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("E0203"), "{}", stderr(&o));
}

#[test]
fn a_shop_spec_extending_haas_adds_its_code() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/shop-haas.xml",
        "check",
        "--dialect",
        "vf2",
        PROGRAM,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    // Read clean; the shop's own code cannot be simulated, which `check`
    // says as a warning (W0511) rather than passing over it.
    assert!(!stderr(&o).contains("error["), "{}", stderr(&o));
    assert!(stderr(&o).contains("W0511"), "{}", stderr(&o));
    let o = cncc(&["--dialect-file", "tests/dialects/shop-haas.xml", "dialects"]);
    assert!(stdout(&o).contains("shop-haas"), "{}", stdout(&o));
}

#[test]
fn a_broken_spec_is_reported_with_places_in_the_xml() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/broken.xml",
        "check",
        PROGRAM,
    ]);
    assert_eq!(o.status.code(), Some(1));
    insta::assert_snapshot!("broken_spec", stderr(&o));
}

#[test]
fn a_missing_spec_file_is_an_io_error() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/nope.xml",
        "check",
        PROGRAM,
    ]);
    assert_eq!(o.status.code(), Some(2));
}

const BUILDER: &str = "tests/programs/fanuc/builder-g100.nc";

#[test]
fn a_builders_g_code_is_a_located_error_whose_help_names_the_dialect_file() {
    let o = cncc(&["check", "--dialect", "fanuc", BUILDER]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("E0203") && err.contains("builder-g100.nc:4:1"),
        "{err}"
    );
    assert!(
        err.contains("--dialect-file") && err.contains("number=\"100\""),
        "{err}"
    );
}

#[test]
fn a_dialect_file_for_the_machine_makes_it_check_clean() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/nomura-6mb.xml",
        "check",
        "--dialect",
        "nomura-6mb",
        BUILDER,
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("error["), "{}", stderr(&o));
    // `run="pass"`: the run goes past the macro and checks what follows.
    assert!(!stderr(&o).contains("W0511"), "{}", stderr(&o));
}

const RETURN: &str = "tests/programs/fanuc/builder-g28-g53.nc";

/// `G91 G28 G53 Z0. W0. H0` (a Kuraki boring mill's NX post): two codes
/// of Fanuc's group 00 in one block, which a stock Fanuc does not take.
/// The error's help gives the dialect-file line for a machine that does.
#[test]
fn two_one_shot_codes_in_a_block_are_an_error_whose_help_names_the_dialect_file() {
    let o = cncc(&["check", "--dialect", "fanuc", RETURN]);
    assert_eq!(o.status.code(), Some(1));
    let err = stderr(&o);
    assert!(
        err.contains("E0202") && err.contains("builder-g28-g53.nc:10:9"),
        "{err}"
    );
    assert!(
        err.contains("--dialect-file") && err.contains("together=\"ref-return.1 machine-coords\""),
        "{err}"
    );
    // The help is for builders' one-shot codes, not for modal groups.
    let dir = tempfile::tempdir().unwrap();
    let modal = dir.path().join("modal.nc");
    std::fs::write(&modal, "O1\nG90 G91 X1.\nM30\n").unwrap();
    let err = stderr(&cncc(&[
        "check",
        "--dialect",
        "fanuc",
        modal.to_str().unwrap(),
    ]));
    assert!(
        err.contains("E0202") && !err.contains("--dialect-file"),
        "{err}"
    );
}

#[test]
fn a_dialect_file_pairing_the_codes_makes_the_return_check_clean() {
    let o = cncc(&[
        "--dialect-file",
        "tests/dialects/kuraki-kbt.xml",
        "check",
        "--dialect",
        "kuraki-kbt",
        RETURN,
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(!err.contains("error[") && !err.contains("W0511"), "{err}");
}

/// `cncc dialects --spec ID` prints each built-in spec exactly as it is
/// built in, and that copy loads back with `--dialect-file`, replacing the
/// built-in of its id with the same listing.
#[test]
fn a_printed_builtin_spec_is_the_file_and_loads_back() {
    let dir = tempfile::tempdir().unwrap();
    let listing = stdout(&cncc(&["dialects"]));
    for id in [
        "iso6983",
        "fanuc",
        "haas",
        "linuxcnc",
        "siemens840d",
        "heidenhain",
    ] {
        let o = cncc(&["dialects", "--spec", id]);
        assert_eq!(o.status.code(), Some(0), "{id}: {}", stderr(&o));
        let built = std::fs::read_to_string(root().join(format!("dialects/{id}.xml"))).unwrap();
        assert_eq!(stdout(&o), built, "{id}");
        let copy = dir.path().join(format!("{id}.xml"));
        std::fs::write(&copy, stdout(&o)).unwrap();
        let copy = copy.to_str().unwrap();
        let o = cncc(&["--dialect-file", copy, "dialects"]);
        assert_eq!(o.status.code(), Some(0), "{id}: {}", stderr(&o));
        let mine = stdout(&o);
        let block = |s: &str| {
            s.split("\n\n")
                .find(|b| b.starts_with(&format!("{id}:")))
                .map(|b| b.trim_end().to_string())
        };
        assert_eq!(block(&mine), block(&listing), "{id}");
    }
}

#[test]
fn a_renamed_copy_of_a_builtin_spec_checks_programs() {
    let dir = tempfile::tempdir().unwrap();
    let text = stdout(&cncc(&["dialects", "--spec", "HAAS"]));
    let text = text.replacen("id=\"haas\"", "id=\"my-haas\"", 1);
    let copy = dir.path().join("my-haas.xml");
    std::fs::write(&copy, text).unwrap();
    let o = cncc(&[
        "--dialect-file",
        copy.to_str().unwrap(),
        "check",
        "--dialect",
        "my-haas",
        "tests/programs/haas/probe-corner.nc",
    ]);
    // The copy behaves as the built-in: the shop code is still unknown.
    assert_eq!(o.status.code(), Some(1), "{}", stderr(&o));
    assert!(stderr(&o).contains("E0203"), "{}", stderr(&o));
}

#[test]
fn asking_for_the_spec_of_an_unknown_dialect_is_a_usage_error() {
    let o = cncc(&["dialects", "--spec", "nonesuch"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("fanuc"), "{}", stderr(&o));
}
