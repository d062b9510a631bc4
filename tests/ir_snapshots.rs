//! The meta-model of our own test programs, one per dialect, covering the
//! constructs of each front end (read each snapshot: it is the spec of what
//! the front end understands).

mod common;
use common::*;

fn ir(dialect: &str, file: &str) -> String {
    let o = cncc(&["ir", "--dialect", dialect, file]);
    assert_eq!(o.status.code(), Some(0), "{file}: {}", stderr(&o));
    stdout(&o)
}

#[test]
fn fanuc_bracket() {
    insta::assert_snapshot!(ir("fanuc", "tests/programs/fanuc/bracket.nc"));
}

#[test]
fn haas_plate() {
    insta::assert_snapshot!(ir("haas", "tests/programs/haas/plate.nc"));
}

#[test]
fn linuxcnc_subs() {
    insta::assert_snapshot!(ir("linuxcnc", "tests/programs/linuxcnc/subs.ngc"));
}

#[test]
fn siemens_plate() {
    insta::assert_snapshot!(ir("siemens840d", "tests/programs/siemens840d/plate.mpf"));
}

#[test]
fn fanuc_macro() {
    insta::assert_snapshot!(ir("fanuc", "tests/programs/fanuc/macro.nc"));
}

#[test]
fn linuxcnc_flow() {
    insta::assert_snapshot!(ir("linuxcnc", "tests/programs/linuxcnc/flow.ngc"));
}

#[test]
fn siemens_control() {
    insta::assert_snapshot!(ir("siemens840d", "tests/programs/siemens840d/control.mpf"));
}
