//! Word-address cycles against LinuxCNC's `rs274`: each scenario is a small
//! program; the snapshot holds our expansion (checked equal to rs274's
//! output by `matches_rs274_live`, which runs when `rs274` is installed).

use super::testhost::drive;
use crate::ir::DwellUnit;

const SETUP_MM: &str = "G21 G90 G17 F100 S500 M3\n";

/// (name, program). Each program has `(CYCLES)` after its set-up and
/// `(END)` before `M2`; only the calls in between are compared.
fn scenarios() -> Vec<(&'static str, String)> {
    let s = |body: &str| format!("{SETUP_MM}{body}\n(END)\nM2\n");
    vec![
        ("g81_g98_g99_sticky", s("G0 X0 Y0 Z10\n(CYCLES)\nG99 G81 X10 Y10 Z-5 R2\nX20\nG98 X30 Z-6 R3\nG80\nG0 Z20\nG91 G99 G81 X10 Y0 Z-7 R-18 L3\nG90 G80")),
        ("g82_g83_g73", s("G0 X0 Y0 Z5\n(CYCLES)\nG98 G82 X5 Y5 Z-3 R1 P0.5\nG80\nG99 G83 X10 Y5 Z-10 R1 Q3\nG80\nG99 G73 X15 Y5 Z-7 R1 Q2.5\nG80")),
        ("g85_g89_g86_g84", s("G0 X0 Y0 Z5\n(CYCLES)\nG98 G85 X5 Y0 Z-4 R1\nG80\nG99 G89 X10 Y0 Z-4 R1 P1.5\nG80\nG98 G86 X15 Y0 Z-4 R1 P0.25\nG80\nG99 G84 X20 Y0 Z-4 R1\nG80")),
        ("g87_g88_g74", s("G0 X0 Y0 Z10\n(CYCLES)\nG98 G87 X5 Y5 Z-8 R2 I1 J0.5 K-3\nG80\nG99 G88 X10 Y5 Z-4 R1 P0.5\nG80\nM4\nG98 G74 X20 Y5 Z-4 R1\nG80")),
        ("g18_g19_planes", s("G18\nG0 X20 Y10 Z5\n(CYCLES)\nG98 G81 X1 Z2 Y-5 R4\nZ3\nG99 G83 X5 Z4 Y-5 R4 Q2\nG80\nG19\nG0 X20 Y5 Z5\nG98 G82 Y1 Z2 X-5 R4 P0.2\nG80")),
        ("g87_incremental_g18_g64", s("G18\nG0 X0 Y10 Z0\nG64 P0.1 Q0.05\n(CYCLES)\nG91 G98 G87 X5 Z5 Y-18 R-8 I1 J-3 K0.5 L2\nG90 G80")),
        ("inch_below_r_incremental", "G20 G90 G17 F10 S500 M3\nG0 X0 Y0 Z-1\n(CYCLES)\nG99 G81 X1 Y1 Z-2 R0.5 L2\nG91 X1 Y0 L2\nG90 G80\nG83 X3 Y3 R0 Q0.3 Z-1\n(END)\nM2\n".into()),
        ("err_q_zero", s("G0 X0 Y0 Z5\n(CYCLES)\nG83 X1 Y1 Z-5 R1 Q0")),
        ("err_l_zero", s("G0 X0 Y0 Z5\n(CYCLES)\nG81 X1 Y1 Z-5 R1 L0")),
        ("err_l_negative", s("G0 X0 Y0 Z5\n(CYCLES)\nG81 X1 Y1 Z-5 R1 L-2")),
        ("err_no_z", s("G0 X0 Y0 Z5\n(CYCLES)\nG81 X1 Y1 R1")),
        ("err_no_r", s("G0 X0 Y0 Z5\n(CYCLES)\nG81 X1 Y1 Z-1\nX2")),
        ("err_no_p_g82", s("G0 X0 Y0 Z5\n(CYCLES)\nG82 X1 Y1 Z-1 R1")),
        ("err_no_q_g83", s("G0 X0 Y0 Z5\n(CYCLES)\nG83 X1 Y1 Z-1 R1")),
        ("err_r_below_z", s("G0 X0 Y0 Z5\n(CYCLES)\nG81 X1 Y1 Z2 R1")),
        ("err_spindle_g86", s("M5\nG0 X0 Y0 Z5\n(CYCLES)\nG86 X1 Y1 Z-1 R1 P1")),
        ("err_spindle_g84_ccw", s("M4\nG0 X0 Y0 Z5\n(CYCLES)\nG84 X1 Y1 Z-1 R1")),
    ]
}

#[test]
fn expansions_match_snapshots() {
    for (name, prog) in scenarios() {
        insta::assert_snapshot!(name, drive(&prog, DwellUnit::Seconds));
    }
}

/// Fanuc: P in milliseconds, G76 fine boring (derived by hand from the
/// Fanuc manual's description; see `body::fine_bore`).
#[test]
fn fanuc_milliseconds_and_fine_boring() {
    let prog = format!("{SETUP_MM}G0 X0 Y0 Z10\n(CYCLES)\nG99 G82 X5 Y5 Z-3 R1 P1500\nG80\nG98 G76 X10 Y5 Z-6 R2 Q0.5 P200\nG80\n(END)\n");
    insta::assert_snapshot!("fanuc_g82_g76", drive(&prog, DwellUnit::Milliseconds));
}

fn oracle_calls(stdout: &str) -> String {
    let mut out = Vec::new();
    let mut on = false;
    for l in stdout.lines() {
        if l.contains("COMMENT(\"CYCLES\")") {
            on = true;
        } else if l.contains("COMMENT(\"END\")") {
            break;
        } else if on && !l.starts_with("COMMENT(") && l != "ON_RESET()" {
            out.push(l.to_string());
        }
    }
    out.join("\n")
}

#[test]
fn matches_rs274_live() {
    let tool = concat!(env!("CARGO_MANIFEST_DIR"), "/../shared/tools/rs274-canon");
    let have = std::process::Command::new("sh")
        .arg("-c")
        .arg("command -v rs274")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false);
    if !have || !std::path::Path::new(tool).exists() {
        eprintln!("skipped: rs274 or shared/tools/rs274-canon not installed");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    for (name, prog) in scenarios() {
        let path = dir.path().join(format!("{name}.ngc"));
        std::fs::write(&path, &prog).unwrap();
        let o = std::process::Command::new(tool)
            .arg(&path)
            .output()
            .unwrap();
        let mut want = oracle_calls(&String::from_utf8_lossy(&o.stdout));
        if let Some(msg) = String::from_utf8_lossy(&o.stderr)
            .lines()
            .next()
            .filter(|_| o.status.code() == Some(1))
        {
            want.push_str(&format!("\nerror: {msg}"));
        }
        let got = drive(&prog, DwellUnit::Seconds);
        let (g, w) = (got.trim().to_lowercase(), want.trim().to_lowercase());
        for (n, (a, b)) in g.lines().zip(w.lines()).enumerate() {
            assert_eq!(a, b, "scenario {name}, line {}", n + 1);
        }
        assert_eq!(
            g.lines().count(),
            w.lines().count(),
            "scenario {name}: {g}\n---\n{w}"
        );
    }
}
