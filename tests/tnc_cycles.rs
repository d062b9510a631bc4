//! Heidenhain cycles 204, 208, 209, 241, 254, 256 and 262 run into
//! canonical calls (one program each in `tests/programs/heidenhain/
//! cycles/`), their run-time diagnostics, and what `stepnc --cc2` makes
//! of the milled ones.
//!
//! Every snapshot's numbers were checked by hand against the cycle's
//! geometry (the assumptions are marked [?] in the code and in
//! `docs/heidenhain-cycles.md`):
//! * 204 at (30, 20): underside -20 (Q250); tool tip -37 with the edge
//!   (Q252 15 above the tip) Q200 2 below it; counterbore top -20 + Q249 5
//!   = -15, tip -30; offset 3.5 towards -X (Q214 1) = X26.5; out to 2, 50.
//! * 208 at (40, 30), R5, Q335 16: circle radius 3; semicircle to (43, 30)
//!   about (41.5, 30); helix from 2 down 5 a turn: -3, -8, then 0.4 turn
//!   (144° ccw) to (37.5729, 31.7634) at -10; full circle there; centre.
//! * 209 pitch 1.5, steps of 5: -5 back to -2 (2 x 1.5), -10 back to -7,
//!   -12 out to 2; left hand (Q239 -1, Q256 0) out to 2 after -5.
//! * 241: entry speed 25 to -7.5 (Q379) at 750, 500 rpm, flood, drill at
//!   100 to -60 (Q435) dwell 0.5, to -80 dwell 0.5, coolant off, 25 rpm,
//!   out at 1000, 1000 rpm again.
//! * 254: centre (50, 50) radius 30 over 0..90°, width 10, R3, allowance
//!   0.5: roughing ring 1.5 each side (radii 31.5/28.5) at -3 and -6;
//!   finishing ring 2 each side (32/28) at -6 at Q385 400.
//! * 256 at (50, 40): stud 40 x 20, blank 50 x 30, R5: one ring 5 off the
//!   stud (25..75 x 25..55, corners R7) clockwise (climb), start point
//!   25 + 5 + 2 = 32 right of the centre (X82), in and out on the
//!   semicircles about (78.5, 40) of radius 3.5.
//! * 262 at (20, 20), M12 x 1.5, R4: circle radius 2; up from -4 (right
//!   hand, climb: ccw rising) three turns to 0.5.
//! * frame: 208 under a datum shift X100 and a rotation of 90°, called
//!   with `CYCL CALL POS X+10 Y+0 Z-1`: centre (100, 10), surface -1, so
//!   from 1 one whole turn (Q334 7) to -6, the circle start (rp, 0) turned
//!   to +Y: (100, 13); out to -1 + 20 = 19.
//! * old: cycle 2 from Z2 (set-up 2 above the surface 0) fed at 750 to
//!   -20, dwell 0.4, spindle reversed, back to 2, forward again; cycle 17
//!   pitch -1 (left hand: M4) rigid tap from 2 to -12.
//! * variants: 262 left hand, up-cut (clockwise, so rising), Q355 2:
//!   one-turn passes 2 pitches apart from the bottom -5: -5→-4, -3→-2,
//!   -1→0, approached at Q512 100; 262 right hand, up-cut (clockwise,
//!   falling), Q355 0: one turn -4→-5; 208 up-cut: clockwise, 2→-1→-4 in
//!   whole turns of 3, full circle at -4.

mod common;
use common::*;

const DIR: &str = "tests/programs/heidenhain/cycles";

fn canon(file: &str) -> std::process::Output {
    cncc(&["canon", "--dialect", "heidenhain", file])
}

#[test]
fn each_cycle_runs_into_canonical_calls() {
    for c in [
        "204", "208", "209", "241", "254", "256", "262", "frame", "old",
    ] {
        let f = match c {
            "frame" | "old" | "variants" => format!("{DIR}/{c}.h"),
            _ => format!("{DIR}/c{c}.h"),
        };
        let o = canon(&f);
        assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
        assert_eq!(stderr(&o), "", "{f}");
        insta::assert_snapshot!(format!("tnc_cycle_{c}"), stdout(&o));
    }
}

#[test]
fn a_missing_parameter_is_reported_where_the_cycle_is_defined() {
    let o = cncc(&[
        "check",
        "--dialect",
        "heidenhain",
        &format!("{DIR}/missing.h"),
    ]);
    assert_eq!(o.status.code(), Some(1));
    let e = stderr(&o);
    assert!(e.contains("E0320") && e.contains("Q334"), "{e}");
}

#[test]
fn a_parameter_missing_at_the_call_stops_the_run() {
    // The front end reports E0320; a run that goes on regardless (the
    // library API) stops at the call with E0523 naming the parameter.
    use cncc::dialect::builtin::builtin;
    let spec = builtin("heidenhain").unwrap();
    let path = root().join(DIR).join("missing.h");
    let text = std::fs::read_to_string(path).unwrap();
    let mut sm = cncc::source::SourceMap::new();
    let id = sm.add("missing.h", text.clone());
    let (p, _) = cncc::driver::read_program(&text, id, &spec);
    let mut sink = |_: cncc::canon::Canon, _: cncc::span::Span| {};
    let diags = cncc::interp::run(
        std::rc::Rc::new(p),
        &spec,
        &cncc::interp::Options::default(),
        &mut cncc::interp::flow::NoLoader,
        &mut sink,
    );
    let d = diags
        .iter()
        .find(|d| d.code == cncc::diag::Code::TncCycleParameterMissing)
        .unwrap_or_else(|| panic!("no E0523 in {diags:?}"));
    assert!(d.message.contains("Q334"), "{}", d.message);
    assert!(d.span().is_some());
}

