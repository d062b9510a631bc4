//! `cncc port` of variables, loops and jumps to and from Heidenhain
//! Klartext (Q parameters, `LBL`, `FN 9..12`), each port verified: the
//! source and the port run and must cut the same. The matrix
//! (`tests/matrix/variables-loops`) holds the plain cases; these are the
//! structures around them (IF/ELSE IF/ELSE, AND/OR, REPEAT, BREAK,
//! CONTINUE, DO/WHILE, CASE, FOR with a computed bound, IF THEN, GOTO N)
//! and the refusals (E0621, E0622).

use std::process::Command;

struct Ported {
    code: Option<i32>,
    text: String,
    err: String,
}

/// Ports `src` (written as `name`) to `to` with `--verify`.
fn port(name: &str, src: &str, to: &str) -> Ported {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join(name);
    std::fs::write(&path, src).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["port", "--strict", "--to", to, "--verify"])
        .arg(&path)
        .output()
        .unwrap();
    Ported {
        code: out.status.code(),
        text: String::from_utf8_lossy(&out.stdout).into_owned(),
        err: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

fn verified(name: &str, src: &str, to: &str) -> String {
    let p = port(name, src, to);
    assert_eq!(p.code, Some(0), "{}", p.err);
    assert!(p.err.contains("verify: OK"), "{}", p.err);
    p.text
}

fn refused(name: &str, src: &str, to: &str, code: &str) -> String {
    let p = port(name, src, to);
    assert_eq!(p.code, Some(1), "{}\n{}", p.text, p.err);
    assert!(p.err.contains(code), "{}", p.err);
    p.err
}

const LINUXCNC: &str = "G21 G17 G90 G94
T1 M6
G43 H1 G0 Z10
S3000 M3
G0 X0 Y0
#1=0
o1 while [#1 LT 4]
  #1=[#1+1]
  o2 if [#1 LE 2 AND #1 GT 0]
    G1 Z-1 F100
  o2 elseif [#1 EQ 3]
    G1 Z-2 F100
  o2 else
    G1 Z-3 F100
  o2 endif
  G1 X[10*#1] F300
  G0 Z1
o1 endwhile
#<n>=0
o3 repeat [5]
  #<n>=[#<n>+1]
  o4 if [#<n> EQ 2 OR #<n> EQ 5]
    o3 continue
  o4 endif
  o5 if [#<n> GT 3]
    o3 break
  o5 endif
  G1 Y[#<n>] F100
o3 endrepeat
o6 do
  #<n>=[#<n>-1]
  G1 X[#<n>] F100
o6 while [#<n> GT 0]
G0 Z10
M2
";

#[test]
fn linuxcnc_structures_to_klartext() {
    let h = verified("s.ngc", LINUXCNC, "heidenhain");
    // #1 → Q1, #<n> → QL1; WHILE #1 LT 4 leaves on GT or EQU, the
    // else branches are jumped around.
    for line in [
        "Q1 = 0",
        "QL1 = 0",
        "FN 11: IF +Q1 GT +4 GOTO LBL 2",
        "FN 9: IF +Q1 EQU +4 GOTO LBL 2",
        "FN 11: IF +Q1 GT +2 GOTO LBL",
        "FN 10: IF +Q1 NE +3 GOTO LBL",
        "FN 9: IF +0 EQU +0 GOTO LBL",
        "FN 11: IF +QL1 GT +0 GOTO LBL",
    ] {
        assert!(h.contains(line), "{line}\n{h}");
    }
    assert!(!h.contains('#'), "{h}");
}

#[test]
fn while_if_else_back_from_klartext_to_linuxcnc() {
    let src: String = LINUXCNC.split("#<n>=0").next().unwrap().to_string() + "G0 Z10\nM2\n";
    let h = verified("w.ngc", &src, "heidenhain");
    let back = verified("w.h", &h, "linuxcnc");
    // The guard before the loop and the test at its end: an if around a
    // do/while.
    for line in ["do\n", " else\n", " endif\n", " while [#1 LT 4]\n"] {
        assert!(back.contains(line), "{line}\n{back}");
    }
    assert!(!back.contains("GOTO"), "{back}");
}

#[test]
fn siemens_repeat_for_case_to_klartext() {
    let src = "; REPEAT UNTIL, CASE, FOR with a computed bound
G71 G17 G90 G94
T1 D1 M6
G0 Z10
S3000 M3
G0 X0 Y0
DEF INT I, N
N=2
R1=0
REPEAT
R1=R1+1
G1 Z=-R1 F100
UNTIL R1>=3
FOR I=1 TO N+1
G1 X=10*I F300
ENDFOR
CASE(R1) OF 2 GOTOF TWO 3 GOTOF THREE DEFAULT GOTOF OTHER
TWO: G1 Y5 F200
THREE: G1 Y10 F200
OTHER: G0 Z10
M30
";
    let h = verified("s.mpf", src, "heidenhain");
    for line in [
        // UNTIL R1>=3 jumps back while R1 < 3.
        "FN 12: IF +Q1 LT +3 GOTO LBL 1",
        // The FOR bound N+1, evaluated once, in a local parameter.
        "QL3 = QL2 + 1",
        "FN 11: IF +QL1 GT +QL3 GOTO LBL",
        "FN 9: IF +Q1 EQU +3 GOTO LBL \"THREE\"",
        "LBL \"OTHER\"",
    ] {
        assert!(h.contains(line), "{line}\n{h}");
    }
    let back = verified("s.h", &h, "siemens840d");
    assert!(back.contains("GOTOB LBL1"), "{back}");
}

#[test]
fn fanuc_if_then_and_goto_to_klartext_and_back() {
    let src = "O1000
G21 G17 G90 G94
T1 M6
G0 G43 H1 Z10.
S3000 M3
#1=2
IF [#1 EQ 2] THEN #2=5
IF [#1 GT 1 AND #2 EQ 5] GOTO 20
G1 Z-1. F100.
N20 G1 X#2 F300.
#3=0
WHILE [#3 LE 2] DO1
#3=#3+1
IF [#3 EQ 2] GOTO 30
G1 Y#3 F100.
N30 END1
G0 Z10.
M30
";
    let h = verified("f.nc", src, "heidenhain");
    assert!(h.contains("LBL 20"), "{h}");
    assert!(h.contains("FN 9: IF +Q3 EQU +2 GOTO LBL 30"), "{h}");
    let back = verified("f.h", &h, "fanuc");
    assert!(back.contains("IF [#3 EQ 2] GOTO"), "{back}");
}

#[test]
fn variables_without_a_q_parameter_are_e0621() {
    let src = "O1
G21 G90
#500=1
G1 X#500 F100.
M30
";
    let err = refused("v.nc", src, "heidenhain", "E0621");
    assert!(err.contains("`#500`"), "{err}");
}

#[test]
fn computed_jumps_and_bitwise_conditions_are_e0622() {
    let computed = "O1
G21 G90
#1=10
GOTO #1
N10 G1 X1. F100.
M30
";
    refused("g.nc", computed, "heidenhain", "E0622");
    let bitwise = "O1
G21 G90
#1=3
IF [#1 AND 1] GOTO 10
G1 X1. F100.
N10 G1 X2. F100.
M30
";
    refused("b.nc", bitwise, "heidenhain", "E0622");
}

const KLARTEXT_CROSSING: &str = "0 BEGIN PGM X MM
1 TOOL CALL 1 Z S3000
2 Q1 = 0
3 LBL 1
4 Q1 = Q1 + 1
5 FN 9: IF +Q1 EQU +2 GOTO LBL 2
6 L X+Q1 F100
7 FN 12: IF +Q1 LT +3 GOTO LBL 1
8 L Y+1 F100
9 LBL 2
10 L Z+1 F100
11 M30
12 END PGM X MM
";

#[test]
fn klartext_jumps_that_do_not_nest_are_e0622_for_linuxcnc_only() {
    refused("c.h", KLARTEXT_CROSSING, "linuxcnc", "E0622");
    let fanuc = verified("c.h", KLARTEXT_CROSSING, "fanuc");
    assert!(fanuc.contains("IF [#1 EQ 2] GOTO"), "{fanuc}");
}

#[test]
fn klartext_local_and_system_parameters() {
    let src = "0 BEGIN PGM X MM
1 TOOL CALL 1 Z S3000
2 QL5 = 2
3 L X+QL5 F100
4 M30
5 END PGM X MM
";
    let fanuc = verified("l.h", src, "fanuc");
    assert!(fanuc.contains("#100=2"), "{fanuc}");
    let linuxcnc = verified("l.h", src, "linuxcnc");
    assert!(linuxcnc.contains("#<ql5>=2"), "{linuxcnc}");
    let system = src.replace("QL5 = 2", "QL5 = Q108");
    refused("q.h", &system, "siemens840d", "E0621");
}

#[test]
fn sequence_numbers_beyond_label_range_get_a_fresh_label() {
    let src = "O1
G21 G90
#1=0
N1000 #1=#1+1
G1 X#1 F100.
IF [#1 LT 2] GOTO 1000
M30
";
    let h = verified("n.nc", src, "heidenhain");
    assert!(h.contains("LBL 1\n"), "{h}");
    assert!(h.contains("FN 12: IF +Q1 LT +2 GOTO LBL 1\n"), "{h}");
}

#[test]
fn functions_through_the_formula_form_or_e0623() {
    let src = "O1
G21 G90
#1=ATAN[1]/[2]
#2=POW[2,3]
#3=SQRT[#2*2]+ABS[-1]
G1 X#1 Y#2 Z#3 F100.
M30
";
    let h = verified("fn.nc", src, "heidenhain");
    for line in [
        "FN 13: Q1 = +2 ANG +1",
        "Q2 = 2 ^ 3",
        "Q3 = SQRT (Q2 * 2) + ABS (-1)",
    ] {
        assert!(h.contains(line), "{line}\n{h}");
    }
    let bad = "O1
G21 G90
#1=FIX[2.5]+ATAN[1]/[2]
G1 X#1 F100.
M30
";
    let err = refused("fn2.nc", bad, "heidenhain", "E0623");
    assert!(err.contains("FIX") && err.contains("arc tangent"), "{err}");
}

/// A WHILE with CONTINUE (and BREAK) to Klartext and back to LinuxCNC:
/// CONTINUE is a jump to the test at the loop's end, which comes back as
/// an if around the rest of the body; BREAK comes back as `break`.
#[test]
fn continue_and_break_back_to_linuxcnc() {
    let src = "G21 G17 G90 G94
T1 M6
G43 H1 G0 Z10
S3000 M3
#2=0
o3 while [#2 LT 6]
  #2=[#2+1]
  o7 if [#2 EQ 2 OR #2 EQ 4]
    o3 continue
  o7 endif
  G1 Y[#2] F100
o3 endwhile
G0 Z10
M2
";
    let h = verified("c.ngc", src, "heidenhain");
    let back = verified("c.h", &h, "linuxcnc");
    assert!(back.contains(" if [[#2 NE 2] AND [#2 NE 4]]\n"), "{back}");
    assert!(
        !back.contains("continue") && !back.contains("GOTO"),
        "{back}"
    );
    let with_break = src.replace(
        "  G1 Y[#2] F100\n",
        "  o8 if [#2 GT 4]\n    o3 break\n  o8 endif\n  G1 Y[#2] F100\n",
    );
    let h = verified("cb.ngc", &with_break, "heidenhain");
    let back = verified("cb.h", &h, "linuxcnc");
    assert!(back.contains(" break\n"), "{back}");
}

/// Klartext jumps back to a loop's top from its middle: `continue` when
/// the loop's own jump back is unconditional, unless a jump out of the
/// loop (`break`) follows it: rs274 runs `o1 continue` as the next `o1`
/// line, which would be that `o1 break` (probed with the oracle); then
/// the jump back becomes a loop of its own.
#[test]
fn klartext_jump_to_the_top_as_continue_only_before_any_break() {
    let program = |body: &str| {
        format!(
            "0 BEGIN PGM K MM\n1 TOOL CALL 1 Z S3000\n2 Q1 = 0\n3 LBL 1\n4 Q1 = Q1 + 1\n{body}7 L X+Q1 F100\n8 FN 9: IF +0 EQU +0 GOTO LBL 1\n9 LBL 2\n10 M30\n11 END PGM K MM\n"
        )
    };
    let leave = "FN 11: IF +Q1 GT +4 GOTO LBL 2\n";
    let again = "FN 9: IF +Q1 EQU +2 GOTO LBL 1\n";
    let first = program(&format!("5 {leave}6 {again}"));
    let back = verified("k1.h", &first, "linuxcnc");
    assert!(
        back.contains(" continue\n") && back.contains(" break\n"),
        "{back}"
    );
    let second = program(&format!("5 {again}6 {leave}"));
    let back = verified("k2.h", &second, "linuxcnc");
    assert!(
        !back.contains("continue") && back.contains(" break\n"),
        "{back}"
    );
    assert!(back.contains(" while [#1 EQ 2]\n"), "{back}");
}
