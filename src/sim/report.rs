//! What `cncc simulate` prints: the stock and grid, per tool the cutter,
//! the volume removed, the feed length and time; the machining time
//! (feed moves at their programmed rate; rapids at a stated rate, or
//! left out); and the rapid hits as located diagnostics (E1001).

use super::{Plunge, RapidHit, Simulation};
use crate::diag::{Code, Diagnostic};
use crate::stats::report::duration;
use crate::toolpath::Stock;
use std::fmt::Write;

/// Where the stock came from, for the report.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum StockFrom {
    Option,
    Blank,
    Guessed,
}

impl StockFrom {
    pub fn says(self) -> &'static str {
        match self {
            StockFrom::Option => "--stock",
            StockFrom::Blank => "the program's BLK FORM",
            StockFrom::Guessed => "guessed from the feed moves (give --stock)",
        }
    }
}

/// How the run is summed up.
pub struct Summary<'a> {
    pub sim: &'a Simulation,
    pub stock_from: StockFrom,
    /// Rapid rate, mm/min; None: rapids left out of the time.
    pub rapid_rate: Option<f64>,
    /// Sizes from cncc's built-in table (invented).
    pub invented: bool,
}

fn num(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}

fn stock_text(s: &Stock) -> String {
    format!(
        "{} x {} x {} mm, lowest corner X{} Y{} Z{}",
        num(s.size[0]),
        num(s.size[1]),
        num(s.size[2]),
        num(s.corner[0]),
        num(s.corner[1]),
        num(s.corner[2])
    )
}

impl Summary<'_> {
    fn rapid_minutes(&self) -> f64 {
        let len: f64 = self.sim.tools.iter().map(|t| t.rapid_length).sum();
        self.rapid_rate.map_or(0.0, |r| len / r)
    }

    /// The report for people.
    pub fn human(&self) -> String {
        let sim = self.sim;
        let f = &sim.field;
        let stock = f.stock();
        let mut o = String::new();
        let _ = writeln!(
            o,
            "stock: {} ({})",
            stock_text(&stock),
            self.stock_from.says()
        );
        let _ = writeln!(
            o,
            "grid: {} x {} cells of {} x {} mm; arcs as chords within {} mm",
            f.nx,
            f.ny,
            num(f.dx),
            num(f.dy),
            num(sim.chord)
        );
        let _ = writeln!(
            o,
            "{:<6} {:<18} {:>14} {:>12} {:>11}",
            "tool", "cutter", "removed mm3", "feed mm", "feed time"
        );
        for t in &sim.tools {
            let cutter = if t.cutter.radius > 0.0 {
                t.cutter.describe()
            } else {
                "size unknown".into()
            };
            let _ = writeln!(
                o,
                "T{:<5} {:<18} {:>14.1} {:>12.1} {:>11}",
                t.tool,
                cutter,
                t.volume,
                t.feed_length,
                duration(t.feed_minutes * 60.0)
            );
        }
        let total = sim.removed();
        let whole = stock.size.iter().product::<f64>();
        let _ = writeln!(
            o,
            "removed: {total:.1} mm3 ({:.2}% of the stock); left: {:.1} mm3",
            100.0 * total / whole,
            whole - total
        );
        let feed: f64 = sim.tools.iter().map(|t| t.feed_minutes).sum();
        let rapid_len: f64 = sim.tools.iter().map(|t| t.rapid_length).sum();
        let rapids = match self.rapid_rate {
            Some(r) => format!(
                "rapids {:.1} mm at {} mm/min {}",
                rapid_len,
                num(r),
                duration(self.rapid_minutes() * 60.0)
            ),
            None => format!("rapids {rapid_len:.1} mm left out"),
        };
        let _ = writeln!(
            o,
            "time: feed {} (length / programmed feed), {rapids}; total {} (no tool changes, no acceleration)",
            duration(feed * 60.0),
            duration((feed + self.rapid_minutes()) * 60.0)
        );
        if sim.tools.iter().any(|t| t.cutter.radius == 0.0) {
            let _ = writeln!(
                o,
                "note: a tool of unknown size cuts as its axis line only (give --tool-table)"
            );
        }
        if self.invented {
            let _ = writeln!(
                o,
                "note: tool sizes from cncc's built-in table are invented (give --tool-table)"
            );
        }
        o
    }

    /// The report as one JSON object.
    pub fn json(&self) -> String {
        let sim = self.sim;
        let s = sim.field.stock();
        let tools: Vec<_> = sim
            .tools
            .iter()
            .map(|t| {
                serde_json::json!({
                    "tool": t.tool,
                    "cutter": t.cutter.describe(),
                    "radius_mm": t.cutter.radius,
                    "removed_mm3": t.volume,
                    "feed_mm": t.feed_length,
                    "feed_min": t.feed_minutes,
                    "rapid_mm": t.rapid_length,
                })
            })
            .collect();
        let feed: f64 = sim.tools.iter().map(|t| t.feed_minutes).sum();
        let v = serde_json::json!({
            "stock": {"corner": s.corner, "size": s.size, "from": self.stock_from.says()},
            "grid": {"nx": sim.field.nx, "ny": sim.field.ny, "dx": sim.field.dx, "dy": sim.field.dy},
            "tools": tools,
            "removed_mm3": sim.removed(),
            "feed_min": feed,
            "rapid_rate_mm_min": self.rapid_rate,
            "rapid_min": self.rapid_rate.map(|_| self.rapid_minutes()),
            "rapid_hits": sim.rapid_hits.len(),
        });
        format!("{v}\n")
    }
}

