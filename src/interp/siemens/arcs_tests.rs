//! Hand-derived checks of the Siemens arc geometry.

use super::*;

fn close(a: P2, b: P2) {
    assert!(
        (a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9,
        "{a:?} != {b:?}"
    );
}

#[test]
fn ar_with_end_point() {
    // (0,0) -> (10,0), 90° CCW: the centre left of the chord (+Y),
    // 5 / tan 45° = 5 from its midpoint.
    close(
        centre_from_angle((0.0, 0.0), (10.0, 0.0), 90.0, true).unwrap(),
        (5.0, 5.0),
    );
    close(
        centre_from_angle((0.0, 0.0), (10.0, 0.0), 90.0, false).unwrap(),
        (5.0, -5.0),
    );
    // 270° CCW: the centre on the other side.
    close(
        centre_from_angle((0.0, 0.0), (10.0, 0.0), 270.0, true).unwrap(),
        (5.0, -5.0),
    );
    // 180°: the midpoint.
    close(
        centre_from_angle((0.0, 0.0), (10.0, 0.0), 180.0, true).unwrap(),
        (5.0, 0.0),
    );
    assert!(centre_from_angle((0.0, 0.0), (0.0, 0.0), 90.0, true).is_none());
}

#[test]
fn cr_negative_is_long_way() {
    // R 5 from (0,0) to (10,0): half circle, centre (5,0) both ways.
    close(
        centre_from_radius((0.0, 0.0), (10.0, 0.0), 5.0, false).unwrap(),
        (5.0, 0.0),
    );
    // R = 5*sqrt2: quarter circle; CW short way centre below, long way above.
    let r = 50f64.sqrt();
    close(
        centre_from_radius((0.0, 0.0), (10.0, 0.0), r, false).unwrap(),
        (5.0, -5.0),
    );
    close(
        centre_from_radius((0.0, 0.0), (10.0, 0.0), -r, false).unwrap(),
        (5.0, 5.0),
    );
    assert!(centre_from_radius((0.0, 0.0), (10.0, 0.0), 4.0, false).is_none());
}

#[test]
fn ar_with_centre() {
    close(
        end_from_angle((10.0, 0.0), (0.0, 0.0), 90.0, true),
        (0.0, 10.0),
    );
    close(
        end_from_angle((10.0, 0.0), (0.0, 0.0), 90.0, false),
        (0.0, -10.0),
    );
}

#[test]
fn cip_circle() {
    let (c, ccw) = circle_through((10.0, 0.0), (0.0, 10.0), (-10.0, 0.0)).unwrap();
    close(c, (0.0, 0.0));
    assert!(ccw);
    let (c, ccw) = circle_through((0.0, 0.0), (5.0, 5.0), (10.0, 0.0)).unwrap();
    close(c, (5.0, 0.0));
    assert!(!ccw);
    assert!(circle_through((0.0, 0.0), (1.0, 1.0), (2.0, 2.0)).is_none());
}

#[test]
fn ct_circle() {
    // Leaving (0,0) along +X to (10,10): quarter circle CCW round (0,10).
    let (c, ccw) = tangent_circle((0.0, 0.0), (1.0, 0.0), (10.0, 10.0)).unwrap();
    close(c, (0.0, 10.0));
    assert!(ccw);
    // To (10,-10): CW round (0,-10).
    let (c, ccw) = tangent_circle((0.0, 0.0), (3.0, 0.0), (10.0, -10.0)).unwrap();
    close(c, (0.0, -10.0));
    assert!(!ccw);
    assert!(tangent_circle((0.0, 0.0), (1.0, 0.0), (5.0, 0.0)).is_none());
    close(end_direction((0.0, 10.0), (10.0, 10.0), true), (0.0, 10.0));
}

#[test]
fn helix_lengths() {
    let pi = std::f64::consts::PI;
    // A quarter circle of radius 10, CCW: 5π.
    let l = helix_length([10.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0; 3], (0, 1), 1);
    assert!((l - 5.0 * pi).abs() < 1e-9);
    // The same end CW: three quarters.
    let l = helix_length([10.0, 0.0, 0.0], [0.0, 10.0, 0.0], [0.0; 3], (0, 1), -1);
    assert!((l - 15.0 * pi).abs() < 1e-9);
    // Two full turns of radius 1 rising 3 (G18: plane Z X, rise along Y).
    let l = helix_length([1.0, 0.0, 0.0], [1.0, 3.0, 0.0], [0.0; 3], (2, 0), 2);
    assert!((l - (4.0 * pi).hypot(3.0)).abs() < 1e-9);
}

/// The arc calls of a Siemens program run through the whole interpreter,
/// or the first error message.
fn arcs_of(src: &str) -> Vec<String> {
    use crate::canon::format_call;
    let spec = crate::dialect::builtin::builtin("siemens840d").unwrap();
    let (program, _) = crate::driver::read_program(src, crate::span::FileId(0), &spec);
    let mut out = Vec::new();
    let mut sink = |c: crate::canon::Canon, _s: crate::span::Span| out.push(format_call(&c));
    let mut files = crate::source::SourceMap::new();
    let mut loader =
        crate::driver::FsLoader::new(std::path::PathBuf::from("."), spec.clone(), &mut files);
    let diags = crate::interp::run(
        std::rc::Rc::new(program),
        &spec,
        &crate::interp::Options::default(),
        &mut loader,
        &mut sink,
    );
    let mut v: Vec<String> = out
        .into_iter()
        .filter(|l| l.starts_with("ARC_FEED") || l.starts_with("STRAIGHT_FEED"))
        .collect();
    v.extend(
        diags
            .iter()
            .filter(|d| d.is_error())
            .map(|d| format!("error: {}", d.message)),
    );
    v
}

#[test]
fn whole_interpreter_ct_after_arc_and_line() {
    // G1 along +X to (10,0); CT to (20,10): CCW round (10,10), ending along
    // +Y. CT on to (10,20): the left normal of +Y is -X, the chord (-10,10),
    // k = |chord|² / (2 * 10) = 10: CCW round (10,10) again.
    let v = arcs_of("G17 G90 G71 F100\nG0 X0 Y0 Z0\nG1 X10\nCT X20 Y10\nCT X10 Y20\nM30\n");
    assert_eq!(
        v[1], "ARC_FEED(20.0000, 10.0000, 10.0000, 10.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
        "{v:?}"
    );
    assert_eq!(
        v[2], "ARC_FEED(10.0000, 20.0000, 10.0000, 10.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
        "{v:?}"
    );
}

#[test]
fn whole_interpreter_frame_rotates_centre_words() {
    // AROT RPL=90: programmed (10,0) is base (0,10); I-10 (programmed -X)
    // is base -Y, so the centre of a half circle from programmed (10,0) to
    // (-10,0) round (0,0) stays at the base origin and the end is (0,-10).
    let v = arcs_of("G17 G90 G71 F100\nROT RPL=90\nG0 X10 Y0 Z0\nG3 X-10 Y0 I-10 J0\nM30\n");
    assert_eq!(
        v[0], "ARC_FEED(0.0000, -10.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
        "{v:?}"
    );
}

#[test]
fn whole_interpreter_other_planes_and_turns() {
    // G18 (first axis Z, second X): (z=0, x=10) turned 90° CCW round the
    // origin goes to (z=-10, x=0).
    let v = arcs_of("G18 G90 G71 F100\nG0 X10 Y0 Z0\nG3 I=AC(0) K=AC(0) AR=90\nM30\n");
    assert_eq!(
        v[0], "ARC_FEED(-10.0000, 0.0000, 0.0000, 0.0000, 1, 0.0000, 0.0000, 0.0000, 0.0000)",
        "{v:?}"
    );
    // G19 (Y, Z) helix: a full circle and one more turn, Y-axis centre 5.
    let v = arcs_of("G19 G90 G71 F100\nG0 X0 Y10 Z0\nG2 Y10 Z0 J-5 K0 TURN=1 X-4\nM30\n");
    assert_eq!(
        v[0], "ARC_FEED(10.0000, 0.0000, 5.0000, 0.0000, -2, -4.0000, 0.0000, 0.0000, 0.0000)",
        "{v:?}"
    );
}

#[test]
fn whole_interpreter_errors() {
    let v = arcs_of("G17 G90 G71 F100\nG0 X0 Y0\nCIP X20 Y0 I1=10 J1=0\nM30\n");
    assert!(v.last().unwrap().contains("lie on a line"), "{v:?}");
    let v = arcs_of("G17 G90 G71 F100\nG0 X0 Y0\nG2 X20 Y0 CR=5\nM30\n");
    assert!(v.last().unwrap().contains("radius too small"), "{v:?}");
    let v = arcs_of("G17 G90 G71 F100\nG0 X0 Y0\nG2 X20 Y0 I3 J0\nM30\n");
    assert!(v.last().unwrap().contains("not on the circle"), "{v:?}");
}
