//! Issue 13: the exact idiom rewrites of `cncc port` (keyed on the
//! construct and on what the target lacks) and the holes of `--verify`.
//! Each test ports a small program of its own with `--verify`.

mod common;
use common::{cncc, stderr, stdout};

const DIALECTS: [&str; 5] = ["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// Ports `file` (read as `from`) to `to` with `--verify`; the output and
/// stderr, or a panic naming what failed.
fn port_verified(from: &str, to: &str, file: &str) -> (String, String) {
    let out = cncc(&["port", "--from", from, "--to", to, "--verify", file]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{from} -> {to} {file}:\n{err}");
    assert!(err.contains("verify: OK"), "{from} -> {to}: {err}");
    (stdout(&out), err)
}

fn to_all_others(from: &str, file: &str) {
    for to in DIALECTS.iter().filter(|t| **t != from) {
        port_verified(from, to, file);
    }
}

/// Fanuc FIX drops the fraction and FUP rounds away from zero:
/// FIX[-1.5] = -1, FUP[-1.5] = -2 (not floor and ceiling).
#[test]
fn fanuc_fix_truncates_and_fup_rounds_away_from_zero() {
    let out = cncc(&["canon", "tests/programs/fanuc/port_rounding.nc"]);
    let canon = stdout(&out);
    assert!(
        canon.contains("STRAIGHT_FEED(-1.0000, -2.0000, -1.0000"),
        "{canon}"
    );
    assert!(
        canon.contains("STRAIGHT_FEED(2.0000, 3.0000, -1.0000"),
        "{canon}"
    );
    assert!(
        canon.contains("STRAIGHT_FEED(-4.0000, -3.0000, -1.0000"),
        "{canon}"
    );
}

#[test]
fn rounding_functions_port_exactly_everywhere() {
    to_all_others("fanuc", "tests/programs/fanuc/port_rounding.nc");
    to_all_others(
        "siemens840d",
        "tests/programs/siemens840d/port_rounding.mpf",
    );
    to_all_others("linuxcnc", "tests/programs/linuxcnc/port_rounding.ngc");
}

#[test]
fn trunc_is_fix_and_pot_is_a_product() {
    let (fanuc, _) = port_verified(
        "siemens840d",
        "fanuc",
        "tests/programs/siemens840d/port_rounding.mpf",
    );
    assert!(fanuc.contains("#2=[FIX[#1]]"), "{fanuc}");
    assert!(fanuc.contains("#4=[#1*#1]"), "{fanuc}");
    let (tnc, _) = port_verified(
        "fanuc",
        "heidenhain",
        "tests/programs/fanuc/port_rounding.nc",
    );
    // FUP as INT + SGN of the fraction.
    assert!(tnc.contains("INT (Q1) + SGN (Q1 - INT (Q1))"), "{tnc}");
}

/// `o<peck_at> sub` has no number: it becomes `O1000 (peck_at)`, called
/// with `G65 P1000`, beside the numbered `o100` (`O0100`).
#[test]
fn named_subroutine_gets_a_free_program_number() {
    let file = "tests/programs/linuxcnc/port_named_sub.ngc";
    for to in ["fanuc", "haas"] {
        let (out, _) = port_verified("linuxcnc", to, file);
        assert!(out.contains("O1000 (peck_at)"), "{out}");
        assert!(out.contains("G65 P1000 A10. B20. C-3."), "{out}");
        assert!(out.contains("G65 P100 A50."), "{out}");
    }
    port_verified("linuxcnc", "siemens840d", file);
}

/// Five levels of subprograms each calling the next ten times: inlined for
/// Siemens that is a million blocks. The budget (100 000 added blocks, all
/// copies charged) refuses it instead of writing them.
#[test]
fn inlining_has_a_real_budget() {
    let file = "tests/programs/heidenhain/port_inline_budget.h";
    let start = std::time::Instant::now();
    // --strict: the inlining is refused (without it the port writes the
    // calls as the moves they make, bounded the same way).
    let out = cncc(&[
        "port",
        "--strict",
        "--from",
        "heidenhain",
        "--to",
        "siemens840d",
        file,
    ]);
    let err = stderr(&out);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("E0617"), "{err}");
    assert!(err.contains("more than 100000 blocks"), "{err}");
    assert!(stdout(&out).len() < 1_000_000, "the blocks were written");
    assert!(start.elapsed().as_secs() < 20, "{:?}", start.elapsed());
}

/// `BLK FORM` for targets without a blank statement: a comment that reads
/// back as one, and the `--stock` that gives the same blank; the old datum
/// shift `CYCL DEF 7` as `G52`/`TRANS`, the dwell `CYCL DEF 9` as `G4`.
#[test]
fn blank_datum_shift_and_dwell_of_old_klartext() {
    let file = "tests/programs/heidenhain/port_old_cycles.h";
    for to in ["fanuc", "haas", "linuxcnc", "siemens840d"] {
        let (out, err) = port_verified("heidenhain", to, file);
        assert!(out.contains("BLANK MIN Z X0 Y0 Z-20"), "{out}");
        assert!(err.contains("--stock 100x80x20+0+0-20"), "{err}");
        let shift = if to == "siemens840d" {
            "TRANS X20 Y10 Z0"
        } else if to == "linuxcnc" {
            "G52 X20 Y10 Z0"
        } else {
            "G52 X20. Y10. Z0."
        };
        assert!(out.contains(shift), "{out}");
        assert!(out.contains("G4 "), "{out}");
    }
}

/// The port of cncc's own Siemens cycle with an SDIS in a variable: the R
/// plane is RFP + SDIS, which is no number here, so the cycle is refused
/// (it was written with R = RFP, rapiding 2 mm lower than the source).
#[test]
fn cycle_with_sdis_in_a_variable_is_not_written_on_the_surface() {
    let file = "tests/programs/siemens840d/port_sdis_variable.mpf";
    let out = cncc(&["port", "--from", "siemens840d", "--to", "fanuc", file]);
    let err = stderr(&out);
    assert_ne!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("SDIS is an expression"), "{err}");
}

