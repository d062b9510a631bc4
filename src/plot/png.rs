//! A [`Picture`] as PNG, drawn with tiny-skia: the same layers, stock,
//! marks and legend as the SVG, arcs flattened to a quarter pixel, text in
//! an 8x8 bitmap font (font8x8; characters outside ASCII show as `?`).

use super::layout::Panel;
use super::legend::{Rgb, MARK, STOCK};
use super::scene::Seg;
use super::Picture;
use tiny_skia::{Color, Paint, PathBuilder, Pixmap, Stroke, StrokeDash, Transform};

/// Most pixels a PNG may have (4 bytes each in memory).
const MAX_PIXELS: f64 = 40e6;

fn paint(c: Rgb) -> Paint<'static> {
    let mut p = Paint::default();
    p.set_color_rgba8(c[0], c[1], c[2], 255);
    p.anti_alias = true;
    p
}

fn stroke(width: f32, dashed: bool) -> Stroke {
    Stroke {
        width,
        dash: if dashed {
            StrokeDash::new(vec![4.0, 3.0], 0.0)
        } else {
            None
        },
        ..Stroke::default()
    }
}

fn build(segs: &[Seg], panel: &Panel) -> Option<tiny_skia::Path> {
    let mut pb = PathBuilder::new();
    let at = |p| {
        let (x, y) = panel.uv(p);
        (x as f32, y as f32)
    };
    for s in segs {
        match *s {
            Seg::Move(p) => {
                let (x, y) = at(p);
                pb.move_to(x, y)
            }
            Seg::Line(p) => {
                let (x, y) = at(p);
                pb.line_to(x, y)
            }
            Seg::Arc {
                to,
                centre,
                r,
                start,
                sweep,
            } => {
                // Chords within a quarter pixel of the circle.
                let rp = r * panel.scale;
                let step = 2.0 * (1.0 - (0.25 / rp).min(1.0)).acos().max(1e-3);
                let n = ((sweep.abs() / step).ceil() as usize).clamp(1, 10_000);
                for k in 1..n {
                    let a = start + sweep * k as f64 / n as f64;
                    let (x, y) = at((centre.0 + r * a.cos(), centre.1 + r * a.sin()));
                    pb.line_to(x, y);
                }
                let (x, y) = at(to);
                pb.line_to(x, y);
            }
            Seg::Hole { centre, r } => {
                let (x, y) = at(centre);
                pb.push_circle(x, y, super::svg::hole_px(r, panel) as f32);
            }
        }
    }
    pb.finish()
}

fn line(pm: &mut Pixmap, a: (f64, f64), b: (f64, f64), c: Rgb, width: f32, dashed: bool) {
    let mut pb = PathBuilder::new();
    pb.move_to(a.0 as f32, a.1 as f32);
    pb.line_to(b.0 as f32, b.1 as f32);
    if let Some(path) = pb.finish() {
        pm.stroke_path(
            &path,
            &paint(c),
            &stroke(width, dashed),
            Transform::identity(),
            None,
        );
    }
}

/// Writes `text` with its top-left corner at (x, y).
pub(crate) fn text(pm: &mut Pixmap, x: i64, y: i64, s: &str, c: Rgb) {
    let (w, h) = (pm.width() as i64, pm.height() as i64);
    let px = pm.pixels_mut();
    for (i, ch) in s.chars().enumerate() {
        let code = if ch.is_ascii() {
            ch as usize
        } else {
            b'?' as usize
        };
        let glyph = font8x8::legacy::BASIC_LEGACY[code];
        for (row, bits) in glyph.iter().enumerate() {
            for col in 0..8 {
                if bits & (1 << col) == 0 {
                    continue;
                }
                let (gx, gy) = (x + i as i64 * 8 + col, y + row as i64);
                if (0..w).contains(&gx) && (0..h).contains(&gy) {
                    px[(gy * w + gx) as usize] =
                        tiny_skia::ColorU8::from_rgba(c[0], c[1], c[2], 255).premultiply();
                }
            }
        }
    }
}

/// The picture as PNG bytes.
pub fn render(p: &Picture) -> Result<Vec<u8>, String> {
    let l = &p.layout;
    if l.width * l.height > MAX_PIXELS {
        return Err(format!(
            "a {}x{} picture is too large for PNG (at most {} Mpx): use a smaller --width or SVG",
            l.width,
            l.height,
            MAX_PIXELS / 1e6
        ));
    }
    let (w, h) = (l.width as u32, l.height as u32);
    let mut pm = Pixmap::new(w.max(1), h.max(1)).ok_or("picture too large")?;
    pm.fill(Color::WHITE);
    for (i, panel) in l.panels.iter().enumerate() {
        let (x0, y0, x1, y1) = (
            panel.x + 2.0,
            panel.y + 2.0,
            panel.x + panel.w - 2.0,
            panel.y + panel.h - 2.0,
        );
        for (a, b) in [
            ((x0, y0), (x1, y0)),
            ((x1, y0), (x1, y1)),
            ((x1, y1), (x0, y1)),
            ((x0, y1), (x0, y0)),
        ] {
            line(&mut pm, a, b, [221, 221, 221], 1.0, false);
        }
        text(
            &mut pm,
            (panel.x + 8.0) as i64,
            (panel.y + 8.0) as i64,
            panel.view.title(),
            [0, 0, 0],
        );
        for (a, b) in p.stock_edges(panel) {
            line(&mut pm, a, b, STOCK, 1.0, false);
        }
        let mut layers: Vec<_> = p
            .scene
            .layers
            .iter()
            .filter(|(k, _)| k.panel == i)
            .collect();
        layers.sort_by_key(|(k, _)| (!k.rapid, k.file, k.tool));
        for (key, layer) in layers {
            let (colour, dashed) = super::legend::style(&p.scene, p.overlay, key);
            if let Some(path) = build(&layer.segs, panel) {
                let width = super::svg::line_width(p.overlay, key);
                pm.stroke_path(
                    &path,
                    &paint(colour),
                    &stroke(width, dashed),
                    Transform::identity(),
                    None,
                );
            }
        }
        for ((x, y), r) in p.marks(panel) {
            if let Some(c) = PathBuilder::from_circle(x as f32, y as f32, r as f32) {
                pm.stroke_path(
                    &c,
                    &paint(MARK),
                    &stroke(2.0, false),
                    Transform::identity(),
                    None,
                );
            }
        }
    }
    let lx = l.width - super::layout::LEGEND_W + 10.0;
    for (i, e) in p.legend.iter().enumerate() {
        let y = 30.0 + 20.0 * i as f64;
        if e.mark {
            if let Some(c) = PathBuilder::from_circle((lx + 15.0) as f32, (y - 4.0) as f32, 6.0) {
                pm.stroke_path(
                    &c,
                    &paint(e.colour),
                    &stroke(2.0, false),
                    Transform::identity(),
                    None,
                );
            }
        } else {
            line(
                &mut pm,
                (lx, y - 4.0),
                (lx + 30.0, y - 4.0),
                e.colour,
                2.0,
                e.dashed,
            );
        }
        text(
            &mut pm,
            (lx + 38.0) as i64,
            (y - 8.0) as i64,
            &e.text,
            [0, 0, 0],
        );
    }
    pm.encode_png().map_err(|e| e.to_string())
}
