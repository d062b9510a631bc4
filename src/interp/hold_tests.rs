//! Without the oracle: a block rs274 cannot read prints none of its own
//! calls, one that fails while running keeps those it made; spline control
//! points (which rs274 does not print) are the documented polygon.

use super::*;
use crate::canon::{format_call, NurbsPoint};
use crate::dialect::builtin::builtin;
use crate::span::FileId;

/// Runs a LinuxCNC program; returns its calls and its first error code.
fn calls(text: &str) -> (Vec<Canon>, Option<crate::diag::Code>) {
    let spec = builtin("linuxcnc").expect("dialect");
    let (program, diags) = crate::driver::read_program(text, FileId(0), &spec);
    assert!(
        !diags.iter().any(|d| d.is_error()),
        "read errors: {diags:?}"
    );
    let mut out = Vec::new();
    let mut sink = |c: Canon, _: Span| out.push(c);
    let opts = Options::default();
    let diags = run(
        std::rc::Rc::new(program),
        &spec,
        &opts,
        &mut flow::NoLoader,
        &mut sink,
    );
    let err = diags.iter().find(|d| d.is_error()).map(|d| d.code);
    (out, err)
}

fn has(calls: &[Canon], text: &str) -> bool {
    calls.iter().any(|c| format_call(c) == text)
}

#[test]
fn unreadable_block_prints_nothing_of_its_own() {
    let (c, e) = calls("G21\nF100 S200 M3 G1 X[1/0]\nM2\n");
    assert_eq!(e, Some(crate::diag::Code::DivisionByZero));
    assert!(!has(&c, "SET_FEED_RATE(100.0000)"), "{c:?}");
    assert!(!has(&c, "START_SPINDLE_CLOCKWISE(0)"), "{c:?}");
    let (c, e) = calls("G21\nF100 G0 X3 ^30\nM2\n");
    assert_eq!(e, Some(crate::diag::Code::BadWordValue));
    assert!(!has(&c, "SET_FEED_RATE(100.0000)"), "{c:?}");
}

#[test]
fn block_failing_while_running_keeps_its_earlier_calls() {
    let (c, e) = calls("G21 F100\nS300 M3 G2 X30 Y0 R5\nM2\n");
    assert_eq!(e, Some(crate::diag::Code::ArcRadiusTooSmall));
    assert!(has(&c, "SET_SPINDLE_SPEED(0, 300.0000)"), "{c:?}");
    assert!(has(&c, "START_SPINDLE_CLOCKWISE(0)"), "{c:?}");
}

#[test]
fn spline_control_polygons() {
    let (c, e) = calls("G21 F100\nG0 X0 Y0\nG5 I0 J3 P4 Q-3 X1 Y1\nG5.1 I2 J2 X4 Y0\nM2\n");
    assert_eq!(e, None);
    let p = |x, y| NurbsPoint { x, y, w: 1.0 };
    let nurbs: Vec<_> = c
        .iter()
        .filter_map(|c| match c {
            Canon::NurbsFeed { points, order } => Some((points.clone(), *order)),
            _ => None,
        })
        .collect();
    assert_eq!(
        nurbs,
        vec![
            (vec![p(0.0, 0.0), p(0.0, 3.0), p(5.0, -2.0), p(1.0, 1.0)], 4),
            (vec![p(1.0, 1.0), p(3.0, 3.0), p(4.0, 0.0)], 3),
        ]
    );
}
