//! The cutting shape of a tool, as a profile: the height of the cutting
//! surface above the tool tip at a distance `rho` from the tool axis
//! (`0 <= rho <= radius`). Every shape here is convex and rises with
//! `rho`, which the sweep relies on (see [`super::sweep`]).
//!
//! The shape comes from the tool data cncc has (see
//! [`crate::interp::tooltable`] and [`crate::interp::tool_header`]):
//! the diameter from the tool table (machine units) or the program's
//! CAM tool list; the kind from a CAM tool-list line (`CR=` corner radius,
//! `TAPER=118DEG` point angle) or from words of the tool's comment:
//! `ball`; `bull` (with `CR=r` or `R r` in the comment for the corner
//! radius); `drill` (118°); `spot`, `centre`/`center`, `chamfer`,
//! `countersink` (90°). An angle written in the comment as `118DEG` or
//! `90°` replaces the default. Anything else is a flat end mill.
//!
//! [?] A chamfer mill's tip flat and a drill's chisel edge are not in
//! the data: both are taken as sharp cones.

use crate::interp::tool_header::HeaderTool;
use crate::interp::tooltable::Tool;

/// The form of the cutting end.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Shape {
    /// A flat end mill.
    Flat,
    /// A ball end mill (corner radius = radius).
    Ball,
    /// A bull nose end mill with this corner radius (mm, below the radius).
    Bull { corner: f64 },
    /// A cone of this included angle (degrees): drill point, spot drill,
    /// chamfer mill.
    Cone { angle: f64 },
}

/// A tool as the simulation cuts with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cutter {
    /// Radius, mm (0: a point; the tool's size is not known).
    pub radius: f64,
    pub shape: Shape,
}

impl Cutter {
    pub fn flat(radius: f64) -> Cutter {
        Cutter {
            radius: radius.max(0.0),
            shape: Shape::Flat,
        }
    }

    /// Height of the cutting surface above the tip at `rho` (clamped to
    /// the radius).
    pub fn profile(&self, rho: f64) -> f64 {
        let r = self.radius;
        let rho = rho.clamp(0.0, r);
        match self.shape {
            Shape::Flat => 0.0,
            Shape::Ball => r - (r * r - rho * rho).max(0.0).sqrt(),
            Shape::Bull { corner } => {
                let flat = r - corner;
                if rho <= flat {
                    0.0
                } else {
                    let d = rho - flat;
                    corner - (corner * corner - d * d).max(0.0).sqrt()
                }
            }
            Shape::Cone { angle } => rho / half_tan(angle),
        }
    }

    /// The profile's slope at `rho` (for the sweep's minimum search).
    pub fn slope(&self, rho: f64) -> f64 {
        let r = self.radius;
        let rho = rho.clamp(0.0, r);
        match self.shape {
            Shape::Flat => 0.0,
            Shape::Ball => rho / (r * r - rho * rho).max(1e-18).sqrt(),
            Shape::Bull { corner } => {
                let d = rho - (r - corner);
                if d <= 0.0 {
                    0.0
                } else {
                    d / (corner * corner - d * d).max(1e-18).sqrt()
                }
            }
            Shape::Cone { angle } => 1.0 / half_tan(angle),
        }
    }

    /// Does the profile rise at all (anything but a flat end)?
    pub fn is_flat(&self) -> bool {
        matches!(self.shape, Shape::Flat) || self.radius == 0.0
    }

    /// `flat D10`, `ball D6`, `bull D10 R2`, `drill D8.5 118°`.
    pub fn describe(&self) -> String {
        let d = fmt(self.radius * 2.0);
        match self.shape {
            Shape::Flat => format!("flat D{d}"),
            Shape::Ball => format!("ball D{d}"),
            Shape::Bull { corner } => format!("bull D{d} R{}", fmt(corner)),
            Shape::Cone { angle } => format!("cone D{d} {}°", fmt(angle)),
        }
    }

