//! Port paths into the target's own forms (issue 13): Siemens `SUPA` (a
//! block in machine coordinates) as the target's machine-coordinate
//! block, commands that change nothing cut (`FNORM`) as comments,
//! `G52 X Y Z` as the Klartext datum-shift cycle, and `G41 D4` with tool 4
//! in the spindle (another made ready) as Klartext `RL`. Each port is
//! verified and read back (ported back, verified) where it goes.

mod common;
use common::*;
use std::path::Path;

fn write(dir: &Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

/// Ports `src` to `to` with `--verify`: the written text, or the stderr.
fn port(src: &str, to: &str, out: &Path) -> Result<String, String> {
    port_verified(Path::new(src), None, to, out)
}

const SUPA: &str = "N10 G90 G71 G17 G94 FNORM\n\
N20 G0 X0 Y0 Z50\n\
N30 G1 Z-1 F100\n\
N40 G1 X20\n\
N50 G0 Z50\n\
N60 G0 SUPA Z0\n\
N70 G0 SUPA X0 Y0\n\
N80 M30\n";

#[test]
fn supa_rapids_become_machine_coordinate_blocks_and_fnorm_a_comment() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "supa.mpf", SUPA);
    for (to, ext, want) in [
        ("fanuc", "nc", "G0 Z0. G53"),
        ("haas", "nc", "G53"),
        ("linuxcnc", "ngc", "G0 Z0 G53"),
        ("heidenhain", "h", "L Z+0 FMAX M91"),
    ] {
        let out = dir.path().join(format!("supa-{to}.{ext}"));
        let text = port(&src, to, &out).unwrap_or_else(|e| panic!("{to}: {e}"));
        assert!(text.contains(want), "{to}: {text}");
        assert!(!text.contains("SUPA"), "{to}: {text}");
        assert!(
            text.contains("FNORM:"),
            "{to}: the comment naming it: {text}"
        );
        // The port reads back in the target and ports back, verified.
        let back = dir.path().join(format!("supa-{to}-back.mpf"));
        let text = port(out.to_str().unwrap(), "siemens840d", &back)
            .unwrap_or_else(|e| panic!("{to} back: {e}"));
        assert!(text.contains("G53") || text.contains("SUPA"), "{text}");
    }
}

#[test]
fn a_feed_in_machine_coordinates_ports_only_where_the_target_feeds_there() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "feed.mpf",
        "N10 G90 G71 G17 G94\nN20 G0 X0 Y0 Z50\nN30 G1 Z-1 F100\nN40 G1 X20\n\
         N50 G0 Z50\nN60 G1 SUPA X-5 F300\nN70 M30\n",
    );
    let out = dir.path().join("feed.ngc");
    let text = port(&src, "linuxcnc", &out).unwrap();
    assert!(text.contains("G1 X-5 G53 F300"), "{text}");
    let out = dir.path().join("feed.h");
    let text = port(&src, "heidenhain", &out).unwrap();
    assert!(text.contains("L X-5 F300 M91"), "{text}");
    // Fanuc's G53 moves at rapid [?]: refused, not written as work moves.
    let err = port(&src, "fanuc", &dir.path().join("feed.nc")).unwrap_err();
    assert!(err.contains("E0601"), "{err}");
    assert!(err.contains("machine coordinates"), "{err}");
}

#[test]
fn supa_runs_in_machine_coordinates_under_a_frame() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "frame.mpf",
        "N10 G90 G71 G0 X0 Y0 Z50\nN20 TRANS X10 Y5\nN30 G0 X0 Y0\nN40 G0 SUPA X0\nN50 G0 X1\nN60 M30\n",
    );
    let o = cncc(&["canon", &src]);
    let text = stdout(&o);
    let moves: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("STRAIGHT_TRAVERSE"))
        .collect();
    assert_eq!(moves.len(), 4, "{text}");
    assert!(
        moves[1].starts_with("STRAIGHT_TRAVERSE(10.0000, 5.0000,"),
        "{text}"
    );
    // SUPA: machine X0 whatever the frame; after it the frame holds again.
    assert!(
        moves[2].starts_with("STRAIGHT_TRAVERSE(0.0000, 5.0000,"),
        "{text}"
    );
    assert!(
        moves[3].starts_with("STRAIGHT_TRAVERSE(11.0000, 5.0000,"),
        "{text}"
    );
}

#[test]
fn a_local_shift_of_three_axes_is_the_klartext_datum_shift() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "g52.nc",
        "%\nO1000\nG90 G21 G17 G94 G54\nG0 X0 Y0 Z50.\nG52 X10. Y5. Z0\nG0 X0 Y0 Z5.\n\
         G1 Z-1. F100\nG1 X20.\nG0 Z50.\nG52 X0 Y0 Z0\nG0 X0 Y0\nM30\n%\n",
    );
    let out = dir.path().join("g52.h");
    let text = port(&src, "heidenhain", &out).unwrap();
    for l in [
        "CYCL DEF 7.0 DATUM SHIFT",
        "CYCL DEF 7.1 X+10",
        "CYCL DEF 7.2 Y+5",
        "CYCL DEF 7.3 Z+0",
    ] {
        assert!(text.contains(l), "{l}: {text}");
    }
    let back = dir.path().join("g52-back.nc");
    let text = port(out.to_str().unwrap(), "fanuc", &back).unwrap();
    assert!(text.contains("G52 X10. Y5. Z0."), "{text}");
}

