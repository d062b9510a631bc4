//! Issue 14: no input brings cncc down, and nothing a program says becomes
//! code it did not mean. Each test is one reproducer of the issue.

mod common;
use common::cncc;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn write(dir: &Path, name: &str, body: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

/// The run ended by itself (no panic, no abort, no signal).
fn ended_normally(out: &Output) {
    let err = text(&out.stderr);
    assert!(
        out.status.code().is_some(),
        "killed by a signal: {err:.2000}"
    );
    assert!(!err.contains("panicked"), "{err:.2000}");
    assert!(!err.contains("overflow"), "{err:.2000}");
}

fn check(dialect: &str, path: &Path) -> Output {
    cncc(&["check", "--dialect", dialect, &path.display().to_string()])
}

#[test]
fn a_sum_of_50000_terms_is_too_deep_not_a_stack_overflow() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "sum.nc",
        &format!("%\nO1\n#1=1{}\nG0 X#1\nM30\n%\n", "+1".repeat(50_000)),
    );
    let out = check("fanuc", &p);
    ended_normally(&out);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        text(&out.stderr).contains("E0190"),
        "{:.2000}",
        text(&out.stderr)
    );
}

#[test]
fn abs_nested_20000_deep_is_too_deep() {
    let dir = tempfile::tempdir().unwrap();
    let e = format!("{}1{}", "ABS[".repeat(20_000), "]".repeat(20_000));
    let p = write(
        dir.path(),
        "abs.nc",
        &format!("%\nO1\n#1={e}\nG0 X#1\nM30\n%\n"),
    );
    let out = check("fanuc", &p);
    ended_normally(&out);
    assert!(text(&out.stderr).contains("E0190"));
}

#[test]
fn a_long_and_chain_is_too_deep() {
    let dir = tempfile::tempdir().unwrap();
    let c = "[1 EQ 1] AND ".repeat(30_000);
    let p = write(
        dir.path(),
        "and.nc",
        &format!("%\nO1\nIF[{c}[1 EQ 1]] GOTO 10\nN10 M30\n%\n"),
    );
    let out = check("fanuc", &p);
    ended_normally(&out);
    assert!(text(&out.stderr).contains("E0190"));
}

#[test]
fn deep_expressions_in_every_family_are_too_deep() {
    let dir = tempfile::tempdir().unwrap();
    let sum = "+1".repeat(20_000);
    for (dialect, name, body) in [
        ("linuxcnc", "a.ngc", format!("#1=1{sum}\nG0 X#1\nM2\n")),
        ("siemens840d", "a.mpf", format!("R1=1{sum}\nG0 X=R1\nM30\n")),
        (
            "heidenhain",
            "a.h",
            format!("BEGIN PGM A MM\nQ1 = 1{sum}\nEND PGM A MM\n"),
        ),
    ] {
        let p = write(dir.path(), name, &body);
        let out = check(dialect, &p);
        ended_normally(&out);
        assert_eq!(out.status.code(), Some(1), "{dialect}");
    }
}

#[test]
fn a_klartext_line_over_1_mib_is_an_error_not_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let body = format!(
        "BEGIN PGM T MM\n; {}\nEND PGM T MM\n",
        "A".repeat((1 << 20) + 10)
    );
    let p = write(dir.path(), "kt.h", &body);
    let out = check("heidenhain", &p);
    ended_normally(&out);
    assert!(text(&out.stderr).contains("E0191"));
}

#[test]
fn a_continuation_over_the_block_limit_is_reported_not_dropped() {
    let dir = tempfile::tempdir().unwrap();
    let body = format!(
        "BEGIN PGM T MM\nL X0 Y0 R0 FMAX\nL X10 ~\n; {} ~\nY5\nL Z5\nEND PGM T MM\n",
        "A".repeat(1 << 20)
    );
    let p = write(dir.path(), "kt2.h", &body);
    let out = check("heidenhain", &p);
    ended_normally(&out);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(err.contains("E0191"), "{err:.2000}");
}