/// Siemens `CASE` for Fanuc and Haas: one `IF [..] GOTO n` per block, then
/// the default jump.
#[test]
fn case_is_a_chain_of_conditional_jumps() {
    let file = "tests/programs/siemens840d/port_case.mpf";
    for to in ["fanuc", "haas"] {
        let (out, _) = port_verified("siemens840d", to, file);
        let lines: Vec<&str> = out.lines().collect();
        let i = lines
            .iter()
            .position(|l| l.starts_with("IF [#1+1 EQ 1] GOTO "))
            .expect(&out);
        assert!(lines[i + 1].starts_with("IF [#1+1 EQ 3] GOTO "), "{out}");
        assert!(lines[i + 2].starts_with("GOTO "), "{out}");
    }
}

/// The positioning blocks under `MCALL` drill: written as moves, the part
/// from `MCALL CYCLE81` to the closing `MCALL` is taken whole, so the
/// three holes the loop positions are drilled (they were lost as plain
/// moves). With `--expand-cycles`, a cycle statement that runs in a loop
/// is not written once per run inside the loop (which drilled each hole
/// three times).
#[test]
fn modal_call_over_a_loop_keeps_its_holes() {
    let file = "tests/programs/siemens840d/port_mcall_loop.mpf";
    for to in ["fanuc", "haas", "linuxcnc", "heidenhain"] {
        let (out, err) = port_verified("siemens840d", to, file);
        assert!(err.contains("the same 3 operations"), "{to}: {err}");
        assert!(!out.contains("WHILE"), "{to}: {out}");
    }
    let out = cncc(&[
        "port",
        "--from",
        "siemens840d",
        "--to",
        "fanuc",
        "--verify",
        "--expand-cycles",
        file,
    ]);
    let err = stderr(&out);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("the same 3 operations"), "{err}");
    assert_eq!(stdout(&out).matches("Z80.").count(), 3, "{}", stdout(&out));
}

/// `T2` after `T1 M6` readies the next tool and loads nothing: to the TNC
/// it is the preselection `TOOL DEF 2`, and the `M6` alone that loads it
/// is `TOOL CALL 2` (a `TOOL CALL` with no tool would change nothing).
/// Back to Fanuc, `G43 H` names the tool the change loaded, not the one
/// preselected after it.
#[test]
fn a_preselected_tool_is_tool_def_and_the_change_names_it() {
    let file = "tests/programs/fanuc/port_preselect.nc";
    let (tnc, _) = port_verified("fanuc", "heidenhain", file);
    let lines: Vec<&str> = tnc.lines().collect();
    let def2 = lines.iter().position(|l| l.ends_with("TOOL DEF 2"));
    let call2 = lines.iter().position(|l| l.contains("TOOL CALL 2"));
    assert!(def2.is_some() && call2.is_some() && def2 < call2, "{tnc}");
    assert!(
        !tnc.lines().any(|l| l.trim_end().ends_with("TOOL CALL")),
        "{tnc}"
    );
    let dir = tempfile::tempdir().unwrap();
    let h = dir.path().join("p.h");
    std::fs::write(&h, &tnc).unwrap();
    let (back, _) = port_verified("heidenhain", "fanuc", h.to_str().unwrap());
    let first_g43 = back.lines().find(|l| l.contains("G43")).unwrap_or("");
    assert!(first_g43.contains("H1"), "{back}");
}

