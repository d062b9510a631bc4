//! Colours and the legend: one colour per tool (one per file when two
//! files are overlaid), rapids dashed, difference marks in red.

use super::scene::{LayerKey, Scene};
use crate::compare::describe::num;

/// An RGB colour.
pub type Rgb = [u8; 3];

const TOOL_COLOURS: [Rgb; 10] = [
    [31, 119, 180],
    [214, 39, 40],
    [44, 160, 44],
    [148, 103, 189],
    [255, 127, 14],
    [23, 190, 207],
    [140, 86, 75],
    [227, 119, 194],
    [188, 189, 34],
    [127, 127, 127],
];
const FILE_COLOURS: [Rgb; 2] = [[31, 119, 180], [255, 127, 14]];
pub const RAPID: Rgb = [150, 150, 150];
pub const MARK: Rgb = [220, 0, 0];
pub const STOCK: Rgb = [90, 90, 90];

/// `#rrggbb`
pub fn hex(c: Rgb) -> String {
    format!("#{:02x}{:02x}{:02x}", c[0], c[1], c[2])
}

/// How a layer is drawn: its colour and whether dashed.
pub fn style(scene: &Scene, overlay: bool, key: &LayerKey) -> (Rgb, bool) {
    if overlay {
        let c = FILE_COLOURS[key.file.min(1)];
        if key.rapid {
            // The file's colour, lighter.
            return (c.map(|v| v / 2 + 110), true);
        }
        return (c, false);
    }
    if key.rapid {
        return (RAPID, true);
    }
    let i = scene
        .tools
        .iter()
        .position(|t| t.tool == key.tool)
        .unwrap_or(0);
    (TOOL_COLOURS[i % TOOL_COLOURS.len()], false)
}

/// One line of the legend.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    pub colour: Rgb,
    pub dashed: bool,
    /// A difference mark (circle) rather than a line.
    pub mark: bool,
    pub text: String,
}

/// The legend: files (overlay) or tools, then rapids and marks.
pub fn entries(
    scene: &Scene,
    names: &[String],
    diameter: impl Fn(i64) -> Option<f64>,
    differences: Option<usize>,
) -> Vec<Entry> {
    let overlay = names.len() > 1;
    let mut out = Vec::new();
    if overlay {
        for (i, n) in names.iter().enumerate() {
            out.push(Entry {
                colour: FILE_COLOURS[i.min(1)],
                dashed: false,
                mark: false,
                text: format!("{}: {n}", ["A", "B"][i.min(1)]),
            });
        }
    }
    for t in scene.tools.iter().filter(|t| !overlay || t.file == 0) {
        let dia = diameter(t.tool).map(|d| format!(" D{}", num((d * 100.0).round() / 100.0)));
        let feeds = match t.feeds {
            None => String::new(),
            Some([a, b]) if (a - b).abs() < 1e-9 => format!(" F{}", num(a.round())),
            Some([a, b]) => format!(" F{}-{}", num(a.round()), num(b.round())),
        };
        let key = LayerKey {
            panel: 0,
            file: 0,
            rapid: false,
            tool: t.tool,
        };
        // Overlaid, colours are the files': tools are listed in black.
        let colour = if overlay {
            [0, 0, 0]
        } else {
            style(scene, overlay, &key).0
        };
        out.push(Entry {
            colour,
            dashed: false,
            mark: false,
            text: format!("T{}{}{}", t.tool, dia.unwrap_or_default(), feeds),
        });
    }
    out.push(Entry {
        colour: RAPID,
        dashed: true,
        mark: false,
        text: "rapid".into(),
    });
    if let Some(n) = differences {
        out.push(Entry {
            colour: MARK,
            dashed: false,
            mark: true,
            text: format!("{n} difference{}", if n == 1 { "" } else { "s" }),
        });
    }
    out
}