#[test]
fn impossible_cycles_stop_with_their_code() {
    for (f, code, what) in [
        ("toowide", "E0524", "wider than the hole"),
        ("noradius", "E0525", "needs the tool radius"),
        ("direction", "E0526", "Q214=0"),
        // 5000 levels x 2500 rings: refused at once, not run for hours.
        ("toomany", "E0524", "more passes than cncc runs"),
    ] {
        let o = canon(&format!("{DIR}/errors/{f}.h"));
        assert_eq!(o.status.code(), Some(1), "{f}");
        let e = stderr(&o);
        assert!(e.contains(code) && e.contains(what), "{f}: {e}");
    }
}

#[test]
fn parameters_the_run_does_not_apply_are_reported() {
    let o = canon(&format!("{DIR}/errors/notapplied.h"));
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(e.contains("W0514") && e.contains("Q437"), "{e}");
    // Q367 1 (tool on the lower left corner) and Q224 30°: the stud's
    // centre is (20, 10) turned by 30° = (12.3205, 18.6603); the start
    // point lies 30 + 5 + 2 = 37 along the turned first axis from it.
    let out = stdout(&o);
    assert!(
        out.contains("STRAIGHT_FEED(44.3634, 37.1603, -3.0000"),
        "{out}"
    );
    // Up-cut (Q351 -1) runs counter-clockwise round the stud.
    assert!(
        out.contains("ARC_FEED(19.5910, 46.0674, 24.6410, 37.3205, 1, -3.0000"),
        "{out}"
    );
}

fn cc2(c: &str) -> String {
    let f = format!("{DIR}/c{c}.h");
    let tools = format!("{DIR}/tools.tbl");
    let o = cncc(&[
        "stepnc",
        "--cc2",
        "--summary",
        "--dialect",
        "heidenhain",
        "--machine-units",
        "mm",
        "--tool-table",
        &tools,
        "--stock",
        "100x100x30+0+0-30",
        &f,
    ]);
    assert_eq!(o.status.code(), Some(0), "{f}: {}", stderr(&o));
    stdout(&o)
}

#[test]
fn cc2_recognises_the_milled_cycles() {
    // 208: the bore milled by the helix is recognised as a circular
    // closed pocket of the nominal diameter and depth (the recogniser
    // has no helical hole milling → ROUND_HOLE rule yet).
    let s = cc2("208");
    assert!(
        s.contains("CLOSED_POCKET circle D16") && s.contains("at (40, 30, 0) depth 10"),
        "{s}"
    );
    // 254: the circular slot becomes closed pockets with the slot's
    // outline (roughing and finishing), not a SLOT (ISO 14649 slots are
    // recognised along straight travel paths only).
    let s = cc2("254");
    assert!(
        s.contains("CLOSED_POCKET general polyline") && s.contains("depth 6"),
        "{s}"
    );
    // 256: a stud is not recognised; its moves are kept as a
    // TOOLPATH_FEATURE (W0870), which is acceptable.
    let s = cc2("256");
    assert!(s.contains("TOOLPATH_FEATURE"), "{s}");
}

/// `CYCL CALL PAT FMAX` and `CYCL CALL POS .. FMAX`: read, run at every
/// point (positioning at rapid), and written back with their `FMAX`;
/// `FMAX` on a plain `CYCL CALL` is still refused.
#[test]
fn pattern_and_position_calls_take_fmax() {
    let dir = tempfile::tempdir().unwrap();
    let h = dir.path().join("pat.h");
    std::fs::write(
        &h,
        "0 BEGIN PGM P MM\n1 TOOL CALL 1 Z S1000\n2 L Z+50 R0 FMAX M3\n3 PATTERN DEF ~\n  POS1 (X+25 Y+33.5 Z+0) ~\n  POS2 (X+50 Y+75 Z+0)\n4 CYCL DEF 200 DRILLING ~\n  Q200=+2 ;SET-UP CLEARANCE ~\n  Q201=-10 ;DEPTH ~\n  Q206=+150 ;FEED RATE FOR PLNGNG ~\n  Q202=+10 ;PLUNGING DEPTH ~\n  Q210=+0 ;DWELL TIME AT TOP ~\n  Q203=+0 ;SURFACE COORDINATE ~\n  Q204=+50 ;2ND SET-UP CLEARANCE ~\n  Q211=+0 ;DWELL TIME AT DEPTH\n5 CYCL CALL PAT FMAX\n6 CYCL CALL POS X+10 Y+10 Z+0 FMAX\n7 L Z+100 R0 FMAX M30\n8 END PGM P MM\n",
    )
    .unwrap();
    let path = h.to_str().unwrap();
    let o = cncc(&["canon", path]);
    let out = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // Three holes, each drilled to z -10.
    for (x, y) in [
        ("25.0000", "33.5000"),
        ("50.0000", "75.0000"),
        ("10.0000", "10.0000"),
    ] {
        assert!(
            out.contains(&format!("STRAIGHT_FEED({x}, {y}, -10.0000")),
            "{out}"
        );
    }
    let o = cncc(&["port", path, "--to", "heidenhain", "--verify"]);
    let text = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(text.contains("5 CYCL CALL PAT FMAX\n"), "{text}");
    assert!(
        text.contains("6 CYCL CALL POS X+10 Y+10 Z+0 FMAX\n"),
        "{text}"
    );
    std::fs::write(&h, "0 BEGIN PGM P MM\n1 CYCL CALL FMAX\n2 END PGM P MM\n").unwrap();
    let o = cncc(&["check", path]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("E0122"));
}