/// A `G1` with no axis word sets the motion mode on a Fanuc or Haas (no
/// feed needed: nothing moves); rs274 moves to where the tool is and
/// wants a feed rate ("Cannot do G1 with zero feed rate"). The port
/// writes such a `G1` for an 840D program, whose power-on mode is G1.
#[test]
fn a_bare_g1_sets_the_mode_and_needs_no_feed_except_on_linuxcnc() {
    let dir = tempfile::tempdir().unwrap();
    let nc = dir.path().join("g1.nc");
    std::fs::write(
        &nc,
        "%\nO1\nG21 G90\nG1\nG0 X1. Y1. Z5.\nG1 Z-1. F100\nM30\n%\n",
    )
    .unwrap();
    let nc = nc.to_str().unwrap();
    for d in ["fanuc", "haas"] {
        let out = cncc(&["check", "--dialect", d, nc]);
        assert_eq!(out.status.code(), Some(0), "{d}: {}", stderr(&out));
    }
    let out = cncc(&["check", "--dialect", "linuxcnc", nc]);
    assert!(stderr(&out).contains("E0507"), "{}", stderr(&out));
    let mpf = dir.path().join("p.mpf");
    std::fs::write(
        &mpf,
        "G17 G90 G71\nT1 D1\nM6\nS1000 M3\nG0 X0 Y0 Z5\nG1 Z-1 F100\nX10\nG0 Z5\nM30\n",
    )
    .unwrap();
    for to in ["fanuc", "haas"] {
        port_verified("siemens840d", to, mpf.to_str().unwrap());
    }
}

/// An operator message (`MSG`) goes to a target that shows none without
/// stopping as a comment with its text, warned once (W0610); LinuxCNC
/// keeps it as `(MSG,..)`.
#[test]
fn an_operator_message_is_a_comment_where_the_target_has_none() {
    let file = "tests/programs/siemens840d/port_message.mpf";
    for to in ["fanuc", "haas", "heidenhain"] {
        let (out, err) = port_verified("siemens840d", to, file);
        assert!(
            out.contains("MSG: ROUGHING [1 OF 2]") || out.contains("MSG: ROUGHING (1 OF 2)"),
            "{to}:\n{out}"
        );
        assert!(out.contains("MSG cleared"), "{to}:\n{out}");
        assert_eq!(err.matches("W0610").count(), 1, "{to}: {err}");
    }
    let (out, _) = port_verified("siemens840d", "linuxcnc", file);
    assert!(out.contains("(MSG,ROUGHING"), "{out}");
}

/// `G4 P.. G0 X.. S.. M3` in one block: LinuxCNC runs speed and spindle,
/// the dwell, then the move. Fanuc reads a dwell block's X as the time
/// and the 840D wants G4 alone, so the port writes three blocks in that
/// order; LinuxCNC to itself keeps the block.
#[test]
fn a_dwell_gets_its_own_block_where_the_target_wants_it() {
    let file = "tests/programs/linuxcnc/port_dwell_block.ngc";
    for (to, dwell, mv) in [
        ("fanuc", "G4 X0.5", "G0 X10. Y5."),
        ("haas", "G4 X0.5", "G0 X10. Y5."),
        ("siemens840d", "G4 F0.5", "G0 X10 Y5"),
    ] {
        let (out, _) = port_verified("linuxcnc", to, file);
        let lines: Vec<&str> = out.lines().map(str::trim).collect();
        let at = lines
            .iter()
            .position(|l| l.starts_with(dwell))
            .unwrap_or_else(|| panic!("{to}: no dwell block:\n{out}"));
        assert!(lines[at - 1].contains("S1000 M3"), "{to}:\n{out}");
        assert!(
            !lines[at].contains('S') && !lines[at].contains("G0"),
            "{to}:\n{out}"
        );
        assert!(lines[at + 1].starts_with(mv), "{to}:\n{out}");
    }
    let (out, _) = port_verified("linuxcnc", "linuxcnc", file);
    assert!(out.contains("G4 P0.5 G0 X10 Y5 S1000 M3"), "{out}");
}

