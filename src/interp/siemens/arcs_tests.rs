//! Hand-derived checks of the Siemens arc geometry.

use super::*;

fn close(a: P2, b: P2) {
    assert!((a.0 - b.0).abs() < 1e-9 && (a.1 - b.1).abs() < 1e-9, "{a:?} != {b:?}");
}

#[test]
fn ar_with_end_point() {
    // (0,0) -> (10,0), 90° CCW: the centre left of the chord (+Y),
    // 5 / tan 45° = 5 from its midpoint.
    close(centre_from_angle((0.0, 0.0), (10.0, 0.0), 90.0, true).unwrap(), (5.0, 5.0));
    close(centre_from_angle((0.0, 0.0), (10.0, 0.0), 90.0, false).unwrap(), (5.0, -5.0));
    // 270° CCW: the centre on the other side.
    close(centre_from_angle((0.0, 0.0), (10.0, 0.0), 270.0, true).unwrap(), (5.0, -5.0));
    // 180°: the midpoint.
    close(centre_from_angle((0.0, 0.0), (10.0, 0.0), 180.0, true).unwrap(), (5.0, 0.0));
    assert!(centre_from_angle((0.0, 0.0), (0.0, 0.0), 90.0, true).is_none());
}

#[test]
fn cr_negative_is_long_way() {
    // R 5 from (0,0) to (10,0): half circle, centre (5,0) both ways.
    close(centre_from_radius((0.0, 0.0), (10.0, 0.0), 5.0, false).unwrap(), (5.0, 0.0));
    // R = 5*sqrt2: quarter circle; CW short way centre below, long way above.
    let r = 50f64.sqrt();
    close(centre_from_radius((0.0, 0.0), (10.0, 0.0), r, false).unwrap(), (5.0, -5.0));
    close(centre_from_radius((0.0, 0.0), (10.0, 0.0), -r, false).unwrap(), (5.0, 5.0));
    assert!(centre_from_radius((0.0, 0.0), (10.0, 0.0), 4.0, false).is_none());
}

#[test]
fn ar_with_centre() {
    close(end_from_angle((10.0, 0.0), (0.0, 0.0), 90.0, true), (0.0, 10.0));
    close(end_from_angle((10.0, 0.0), (0.0, 0.0), 90.0, false), (0.0, -10.0));
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