#[test]
fn nan_and_infinity_are_located_errors() {
    let dir = tempfile::tempdir().unwrap();
    for (e, what) in [
        ("[-1]**0.5", "NaN"),
        ("EXP[1000]", "infinity"),
        ("[10**308]*10", "infinity"),
    ] {
        let p = write(dir.path(), "n.ngc", &format!("#1={e}\nG0 X#1\nM2\n"));
        let out = check("linuxcnc", &p);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{e}: {err}");
        assert!(err.contains("E0590") && err.contains(what), "{e}: {err}");
        assert!(err.contains("n.ngc:1:4"), "{e}: {err}");
        let canon = cncc(&["canon", "--dialect", "linuxcnc", &p.display().to_string()]);
        assert!(!text(&canon.stdout).contains("NaN") && !text(&canon.stdout).contains("inf"));
    }
}

#[test]
fn one_failing_file_does_not_stop_the_others() {
    let dir = tempfile::tempdir().unwrap();
    let bad = write(dir.path(), "bad.ngc", "G0 X[1/0]\nM2\n");
    let good = write(
        dir.path(),
        "good.ngc",
        "G0 X1 (UNKNOWN WORD FOLLOWS) Q\nM2\n",
    );
    let missing = dir.path().join("missing.ngc");
    let out = cncc(&[
        "check",
        "--dialect",
        "linuxcnc",
        &missing.display().to_string(),
        &bad.display().to_string(),
        &good.display().to_string(),
    ]);
    ended_normally(&out);
    let err = text(&out.stderr);
    assert!(err.contains("missing.ngc"), "{err}");
    assert!(err.contains("bad.ngc") && err.contains("good.ngc"), "{err}");
    // The missing file is an I/O failure (2), reported after the others.
    assert_eq!(out.status.code(), Some(2));
}

/// `cncc ... | head`: the reader closes the pipe early.
fn closed_pipe(args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    let _ = std::io::Read::read(&mut out, &mut first);
    drop(out);
    child.wait_with_output().unwrap()
}

#[test]
fn a_closed_pipe_ends_the_run_quietly() {
    use std::os::unix::process::ExitStatusExt;
    let dir = tempfile::tempdir().unwrap();
    let mut big = String::from("G21 G90 G94 F100\n");
    for i in 0..200_000 {
        big.push_str(&format!("G1 X{}\n", i % 100));
    }
    big.push_str("M2\n");
    let p = write(dir.path(), "big.ngc", &big);
    let out = closed_pipe(&["canon", "--dialect", "linuxcnc", &p.display().to_string()]);
    let err = text(&out.stderr);
    assert!(
        !err.contains("Broken pipe") && !err.contains("panicked"),
        "{err}"
    );
    assert_eq!(out.status.signal(), Some(13), "{:?} {err}", out.status);
}

#[test]
fn outputs_get_the_umask_permissions_and_keep_an_existing_mode() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "a.ngc", "G0 X1\nM2\n");
    let out_path = dir.path().join("new.mpf");
    let out = cncc(&[
        "port",
        &src.display().to_string(),
        "--to",
        "siemens840d",
        "-o",
        &out_path.display().to_string(),
    ]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let mode = std::fs::metadata(&out_path).unwrap().permissions().mode() & 0o777;
    // SAFETY: reading the umask (set and restored at once).
    let umask = unsafe {
        let m = libc_umask(0o022);
        libc_umask(m);
        m
    };
    assert_eq!(mode, 0o666 & !umask, "{mode:o}");
    std::fs::set_permissions(&out_path, std::fs::Permissions::from_mode(0o640)).unwrap();
    let out = cncc(&[
        "port",
        &src.display().to_string(),
        "--to",
        "siemens840d",
        "-o",
        &out_path.display().to_string(),
    ]);
    assert_eq!(out.status.code(), Some(0));
    let mode = std::fs::metadata(&out_path).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o640, "{mode:o}");
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(
        left.iter().all(|n| !n.to_string_lossy().contains(".cncc-")),
        "{left:?}"
    );
}

extern "C" {
    #[link_name = "umask"]
    fn libc_umask(mask: u32) -> u32;
}

#[test]
fn a_failed_output_names_the_real_path() {
    let dir = tempfile::tempdir().unwrap();
    let src = write(dir.path(), "a.ngc", "G0 X1\nM2\n");
    let out_path = dir.path().join("no/such/dir/out.mpf");
    let out = cncc(&[
        "port",
        &src.display().to_string(),
        "--to",
        "siemens840d",
        "-o",
        &out_path.display().to_string(),
    ]);
    let err = text(&out.stderr);
    assert_ne!(out.status.code(), Some(0));
    assert!(err.contains("no/such/dir/out.mpf"), "{err}");
    assert!(!err.contains(".cncc-"), "{err}");
}

