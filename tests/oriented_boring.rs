//! Oriented boring as each control runs it (issue 12): Fanuc G76 fine
//! boring and G87 back boring shift the tool by the retained Q in the
//! direction the dialect spec gives (`shift`), Haas G76/G77 by Q or by I/J;
//! LinuxCNC's G87 keeps its I J K and its G76 stays lathe threading.

mod common;
use common::*;

fn canon(dialect: &str, file: &str) -> String {
    let o = cncc(&["canon", "--dialect", dialect, file]);
    assert!(o.status.success(), "{}", stderr(&o));
    stdout(&o)
}

fn check(dialect: &str, file: &str) -> (Option<i32>, String) {
    let o = cncc(&["check", "--dialect", dialect, file]);
    (o.status.code(), stderr(&o))
}

fn tr(x: f64, y: f64, z: f64) -> String {
    format!("STRAIGHT_TRAVERSE({x:.4}, {y:.4}, {z:.4}, 0.0000, 0.0000, 0.0000)")
}

fn feed(x: f64, y: f64, z: f64) -> String {
    format!("STRAIGHT_FEED({x:.4}, {y:.4}, {z:.4}, 0.0000, 0.0000, 0.0000)")
}

const ORIENT: &str = "STOP_SPINDLE_TURNING(0)\nORIENT_SPINDLE(0, 0.0000, 2)";
const START: &str = "START_SPINDLE_CLOCKWISE(0)";

#[test]
fn fanuc_g76_bores_orients_shifts_by_q_and_rapids_out() {
    let out = canon("fanuc", "tests/programs/fanuc/oriented_boring.nc");
    // Feed to Z, dwell P500 (ms), orient, shift +X by Q1, rapid to the
    // initial level (G98), shift back, spindle on.
    let want = [
        feed(10.0, 10.0, -20.0),
        "DWELL(0.5000)".into(),
        ORIENT.into(),
        tr(11.0, 10.0, -20.0),
        tr(11.0, 10.0, 50.0),
        tr(10.0, 10.0, 50.0),
        START.into(),
    ]
    .join("\n");
    assert!(out.contains(&want), "{out}");
    // The next hole of the same cycle keeps Q.
    assert!(
        out.contains(&format!("{ORIENT}\n{}", tr(31.0, 10.0, -20.0))),
        "{out}"
    );
}

#[test]
fn fanuc_g87_enters_below_the_part_shifted_and_bores_upwards() {
    let out = canon("fanuc", "tests/programs/fanuc/oriented_boring.nc");
    // No Q in the G87 block: the retained Q1. shifts. R-30 is below the
    // part, Z-5 the top of the back bore; back to the initial level.
    let want = [
        tr(10.0, 10.0, 50.0),
        ORIENT.into(),
        tr(11.0, 10.0, 50.0),
        tr(11.0, 10.0, -30.0),
        tr(10.0, 10.0, -30.0),
        START.into(),
        feed(10.0, 10.0, -5.0),
        // P is retained cycle data as well (the G76's P500).
        "DWELL(0.5000)".into(),
        ORIENT.into(),
        tr(11.0, 10.0, -5.0),
        tr(11.0, 10.0, 50.0),
        tr(10.0, 10.0, 50.0),
        START.into(),
    ]
    .join("\n");
    assert!(out.contains(&want), "{out}");
    let (code, err) = check("fanuc", "tests/programs/fanuc/oriented_boring.nc");
    assert_eq!(code, Some(0), "{err}");
    // An R below the part is what back boring wants: no lint about it.
    assert!(!err.contains("W0712") && !err.contains("warning"), "{err}");
}

