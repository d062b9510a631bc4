//! Tools a program's tool list gives, through a port to a target whose
//! tool table must list every tool (LinuxCNC) and back (issue 13): the
//! proof runs both programs with the tools their CAM header lists, as
//! `check` runs them, and a tool called by name is numbered and listed
//! at the head of the port, `(T1001 - DRILL 6)`, so the port reads back.

mod common;
use common::*;
use std::path::Path;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// Ports `src` (read as `from`) to `to` with `--verify`: the written text.
fn port(src: &str, from: &str, to: &str, out: &Path) -> String {
    port_verified(Path::new(src), Some(from), to, out)
        .unwrap_or_else(|e| panic!("{from} -> {to}: {e}"))
}

const FUSION: &str = "%\nO1000\n\
(T23 D=0.375 CR=0. TAPER=90DEG - ZMIN=-0.2 - SPOT DRILL)\n\
G90 G94 G17 G20\nT23 M6\nS2000 M3\nG54 G0 X1. Y1.\nG43 Z1. H23\n\
G81 X1. Y1. Z-0.2 R0.1 F10.\nX2.\nG80\nG0 Z1.\nM30\n%\n";

#[test]
fn a_tool_the_cam_header_lists_ports_to_linuxcnc_and_back() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "a.nc", FUSION);
    let there = dir.path().join("a.ngc");
    let text = port(&src, "fanuc", "linuxcnc", &there);
    assert!(text.contains("(T23 D=0.375"), "the header stays:\n{text}");
    // T23 is not in the built-in table: the LinuxCNC program runs with
    // the tool its header lists, as `check` runs it.
    let back = dir.path().join("a2.nc");
    port(there.to_str().unwrap(), "linuxcnc", "fanuc", &back);
}

const NAMED: &str = "0 BEGIN PGM B MM\n\
1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+100 Z+0\n\
3 TOOL CALL \"DRILL 6\" Z S2000\n4 L Z+50 R0 FMAX M3\n5 L X+10 Y+10 R0 FMAX\n\
6 L Z+2 R0 FMAX\n7 L Z-5 R0 F100\n8 L Z+50 R0 FMAX\n9 END PGM B MM\n";

#[test]
fn a_tool_called_by_name_is_listed_for_linuxcnc_and_ports_back() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "b.h", NAMED);
    let there = dir.path().join("b.ngc");
    let text = port(&src, "heidenhain", "linuxcnc", &there);
    assert!(text.contains("(T1001 - DRILL 6)"), "{text}");
    assert!(text.contains("T1001"), "{text}");
    let check = cncc(&["check", "--dialect", "linuxcnc", there.to_str().unwrap()]);
    assert_eq!(check.status.code(), Some(0), "{}", stderr(&check));
    let back = dir.path().join("b2.h");
    port(there.to_str().unwrap(), "linuxcnc", "heidenhain", &back);
}

#[test]
fn a_tool_no_list_gives_still_needs_the_table() {
    // The list is what makes the tool known: without it LinuxCNC refuses.
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "c.ngc", "G21 G90\nT1001 M6\nG0 X0 Y0 Z5\nM2\n");
    let o = cncc(&["check", "--dialect", "linuxcnc", &src]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stderr(&o).contains("E0501"), "{}", stderr(&o));
}
