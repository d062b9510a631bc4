//! Recognisers on synthetic move lists: what each one makes of the moves
//! it is meant for (and that nothing is dropped when none applies).

mod faces;
mod others;
mod pockets;

pub use super::segment::tests::{circle, path};
use super::{recognise_report, Cc2Context};
use crate::stepnc::model::*;
use crate::toolpath::Event;

pub fn run(ev: &[Event], diameter: f64, stock: Option<([f64; 3], [f64; 3])>) -> (Project, usize) {
    let ctx = Cc2Context {
        tool_diameter: Box::new(move |_| Some(diameter)),
        stock,
        secplane_z: 20.0,
    };
    let mut p = Project::default();
    let notes = recognise_report(ev, &mut p, &|t| ToolId(t as u32), &ctx);
    (p, notes.len())
}

pub fn z(x: f64, y: f64, z: f64) -> [f64; 3] {
    [x, y, z]
}

/// A closed rectangle loop at `zz` from (a, b) to (c, d), counter-clockwise.
pub fn rect(a: f64, b: f64, c: f64, d: f64, zz: f64) -> Vec<[f64; 3]> {
    vec![
        z(a, b, zz),
        z(c, b, zz),
        z(c, d, zz),
        z(a, d, zz),
        z(a, b, zz),
    ]
}

pub fn op(p: &Project, f: usize, i: usize) -> &Operation {
    p.operation(p.features[f].operations[i])
}
