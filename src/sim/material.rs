//! Two runs compared by the part they cut (`cncc port --verify` by
//! material): both cut the same stock on the same grid, the fields are
//! compared cell by cell ([`super::compare`]), and where they differ most
//! each run is cut again watching that cell, so the report names the move
//! of each program that left it as it is.
//!
//! The runs are held as event lists (a port holds both programs whole
//! anyway); `cncc diff --material` streams instead
//! ([`crate::cli::diff_material`]).

use super::compare::{compare, Comparison};
use super::{Cutters, HeightField, Simulation, Watch};
use crate::span::Span;
use crate::toolpath::{Event, Stock, P3};

/// One program: its moves and its tools' cutters.
pub struct Side<'a> {
    pub events: &'a [Event],
    pub cutters: Cutters,
}

/// The outcome.
#[derive(Clone, Debug)]
pub struct MaterialVerdict {
    pub comparison: Comparison,
    pub tolerance: f64,
    /// The field both were cut on (its stock and cells).
    pub stock: Stock,
    pub cells: [usize; 2],
    pub cell: [f64; 2],
    /// Where the parts differ most, the move of each program that last
    /// cut that cell and the height it left (None: never cut there).
    pub made: [Option<(Span, f64)>; 2],
}

impl MaterialVerdict {
    pub fn same(&self) -> bool {
        self.comparison.same(self.tolerance)
    }
}

/// The box round a run's feed moves and the tools that feed.
pub fn feed_box(events: &[Event]) -> (Option<[P3; 2]>, Vec<i64>) {
    let mut b: Option<[P3; 2]> = None;
    let mut tools = Vec::new();
    for e in events {
        let Event::Move(m) = e else { continue };
        if !m.is_feed() {
            continue;
        }
        if !tools.contains(&m.tool) {
            tools.push(m.tool);
        }
        for p in [m.from, m.to] {
            let u = b.get_or_insert([p, p]);
            for k in 0..3 {
                u[0][k] = u[0][k].min(p[k]);
                u[1][k] = u[1][k].max(p[k]);
            }
        }
    }
    (b, tools)
}

/// A stock round the feed moves (widened by the largest tool radius):
/// top at Z0 when the moves go below it, else at their top; bottom 1 mm
/// (or a tenth of the depth) under the lowest move.
pub fn guess_stock(b: [P3; 2], radius: f64) -> Stock {
    let [lo, hi] = b;
    let top = if lo[2] < 0.0 { 0.0 } else { hi[2] };
    let depth = (top - lo[2]).max(0.0);
    let bottom = lo[2] - (0.1 * depth).max(1.0);
    let r = radius.max(1.0);
    Stock {
        corner: [lo[0] - r, lo[1] - r, bottom],
        size: [
            hi[0] - lo[0] + 2.0 * r,
            hi[1] - lo[1] + 2.0 * r,
            top - bottom,
        ],
    }
}

