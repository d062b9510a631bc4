//! `cncc port` of what one control sets up and another spells otherwise:
//! work offsets as TNC presets and back, the continuous-path mode as the
//! TNC tolerance cycle, named tools for number-only targets, axis words
//! after G80 where cycles are motion codes, the source machine's own M
//! codes, and a label subprogram the program never calls (W0613). Each
//! port is verified.

mod common;
use common::{cncc, root, stderr};

fn program(name: &str) -> String {
    root()
        .join("tests/programs/port_machine")
        .join(name)
        .display()
        .to_string()
}

/// Ports `name` to `to` with `--verify`; the written text and stderr.
fn port(name: &str, to: &str, ext: &str) -> (String, String) {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join(format!("out.{ext}"));
    let o = cncc(&[
        "port",
        &program(name),
        "--to",
        to,
        "--verify",
        "-o",
        &out.display().to_string(),
    ]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{name} to {to}: {err}");
    assert!(err.contains("verify: OK"), "{err}");
    (std::fs::read_to_string(&out).unwrap(), err)
}

#[test]
fn work_offsets_become_presets_and_come_back() {
    let (tnc, _) = port("presets.ngc", "heidenhain", "h");
    assert!(
        tnc.contains("CYCL DEF 247 DATUM SETTING ~\n  Q339=+2"),
        "{tnc}"
    );
    assert!(tnc.contains("Q339=+1"), "G54 after G55 is preset 1: {tnc}");
    // G64 P0.02: the TNC's tolerance cycle with T.
    assert!(tnc.contains("CYCL DEF 32.0 TOLERANCE\n"), "{tnc}");
    assert!(tnc.contains("CYCL DEF 32.1 T+0.02"), "{tnc}");
    // No empty positioning block where a modal rapid would be restored.
    assert!(
        !tnc.lines().any(|l| l.trim_end().ends_with(" L FMAX")),
        "{tnc}"
    );
    // And back: the preset cycle is the work offset again.
    let dir = tempfile::tempdir().unwrap();
    let h = dir.path().join("p.h");
    std::fs::write(&h, &tnc).unwrap();
    let back = dir.path().join("b.nc");
    let o = cncc(&[
        "port",
        &h.display().to_string(),
        "--to",
        "fanuc",
        "--verify",
        "-o",
        &back.display().to_string(),
    ]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let fanuc = std::fs::read_to_string(&back).unwrap();
    assert!(fanuc.lines().any(|l| l.trim() == "G55"), "{fanuc}");
    assert!(fanuc.lines().any(|l| l.trim() == "G54"), "{fanuc}");
}

#[test]
fn a_named_tool_gets_the_number_the_run_gives_it() {
    for (to, ext) in [("fanuc", "nc"), ("linuxcnc", "ngc")] {
        let (text, err) = port("named_tool.mpf", to, ext);
        assert!(text.contains("T1001"), "{text}");
        assert!(
            err.contains("tool \"DRILL_10\" is written as T1001"),
            "{err}"
        );
        // Only LinuxCNC needs the tool in its table; the proof says so.
        let told = err.contains("needs tool 1001 in its tool table");
        assert_eq!(told, to == "linuxcnc", "{err}");
    }
}

#[test]
fn axis_words_after_g80_keep_the_motion_mode_the_source_left() {
    // Fanuc keeps G00 through the cycle; LinuxCNC's G80 leaves no motion
    // mode, so `Z20.` alone must become `G0 Z20`.
    let (text, _) = port("after_g80.nc", "linuxcnc", "ngc");
    let after: Vec<&str> = text.lines().skip_while(|l| !l.contains("G80")).collect();
    assert!(
        after.iter().any(|l| l.contains("G0") && l.contains("Z20")),
        "{text}"
    );
}

#[test]
fn machine_functions_the_target_lacks_are_not_written_as_codes() {
    for (to, ext) in [("fanuc", "nc"), ("linuxcnc", "ngc")] {
        let (text, err) = port("builder_m.h", to, ext);
        // M126 (TNC: shortest rotary path) means something else or
        // nothing elsewhere: a comment.
        assert!(
            !text
                .lines()
                .any(|l| l.split_whitespace().any(|w| w == "M126")),
            "{text}"
        );
        assert!(text.contains("(M126"), "{text}");
        assert!(
            err.contains("M126 is a function of the Heidenhain"),
            "{err}"
        );
    }
    // A builder's code neither control lists: kept for a control that
    // takes unknown M codes, a comment for LinuxCNC (M100..M199 would run
    // user programs, others are refused).
    let (fanuc, _) = port("builder_m.h", "fanuc", "nc");
    assert!(fanuc.lines().any(|l| l.trim() == "M55"), "{fanuc}");
    let (lcnc, _) = port("builder_m.h", "linuxcnc", "ngc");
    assert!(!lcnc.lines().any(|l| l.trim() == "M55"), "{lcnc}");
}

#[test]
fn a_never_called_label_subprogram_is_carried_as_comments() {
    for (to, ext) in [("fanuc", "nc"), ("linuxcnc", "ngc")] {
        let (text, err) = port("dead_label.h", to, ext);
        assert!(err.contains("W0613"), "{err}");
        assert!(text.contains("(9 PLANE RESET STAY)"), "{text}");
        assert!(!text.lines().any(|l| l.starts_with("PLANE")), "{text}");
    }
    // --strict refuses instead.
    let o = cncc(&[
        "port",
        &program("dead_label.h"),
        "--to",
        "fanuc",
        "--strict",
    ]);
    assert_ne!(o.status.code(), Some(0));
}

#[test]
fn an_unknown_m_code_does_not_stop_the_run() {
    let o = cncc(&["check", &program("builder_m.h")]);
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("W0519"), "{err}");
    assert!(!err.contains("W0511"), "the run goes on: {err}");
    assert_eq!(
        err.matches("warning[W0519").count(),
        1,
        "once per run: {err}"
    );
}
