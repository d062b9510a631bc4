//! The views a plot draws and how each projects a point: top (XY, seen
//! from +Z), side (XZ, seen from -Y, the front) and isometric.

use crate::toolpath::{ArcGeom, P3};

/// One view of the part.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum View {
    Top,
    Side,
    Iso,
}

impl View {
    /// `top`, `side` (or `front`), `iso`.
    pub fn parse(s: &str) -> Option<View> {
        match s.trim().to_ascii_lowercase().as_str() {
            "top" | "xy" => Some(View::Top),
            "side" | "front" | "xz" => Some(View::Side),
            "iso" | "isometric" => Some(View::Iso),
            _ => None,
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            View::Top => "top (XY)",
            View::Side => "side (XZ)",
            View::Iso => "isometric",
        }
    }

    /// The point in the view's plane: (right, up), millimetres.
    pub fn project(self, p: P3) -> (f64, f64) {
        match self {
            View::Top => (p[0], p[1]),
            View::Side => (p[0], p[2]),
            View::Iso => {
                let (s, c) = (0.5, 3f64.sqrt() / 2.0);
                ((p[0] - p[1]) * c, (p[0] + p[1]) * s + p[2])
            }
        }
    }

    /// How an arc's sweep shows in this view, when it shows as a circular
    /// arc: the factor (+1 or -1) from the arc's signed sweep to the sweep
    /// in view-plane angles (counter-clockwise positive, v up). None: draw
    /// it as a polyline.
    pub fn arc_sign(self, g: &ArcGeom) -> Option<f64> {
        match (self, g.axes) {
            (View::Top, [0, 1, 2]) => Some(1.0),
            // XZ arcs measure from Z towards X; seen with X right and Z
            // up, the view angle is 90 degrees less the arc's: reversed.
            (View::Side, [2, 0, 1]) => Some(-1.0),
            _ => None,
        }
    }
}