/// A Klartext line is held back until the next block says whether a
/// `RND`/`CHF` follows: a part written as its moves must not end between
/// the line and the block its calls come out in (the plunge `L IZ-6` was
/// lost and its feed went to the next line).
#[test]
fn a_held_klartext_line_stays_in_the_part_written_as_moves() {
    for to in ["fanuc", "haas", "linuxcnc", "siemens840d"] {
        let (out, _) = port_verified(
            "heidenhain",
            to,
            "tests/programs/heidenhain/port_held_line.h",
        );
        assert!(out.contains("Z-1"), "{to}: the plunge is lost:\n{out}");
    }
}

/// `FN 18: SYSREAD .. ID270` right after a `STOP` reads where the
/// operator jogged the axes (a touch-off program): only the machine
/// knows it, so the port refuses instead of writing the value the
/// check-time run assumed (0).
#[test]
fn a_position_read_after_a_stop_is_not_written_as_a_number() {
    for to in ["fanuc", "haas", "linuxcnc", "siemens840d"] {
        let out = cncc(&[
            "port",
            "--from",
            "heidenhain",
            "--to",
            to,
            "--verify",
            "tests/programs/heidenhain/port_touch_off.h",
        ]);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(1), "{to}: {err}");
        assert!(
            err.contains("known only while the machine runs"),
            "{to}: {err}"
        );
        assert!(!stdout(&out).contains("#10=0"), "{to}");
    }
}

/// `Z50. H2` while G43 is in force: Fanuc replaces the length by H2's
/// (capability `offset-register-alone`); the port writes `G43 H2` (or the
/// target's tool call) where an H needs its G43, and the run agrees.
#[test]
fn an_h_alone_in_g43_mode_changes_the_length_and_ports() {
    let out = cncc(&[
        "canon",
        "--dialect",
        "fanuc",
        "tests/programs/fanuc/port_h_alone.nc",
    ]);
    let canon = stdout(&out);
    assert!(
        canon.contains("USE_TOOL_LENGTH_OFFSET(0.0000 0.0000 30.4800"),
        "{canon}"
    );
    let (ngc, _) = port_verified("fanuc", "linuxcnc", "tests/programs/fanuc/port_h_alone.nc");
    assert!(ngc.contains("G43 H2"), "{ngc}");
    for to in ["haas", "siemens840d", "heidenhain"] {
        port_verified("fanuc", to, "tests/programs/fanuc/port_h_alone.nc");
    }
}

/// `G41` without D takes the spindle tool's radius on LinuxCNC but the
/// D last programmed (D0 before any: no radius) on Fanuc and Haas
/// (capability `comp-register-modal`): the port names `D1` for the tool
/// selected, and the proof compensates the target by the sizes the
/// source ran with (the same physical tools), not by none.
#[test]
fn g41_without_d_gets_the_tools_register_where_d_is_modal() {
    let file = "tests/programs/linuxcnc/port_comp_no_d.ngc";
    for to in ["fanuc", "haas"] {
        let (out, _) = port_verified("linuxcnc", to, file);
        assert!(out.contains("G41 D1"), "{to}:\n{out}");
    }
    for to in ["heidenhain", "siemens840d"] {
        port_verified("linuxcnc", to, file);
    }
}

/// A G95 tapping feed is the tap's pitch (M4x0.7 is F0.02756 in/rev):
/// rs274 reads numbers as doubles, so LinuxCNC takes it as written
/// instead of refusing it as more places than it writes (E0603).
#[test]
fn a_tapping_pitch_keeps_its_places_where_the_target_reads_doubles() {
    let (ngc, _) = port_verified(
        "fanuc",
        "linuxcnc",
        "tests/programs/fanuc/port_tap_pitch.nc",
    );
    assert!(ngc.contains("F0.02756"), "{ngc}");
}

/// A cycle before any G98/G99 retracts to the initial level on Fanuc and
/// to R on LinuxCNC (`cycle-retract-r-plane-at-start`): the port writes
/// the source's mode before the first cycle.
#[test]
fn the_power_on_cycle_retract_level_is_written_where_the_target_differs() {
    let (ngc, _) = port_verified(
        "fanuc",
        "linuxcnc",
        "tests/programs/fanuc/port_cycle_return.nc",
    );
    assert!(ngc.contains("G98 G81"), "{ngc}");
}