/// The located error for a rapid that cut into the stock.
pub fn rapid_diagnostic(hit: &RapidHit, stock_from: StockFrom) -> Diagnostic {
    Diagnostic::new(
        Code::RapidIntoStock,
        format!(
            "this rapid moves T{} {} mm into the material",
            hit.tool,
            num((hit.depth * 1000.0).round() / 1000.0)
        ),
    )
    .primary(hit.span, "rapid through the stock")
    .note(format!(
        "deepest at X{} Y{}, where the material stands at Z{} (stock from {})",
        num(hit.at[0]),
        num(hit.at[1]),
        num(hit.at[2]),
        stock_from.says()
    ))
    .help("retract above the material before the rapid, or make this move a feed (G1)")
}

/// The warning for a flat tool fed straight down into material (W1004).
pub fn plunge_diagnostic(p: &Plunge, stock_from: StockFrom) -> Diagnostic {
    let more = match p.count {
        1 => String::new(),
        n => format!(
            "; T{} plunges so {n} times in all, the first is shown",
            p.tool
        ),
    };
    Diagnostic::new(
        Code::PlungeWithoutCentreCutting,
        format!(
            "the flat end mill T{} is fed straight down {} mm into solid material",
            p.tool,
            num((p.depth * 1000.0).round() / 1000.0)
        ),
    )
    .primary(p.span, "plunge")
    .note(format!(
        "at X{} Y{}, where the material stands at Z{} (stock from {}){more}",
        num(p.at[0]),
        num(p.at[1]),
        num(p.at[2]),
        stock_from.says()
    ))
    .help("ramp or helix into the material, drill a start hole first, or use a centre-cutting tool (say so in its name)")
}

/// The note where the checks against the stock stopped (W1003).
pub fn stopped_diagnostic(span: crate::span::Span, tool: i64) -> Diagnostic {
    Diagnostic::new(
        Code::MaterialCheckStopped,
        format!("T{tool}'s size is not known: rapids and plunges after its first cut are not checked against the stock"),
    )
    .primary(span, "first cut of a tool of unknown size")
    .help("give the tool's size with --tool-table")
}

/// Drops the rapid hits and plunges after `at` (in its file), where the
/// run met a tilted working plane it does not make (W0518): positions
/// after it are the untilted ones, not the machine's, so a hit there is
/// no finding. True when the checks stop there (the stock was checked
/// that far).
pub fn stop_at_tilt(sim: &mut Simulation, at: crate::span::Span) -> bool {
    let after = |s: &crate::span::Span| s.file == at.file && s.start > at.start;
    sim.rapid_hits.retain(|h| !after(&h.span));
    sim.plunges.retain(|p| !after(&p.span));
    sim.probe_stopped.is_none()
}

/// The note where the checks against the stock stopped at a tilt (W1003).
pub fn tilt_stopped_diagnostic(span: crate::span::Span) -> Diagnostic {
    Diagnostic::new(
        Code::MaterialCheckStopped,
        "the working plane is tilted here and the 3-axis run does not tilt it: rapids and plunges after it are not checked against the stock",
    )
    .primary(span, "tilted plane, not made by the run")
    .help("the positions the run shows after the tilt are the untilted ones (see `cncc explain W0518`)")
}

/// Every diagnostic of the checks against the stock, in program order
/// of kind: rapid hits, plunges, where the checks stopped.
pub fn safety_diagnostics(sim: &Simulation, stock_from: StockFrom) -> Vec<Diagnostic> {
    let mut d: Vec<Diagnostic> = sim
        .rapid_hits
        .iter()
        .map(|h| rapid_diagnostic(h, stock_from))
        .collect();
    d.extend(sim.plunges.iter().map(|p| plunge_diagnostic(p, stock_from)));
    d.extend(sim.probe_stopped.map(|(s, t)| stopped_diagnostic(s, t)));
    d
}