#[test]
fn the_register_of_the_tool_in_the_spindle_is_klartext_rl() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "comp.nc",
        "%\nO1000\nG90 G21 G17 G94 G40\nT4 M6\nG0 G54 X0 Y0 T14\nS1000 M3\nG43 Z5. H4\n\
         G1 Z-1. F100\nG1 X10. Y-10. G41 D4\nG1 X30.\nG1 Y10.\nG1 G40 X40. Y20.\nG0 Z50.\nM30\n%\n",
    );
    let out = dir.path().join("comp.h");
    let text = port(&src, "heidenhain", &out).unwrap();
    assert!(text.contains("L X+10 Y-10 RL"), "{text}");
    let back = dir.path().join("comp-back.nc");
    let text = port(out.to_str().unwrap(), "fanuc", &back).unwrap();
    assert!(text.contains("G41"), "{text}");
    // D5 is another tool's register: still refused.
    let other = write(
        dir.path(),
        "other.nc",
        &std::fs::read_to_string(&src)
            .unwrap()
            .replace("G41 D4", "G41 D5"),
    );
    let err = port(&other, "heidenhain", &dir.path().join("other.h")).unwrap_err();
    assert!(err.contains("E0601"), "{err}");
}

#[test]
fn a_drilling_cycle_with_computed_planes_keeps_them_as_expressions() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "dpr.mpf",
        "N10 G90 G71 G17 G94\nN20 R1=2 R2=5\nN30 T1 D1 M6\nN40 S1000 M3 F100\n\
         N50 G0 X0 Y0 Z50\nN60 MCALL CYCLE81(R1+20,R1,2,,R2+1)\nN70 X10 Y10\nN80 X20\n\
         N90 MCALL\nN100 G0 Z50\nN110 M30\n",
    );
    let out = dir.path().join("dpr.nc");
    let text = port(&src, "fanuc", &out).unwrap();
    // R = RFP + SDIS, Z = RFP - ABS(DPR), computed by the target.
    assert!(text.contains("Z[#1-ABS[#2+1]] R[#1+2.]"), "{text}");
    let back = dir.path().join("dpr-back.mpf");
    port(out.to_str().unwrap(), "siemens840d", &back).unwrap();
}

/// LinuxCNC `G64 P0.01` (blending within 0.01 mm): Fanuc's and the 840D's
/// G64 take no word, and the 840D's `P` is a subprogram pass count, so the
/// tolerance is left out with W0610, never written after their G64; the
/// TNC gets it as its tolerance cycle, LinuxCNC keeps it.
#[test]
fn a_path_tolerance_goes_only_where_the_code_takes_it() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "blend.ngc",
        "G21 G90 G17\nG64 P0.01\nG0 X0 Y0 Z5\nG1 Z-1 F100\nX10\nM2\n",
    );
    for (to, name) in [("fanuc", "b.nc"), ("siemens840d", "b.mpf")] {
        let out = dir.path().join(name);
        let o = cncc(&[
            "port",
            &src,
            "--to",
            to,
            "--verify",
            "-o",
            out.to_str().unwrap(),
        ]);
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(0), "{to}: {err}");
        assert!(
            err.contains("W0610") && err.contains("`P` of the path mode"),
            "{to}: {err}"
        );
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.lines().any(|l| l.trim() == "G64"), "{to}: {text}");
        assert!(!text.contains("P0.01"), "{to}: {text}");
    }
    let text = port(&src, "heidenhain", &dir.path().join("b.h")).unwrap();
    assert!(text.contains("CYCL DEF 32.1 T+0.01"), "{text}");
    let text = port(&src, "linuxcnc", &dir.path().join("b.ngc")).unwrap();
    assert!(text.contains("G64 P0.01"), "{text}");
}

/// The 840D's tolerance cycle `CYCLE832(tol, type)` is a path mode, not a
/// motion: ported it becomes the continuous-path mode with the tolerance
/// (LinuxCNC `G64 P`, the TNC's cycle 32, Fanuc `G64` with W0610 for the
/// tolerance the machine keeps), and deselection plain `G64`. It used to
/// be "written as the moves it makes", a bare `G1`, which LinuxCNC then
/// refused for lack of a feed (the port failed its proof).
#[test]
fn a_tolerance_cycle_ports_as_the_path_mode() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(
        dir.path(),
        "tol.mpf",
        "G17 G90 G54\nT1 D1\nM6\nS8000 M3\nCYCLE832(0.02,_FINISH,1)\nG0 X0 Y0 Z5\n\
         G1 Z-1 F500\nX20 Y5\nCYCLE832(0,_OFF,1)\nG0 Z50\nM30\n",
    );
    let text = port(&src, "linuxcnc", &dir.path().join("t.ngc")).unwrap();
    let lines: Vec<&str> = text.lines().map(str::trim).collect();
    assert!(lines.contains(&"G64 P0.02"), "{text}");
    assert!(lines.contains(&"G64"), "deselection: {text}");
    assert!(!lines.contains(&"G1"), "no bare G1: {text}");
    let text = port(&src, "heidenhain", &dir.path().join("t.h")).unwrap();
    assert!(text.contains("CYCL DEF 32.1 T+0.02"), "{text}");
    let out = dir.path().join("t.nc");
    let o = cncc(&[
        "port",
        &src,
        "--to",
        "fanuc",
        "--verify",
        "-o",
        out.to_str().unwrap(),
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("W0610") && !err.contains("W0612"), "{err}");
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(
        text.lines().filter(|l| l.trim() == "G64").count() == 2,
        "{text}"
    );
}
