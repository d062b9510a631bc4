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