#[test]
fn a_killed_run_leaves_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let mut big = String::from("G21 G90 G94 F100\n");
    for i in 0..400_000 {
        big.push_str(&format!("G1 X{} Y{}\n", i % 100, i % 37));
    }
    big.push_str("M2\n");
    let src = write(dir.path(), "big.ngc", &big);
    let out_path = dir.path().join("out.svg");
    let mut child = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args([
            "plot",
            &src.display().to_string(),
            "-o",
            &out_path.display().to_string(),
        ])
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    std::thread::sleep(std::time::Duration::from_millis(300));
    // SAFETY: sending SIGTERM to our own child.
    unsafe { kill(child.id() as i32, 15) };
    let _ = child.wait();
    let left: Vec<_> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert!(
        left.iter().all(|n| !n.to_string_lossy().starts_with('.')),
        "{left:?}"
    );
    let _ = std::io::stderr().flush();
}

extern "C" {
    fn kill(pid: i32, sig: i32) -> i32;
}

#[test]
fn a_50_mb_single_line_is_refused_quickly() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "words.nc",
        &format!("%\nO1\nG1 {}\nM30\n%\n", "X1 Y2 ".repeat(8 << 20)),
    );
    let t = std::time::Instant::now();
    let out = check("fanuc", &p);
    ended_normally(&out);
    assert!(text(&out.stderr).contains("E0191"));
    assert!(t.elapsed().as_secs() < 30);
}

#[test]
fn thousands_of_errors_on_a_long_line_print_a_window_and_a_count() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "rep.nc",
        &format!("%\nO1\nG0 {}\nM30\n%\n", "X1 ".repeat(50_000)),
    );
    let out = check("fanuc", &p);
    ended_normally(&out);
    let err = text(&out.stderr);
    assert!(err.len() < 200_000, "{} bytes of diagnostics", err.len());
    assert!(
        err.contains("more E0205 repeated-word diagnostics not shown"),
        "{:.2000}",
        &err[err.len().saturating_sub(2000)..]
    );
}

#[test]
fn a_tool_table_from_dev_zero_is_a_clear_error() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "a.ngc", "G0 X1\nM2\n");
    let out = cncc(&[
        "check",
        "--tool-table",
        "/dev/zero",
        &p.display().to_string(),
    ]);
    ended_normally(&out);
    assert!(
        text(&out.stderr).contains("larger than 16 MiB"),
        "{}",
        text(&out.stderr)
    );
}

/// The port reads its input with the same limit as every other command:
/// an endless file is refused, not read until memory runs out.
#[test]
fn a_port_of_dev_zero_is_a_clear_error() {
    let out = cncc(&[
        "port",
        "/dev/zero",
        "--from",
        "fanuc",
        "--to",
        "siemens840d",
    ]);
    ended_normally(&out);
    assert!(
        text(&out.stderr).contains("larger than 256 MiB"),
        "{}",
        text(&out.stderr)
    );
}

fn port(file: &Path, from: &str, to: &str) -> Output {
    cncc(&[
        "port",
        &file.display().to_string(),
        "--from",
        from,
        "--to",
        to,
        "--verify",
    ])
}

#[test]
fn fanuc_logopen_ported_to_linuxcnc_is_neutralised_with_a_warning() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "a.nc",
        "%\nO1\n(LOGOPEN,/home/cnc/x.txt)\n( py ,print[1])\nG0 X1.\nM30\n%\n",
    );
    let out = port(&p, "fanuc", "linuxcnc");
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert!(e.contains("W0690") && e.contains("a.nc:3:1"), "{e}");
    assert!(
        o.contains("(LOGOPEN:/home/cnc/x.txt)") && o.contains("( py :print[1])"),
        "{o}"
    );
    assert!(!o.contains("LOGOPEN,") && !o.contains("py ,"), "{o}");
}

