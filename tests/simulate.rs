//! `cncc simulate`: removed volumes against their analytic values (within
//! 0.5%), the picture and mesh written, a rapid through the stock located.

use std::f64::consts::PI;
use std::process::Command;

fn simulate(program: &str, stock: &str, extra: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .arg("simulate")
        .arg(format!("tests/programs/simulate/{program}"))
        .args([
            "--stock",
            stock,
            "--machine-units",
            "mm",
            "--format",
            "json",
        ])
        .args(extra)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn removed(program: &str, stock: &str) -> f64 {
    let (code, out, err) = simulate(program, stock, &[]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    v["removed_mm3"].as_f64().unwrap()
}

fn close(got: f64, exact: f64) {
    assert!(
        (got - exact).abs() / exact < 0.005,
        "{got} mm3 against {exact} mm3"
    );
}

#[test]
fn a_straight_slot_with_a_flat_end_mill() {
    // 50 mm long, 10 wide, round ends, 3 deep.
    close(removed("slot.nc", "100x50x20"), 3.0 * (500.0 + 25.0 * PI));
}

#[test]
fn a_rectangular_pocket() {
    // Tool centre over 30 x 20, tool radius 5: 40 x 30 with R5 corners, 5 deep.
    close(
        removed("pocket.nc", "100x50x20"),
        5.0 * (600.0 + 100.0 * 5.0 + 25.0 * PI),
    );
}

#[test]
fn a_drilled_hole_with_a_118_degree_point() {
    let (r, depth) = (5.0, 20.0);
    let cone = r / (59.0f64).to_radians().tan();
    let exact = PI * r * r * (depth - cone) + PI * r * r * cone / 3.0;
    close(removed("drill.nc", "100x50x20"), exact);
}

#[test]
fn a_helix_then_a_flat_circle() {
    // Path radius 10, tool radius 5: an annulus 5..15, 10 deep.
    close(
        removed("helix.nc", "40x40x20-20-20-20"),
        10.0 * PI * (225.0 - 25.0),
    );
}

#[test]
fn a_rapid_into_the_stock_is_a_located_error() {
    let (code, _, err) = simulate("rapid_into_stock.nc", "100x50x20", &[]);
    assert_eq!(code, 1, "{err}");
    assert!(err.contains(r#""code":"E1001""#), "{err}");
    assert!(err.contains(r#""line":8,"column":1"#), "{err}");
    let (code, _, err) = simulate("slot.nc", "100x50x20", &[]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn the_part_is_written_as_png_and_stl() {
    let dir = tempfile::tempdir().unwrap();
    let png = dir.path().join("part.png");
    let stl = dir.path().join("part.stl");
    for out in [&png, &stl] {
        let (code, _, err) = simulate("slot.nc", "100x50x20", &["-o", out.to_str().unwrap()]);
        assert_eq!(code, 0, "{err}");
    }
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
    let mesh = std::fs::read(&stl).unwrap();
    let n = u32::from_le_bytes(mesh[80..84].try_into().unwrap()) as usize;
    assert_eq!(mesh.len(), 84 + 50 * n);
}

#[test]
fn check_reports_a_rapid_into_a_given_stock() {
    let check = |program: &str, stock: Option<&str>| {
        let mut c = Command::new(env!("CARGO_BIN_EXE_cncc"));
        c.args(["check", "--machine-units", "mm", "--format", "json"])
            .arg(format!("tests/programs/simulate/{program}"));
        if let Some(s) = stock {
            c.args(["--stock", s]);
        }
        let out = c.output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr).into_owned();
        (out.status.code().unwrap_or(-1), err)
    };
    let (code, err) = check("rapid_into_stock.nc", Some("100x50x20"));
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains(r#""code":"E1001""#) && err.contains(r#""line":8"#),
        "{err}"
    );
    let (code, err) = check("rapid_into_stock.nc", None);
    assert_eq!(code, 0, "without a stock nothing is known: {err}");
    for clean in ["slot.nc", "pocket.nc", "drill.nc", "helix.nc"] {
        let (code, err) = check(clean, Some("100x50x20-50-25-20"));
        assert!(!err.contains("E1001"), "{clean}: {err}");
        assert_eq!(code, 0, "{clean}: {err}");
    }
}

fn diff_material(a: &str, b: &str) -> (i32, String) {
    diff_material_on(a, b, "40x40x20-20-20-20")
}

fn diff_material_on(a: &str, b: &str, stock: &str) -> (i32, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(["diff", "--material", "--machine-units", "mm"])
        .args(["--stock", stock])
        .arg(format!("tests/programs/simulate/{a}"))
        .arg(format!("tests/programs/simulate/{b}"))
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
    )
}

#[test]
fn a_ring_and_a_full_pocket_differ_by_material() {
    let (code, out) = diff_material("ring.nc", "full_pocket.nc");
    assert_eq!(code, 1, "{out}");
    assert!(out.contains("largest deviation 5.000 mm"), "{out}");
    // The island: inside the tool's radius round the centre.
    assert!(
        out.contains("within X-4.950..4.950 Y-4.950..4.950"),
        "{out}"
    );
    // Where: the ring never reaches the island; the full pocket's plunge
    // at the centre cut it.
    assert!(out.contains("A: no move cuts there"), "{out}");
    assert!(
        out.contains("B: line 9 cut there last, to Z-5.000: G1 Z-5. F100."),
        "{out}"
    );
    let (code, out) = diff_material("ring.nc", "ring_again.nc");
    assert_eq!(code, 0, "the same ring cut the other way round: {out}");
}

#[test]
fn a_zigzag_and_a_spiral_pocket_compare_equal() {
    // pocket.nc clears 40 x 30 R5 by zigzag and a finishing contour;
    // spiral_pocket.nc from the middle out, contour after contour.
    let stock = "100x50x20-30-10-20";
    let (code, out) = diff_material_on("pocket.nc", "spiral_pocket.nc", stock);
    assert_eq!(code, 0, "{out}");
    assert!(out.contains("the parts are the same"), "{out}");
    let (code, out) = diff_material_on("pocket.nc", "slot.nc", stock);
    assert_eq!(code, 1, "a pocket is not a slot: {out}");
}

fn cncc(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_cncc"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

#[test]
fn port_verify_material_compares_the_cut_parts() {
    let port = |file: &str, to: &str, extra: &[&str]| {
        let file = format!("tests/programs/simulate/{file}");
        let mut args = vec!["port", file.as_str(), "--to", to, "--verify", "--material"];
        args.extend(["--machine-units", "mm"]);
        args.extend(extra);
        cncc(&args)
    };
    for to in ["heidenhain", "siemens840d", "linuxcnc"] {
        let (code, out, err) = port("pocket.nc", to, &[]);
        assert_eq!(code, 0, "{to}: {err}");
        assert!(!out.is_empty(), "{to}: the port is written");
        assert!(err.contains("verify: OK: the same"), "{to}: {err}");
        assert!(
            err.contains("verify: material: the same part within 0.01 mm")
                && err.contains("stock: guessed from the feed moves"),
            "{to}: {err}"
        );
    }
    let (code, _, err) = port("ring.nc", "heidenhain", &["--stock", "40x40x20-20-20-20"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("grid 400 x 400 cells") && err.contains("stock: --stock"),
        "{err}"
    );
    let (code, _, err) = port("blk_slot.h", "fanuc", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("stock: the program's BLK FORM"), "{err}");
    // Without --material the parts are not compared.
    let (code, _, err) = cncc(&[
        "port",
        "tests/programs/simulate/pocket.nc",
        "--to",
        "heidenhain",
        "--verify",
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("material"), "{err}");
    let (code, _, err) = cncc(&[
        "port",
        "tests/programs/simulate/pocket.nc",
        "--to",
        "heidenhain",
        "--stock",
        "10x10x10",
    ]);
    assert_ne!(code, 0, "--stock alone means nothing: {err}");
    assert!(err.contains("--features or --verify --material"), "{err}");
}

fn check_json(program: &str, extra: &[&str]) -> (i32, String) {
    let file = format!("tests/programs/simulate/{program}");
    let mut args = vec!["check", "--machine-units", "mm", "--format", "json", &file];
    args.extend(extra);
    let (code, _, err) = cncc(&args);
    (code, err)
}

#[test]
fn check_takes_the_stock_from_blk_form() {
    let (code, err) = check_json("blk_rapid.h", &[]);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains(r#""code":"E1001""#) && err.contains(r#""line":7"#),
        "{err}"
    );
    assert!(err.contains("stock from the program's BLK FORM"), "{err}");
    let (code, err) = check_json("blk_slot.h", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("E1001"), "{err}");
    // --stock wins: a blank whose top is at Z-10 lies below the rapid.
    let (code, err) = check_json("blk_rapid.h", &["--stock", "100x50x10-0-0-20"]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("E1001"), "{err}");
}

#[test]
fn a_flat_end_mill_plunging_into_solid_stock_is_a_warning() {
    let (code, err) = check_json("plunge.nc", &["--stock", "100x50x20"]);
    assert_eq!(code, 0, "a warning only: {err}");
    // Only T1 straight down at X20: not T2 (a drill), not T1 into T2's
    // hole, not the ramp, not T3 (a ball).
    assert_eq!(err.matches(r#""code":"W1004""#).count(), 1, "{err}");
    assert!(err.contains(r#""line":18"#), "{err}");
    let (_, err) = check_json("plunge.nc", &[]);
    assert!(!err.contains("W1004"), "no stock, no check: {err}");
}

#[test]
fn the_stock_checks_stop_after_a_tool_of_unknown_size_cuts() {
    // blk_unknown.h: T1 of no known size ramps in and cuts a slot; the
    // later rapid into it (3 mm beside the axis line the simulation cut)
    // is not judged.
    let (code, err) = check_json("blk_unknown.h", &["--stock", "100x50x20"]);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains(r#""code":"W1003""#) && err.contains(r#""line":7"#),
        "{err}"
    );
    assert!(!err.contains("E1001"), "{err}");
    // With the program's own BLK FORM (not asked for) the checks stop
    // without a word: a clean program checks silently.
    let (code, err) = check_json("blk_unknown.h", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("W1003") && !err.contains("E1001"), "{err}");
    // blk_slot.h gives T1 its size with TOOL DEF: checked to the end.
    let (code, err) = check_json("blk_slot.h", &[]);
    assert_eq!(code, 0, "{err}");
    assert!(!err.contains("W1003"), "{err}");
}

#[test]
fn tool_def_gives_the_simulation_its_tool() {
    // blk_slot.h: TOOL DEF 1 R+5, a slot 10 wide, 2 deep from X30 to X60
    // with a ramp from X20 (Z+2) to X30 (Z-2) in front.
    let (code, out, err) = cncc(&[
        "simulate",
        "--machine-units",
        "mm",
        "--format",
        "json",
        "tests/programs/simulate/blk_slot.h",
    ]);
    assert_eq!(code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    assert_eq!(v["tools"][0]["radius_mm"].as_f64(), Some(5.0), "{out}");
    assert_eq!(v["stock"]["from"], "the program's BLK FORM", "{out}");
}