    /// The cutter of a tool from its table row and its CAM tool-list
    /// line (see the module doc); `mm`: millimetres per table unit.
    pub fn from_tool(tool: Option<&Tool>, header: Option<&HeaderTool>, mm: f64) -> Cutter {
        let radius = tool.map_or(0.0, |t| t.diameter * mm / 2.0);
        let radius = if radius.is_finite() && radius > 0.0 {
            radius
        } else {
            0.0
        };
        let comment = tool.map_or("", |t| t.comment.as_str());
        let shape = header
            .and_then(|h| from_header(h, radius))
            .or_else(|| from_comment(comment, radius))
            .unwrap_or(Shape::Flat);
        Cutter { radius, shape }
    }
}

/// Does the tool's data say what shape it is (the CAM tool list or the
/// tool's comment), rather than leave it to the flat default?
/// A corner radius written (`CR=0.` is a flat end), a shape the list
/// or the comment names, or a name that says flat or end mill counts.
pub fn shape_stated(tool: &Tool, header: Option<&HeaderTool>) -> bool {
    let r = (tool.diameter / 2.0).max(1.0);
    let names_flat = |name: &str| {
        let c = name.to_ascii_lowercase();
        [
            "flat",
            "end mill",
            "endmill",
            "face mill",
            "facemill",
            "slot",
        ]
        .iter()
        .any(|w| c.contains(w))
    };
    header.is_some_and(|h| h.corner.is_some() || from_header(h, r).is_some() || names_flat(&h.name))
        || from_comment(&tool.comment, r).is_some()
        || names_flat(&tool.comment)
}

/// Does a tool's name say it is made to feed along its axis: a drill, a
/// tap, a reamer, a boring or counterboring tool, a plunge mill, a
/// centre-cutting end mill (English and German words)? [?] Names are
/// free text: a name that says none of these is taken as a tool that
/// cannot plunge only when its shape is flat.
pub fn axial_name(name: &str) -> bool {
    let c = name.to_ascii_lowercase();
    let words: Vec<&str> = c
        .split(|ch: char| !ch.is_ascii_alphabetic())
        .filter(|w| !w.is_empty())
        .collect();
    let centre_cutting = c.contains("center cut") || c.contains("centre cut");
    centre_cutting
        || words.iter().any(|w| {
            *w == "tap"
                || w.starts_with("tapping")
                || w.starts_with("ream")
                || w.contains("bor")
                || w.contains("bohr")
                || w.contains("drill")
                || w.starts_with("plung")
                || w.starts_with("gewinde")
        })
}

fn half_tan(angle: f64) -> f64 {
    (angle.to_radians() / 2.0).tan().max(1e-9)
}

/// The shape a CAM tool-list line gives (its sizes are in program units:
/// scaled to `radius` by the line's own diameter).
fn from_header(h: &HeaderTool, radius: f64) -> Option<Shape> {
    if let Some(a) = h.taper.filter(|a| *a > 0.0 && *a < 180.0) {
        return Some(Shape::Cone { angle: a });
    }
    let cr = h.corner.filter(|c| *c > 0.0)?;
    let scale = if h.diameter > 0.0 {
        2.0 * radius / h.diameter
    } else {
        return None;
    };
    Some(corner_shape(cr * scale, radius))
}

fn corner_shape(corner: f64, radius: f64) -> Shape {
    if corner >= radius * (1.0 - 1e-6) {
        Shape::Ball
    } else {
        Shape::Bull { corner }
    }
}

/// The shape a tool's comment names.
fn from_comment(comment: &str, radius: f64) -> Option<Shape> {
    let c = comment.to_ascii_lowercase();
    let has = |w: &str| c.contains(w);
    let cone = |default: f64| Shape::Cone {
        angle: angle_in(&c).unwrap_or(default),
    };
    Some(if has("ball") {
        Shape::Ball
    } else if has("bull") {
        match corner_in(&c) {
            Some(r) if r > 0.0 => corner_shape(r, radius),
            _ => Shape::Flat,
        }
    } else if has("spot") || has("centre") || has("center") {
        cone(90.0)
    } else if has("chamfer") || has("countersink") {
        cone(90.0)
    } else if has("drill") && !has("end mill") && !has("endmill") {
        cone(118.0)
    } else {
        return None;
    })
}

