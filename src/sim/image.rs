//! The cut part as a shaded top view (PNG, drawn with tiny-skia): each
//! pixel the cell under it, coloured by depth (grey: the stock's top
//! untouched; yellow to red: shallow to deep; dark grey: cut through),
//! lit from the upper left so walls and slopes read. Axes along the
//! bottom (X) and left (Y) carry a scale in mm, and the stock's corners
//! their coordinates.

use super::grid::HeightField;
use crate::plot::png::text;
use tiny_skia::{Color, Paint, PathBuilder, Pixmap, Stroke, Transform};

const LEFT: f64 = 80.0;
const RIGHT: f64 = 30.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 60.0;
const INK: [u8; 3] = [0, 0, 0];

/// The picture, `width` pixels wide (the height follows the stock).
pub fn render(f: &HeightField, width: u32, title: &str) -> Result<Vec<u8>, String> {
    let stock = f.stock();
    let (lx, ly) = (stock.size[0], stock.size[1]);
    let mut scale = (width as f64 - LEFT - RIGHT).max(50.0) / lx;
    // A tall stock: at most twice as high as wide.
    scale = scale.min(2.0 * width as f64 / ly);
    let (aw, ah) = ((lx * scale).round(), (ly * scale).round());
    let h = (ah + TOP + BOTTOM) as u32;
    let mut pm = Pixmap::new(width.max(1), h.max(1)).ok_or("picture too large")?;
    pm.fill(Color::WHITE);
    shade(&mut pm, f, scale, aw as u32, ah as u32);
    axes(&mut pm, f, scale, aw, ah);
    text(&mut pm, LEFT as i64, 12, title, INK);
    pm.encode_png().map_err(|e| e.to_string())
}

fn shade(pm: &mut Pixmap, f: &HeightField, scale: f64, aw: u32, ah: u32) {
    let w = pm.width() as usize;
    let light = nalgebra::Vector3::new(-1.0, 1.0, 2.0).normalize();
    let depth = (f.top - f.bottom).max(1e-9);
    let cell = |i: i64, j: i64| -> f64 {
        let i = i.clamp(0, f.nx as i64 - 1) as usize;
        let j = j.clamp(0, f.ny as i64 - 1) as usize;
        f.z[j * f.nx + i] as f64
    };
    let px = pm.pixels_mut();
    for py in 0..ah {
        let y = (ah as f64 - py as f64 - 0.5) / scale;
        let j = ((y / f.dy).floor() as i64).clamp(0, f.ny as i64 - 1);
        for qx in 0..aw {
            let x = (qx as f64 + 0.5) / scale;
            let i = ((x / f.dx).floor() as i64).clamp(0, f.nx as i64 - 1);
            let z = cell(i, j);
            let gx = (cell(i + 1, j) - cell(i - 1, j)) / (2.0 * f.dx);
            let gy = (cell(i, j + 1) - cell(i, j - 1)) / (2.0 * f.dy);
            let n = nalgebra::Vector3::new(-gx, -gy, 1.0).normalize();
            let lit = 0.35 + 0.65 * n.dot(&light).max(0.0) / light.z;
            let d = ((f.top - z) / depth).clamp(0.0, 1.0);
            let base = if d < 1e-6 {
                [205.0, 208.0, 214.0]
            } else if z <= f.bottom + 1e-6 {
                [60.0, 60.0, 60.0]
            } else {
                mix([250.0, 214.0, 110.0], [178.0, 40.0, 30.0], d)
            };
            let c = base.map(|v| (v * lit.min(1.15)).clamp(0.0, 255.0) as u8);
            let at = (TOP as usize + py as usize) * w + LEFT as usize + qx as usize;
            if let Some(p) = px.get_mut(at) {
                *p = tiny_skia::ColorU8::from_rgba(c[0], c[1], c[2], 255).premultiply();
            }
        }
    }
}