/// The stock (`given`, else round both runs' feed moves) and the cell
/// (`resolution`, else the finer of the two runs' automatic cells).
pub fn grid_for(
    sides: &[Side<'_>; 2],
    given: Option<Stock>,
    resolution: Option<f64>,
) -> Result<(Stock, f64), String> {
    let mut bx: Option<[P3; 2]> = None;
    let mut radius = 0.0f64;
    let mut smallest: Option<f64> = None;
    for s in sides {
        let (b, tools) = feed_box(s.events);
        for t in tools {
            let r = s.cutters.get(t).radius;
            radius = radius.max(r);
            if r > 0.0 {
                smallest = Some(smallest.map_or(2.0 * r, |d: f64| d.min(2.0 * r)));
            }
        }
        if let Some(b) = b {
            let u = bx.get_or_insert(b);
            for k in 0..3 {
                u[0][k] = u[0][k].min(b[0][k]);
                u[1][k] = u[1][k].max(b[1][k]);
            }
        }
    }
    let stock = match given {
        Some(s) => s,
        None => guess_stock(bx.ok_or("neither program cuts")?, radius),
    };
    let cell = resolution.unwrap_or_else(|| HeightField::auto_cell(&stock, smallest));
    Ok((stock, cell))
}

/// Cuts `stock` with each side on cells of `cell` mm and compares.
pub fn compare_runs(
    sides: [Side<'_>; 2],
    stock: &Stock,
    cell: f64,
    tolerance: f64,
) -> Result<MaterialVerdict, String> {
    let cut = |s: &Side<'_>, watch: Option<usize>| -> Result<Simulation, String> {
        let mut sim = Simulation::new(HeightField::new(stock, cell)?, s.cutters.clone());
        sim.watch = watch.map(|cell| Watch { cell, last: None });
        for e in s.events {
            sim.push(e);
        }
        Ok(sim)
    };
    let a = cut(&sides[0], None)?;
    let b = cut(&sides[1], None)?;
    let comparison = compare(&a.field, &b.field, tolerance)?;
    let f = &a.field;
    let mut made = [None, None];
    if !comparison.same(tolerance) {
        if let Some(k) = f.cell_at(comparison.at[0], comparison.at[1]) {
            for (n, s) in sides.iter().enumerate() {
                made[n] = cut(s, Some(k))?.watch.and_then(|w| w.last);
            }
        }
    }
    Ok(MaterialVerdict {
        tolerance,
        stock: f.stock(),
        cells: [f.nx, f.ny],
        cell: [f.dx, f.dy],
        comparison,
        made,
    })
}

fn num(v: f64) -> String {
    crate::ir::num::short_text(v, 3)
}

/// One line for `verify:` output.
pub fn summary(v: &MaterialVerdict) -> String {
    let c = &v.comparison;
    let s = &v.stock;
    let grid = format!(
        "grid {} x {} cells of {} mm over {} x {} x {} mm",
        v.cells[0],
        v.cells[1],
        num(v.cell[0].max(v.cell[1])),
        num(s.size[0]),
        num(s.size[1]),
        num(s.size[2])
    );
    let removed = format!(
        "removed {} mm3 by the source, {} mm3 by the port",
        num(c.removed[0]),
        num(c.removed[1])
    );
    if v.same() {
        return format!(
            "the same part within {} mm (largest deviation {} mm); {removed}; {grid}",
            v.tolerance,
            crate::ir::num::short_text(c.largest, 4)
        );
    }
    let mut t = format!(
        "the parts differ: largest deviation {} mm at X{} Y{} (the source leaves Z{}, the port Z{})",
        num(c.largest),
        num(c.at[0]),
        num(c.at[1]),
        num(c.heights[0]),
        num(c.heights[1])
    );
    if let Some(r) = c.region {
        t += &format!(
            "; {} cells differ, within X{}..{} Y{}..{}",
            c.cells,
            num(r[0]),
            num(r[2]),
            num(r[1]),
            num(r[3])
        );
    }
    t + &format!(
        "; {removed} (only the source {} mm3, only the port {} mm3); {grid}",
        num(c.only[0]),
        num(c.only[1])
    )
}

/// The located error for a port that cuts another part (E1002): the
/// port's move that last cut the worst cell (or the source's), with the
/// other program's move beside it.
pub fn diagnostic(v: &MaterialVerdict) -> crate::diag::Diagnostic {
    use crate::diag::{Code, Diagnostic};
    let c = &v.comparison;
    let mut d = Diagnostic::new(
        Code::MaterialDiffers,
        format!(
            "the port cuts another part: {} mm off at X{} Y{}",
            num(c.largest),
            num(c.at[0]),
            num(c.at[1])
        ),
    );
    let what = |h: f64| format!("last cut there, to Z{}", num(h));
    let mut first = true;
    for (k, who) in [(1, "port"), (0, "source")] {
        match v.made[k] {
            Some((span, h)) if first => {
                d = d.primary(span, format!("{who}: {}", what(h)));
                first = false;
            }
            Some((span, h)) => d = d.secondary(span, format!("{who}: {}", what(h))),
            None => d = d.note(format!("the {who} never cuts there")),
        }
    }
    d.note(summary(v))
        .help("the port is not written; port without --features, or report the program")
}