/// `118deg`, `118 deg`, `118°` in a comment.
fn angle_in(c: &str) -> Option<f64> {
    let words: Vec<&str> = c.split_whitespace().collect();
    for (i, w) in words.iter().enumerate() {
        let w = w.trim_start_matches("taper=");
        for suffix in ["deg", "°"] {
            if let Some(n) = w.strip_suffix(suffix) {
                if let Ok(v) = n.parse::<f64>() {
                    return Some(v).filter(|v| *v > 0.0 && *v < 180.0);
                }
            }
        }
        if matches!(words.get(i + 1), Some(&"deg") | Some(&"°")) {
            if let Ok(v) = w.parse::<f64>() {
                return Some(v).filter(|v| *v > 0.0 && *v < 180.0);
            }
        }
    }
    None
}

/// `cr=2`, `r2`, `r 2` in a comment.
fn corner_in(c: &str) -> Option<f64> {
    let words: Vec<&str> = c.split_whitespace().collect();
    for (i, w) in words.iter().enumerate() {
        if let Some(n) = w.strip_prefix("cr=").or_else(|| w.strip_prefix('r')) {
            if let Ok(v) = n.parse::<f64>() {
                return Some(v);
            }
            if n.is_empty() {
                if let Some(v) = words.get(i + 1).and_then(|n| n.parse().ok()) {
                    return Some(v);
                }
            }
        }
    }
    None
}

fn fmt(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tool(d: f64, comment: &str) -> Tool {
        let mut t = Tool::blank(1, comment.into());
        t.diameter = d;
        t
    }

    #[test]
    fn profiles() {
        let ball = Cutter {
            radius: 5.0,
            shape: Shape::Ball,
        };
        assert!((ball.profile(5.0) - 5.0).abs() < 1e-12);
        assert!((ball.profile(3.0) - 1.0).abs() < 1e-12);
        let drill = Cutter {
            radius: 5.0,
            shape: Shape::Cone { angle: 90.0 },
        };
        assert!((drill.profile(5.0) - 5.0).abs() < 1e-9);
        let bull = Cutter {
            radius: 5.0,
            shape: Shape::Bull { corner: 1.0 },
        };
        assert_eq!(bull.profile(3.5), 0.0);
        assert!((bull.profile(5.0) - 1.0).abs() < 1e-12);
    }

    #[test]
    fn shapes_from_comments_and_headers() {
        let c = Cutter::from_tool(Some(&tool(10.0, "6 mm ball end mill")), None, 1.0);
        assert_eq!(c.shape, Shape::Ball);
        let c = Cutter::from_tool(Some(&tool(10.0, "bull nose CR=2")), None, 1.0);
        assert_eq!(c.shape, Shape::Bull { corner: 2.0 });
        let c = Cutter::from_tool(Some(&tool(8.5, "8.5 drill 135deg")), None, 1.0);
        assert_eq!(c.shape, Shape::Cone { angle: 135.0 });
        let c = Cutter::from_tool(Some(&tool(0.5, "spot drill")), None, 25.4);
        assert_eq!((c.radius, c.shape), (6.35, Shape::Cone { angle: 90.0 }));
        let c = Cutter::from_tool(Some(&tool(10.0, "end mill")), None, 1.0);
        assert_eq!(c.shape, Shape::Flat);
        let h = crate::interp::tool_header::parse("T1 D=0.5 CR=0.1 - BULL NOSE END MILL").unwrap();
        let c = Cutter::from_tool(Some(&tool(12.7, "BULL NOSE END MILL")), Some(&h), 1.0);
        let Shape::Bull { corner } = c.shape else {
            panic!("{c:?}")
        };
        assert!((corner - 2.54).abs() < 1e-9);
        assert_eq!(Cutter::from_tool(None, None, 1.0).radius, 0.0);
    }

    #[test]
    fn axial_tools_by_name() {
        for yes in [
            "M8 TAP",
            "10H7 REAMER",
            "boring bar",
            "COUNTERBORE",
            "FLAT BOTTOM DRILL",
            "Gewindebohrer M6",
            "center cutting end mill",
        ] {
            assert!(axial_name(yes), "{yes}");
        }
        for no in ["FLAT END MILL", "tapered end mill", "face mill", ""] {
            assert!(!axial_name(no), "{no}");
        }
    }
}
