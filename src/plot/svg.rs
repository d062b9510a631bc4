//! A [`Picture`] as SVG text: one `<path>` per layer (view, file, tool,
//! feed or rapid), arcs as SVG arcs, legend entries as
//! `<g class="legend-entry">`, difference marks as
//! `<circle class="mark">`.

use super::layout::Panel;
use super::legend::{hex, Entry, MARK, STOCK};
use super::scene::Seg;
use super::Picture;
use std::f64::consts::PI;
use std::fmt::Write;

fn esc(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// Path data of one layer, in the panel's pixels.
fn path_data(segs: &[Seg], panel: &Panel) -> String {
    let mut d = String::with_capacity(segs.len() * 14);
    for s in segs {
        let _ = match *s {
            Seg::Move(p) => {
                let (x, y) = panel.uv(p);
                write!(d, "M{x:.1} {y:.1}")
            }
            Seg::Line(p) => {
                let (x, y) = panel.uv(p);
                write!(d, "L{x:.1} {y:.1}")
            }
            Seg::Arc {
                to,
                centre,
                r,
                start,
                sweep,
            } => {
                let rp = r * panel.scale;
                // At most a half turn per SVG arc (a full circle needs two).
                // Counter-clockwise with v up is clockwise in SVG's y down:
                // sweep-flag 1 is clockwise as seen.
                let n = (sweep.abs() / PI).ceil().max(1.0) as usize;
                let flag = u8::from(sweep < 0.0);
                for k in 1..=n {
                    let p = if k == n {
                        to
                    } else {
                        let a = start + sweep * k as f64 / n as f64;
                        (centre.0 + r * a.cos(), centre.1 + r * a.sin())
                    };
                    let (x, y) = panel.uv(p);
                    let _ = write!(d, "A{rp:.1} {rp:.1} 0 0 {flag} {x:.1} {y:.1}");
                }
                Ok(())
            }
            Seg::Hole { centre, r } => {
                let (x, y) = panel.uv(centre);
                let rp = hole_px(r, panel);
                write!(
                    d,
                    "M{:.1} {y:.1}A{rp:.1} {rp:.1} 0 1 0 {:.1} {y:.1}A{rp:.1} {rp:.1} 0 1 0 {:.1} {y:.1}",
                    x + rp,
                    x - rp,
                    x + rp
                )
            }
        };
    }
    d
}

/// A hole's radius in pixels: the tool's, at least 3.
pub fn hole_px(r: f64, panel: &Panel) -> f64 {
    (r * panel.scale).max(3.0)
}

fn legend(out: &mut String, entries: &[Entry], x: f64) {
    let _ = writeln!(
        out,
        r#"<g class="legend" font-family="monospace" font-size="13">"#
    );
    for (i, e) in entries.iter().enumerate() {
        let y = 30.0 + 20.0 * i as f64;
        let c = hex(e.colour);
        let _ = write!(out, r#"<g class="legend-entry">"#);
        let _ = if e.mark {
            write!(
                out,
                r#"<circle cx="{:.1}" cy="{:.1}" r="6" fill="none" stroke="{c}" stroke-width="2"/>"#,
                x + 15.0,
                y - 4.0
            )
        } else {
            let dash = if e.dashed {
                r#" stroke-dasharray="4 3""#
            } else {
                ""
            };
            write!(
                out,
                r#"<line x1="{x:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{c}" stroke-width="2"{dash}/>"#,
                y - 4.0,
                x + 30.0,
                y - 4.0
            )
        };
        let _ = writeln!(
            out,
            r#"<text x="{:.1}" y="{y:.1}">{}</text></g>"#,
            x + 38.0,
            esc(&e.text)
        );
    }
    let _ = writeln!(out, "</g>");
}

/// Stroke width: overlaid, A is drawn wider under B so both show.
pub fn line_width(overlay: bool, key: &super::scene::LayerKey) -> f32 {
    match (key.rapid, overlay, key.file) {
        (true, _, _) => 0.8,
        (false, true, 0) => 3.0,
        (false, _, _) => 1.0,
    }
}

/// The picture as an SVG document.
pub fn render(p: &Picture) -> String {
    let l = &p.layout;
    let mut out = String::new();
    let _ = writeln!(
        out,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" viewBox="0 0 {w} {h}">"#,
        w = l.width,
        h = l.height
    );
    let _ = writeln!(out, r#"<rect width="100%" height="100%" fill="white"/>"#);
    for (i, panel) in l.panels.iter().enumerate() {
        let _ = writeln!(
            out,
            r##"<g class="view" id="view-{i}"><rect x="{:.1}" y="{:.1}" width="{:.1}" height="{:.1}" fill="none" stroke="#ddd"/><text x="{:.1}" y="{:.1}" font-family="monospace" font-size="13">{}</text>"##,
            panel.x + 2.0,
            panel.y + 2.0,
            panel.w - 4.0,
            panel.h - 4.0,
            panel.x + 8.0,
            panel.y + 18.0,
            panel.view.title()
        );
        for (a, b) in p.stock_edges(panel) {
            let _ = writeln!(
                out,
                r#"<line class="stock" x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="{}" stroke-width="1"/>"#,
                a.0,
                a.1,
                b.0,
                b.1,
                hex(STOCK)
            );
        }
        // Rapids first, under the cuts.
        let mut layers: Vec<_> = p
            .scene
            .layers
            .iter()
            .filter(|(k, _)| k.panel == i)
            .collect();
        layers.sort_by_key(|(k, _)| (!k.rapid, k.file, k.tool));
        for (key, layer) in layers {
            if layer.segs.is_empty() {
                continue;
            }
            let (colour, dashed) = super::legend::style(&p.scene, p.overlay, key);
            let dash = if dashed {
                r#" stroke-dasharray="4 3""#
            } else {
                ""
            };
            let _ = writeln!(
                out,
                r#"<path class="{}" data-file="{}" data-tool="{}" fill="none" stroke="{}" stroke-width="{}"{dash} d="{}"/>"#,
                if key.rapid { "rapid" } else { "feed" },
                key.file,
                key.tool,
                hex(colour),
                line_width(p.overlay, key),
                path_data(&layer.segs, panel)
            );
        }
        for ((x, y), r) in p.marks(panel) {
            let _ = writeln!(
                out,
                r#"<circle class="mark" cx="{x:.1}" cy="{y:.1}" r="{r:.1}" fill="none" stroke="{}" stroke-width="2"/>"#,
                hex(MARK)
            );
        }
        let _ = writeln!(out, "</g>");
    }
    legend(
        &mut out,
        &p.legend,
        l.width - super::layout::LEGEND_W + 10.0,
    );
    let _ = writeln!(out, "</svg>");
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::{Scene, View};
    use crate::stats::Bounds;
    use crate::toolpath::{ArcGeom, CoolantState, Event, FeedMode, Move, MoveKind};

    /// The path of one XY arc from (10, 0) to (0, 10) about the origin.
    fn arc_path(rotation: i64) -> String {
        let mut b = Bounds::default();
        b.add([-10.0, -10.0, 0.0]);
        b.add([10.0, 10.0, 1.0]);
        let mut s = Scene::new(vec![View::Top], 600.0, b);
        let m = Move {
            kind: MoveKind::Arc(ArcGeom {
                axes: [0, 1, 2],
                centre: [0.0; 3],
                rotation,
            }),
            from: [10.0, 0.0, 0.0],
            to: [0.0, 10.0, 0.0],
            feed: 100.0,
            feed_mode: FeedMode::PerMinute,
            tool: 1,
            spindle: 0.0,
            coolant: CoolantState::default(),
            span: Default::default(),
        };
        s.push(0, &Event::Move(m));
        let layout = s.layout();
        let layer = s.layers.values().next().unwrap();
        path_data(&layer.segs, &layout.panels[0])
    }

    #[test]
    fn counter_clockwise_arcs_turn_counter_clockwise_on_screen() {
        // G3 a quarter turn: SVG's sweep-flag 0 (y down: counter-clockwise
        // as seen), one piece.
        let ccw = arc_path(1);
        assert_eq!(ccw.matches('A').count(), 1, "{ccw}");
        assert!(ccw.contains(" 0 0 0 "), "{ccw}");
        // G2 the other way round, three quarters: flag 1, in two pieces.
        let cw = arc_path(-1);
        assert_eq!(cw.matches('A').count(), 2, "{cw}");
        assert!(cw.contains(" 0 0 1 ") && !cw.contains(" 0 0 0 "), "{cw}");
    }
}