#[test]
fn siemens_py_comment_ported_to_linuxcnc_is_neutralised() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "a.mpf",
        "G0 X0\n; py,__import__('os')\nG0 Z50\nM30\n",
    );
    let out = port(&p, "siemens840d", "linuxcnc");
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert!(e.contains("W0690") && e.contains("`PY`"), "{e}");
    assert!(o.contains("py:__import__"), "{o}");
}

#[test]
fn a_fanuc_comment_ending_in_tilde_does_not_swallow_the_retract_in_klartext() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "a.nc",
        "%\nO1\nG0 X0. Y0. Z5.\n(RETRACT ~)\nG0 Z50.\nG0 X100.\nM30\n%\n",
    );
    let out = port(&p, "fanuc", "heidenhain");
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{e}");
    assert!(e.contains("verify: OK"), "{e}");
    assert!(o.contains("L Z+50 FMAX"), "{o}");
    assert!(!o.lines().any(|l| l.trim_end().ends_with('~')), "{o}");
    // Read back, the retract is still a move of its own.
    let h = write(dir.path(), "a.h", &o);
    let canon = cncc(&["canon", "--dialect", "heidenhain", &h.display().to_string()]);
    assert!(
        text(&canon.stdout).contains("50.0000"),
        "{}",
        text(&canon.stdout)
    );
}

#[test]
fn percent_and_non_ascii_in_fanuc_comments_are_escaped() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "a.ngc",
        "(50% OFF, Bohrung Ø12 für)\nG0 X1\nM2\n",
    );
    for to in ["fanuc", "haas"] {
        let out = port(&p, "linuxcnc", to);
        let (o, e) = (text(&out.stdout), text(&out.stderr));
        let body: Vec<&str> = o.lines().filter(|l| l.starts_with('(')).collect();
        assert!(
            body.iter().all(|l| !l.contains('%') && l.is_ascii()),
            "{to}: {o}"
        );
        assert!(e.contains("W0690") || e.contains("W0691"), "{to}: {e}");
    }
}

/// The Part 21 fixture with its project id and first workingstep's name.
fn evil_stepnc(dir: &Path, id: &str, ws: &str, z: &str) -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let s = std::fs::read_to_string(root.join("tests/programs/stepnc/tapped_holes.stp")).unwrap();
    let s = s
        .replace("PROJECT('TAPPED HOLES'", &format!("PROJECT('{id}'"))
        .replace(
            "MACHINING_WORKINGSTEP('WS DRILL M8'",
            &format!("MACHINING_WORKINGSTEP('{ws}'"),
        )
        .replace(
            "#62=CARTESIAN_POINT('',(0.,0.,-16.));",
            &format!("#62=CARTESIAN_POINT('',(0.,0.,{z}));"),
        );
    write(dir, "evil.stp", &s)
}

#[test]
fn a_stepnc_project_id_never_becomes_a_linuxcnc_command() {
    let dir = tempfile::tempdir().unwrap();
    let p = evil_stepnc(dir.path(), "LOGOPEN,/home/cnc/x", "py,import os ~", "-16.");
    let out = cncc(&["post", &p.display().to_string(), "--to", "linuxcnc"]);
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{e}");
    assert!(e.contains("W0690"), "{e}");
    assert!(
        o.contains("(LOGOPEN:/home/cnc/x)") && !o.contains("LOGOPEN,"),
        "{o}"
    );
    let out = cncc(&["post", &p.display().to_string(), "--to", "heidenhain"]);
    let o = text(&out.stdout);
    assert!(!o.lines().any(|l| l.trim_end().ends_with('~')), "{o}");
}

#[test]
fn a_hole_depth_of_1e12_mm_is_refused_by_the_post() {
    let dir = tempfile::tempdir().unwrap();
    let p = evil_stepnc(dir.path(), "TAPPED HOLES", "WS DRILL M8", "-1.E12");
    for to in ["fanuc", "linuxcnc", "siemens840d", "heidenhain", "haas"] {
        let out = cncc(&["post", &p.display().to_string(), "--to", to]);
        let e = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{to}: {e}");
        // The validator refuses it first: deeper than the stock's block
        // (E0908); without a block the number's size is refused (E0690).
        assert!(e.contains("E0908") || e.contains("E0690"), "{to}: {e}");
        assert!(text(&out.stdout).is_empty(), "{to}");
    }
}

