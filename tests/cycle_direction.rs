//! Which way a drilling cycle feeds (issue 12): Fanuc and Haas drill from
//! R towards the bottom whichever way that is along the drilling axis (a
//! right-angle head drilling up the Y axis in G18, as NX's Mitsubishi
//! right-angle-head post writes it); LinuxCNC refuses R below the bottom
//! ("R less than Z", capability `cycle-r-above-bottom`).

mod common;
use common::*;

const FILE: &str = "tests/programs/fanuc/right_angle_head.nc";

fn pos(x: f64, y: f64, z: f64) -> String {
    format!("({x:.4}, {y:.4}, {z:.4}, 0.0000, 0.0000, 0.0000)")
}

#[test]
fn fanuc_drills_up_the_axis_when_r_is_below_the_bottom() {
    let o = cncc(&["check", "--dialect", "fanuc", FILE]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
    let o = cncc(&["canon", "--dialect", "fanuc", FILE]);
    let out = stdout(&o);
    assert!(o.status.success(), "{}", stderr(&o));
    let z = out
        .lines()
        .find_map(|l| l.strip_prefix("STRAIGHT_FEED(0.5000, 0.5000, "))
        .and_then(|r| r.split(',').next())
        .and_then(|v| v.trim().parse::<f64>().ok())
        .expect("a G81 feed to Y.5");
    // G81: R-.1, feed up to Y.5, back to R (G99).
    let g81 = format!(
        "STRAIGHT_TRAVERSE{}\nSTRAIGHT_FEED{}\nSTRAIGHT_TRAVERSE{}",
        pos(0.5, -0.1, z),
        pos(0.5, 0.5, z),
        pos(0.5, -0.1, z)
    );
    assert!(out.contains(&g81), "{out}");
    // G83 pecks upwards by Q.25: .15, .4, then .5; each time back to R
    // and down again to 0.010 in short of the last depth.
    let pecks = [
        format!("STRAIGHT_FEED{}", pos(0.5, 0.15, 0.6)),
        format!("STRAIGHT_TRAVERSE{}", pos(0.5, -0.1, 0.6)),
        format!("STRAIGHT_TRAVERSE{}", pos(0.5, 0.14, 0.6)),
        format!("STRAIGHT_FEED{}", pos(0.5, 0.4, 0.6)),
        format!("STRAIGHT_TRAVERSE{}", pos(0.5, -0.1, 0.6)),
        format!("STRAIGHT_TRAVERSE{}", pos(0.5, 0.39, 0.6)),
        format!("STRAIGHT_FEED{}", pos(0.5, 0.5, 0.6)),
    ]
    .join("\n");
    assert!(out.contains(&pecks), "{out}");
}

#[test]
fn linuxcnc_refuses_r_below_the_bottom() {
    let o = cncc(&["check", "--dialect", "linuxcnc", FILE]);
    let err = stderr(&o);
    assert!(err.contains("error[E0540"), "{err}");
    assert!(err.contains("R less than y in cycle in xz plane"), "{err}");
}
