//! Where each view goes in the picture and at what scale: the views are
//! stacked top to bottom at one common scale (so the side view lines up
//! with the top view's X), the legend in a column on the right.

use super::view::View;
use crate::stats::Bounds;
use crate::toolpath::P3;

/// Pixels around each view.
const MARGIN: f64 = 24.0;
/// Room for a view's title.
const TITLE: f64 = 18.0;
/// Width of the legend column.
pub const LEGEND_W: f64 = 300.0;

/// One view's panel: the view, its box in the picture, and its mapping.
#[derive(Clone, Copy, Debug)]
pub struct Panel {
    pub view: View,
    /// Top-left corner and size of the panel, pixels.
    pub x: f64,
    pub y: f64,
    pub w: f64,
    pub h: f64,
    /// Pixels per millimetre.
    pub scale: f64,
    /// The view-plane point at the panel's drawing origin (left, top).
    left: f64,
    top: f64,
}

impl Panel {
    /// A point in picture pixels.
    pub fn px(&self, p: P3) -> (f64, f64) {
        self.uv(self.view.project(p))
    }

    /// A view-plane point (mm, v up) in picture pixels.
    pub fn uv(&self, (u, v): (f64, f64)) -> (f64, f64) {
        (
            self.x + MARGIN + (u - self.left) * self.scale,
            self.y + MARGIN + TITLE + (self.top - v) * self.scale,
        )
    }
}

/// The whole picture.
#[derive(Clone, Debug)]
pub struct Layout {
    pub width: f64,
    pub height: f64,
    pub panels: Vec<Panel>,
}

/// The extent of the box's eight corners in a view.
fn extent(view: View, b: &Bounds) -> (f64, f64, f64, f64) {
    let (mut l, mut r, mut bot, mut top) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for k in 0..8 {
        let p = [
            if k & 1 == 0 { b.min[0] } else { b.max[0] },
            if k & 2 == 0 { b.min[1] } else { b.max[1] },
            if k & 4 == 0 { b.min[2] } else { b.max[2] },
        ];
        let (u, v) = view.project(p);
        l = l.min(u);
        r = r.max(u);
        bot = bot.min(v);
        top = top.max(v);
    }
    (l, r, bot, top)
}

/// The box, grown to at least a millimetre along each axis.
fn padded(bounds: &Bounds) -> Bounds {
    let mut b = *bounds;
    if b.is_empty() {
        b.add([0.0; 3]);
    }
    // A flat or empty extent still gets a millimetre (as a function of
    // the extent that never falls as the extent grows).
    for k in 0..3 {
        let short = 1.0 - (b.max[k] - b.min[k]);
        if short > 0.0 {
            b.min[k] -= short / 2.0;
            b.max[k] += short / 2.0;
        }
    }
    b
}

/// The common scale (pixels per mm) and each view's extent.
fn scale_and_extents(
    views: &[View],
    bounds: &Bounds,
    width: f64,
) -> (f64, Vec<(f64, f64, f64, f64)>) {
    let b = padded(bounds);
    let draw_w = (width - LEGEND_W - 2.0 * MARGIN).max(100.0);
    let ext: Vec<_> = views.iter().map(|v| extent(*v, &b)).collect();
    let widest = ext.iter().map(|e| e.1 - e.0).fold(1e-9, f64::max);
    let mut scale = draw_w / widest;
    // Keep the picture no taller than three widths.
    let tall: f64 = ext.iter().map(|e| e.3 - e.2).sum();
    if tall * scale > 3.0 * width {
        scale = 3.0 * width / tall;
    }
    (scale, ext)
}

impl Layout {
    /// The scale a picture of what lies in `bounds` would have. It only
    /// falls as the box grows: a scene simplified at the scale of a part
    /// of the program is fine enough for the whole.
    pub fn scale(views: &[View], bounds: &Bounds, width: f64) -> f64 {
        scale_and_extents(views, bounds, width).0
    }

    /// Panels for `views` of what lies in `bounds`, `width` pixels wide.
    pub fn new(views: &[View], bounds: &Bounds, width: f64) -> Layout {
        let (scale, ext) = scale_and_extents(views, bounds, width);
        let draw_w = (width - LEGEND_W - 2.0 * MARGIN).max(100.0);
        let mut y = 0.0;
        let mut panels = Vec::new();
        for (view, e) in views.iter().zip(&ext) {
            let h = (e.3 - e.2) * scale + 2.0 * MARGIN + TITLE;
            panels.push(Panel {
                view: *view,
                x: 0.0,
                y,
                w: draw_w + 2.0 * MARGIN,
                h,
                scale,
                left: e.0,
                top: e.3,
            });
            y += h;
        }
        Layout {
            width,
            height: y.max(400.0).ceil(),
            panels,
        }
    }
}