fn mix(a: [f64; 3], b: [f64; 3], t: f64) -> [f64; 3] {
    [0, 1, 2].map(|k| a[k] + (b[k] - a[k]) * t)
}

fn line(pm: &mut Pixmap, a: (f64, f64), b: (f64, f64)) {
    let mut pb = PathBuilder::new();
    pb.move_to(a.0 as f32, a.1 as f32);
    pb.line_to(b.0 as f32, b.1 as f32);
    if let Some(p) = pb.finish() {
        let mut paint = Paint::default();
        paint.set_color_rgba8(0, 0, 0, 255);
        pm.stroke_path(&p, &paint, &Stroke::default(), Transform::identity(), None);
    }
}

/// The frame, ticks every 1, 2 or 5 times a power of ten, and the corners.
fn axes(pm: &mut Pixmap, f: &HeightField, scale: f64, aw: f64, ah: f64) {
    let (x0, y0) = (f.origin[0], f.origin[1]);
    let s = f.stock();
    let (x1, y1) = (x0 + s.size[0], y0 + s.size[1]);
    let (l, t, r, b) = (LEFT, TOP, LEFT + aw, TOP + ah);
    for (a, c) in [
        ((l, t), (r, t)),
        ((r, t), (r, b)),
        ((r, b), (l, b)),
        ((l, b), (l, t)),
    ] {
        line(pm, a, c);
    }
    let step = nice_step(s.size[0].max(s.size[1]) / 8.0);
    for v in ticks(x0, x1, step) {
        let px = l + (v - x0) * scale;
        line(pm, (px, b), (px, b + 5.0));
        let label = num(v);
        text(
            pm,
            (px - 4.0 * label.len() as f64) as i64,
            (b + 8.0) as i64,
            &label,
            INK,
        );
    }
    for v in ticks(y0, y1, step) {
        let py = b - (v - y0) * scale;
        line(pm, (l - 5.0, py), (l, py));
        let label = num(v);
        text(
            pm,
            (l - 8.0 - 8.0 * label.len() as f64) as i64,
            (py - 4.0) as i64,
            &label,
            INK,
        );
    }
    text(pm, (r + 8.0) as i64, (b - 4.0) as i64, "X", INK);
    text(pm, (l - 4.0) as i64, (t - 14.0) as i64, "Y", INK);
    let corner = |x: f64, y: f64| format!("X{} Y{}", num(x), num(y));
    let below = (b + 24.0) as i64;
    text(pm, l as i64, below, &corner(x0, y0), INK);
    let c = corner(x1, y0);
    text(pm, (r - 8.0 * c.len() as f64) as i64, below, &c, INK);
    text(pm, l as i64 + 16, (t - 14.0) as i64, &corner(x0, y1), INK);
    let c = corner(x1, y1);
    text(
        pm,
        (r - 8.0 * c.len() as f64) as i64,
        (t - 14.0) as i64,
        &c,
        INK,
    );
    let z = format!("Z{} to Z{} mm", num(f.bottom), num(f.top));
    text(pm, l as i64, below + 14, &z, INK);
}

fn nice_step(raw: f64) -> f64 {
    let p = 10f64.powf(raw.max(1e-9).log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * p)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * p)
}

fn ticks(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step).ceil() as i64;
    let last = (hi / step).floor() as i64;
    (first..=last).take(100).map(|k| k as f64 * step).collect()
}

fn num(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_and_ticks() {
        assert_eq!(nice_step(12.5), 20.0);
        assert_eq!(nice_step(0.3), 0.5);
        assert_eq!(
            ticks(-50.0, 50.0, 20.0),
            vec![-40.0, -20.0, 0.0, 20.0, 40.0]
        );
    }

    #[test]
    fn a_field_renders() {
        let s: crate::toolpath::Stock = "40x20x10".parse().unwrap();
        let mut f = HeightField::new(&s, 0.5).unwrap();
        f.z[5] = -3.0;
        let png = render(&f, 400, "test").unwrap();
        assert_eq!(&png[1..4], b"PNG");
    }
}
