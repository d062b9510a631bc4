//! Features whose axis is not the machine's Z (issue 15): on a target
//! whose spec declares `tilted-working-plane` (Siemens 840D CYCLE800,
//! Heidenhain PLANE SPATIAL) they are machined in a plane tilted onto the
//! feature's frame (3+2); on the others (Fanuc and Haas, whose G68.2 is an
//! option the specs do not declare, and 3-axis LinuxCNC) each is a located
//! refusal naming that limit. `tests/stepnc/tilted.stp`: a hole on top, a
//! hole in the right face (axis +X) and a pocket in the front face (axis
//! -Y) of a 100 x 80 x 50 block. Every post checks clean in its dialect.

mod common;

use std::path::PathBuf;

fn plan() -> PathBuf {
    common::root().join("tests/stepnc/tilted.stp")
}

fn post(target: &str) -> (Option<String>, String) {
    let dir = common::root().join("target/tmp/post-tilt");
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join(format!("tilted.{target}"));
    let _ = std::fs::remove_file(&out);
    let o = common::cncc(&[
        "post",
        plan().to_str().unwrap(),
        "--to",
        target,
        "-o",
        out.to_str().unwrap(),
    ]);
    let err = common::stderr(&o);
    if o.status.code() != Some(0) {
        return (None, err);
    }
    let c = common::cncc(&["check", "--dialect", target, out.to_str().unwrap()]);
    assert_eq!(c.status.code(), Some(0), "{target}: {}", common::stderr(&c));
    (Some(std::fs::read_to_string(&out).unwrap()), err)
}

#[test]
fn siemens_swivels_with_cycle800_about_each_feature() {
    let (text, err) = post("siemens840d");
    let text = text.unwrap_or_else(|| panic!("{err}"));
    // The right-hand hole: X then Y' by 90 puts Z along +X, X along +Y;
    // the front pocket: X by 90 puts Z along -Y. The reference point is
    // the feature's origin; each tilted step swivels back at its end.
    assert!(
        text.contains("CYCLE800(1,\"TC1\",0,57,100,40,25,90,90,0,0,0,0,-1,100,1)"),
        "{text}"
    );
    assert!(
        text.contains("CYCLE800(1,\"TC1\",0,57,50,0,25,90,0,0,0,0,0,-1,100,1)"),
        "{text}"
    );
    assert_eq!(
        text.matches("CYCLE800(1,\"TC1\",0,57,0,0,0,0,0,0").count(),
        2,
        "{text}"
    );
    // In the tilted plane the hole is at the origin, its top at Z0, 20
    // deep, the security plane 20 out and the retract plane 5.
    assert!(text.contains("MCALL CYCLE81(20,0,5,-20,)"), "{text}");
    assert!(text.contains("POCKET1(20,0,5,-5,,30,20,4,0,0,0,"), "{text}");
    // The top hole is not tilted.
    assert!(text.contains("MCALL CYCLE81(70,50,5,30,)"), "{text}");
}

#[test]
fn heidenhain_shifts_the_datum_and_tilts_with_plane_spatial() {
    let (text, err) = post("heidenhain");
    let text = text.unwrap_or_else(|| panic!("{err}"));
    // Spatial angles about the fixed X, Y, Z: the right-hand hole is A 90
    // then C 90; the front pocket A 90.
    assert!(text.contains("CYCL DEF 7.1 X100\nCYCL DEF 7.2 Y40\nCYCL DEF 7.3 Z25\nPLANE SPATIAL SPA90 SPB0 SPC90 TURN MB MAX FMAX"), "{text}");
    assert!(
        text.contains("PLANE SPATIAL SPA90 SPB0 SPC0 TURN MB MAX FMAX"),
        "{text}"
    );
    assert_eq!(
        text.matches("PLANE RESET TURN MB MAX FMAX").count(),
        2,
        "{text}"
    );
    assert!(text.contains("Q203=0 Q204=20"), "{text}");
}

#[test]
fn targets_that_cannot_tilt_refuse_each_tilted_feature_at_its_line() {
    for t in ["fanuc", "haas", "linuxcnc"] {
        let (text, err) = post(t);
        assert!(text.is_none(), "{t} posted a tilted feature");
        assert_eq!(err.matches("error[E0900").count(), 2, "{t}: {err}");
        assert!(err.contains("`HOLE RIGHT`: a feature whose axis (1, 0, 0) is not the machine's Z axis, on a target that cannot tilt its working plane"), "{t}: {err}");
        assert!(
            err.contains("tilted.stp:29:1") && err.contains("tilted.stp:30:1"),
            "{t}: {err}"
        );
        assert!(err.contains("`tilted-working-plane`"), "{t}: {err}");
    }
}
