//! `cncc port` end to end: the Fanuc demo (facing, G81 holes, a G83 hole,
//! a pocket and a slot) to Siemens 840D and back, both verified; the tool
//! map; the `--expand-cycles` fallback; the first difference a failed
//! verification names.

use std::path::PathBuf;
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn cncc(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .output()
        .unwrap()
}

fn text(b: &[u8]) -> String {
    String::from_utf8_lossy(b).into_owned()
}

fn demo() -> String {
    root()
        .join("tests/programs/fanuc/port_demo.nc")
        .display()
        .to_string()
}

#[test]
fn demo_to_siemens_and_back_verifies() {
    let dir = tempfile::tempdir().unwrap();
    let mpf = dir.path().join("demo.mpf");
    let mpf_s = mpf.display().to_string();
    let out = cncc(&[
        "port",
        &demo(),
        "--to",
        "siemens840d",
        "--verify",
        "-o",
        &mpf_s,
    ]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    let siemens = std::fs::read_to_string(&mpf).unwrap();
    assert!(siemens.contains("MCALL CYCLE81(2,2,0,-10)"), "{siemens}");
    assert!(
        // G98 after G99 G81 without G80: back to the initial level Z25,
        // the Z when cycle mode began.
        siemens.contains("MCALL CYCLE83(25,2,0,-20,,,5,0,,,1,1,,,,,0.254)"),
        "{siemens}"
    );
    // The explicit moves are the same statements in Siemens form.
    for line in [
        "G1 Z-3 F150",
        "G3 X80 Y20 I0 J5",
        "G3 X75 Y35 CR=5",
        "X90 F300",
    ] {
        assert!(
            siemens.lines().any(|l| l == line),
            "no `{line}` in\n{siemens}"
        );
    }
    let back = dir.path().join("back.nc");
    let back_s = back.display().to_string();
    let out = cncc(&["port", &mpf_s, "--to", "fanuc", "--verify", "-o", &back_s]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(0), "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    let fanuc = std::fs::read_to_string(&back).unwrap();
    assert!(fanuc.contains("G99 G81 X10. Y10. Z-10. R2."), "{fanuc}");
    // RTP 25 above R: a G98 cycle from Z25, reached in the one rapid the
    // source makes from the G99 holes' R plane (X Y and up to Z25).
    assert!(
        fanuc.contains("G0 X50. Y40. Z25.\nG98 G83 X50. Y40. Z-20. R2. Q5."),
        "{fanuc}"
    );
    assert!(fanuc.contains("G80"), "{fanuc}");
    // The tape frame and the reference return in Siemens' own forms.
    assert!(siemens.starts_with("%_N_O2000_MPF"), "{siemens}");
    assert!(!siemens.lines().any(|l| l == "%"), "{siemens}");
    assert!(siemens.contains("\nG91 G74 Z1=0\nM30"), "{siemens}");
    assert!(fanuc.contains("\nG91 G28 Z0.\nM30"), "{fanuc}");
}

/// Siemens `G74` names machine axes and goes straight home: it runs as
/// that (Z alone, no intermediate move), reads without warnings, and
/// ports to `G91 G28 Z0` with `G90` after it when the program was
/// absolute; a Fanuc return through a point of its own is refused.
#[test]
fn reference_returns_between_g28_and_g74() {
    let dir = tempfile::tempdir().unwrap();
    let mpf = dir.path().join("home.mpf");
    std::fs::write(&mpf, "G90 G0 X10 Y20 Z10\nG74 Z1=0\nG1 X5 F100\nM30\n").unwrap();
    let mpf_s = mpf.display().to_string();
    // (The program cuts without starting the spindle: lint W0701, not
    // what this test is about.)
    let check = cncc(&["check", "--no-lint", &mpf_s]);
    assert_eq!(check.status.code(), Some(0));
    assert!(text(&check.stderr).is_empty(), "{}", text(&check.stderr));
    let canon = text(&cncc(&["canon", &mpf_s]).stdout);
    let moves: Vec<&str> = canon
        .lines()
        .filter(|l| l.starts_with("STRAIGHT"))
        .collect();
    assert_eq!(
        moves,
        [
            "STRAIGHT_TRAVERSE(10.0000, 20.0000, 10.0000, 0.0000, 0.0000, 0.0000)",
            "STRAIGHT_TRAVERSE(10.0000, 20.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
            "STRAIGHT_FEED(5.0000, 20.0000, 0.0000, 0.0000, 0.0000, 0.0000)",
        ]
    );
    let fanuc = port_verified(&mpf_s, "siemens840d", "fanuc", &dir.path().join("home.nc"));
    assert!(fanuc.contains("G91 G28 Z0.\nG90\nG1 X5. F100"), "{fanuc}");
    let nc = dir.path().join("through.nc");
    std::fs::write(&nc, "G21 G90\nG0 X1. Y1. Z5.\nG28 Z5.\nM30\n").unwrap();
    let out = cncc(&[
        "port",
        "--strict",
        &nc.display().to_string(),
        "--to",
        "siemens840d",
    ]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("error[E0601 cannot-express]"), "{err}");
    assert!(err.contains("not through a point"), "{err}");
}

#[test]
fn tool_map_renumbers_tools_and_registers() {
    let out = cncc(&[
        "port",
        &demo(),
        "--to",
        "fanuc",
        "--tool-map",
        "1=11,2=12",
        "--verify",
    ]);
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{e}");
    assert!(o.contains("T11 M6") && o.contains("G43 H11"), "{o}");
    assert!(o.contains("T12 M6") && o.contains("T3 M6"), "{o}");
    let bad = cncc(&["port", &demo(), "--to", "fanuc", "--tool-map", "1=5,1=6"]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(text(&bad.stderr).contains("E0615"), "{}", text(&bad.stderr));
}

#[test]
fn chip_breaking_needs_the_fallback() {
    let src = root().join("tests/matrix/pecking/from-linuxcnc.ngc");
    let src = src.display().to_string();
    let refused = cncc(&["port", "--strict", &src, "--to", "siemens840d"]);
    assert_eq!(refused.status.code(), Some(1));
    assert!(text(&refused.stderr).contains("E0610"));
    // Without --strict the port writes the cycle as its moves by itself.
    let auto = cncc(&["port", &src, "--to", "siemens840d"]);
    assert_eq!(auto.status.code(), Some(0), "{}", text(&auto.stderr));
    assert!(
        text(&auto.stderr).contains("W0612"),
        "{}",
        text(&auto.stderr)
    );
    let out = cncc(&[
        "port",
        &src,
        "--to",
        "siemens840d",
        "--expand-cycles",
        "--verify",
    ]);
    let (o, e) = (text(&out.stdout), text(&out.stderr));
    assert_eq!(out.status.code(), Some(0), "{e}");
    assert!(e.contains("verify: OK"), "{e}");
    assert!(!o.contains("CYCLE"), "{o}");
    assert!(o.contains("G1 X40 Y20 Z-1"), "{o}");
}

#[test]
fn verification_names_the_first_cutting_difference() {
    use cncc::dialect::builtin::builtin;
    use cncc::driver::read_program;
    use cncc::interp::{flow::NoLoader, Options};
    use cncc::port::{verify, ToolMap};
    use cncc::span::FileId;
    let spec = builtin("fanuc").unwrap();
    let run = |text: &str, file: u32| {
        let (p, d) = read_program(text, FileId(file), &spec);
        assert!(d.iter().all(|d| !d.is_error()), "{d:?}");
        verify::events(
            std::rc::Rc::new(p),
            &spec,
            &Options::default(),
            &mut NoLoader,
        )
        .0
    };
    let head = "G21 G90 G94\nT1 M6\nS1000 M3\nG0 X0 Y0 Z5.\nG1 Z-1. F100.\n";
    let a = run(&format!("{head}X10.\nY10.\nM30\n"), 0);
    let same = run(&format!("{head}X10.\nY10.\nM30\n"), 1);
    let off = run(&format!("{head}X10.\nY10.002\nM30\n"), 2);
    let tools = ToolMap::default();
    assert!(verify::compare(&a, &same, &tools).same());
    let v = verify::compare(&a, &off, &tools);
    assert!(!v.same());
    let d = v.cutting.unwrap();
    // Both sides point at line 7 (`Y10.` / `Y10.002`).
    let line_of = |sp: Option<cncc::span::Span>, text: &str| {
        let sp = sp.unwrap();
        text[..sp.start as usize].matches('\n').count() + 1
    };
    let ta = format!("{head}X10.\nY10.\nM30\n");
    let tb = format!("{head}X10.\nY10.002\nM30\n");
    assert_eq!((line_of(d.a, &ta), line_of(d.b, &tb)), (7, 7), "{}", d.what);
    // A tool map renumbers the source's tools before comparing.
    let t5 = run(
        &format!("G21 G90 G94\nT5 M6\nS1000 M3\nG0 X0 Y0 Z5.\nG1 Z-1. F100.\nX10.\nY10.\nM30\n"),
        3,
    );
    assert!(!verify::compare(&a, &t5, &tools).same());
    let map = ToolMap::parse("1=5").unwrap();
    assert!(verify::compare(&a, &t5, &map).same());
}

#[test]
fn siemens_pocket_and_face_cycles_expand_for_fanuc() {
    for topic in ["pockets", "faces"] {
        let src = root().join(format!("tests/matrix/{topic}/from-siemens840d.mpf"));
        let src = src.display().to_string();
        let refused = cncc(&["port", "--strict", &src, "--to", "fanuc"]);
        assert_eq!(refused.status.code(), Some(1), "{topic}");
        let out = cncc(&["port", &src, "--to", "fanuc", "--expand-cycles", "--verify"]);
        let (o, e) = (text(&out.stdout), text(&out.stderr));
        assert_eq!(out.status.code(), Some(0), "{topic}: {e}");
        assert!(e.contains("verify: OK"), "{e}");
        assert!(!o.contains("POCKET") && !o.contains("CYCLE"), "{o}");
        assert!(o.lines().any(|l| l.starts_with("G1 X")), "{o}");
    }
}

fn port_verified(src: &str, from: &str, to: &str, out: &std::path::Path) -> String {
    let o = out.display().to_string();
    let res = cncc(&[
        "port", src, "--from", from, "--to", to, "--verify", "-o", &o,
    ]);
    let err = text(&res.stderr);
    assert_eq!(res.status.code(), Some(0), "{from} -> {to}: {err}");
    assert!(err.contains("verify: OK"), "{from} -> {to}: {err}");
    std::fs::read_to_string(out).unwrap()
}

#[test]
fn heidenhain_to_fanuc_and_back_verifies() {
    let dir = tempfile::tempdir().unwrap();
    for (topic, fanuc_has, tnc_has) in [
        (
            "drilling",
            vec![
                "G98 G81 X10. Y10. Z-10. R2. F120",
                "X20.",
                "G98 G82 X30. Y10. Z-5. R2. P500 F120",
            ],
            vec!["CYCL DEF 200 DRILLING", "Q211=+0.5 ;DWELL TIME AT DEPTH"],
        ),
        (
            "pecking",
            vec!["G98 G83 X40. Y20. Z-23. R3. Q6. F90", "Y30.", "G80"],
            vec!["CYCL DEF 203 UNIVERSAL DRILLING", "Q202=+6 ;PLUNGING DEPTH"],
        ),
    ] {
        let src = root().join(format!("tests/matrix/{topic}/from-heidenhain.h"));
        let nc = dir.path().join(format!("{topic}.nc"));
        let fanuc = port_verified(&src.display().to_string(), "heidenhain", "fanuc", &nc);
        for line in fanuc_has {
            assert!(fanuc.lines().any(|l| l == line), "{line}:\n{fanuc}");
        }
        let h = dir.path().join(format!("{topic}.h"));
        let back = port_verified(&nc.display().to_string(), "fanuc", "heidenhain", &h);
        for part in tnc_has {
            assert!(back.contains(part), "{part}:\n{back}");
        }
        assert!(back.contains(" R0 FMAX M99"), "{back}");
    }
}

#[test]
fn fanuc_g81_g83_become_cycl_def_200_203() {
    let dir = tempfile::tempdir().unwrap();
    let src = dir.path().join("holes.nc");
    std::fs::write(
        &src,
        "O1 (HOLES)\nG21 G17 G90 G94\nT2 M6\nG0 G43 H2 Z25.\nS2000 M3\n\
         G0 X10. Y10.\nG99 G81 X10. Y10. Z-10. R2. F100.\nX30.\n\
         G98 G83 X50. Y40. Z-20. R2. Q5. F80.\nG80\nG0 Z25.\nM30\n",
    )
    .unwrap();
    let h = dir.path().join("holes.h");
    let tnc = port_verified(&src.display().to_string(), "fanuc", "heidenhain", &h);
    // G81: surface = R, no set-up clearance, depth Z - R, one plunge;
    // G99 returns to R (Q204 = 0).
    for part in [
        "CYCL DEF 200 DRILLING ~\n  Q200=+0 ;SET-UP CLEARANCE ~\n  Q201=-12 ;DEPTH ~\n  \
         Q206=+100 ;FEED RATE FOR PLNGNG ~\n  Q202=+12 ;PLUNGING DEPTH",
        "Q203=+2 ;SURFACE COORDINATE ~\n  Q204=+0 ;2ND SET-UP CLEARANCE",
        "L X+10 Y+10 R0 FMAX M99",
        "L X+30 R0 FMAX M99",
        // G83 Q5 under G98: the initial level is the Z when cycle mode
        // began (25, Q204 = 25 - 2), infeed Q202 = 5, full retract.
        "CYCL DEF 203 UNIVERSAL DRILLING ~\n  Q200=+0 ;SET-UP CLEARANCE ~\n  Q201=-22 ;DEPTH",
        "Q202=+5 ;PLUNGING DEPTH",
        "Q213=+0 ;NR OF BREAKS",
        "Q204=+23 ;2ND SET-UP CLEARANCE",
        "L X+50 Y+40 R0 FMAX M99",
    ] {
        assert!(tnc.contains(part), "{part}:\n{tnc}");
    }
    assert!(!tnc.contains("G8"), "{tnc}");
}

#[test]
fn siemens_pocket1_to_cycl_def_251_and_back_verifies() {
    let dir = tempfile::tempdir().unwrap();
    let src = root().join("tests/matrix/pockets/from-siemens840d.mpf");
    let h = dir.path().join("pocket.h");
    let tnc = port_verified(&src.display().to_string(), "siemens840d", "heidenhain", &h);
    for part in [
        "CYCL DEF 251 RECTANGULAR POCKET",
        "Q218=+40 ;FIRST SIDE LENGTH",
        "Q201=-4 ;DEPTH",
        "Q204=+10 ;2ND SET-UP CLEARANCE",
        "L X+30 Y+20 R0 FMAX M99",
    ] {
        assert!(tnc.contains(part), "{part}:\n{tnc}");
    }
    let mpf = dir.path().join("pocket.mpf");
    let back = port_verified(&h.display().to_string(), "heidenhain", "siemens840d", &mpf);
    assert!(
        back.contains("POCKET1(10,0,1,-4,,40,20,5,30,20,0,200,400,2,2,0,0)"),
        "{back}"
    );
}

/// LinuxCNC o-word subroutines to Fanuc: `O n` .. `M99` after the main
/// program (numbered O1 when it has no number), `G65 P n` with Fanuc's
/// argument letters for `#1` `#2` `#3` `#4` (A B C I), numbers or
/// expressions; verified. A named subroutine and an argument no letter reaches (#10)
/// are refused.
#[test]
fn oword_subroutines_become_g65_programs() {
    let dir = tempfile::tempdir().unwrap();
    let ngc = dir.path().join("subs.ngc");
    std::fs::write(
        &ngc,
        "o200 sub\n  G1 X[#1] Y[#2] Z[#4] F300\no200 endsub\nG21 G17 G90 G94\nG0 X0 Y0 Z1\nG1 Z-1 F100\no200 call [20] [5] [0] [-1]\n#3 = 2\no200 call [30] [#3 * 5] [0] [-2]\nG0 Z10\nM2\n",
    )
    .unwrap();
    let fanuc = port_verified(
        &ngc.display().to_string(),
        "linuxcnc",
        "fanuc",
        &dir.path().join("subs.nc"),
    );
    assert!(fanuc.starts_with("O0001\n"), "{fanuc}");
    assert!(fanuc.contains("\nG65 P200 A20. B5. C0. I-1.\n"), "{fanuc}");
    assert!(
        fanuc.contains("\nG65 P200 A30. B[#3*5] C0. I-2.\n"),
        "{fanuc}"
    );
    assert!(fanuc.contains("\nM2\nO0200\n"), "{fanuc}");
    assert!(fanuc.trim_end().ends_with("M99"), "{fanuc}");
    assert_eq!(fanuc.matches("M99").count(), 1, "{fanuc}");
    for (program, why) in [
        // A named subroutine of another file (one defined here gets a
        // number: tests/port_rules.rs).
        ("o100 sub\nG1 X1 F100\no100 endsub\no<side> call\nM2\n", "a call of `o<side>`"),
        (
            "o300 sub\nG1 X[#10] F100\no300 endsub\no300 call [1] [2] [3] [4] [5] [6] [7] [8] [9] [10]\nM2\n",
            "the argument #10",
        ),
    ] {
        let bad = dir.path().join("bad.ngc");
        std::fs::write(&bad, program).unwrap();
        let out = cncc(&["port", "--strict", &bad.display().to_string(), "--to", "fanuc"]);
        let err = text(&out.stderr);
        assert_eq!(out.status.code(), Some(1), "{err}");
        assert!(err.contains("E0617"), "{err}");
        assert!(err.contains(why), "{err}");
    }
}

/// The same subroutines for Siemens (subprograms live in `.SPF` files the
/// port does not write): each call inlined with its arguments set in R
/// parameters first, nested calls too; verified. A subroutine that reads
/// its own #1 after calling another is refused (the callee's arguments
/// would overwrite it).
#[test]
fn oword_subroutines_are_inlined_for_siemens() {
    let dir = tempfile::tempdir().unwrap();
    let ngc = dir.path().join("nested.ngc");
    std::fs::write(
        &ngc,
        "o200 sub\n  G1 X[#1] Y[#2] F300\n  o201 call [3]\no200 endsub\no201 sub\n  G1 Z[-#1]\no201 endsub\nG21 G17 G90 G94\nG0 X0 Y0 Z1\nG1 Z-1 F100\no200 call [20] [5]\no200 call [30] [10]\nG0 Z10\nM2\n",
    )
    .unwrap();
    let mpf = port_verified(
        &ngc.display().to_string(),
        "linuxcnc",
        "siemens840d",
        &dir.path().join("nested.mpf"),
    );
    assert!(
        mpf.contains("R1=20 R2=5\nG1 X=R1 Y=R2 F300\nR1=3\nG1 Z=-R1\nR1=30 R2=10\n"),
        "{mpf}"
    );
    let bad = dir.path().join("after.ngc");
    std::fs::write(
        &bad,
        "o200 sub\n  o201 call [3]\n  G1 X[#1] F300\no200 endsub\no201 sub\n  G1 Z[-#1]\no201 endsub\nG0 X0 Y0 Z1\no200 call [20]\nM2\n",
    )
    .unwrap();
    let out = cncc(&[
        "port",
        "--strict",
        &bad.display().to_string(),
        "--to",
        "siemens840d",
    ]);
    let err = text(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("E0617"), "{err}");
    assert!(err.contains("read after it calls another"), "{err}");
}

/// A construct the target has no form for (Fanuc's G52 local shift for
/// the 840D) is written as the moves it makes, with the shift folded into
/// the coordinates, a W0612 warning per construct and a proof; `--strict`
/// refuses it instead.
#[test]
fn a_construct_without_a_target_form_is_written_as_its_moves() {
    let src = root().join("tests/programs/port/g52_shift.nc");
    let src = src.to_str().unwrap();
    let o = cncc(&["port", "--from", "fanuc", "--to", "siemens840d", src]);
    let (out, err) = (text(&o.stdout), text(&o.stderr));
    assert_eq!(o.status.code(), Some(0), "{err}");
    assert!(err.contains("W0612 port-expanded"), "{err}");
    assert!(
        err.contains("verify: OK"),
        "the expansion is always verified: {err}"
    );
    assert!(!out.contains("G52"), "{out}");
    for want in [
        "G0 X20 Y10 Z10",
        "G1 X20 Y10 Z-1 F200",
        "G2 X40 Y10 Z-1 I5 J0",
        "G0 X0 Y0",
    ] {
        assert!(out.contains(want), "want `{want}` in:\n{out}");
    }
    let strict = cncc(&[
        "port",
        "--strict",
        "--from",
        "fanuc",
        "--to",
        "siemens840d",
        src,
    ]);
    assert_eq!(strict.status.code(), Some(1));
    assert!(
        text(&strict.stderr).contains("E0601"),
        "{}",
        text(&strict.stderr)
    );
}

/// A Fusion 360 style Fanuc program (tool header, `G28 G91 Z0.`, `G43 H`,
/// a G41 D1 contour with arcs, G81/G83 over several holes) ports to the
/// 840D and the TNC in their own idioms, verified, and both outputs port
/// back to Fanuc, verified.
#[test]
fn a_fusion_style_program_ports_to_siemens_and_heidenhain_and_back() {
    let src = root().join("tests/programs/port/fusion_style.nc");
    let dir = tempfile::tempdir().unwrap();
    let wants: &[(&str, &str, &[&str])] = &[
        (
            "siemens840d",
            "mpf",
            &[
                "G41 D1 X0 Y0 F800",
                "MCALL CYCLE81(",
                "MCALL CYCLE83(",
                "G74 Z1=0",
            ],
        ),
        (
            "heidenhain",
            "h",
            &[
                "L X+0 Y+0 RL F800",
                "CYCL DEF 200",
                "CYCL DEF 203",
                "TOOL CALL 1",
                "L X-10 Y-10 R0",
            ],
        ),
    ];
    for (to, ext, want) in wants {
        let out = dir.path().join(format!("bracket.{ext}"));
        let o = cncc(&[
            "port",
            "--from",
            "fanuc",
            "--to",
            to,
            "--verify",
            src.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{to}: {}", text(&o.stderr));
        assert!(
            text(&o.stderr).contains("verify: OK"),
            "{}",
            text(&o.stderr)
        );
        let written = std::fs::read_to_string(&out).unwrap();
        for w in *want {
            assert!(written.contains(w), "{to}: want `{w}` in:\n{written}");
        }
        assert!(
            !written.lines().any(|l| l.trim_end().ends_with(" L R0")),
            "{written}"
        );
        let back = dir.path().join(format!("back-{to}.nc"));
        let o = cncc(&[
            "port",
            "--from",
            to,
            "--to",
            "fanuc",
            "--verify",
            out.to_str().unwrap(),
            "-o",
            back.to_str().unwrap(),
        ]);
        assert_eq!(o.status.code(), Some(0), "{to} back: {}", text(&o.stderr));
    }
}