#[test]
fn fanuc_boring_without_any_q_runs_with_no_shift_and_says_so() {
    let file = "tests/programs/fanuc/oriented_boring_mistakes.nc";
    let (code, err) = check("fanuc", file);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("error["), "{err}");
    assert!(err.contains("warning[W0520"), "{err}");
    assert!(err.contains("oriented_boring_mistakes.nc:7:"), "{err}");
    // A G87 written with the R and Z of a drilling cycle feeds downwards.
    assert!(err.contains("warning[W0521"), "{err}");
    assert!(
        err.contains("back boring from R 2.0000 down to Z -15.0000"),
        "{err}"
    );
    let out = canon("fanuc", file);
    assert!(
        out.contains(&format!("{ORIENT}\n{}", tr(10.0, 10.0, -20.0))),
        "{out}"
    );
}

#[test]
fn haas_g76_shifts_by_i_j_and_g77_by_q() {
    let file = "tests/programs/haas/oriented_boring.nc";
    let out = canon("haas", file);
    // G76 I0 J-0.02: the shift is the I/J vector.
    let g76 = [
        feed(1.0, 1.0, -1.0),
        ORIENT.into(),
        tr(1.0, 0.98, -1.0),
        tr(1.0, 0.98, 1.0),
        tr(1.0, 1.0, 1.0),
        START.into(),
    ]
    .join("\n");
    assert!(out.contains(&g76), "{out}");
    // G77 Q0.03: +X (setting 27), down to R-1 below the part, up to Z-0.2.
    let g77 = [
        ORIENT.into(),
        tr(2.03, 1.0, 1.0),
        tr(2.03, 1.0, -1.0),
        tr(2.0, 1.0, -1.0),
        START.into(),
        feed(2.0, 1.0, -0.2),
    ]
    .join("\n");
    assert!(out.contains(&g77), "{out}");
    let (code, err) = check("haas", file);
    assert_eq!(code, Some(0), "{err}");
    assert!(!err.contains("warning"), "{err}");
}

#[test]
fn linuxcnc_g87_still_takes_i_j_k() {
    let (_, err) = check("linuxcnc", "tests/programs/linuxcnc/back_bore_ijk.ngc");
    assert!(err.contains("error[E0541"), "{err}");
    assert!(err.contains("I word missing with G87"), "{err}");
}

#[test]
fn a_dialect_file_sets_the_shift_direction() {
    let dir = std::env::temp_dir().join(format!("cncc-shift-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let spec = dir.join("minus-y.xml");
    std::fs::write(
        &spec,
        r#"<dialect id="fanuc-minus-y" name="Fanuc, G76 shift -Y" family="word-address" extends="fanuc">
  <code letter="G" number="76" group="canned-cycle" meaning="cycle.fine-bore" uses="RQPFK" shift="-Y" doc="fine boring, parameter 5101 RD2/RD1 = 1/1"/>
</dialect>"#,
    )
    .unwrap();
    let o = cncc(&[
        "--dialect-file",
        spec.to_str().unwrap(),
        "canon",
        "--dialect",
        "fanuc-minus-y",
        "tests/programs/fanuc/oriented_boring.nc",
    ]);
    let out = stdout(&o);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        out.contains(&format!("{ORIENT}\n{}", tr(10.0, 9.0, -20.0))),
        "{out}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_port_writes_oriented_boring_only_where_it_means_the_same() {
    // Fanuc G76/G87 (shift by Q) are Haas G76/G77.
    let o = cncc(&[
        "port",
        "--to",
        "haas",
        "tests/programs/fanuc/oriented_boring.nc",
    ]);
    let out = stdout(&o);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        out.contains("G98 G76 X10. Y10. Z-20. R2. Q1. P500 F100"),
        "{out}"
    );
    assert!(out.contains("G77 X10. Y10. Z-5. R-30. F80"), "{out}");
    // LinuxCNC's G87 takes I J K: another cycle.
    let o = cncc(&[
        "port",
        "--to",
        "linuxcnc",
        "tests/programs/fanuc/oriented_boring.nc",
    ]);
    let err = stderr(&o);
    assert!(!o.status.success(), "{}", stdout(&o));
    assert!(err.contains("error[E0601"), "{err}");
    assert!(err.contains("different cycles"), "{err}");
}
