//! Subprograms and cycles ported to and from Heidenhain beyond the matrix
//! cells: the Siemens header of a ported subprogram, refusals with E0617,
//! and the CYCLE71 stepover carried through Q108.

use std::path::Path;
use std::process::Command;

fn cncc(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn temp(name: &str, text: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("cncc-tncport-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

#[test]
fn fanuc_subprogram_to_siemens_is_an_spf() {
    let sub = "tests/matrix/subprograms/O1000.nc";
    assert!(Path::new(env!("CARGO_MANIFEST_DIR")).join(sub).exists());
    let (code, out, err) = cncc(&["port", "--from", "fanuc", "--to", "siemens840d", sub]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("%_N_L1000_SPF"), "{out}");
    assert!(out.contains("M17"), "{out}");
    // A main program keeps its _MPF header.
    let main = "tests/matrix/subprograms/from-fanuc.nc";
    let (code, out, err) = cncc(&["port", "--from", "fanuc", "--to", "siemens840d", main]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("%_N_O3009_MPF"), "{out}");
}

#[test]
fn missing_subprogram_file_is_e0617() {
    let p = temp(
        "main.nc",
        "O1\nG21 G90\nT1 M6\nG0 X0 Y0 Z5.\nM98 P4321\nM30\n",
    );
    let p = p.to_string_lossy().into_owned();
    let (code, _, err) = cncc(&[
        "port",
        "--strict",
        "--from",
        "fanuc",
        "--to",
        "heidenhain",
        &p,
    ]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("[E0617"), "{err}");
    assert!(err.contains("4321"), "{err}");
}

#[test]
fn label_subprogram_to_siemens_is_inlined() {
    let src = "tests/matrix/subprograms/from-heidenhain.h";
    let (code, out, err) = cncc(&[
        "port",
        "--from",
        "heidenhain",
        "--to",
        "siemens840d",
        "--verify",
        src,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("LBL2:") && out.contains("REPEAT LBL2 P=1"),
        "{out}"
    );
    assert_eq!(out.matches("G1 X10 F300").count(), 1, "{out}");
    // A call of a label that is no subprogram is refused.
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(src))
        .unwrap()
        .replace("CALL LBL 1\n", "CALL LBL 7\n");
    let p = temp("sub.h", &text);
    let p = p.to_string_lossy().into_owned();
    let (code, _, err) = cncc(&[
        "port",
        "--strict",
        "--from",
        "heidenhain",
        "--to",
        "siemens840d",
        &p,
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("[E0617") || err.contains("[E0321"), "{err}");
}

#[test]
fn face_with_a_stepover_other_than_the_radius_is_refused_from_heidenhain() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/matrix/faces/from-heidenhain.h"),
    )
    .unwrap()
    .replace("Q370=+1 ;", "Q370=+1.6 ;");
    let p = temp("face.h", &text);
    let p = p.to_string_lossy().into_owned();
    let (code, _, err) = cncc(&[
        "port",
        "--strict",
        "--from",
        "heidenhain",
        "--to",
        "siemens840d",
        &p,
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("[E0610") && err.contains("Q370"), "{err}");
}

#[test]
fn cycle71_stepover_is_a_factor_of_q108() {
    let src = "tests/matrix/faces/from-siemens840d.mpf";
    let (code, out, err) = cncc(&[
        "port",
        "--from",
        "siemens840d",
        "--to",
        "heidenhain",
        "--verify",
        src,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    assert!(out.contains("QL1 = 40 / Q108"), "{out}");
    assert!(out.contains("Q370=+QL1"), "{out}");
    // Another strategy than the 1st axis has no 232 form.
    let text = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join(src))
        .unwrap()
        .replace(",1000,31,0)", ",1000,41,0)");
    let p = temp("face.mpf", &text);
    let p = p.to_string_lossy().into_owned();
    let (code, _, err) = cncc(&[
        "port",
        "--strict",
        "--from",
        "siemens840d",
        "--to",
        "heidenhain",
        &p,
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("[E0610") && err.contains("VARI 41"), "{err}");
}

#[test]
fn fanuc_tape_with_two_programs_to_heidenhain_labels() {
    let p = temp(
        "tape.nc",
        "%\nO3009 (MAIN)\nG21 G17 G90 G94\nT9 M6\nG0 G43 H9 Z10.\nS3000 M3\nG0 X0 Y0\n\
         M98 P1000 L3\nG0 Z10.\nM30\nO1000 (SQUARE)\nG1 Z-1. F100.\nX10. F300.\nY10.\n\
         X0.\nY0.\nG0 Z10.\nM99\n%\n",
    );
    let p = p.to_string_lossy().into_owned();
    let (code, out, err) = cncc(&[
        "port",
        "--from",
        "fanuc",
        "--to",
        "heidenhain",
        "--verify",
        &p,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    for line in [
        "LBL 1000 ;SQUARE",
        "CALL LBL 1000",
        "CALL LBL 1 REP 2/2",
        "LBL 0",
    ] {
        assert!(out.contains(line), "{line} missing in\n{out}");
    }
    assert!(!out.contains("BEGIN PGM 1000"), "{out}");
}

#[test]
fn heidenhain_face_expands_for_fanuc_only_when_allowed() {
    let src = "tests/matrix/faces/from-heidenhain.h";
    let (code, _, err) = cncc(&[
        "port",
        "--strict",
        "--from",
        "heidenhain",
        "--to",
        "fanuc",
        src,
    ]);
    assert_eq!(code, 1);
    assert!(err.contains("[E0610"), "{err}");
    let (code, out, err) = cncc(&[
        "port",
        "--from",
        "heidenhain",
        "--to",
        "fanuc",
        "--verify",
        "--expand-cycles",
        src,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    assert!(
        !out.contains("CYCL") && out.contains("G1 X121.794"),
        "{out}"
    );
}

#[test]
fn haas_m97_local_subprogram_to_heidenhain_label() {
    let p = temp(
        "haas97.nc",
        "%\nO3010 (LOCAL SUB)\nG20 G17 G90 G94\nT9 M6\nG0 G43 H9 Z0.5\nS3000 M3\nG0 X0 Y0\n\
         M97 P100 L3\nG0 Z0.5\nM30\nN100 G1 Z-0.05 F10.\nX0.5 F20.\nY0.5\nX0.\nY0.\n\
         G0 Z0.5\nM99\n%\n",
    );
    let p = p.to_string_lossy().into_owned();
    let (code, out, err) = cncc(&[
        "port",
        "--from",
        "haas",
        "--to",
        "heidenhain",
        "--verify",
        &p,
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    for line in ["CALL LBL 100", "CALL LBL 1 REP 2/2", "LBL 100", "LBL 0"] {
        assert!(out.contains(line), "{line} missing in\n{out}");
    }
}
