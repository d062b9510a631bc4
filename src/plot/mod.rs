//! Plots of toolpaths (`cncc plot`): top, side and isometric views, feed
//! moves coloured by tool, rapids dashed, arcs drawn as arcs where they lie
//! in the view's plane, the stock outline when known, a legend (tools with
//! diameters and feeds); two programs overlaid, one colour each, with
//! their differences (from [`crate::compare`]) circled in red.
//!
//! A plot is made in one pass over the events: a [`scene::Scene`] takes
//! the moves as they stream in, in view-plane millimetres, and drops
//! detail below the pixel as it comes (at the scale of the box seen so
//! far, which is never coarser than the final one); the
//! [`layout::Layout`] is made at the end from the whole box.
//! [`svg::render`] writes SVG text directly; [`png::render`] rasterises
//! with tiny-skia.

pub mod layer;
pub mod layout;
pub mod legend;
pub mod png;
pub mod scene;
pub mod svg;
pub mod view;

pub use layout::Layout;
pub use scene::Scene;
pub use view::View;

use crate::toolpath::{Stock, P3};

/// Everything a renderer needs.
#[derive(Clone, Debug)]
pub struct Picture {
    pub scene: Scene,
    /// Where the views go (from [`Scene::layout`]).
    pub layout: Layout,
    pub stock: Option<Stock>,
    pub legend: Vec<legend::Entry>,
    /// Two files overlaid.
    pub overlay: bool,
}

type Pt = (f64, f64);

impl Picture {
    /// The stock's twelve edges in a panel, pixels.
    pub fn stock_edges(&self, panel: &layout::Panel) -> Vec<(Pt, Pt)> {
        let Some(s) = self.stock else {
            return Vec::new();
        };
        let (lo, hi) = (s.corner, s.max());
        let corner = |k: usize| -> P3 {
            [
                if k & 1 == 0 { lo[0] } else { hi[0] },
                if k & 2 == 0 { lo[1] } else { hi[1] },
                if k & 4 == 0 { lo[2] } else { hi[2] },
            ]
        };
        let mut edges = Vec::new();
        for a in 0..8usize {
            for bit in [1, 2, 4] {
                if a & bit == 0 {
                    edges.push((panel.px(corner(a)), panel.px(corner(a | bit))));
                }
            }
        }
        edges
    }

    /// Circles (centre, radius in pixels) around the differences in a panel.
    pub fn marks(&self, panel: &layout::Panel) -> Vec<(Pt, f64)> {
        self.scene
            .marks
            .iter()
            .map(|b| {
                let (mut l, mut r, mut t, mut bo) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
                for k in 0..8usize {
                    let p = [b[k & 1][0], b[(k >> 1) & 1][1], b[(k >> 2) & 1][2]];
                    let (x, y) = panel.px(p);
                    l = l.min(x);
                    r = r.max(x);
                    t = t.min(y);
                    bo = bo.max(y);
                }
                let c = ((l + r) / 2.0, (t + bo) / 2.0);
                let half = ((r - l).powi(2) + (bo - t).powi(2)).sqrt() / 2.0;
                (c, (half + 6.0).max(9.0))
            })
            .collect()
    }
}