/// The fuzz targets' entry points (interpreter, port, post) on hostile
/// samples, so CI runs them briefly even without cargo-fuzz.
#[test]
fn fuzz_entry_points_survive_hostile_samples() {
    let samples: Vec<Vec<u8>> = vec![
        b"#1=[-1]**0.5\nG0 X#1\nM2\n".to_vec(),
        b"WHILE[1 EQ 1]DO1\nG91 G0 X1\nEND1\nM30\n".to_vec(),
        b"o1 while [1]\nG0 X1\no1 endwhile\nM2\n".to_vec(),
        b"R1=1\nLOOP\nG0 X=R1\nENDLOOP\nM30\n".to_vec(),
        b"BEGIN PGM A MM\nLBL 1\nCALL LBL 1\nEND PGM A MM\n".to_vec(),
        format!("#1=1{}\n", "+1".repeat(5000)).into_bytes(),
        (0u8..=255).collect(),
        b"(LOGOPEN,x)\n(50% ~)\nG0 X1\nM30\n".to_vec(),
    ];
    for s in &samples {
        for d in cncc::fuzzing::DIALECTS {
            cncc::fuzzing::interpret(d, s);
            cncc::fuzzing::port(d, s);
        }
        cncc::fuzzing::post(s);
    }
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let stp = std::fs::read(root.join("tests/programs/stepnc/tapped_holes.stp")).unwrap();
    cncc::fuzzing::post(&stp);
}

#[test]
fn a_plot_of_a_long_helix_is_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let p = write(
        dir.path(),
        "helix.ngc",
        "G21 G90 G17 F100\nG0 X0 Y0 Z0\nG1 X5\nG2 X5 Y0 I-5 J0 Z-100 P100000000\nM2\n",
    );
    let svg = dir.path().join("x.svg");
    let t = std::time::Instant::now();
    let out = cncc(&[
        "plot",
        &p.display().to_string(),
        "-o",
        &svg.display().to_string(),
    ]);
    ended_normally(&out);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(std::fs::metadata(&svg).unwrap().len() < 10_000_000);
    assert!(t.elapsed().as_secs() < 30);
}

/// The fixture with `count` more instances of `entity` (`{}` is the id).
fn part21_with(dir: &Path, count: usize, entity: &str) -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let s = std::fs::read_to_string(root.join("tests/programs/stepnc/tapped_holes.stp")).unwrap();
    let (head, tail) = s.split_once("ENDSEC;\nEND-ISO-10303-21;").unwrap();
    let filler: String = (1000..1000 + count)
        .map(|n| entity.replace("{}", &n.to_string()))
        .collect();
    let body = format!("{head}{filler}\nENDSEC;\nEND-ISO-10303-21;{tail}");
    write(dir, "many.stp", &body)
}

/// Ten million unknown entities made ten million diagnostics (over 3 GB
/// and minutes); a thousand of one code are kept, the first says how many.
#[test]
fn part21_diagnostics_of_one_kind_are_kept_to_a_thousand() {
    let dir = tempfile::tempdir().unwrap();
    let p = part21_with(dir.path(), 3000, "#{}=A();");
    let out = cncc(&["check", &p.display().to_string()]);
    ended_normally(&out);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1));
    assert!(
        err.contains("3000 E0805 diagnostics in all; the first 1000 are kept"),
        "{err:.3000}"
    );
    assert!(
        err.contains("1000 errors"),
        "{}",
        &err[err.len().saturating_sub(500)..]
    );
    // Unused (valid) instances: W0801, the same cap.
    let p = part21_with(dir.path(), 1500, "#{}=CARTESIAN_POINT('',(0.,0.,0.));");
    let out = cncc(&["check", &p.display().to_string()]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err:.2000}");
    assert!(err.contains("1500 W0801 diagnostics in all"), "{err:.2000}");
}

/// Found by fuzzing (the `sinumerik` target, after 277 s, minimised): a D
/// number with 19 places overflowed while checking it is an integer.
#[test]
fn a_d_number_with_19_places_is_no_overflow() {
    cncc::fuzzing::read_and_write("siemens840d", b"D.0349334934933493493");
    let dir = tempfile::tempdir().unwrap();
    let p = write(dir.path(), "d.mpf", "D.0349334934933493493\nM30\n");
    let out = check("siemens840d", &p);
    ended_normally(&out);
}
