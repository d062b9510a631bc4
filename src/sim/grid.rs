//! The stock as a height field: a grid of cells over the stock's XY
//! rectangle, each holding the height of the material at its centre
//! (from the stock's bottom to its top). Cells divide the stock exactly
//! (the cell size is adjusted so that whole cells fill each side), so an
//! uncut field holds exactly the stock's volume.
//!
//! A height field holds what a 3-axis tool pointing down can cut: no
//! undercuts. Memory is 4 bytes a cell (and 4 bytes per tile of
//! [`TILE`] x [`TILE`] cells for [`HeightField::peaks`]), whatever the
//! program's length.

use crate::toolpath::{Stock, P3};
use std::ops::Range;

/// Cells along each side of a tile (see [`HeightField::peaks`]).
pub const TILE: usize = 8;
/// Most cells a field may have (100 MB).
pub const MAX_CELLS: usize = 25_000_000;
/// Cells across the longest side of the stock at most / at least, when
/// the size comes from the tools.
const MOST_ACROSS: f64 = 4000.0;
const LEAST_ACROSS: f64 = 200.0;
/// Cells across the smallest tool's diameter, when the size comes from
/// the tools.
const PER_DIAMETER: f64 = 100.0;

#[derive(Clone, Debug)]
pub struct HeightField {
    /// The stock's lowest corner.
    pub origin: P3,
    pub nx: usize,
    pub ny: usize,
    /// Cell sizes along X and Y, mm.
    pub dx: f64,
    pub dy: f64,
    pub top: f64,
    pub bottom: f64,
    /// Heights, row by row (`j * nx + i`).
    pub z: Vec<f32>,
    /// For each tile of [`TILE`] x [`TILE`] cells (row by row, `tj *
    /// tiles_x + ti`), a height no cell of it stands above: the sweep
    /// passes over a tile whose material the tool cannot reach. Lowering
    /// a cell keeps it true; whoever raises a cell must raise its tile's
    /// peak too.
    pub peaks: Vec<f32>,
    /// Tiles across (X).
    pub tiles_x: usize,
}

/// Two fields are equal when they cover the same cells with the same
/// heights (the tiles' peaks are bounds, not part of the part).
impl PartialEq for HeightField {
    fn eq(&self, o: &HeightField) -> bool {
        (
            self.origin,
            self.nx,
            self.ny,
            self.dx,
            self.dy,
            self.top,
            self.bottom,
        ) == (o.origin, o.nx, o.ny, o.dx, o.dy, o.top, o.bottom)
            && self.z == o.z
    }
}

impl HeightField {
    /// An uncut field over `stock` with cells of about `cell` mm.
    pub fn new(stock: &Stock, cell: f64) -> Result<HeightField, String> {
        if !(cell.is_finite() && cell > 0.0) {
            return Err("the resolution must be a positive number of mm".into());
        }
        let nx = (stock.size[0] / cell).round().max(1.0);
        let ny = (stock.size[1] / cell).round().max(1.0);
        if nx * ny > MAX_CELLS as f64 {
            return Err(format!(
                "a {cell} mm grid over a {} x {} mm stock is {:.0} cells, over the limit of {MAX_CELLS}: give a coarser --resolution",
                stock.size[0], stock.size[1], nx * ny
            ));
        }
        let (nx, ny) = (nx as usize, ny as usize);
        let tiles_x = nx.div_ceil(TILE);
        Ok(HeightField {
            peaks: vec![stock.top() as f32; tiles_x * ny.div_ceil(TILE)],
            tiles_x,
            origin: stock.corner,
            nx,
            ny,
            dx: stock.size[0] / nx as f64,
            dy: stock.size[1] / ny as f64,
            top: stock.top(),
            bottom: stock.corner[2],
            z: vec![stock.top() as f32; nx * ny],
        })
    }

    /// The cell size for a stock and the smallest tool diameter used (see
    /// the constants): fine enough for the tool, bounded by the part.
    pub fn auto_cell(stock: &Stock, smallest_tool: Option<f64>) -> f64 {
        let longest = stock.size[0].max(stock.size[1]);
        let finest =
            (longest / MOST_ACROSS).max((stock.size[0] * stock.size[1] / MAX_CELLS as f64).sqrt());
        let coarsest = longest / LEAST_ACROSS;
        let wanted = smallest_tool
            .filter(|d| *d > 0.0)
            .map_or(coarsest, |d| d / PER_DIAMETER);
        wanted.clamp(finest, coarsest.max(finest))
    }

    /// Sets the peak of tile (`ti`, `tj`) to its highest cell.
    pub fn refresh_peak(&mut self, ti: usize, tj: usize) {
        let cols = ti * TILE..((ti + 1) * TILE).min(self.nx);
        let mut peak = f32::NEG_INFINITY;
        for j in tj * TILE..((tj + 1) * TILE).min(self.ny) {
            let row = &self.z[j * self.nx + cols.start..j * self.nx + cols.end];
            peak = row.iter().fold(peak, |m, h| m.max(*h));
        }
        self.peaks[tj * self.tiles_x + ti] = peak;
    }

    pub fn cell_area(&self) -> f64 {
        self.dx * self.dy
    }

    /// The centre of cell (i, j).
    pub fn centre(&self, i: usize, j: usize) -> (f64, f64) {
        (
            self.origin[0] + (i as f64 + 0.5) * self.dx,
            self.origin[1] + (j as f64 + 0.5) * self.dy,
        )
    }

    /// Columns whose centres lie in `[lo, hi]`.
    pub fn columns(&self, lo: f64, hi: f64) -> Range<usize> {
        span(lo, hi, self.origin[0], self.dx, self.nx)
    }

    /// Rows whose centres lie in `[lo, hi]`.
    pub fn rows(&self, lo: f64, hi: f64) -> Range<usize> {
        span(lo, hi, self.origin[1], self.dy, self.ny)
    }

    /// The volume cut away, mm³.
    pub fn removed(&self) -> f64 {
        let top = self.top as f32;
        self.z.iter().map(|h| (top - h) as f64).sum::<f64>() * self.cell_area()
    }

    /// The stock it was made from.
    pub fn stock(&self) -> Stock {
        Stock {
            corner: self.origin,
            size: [
                self.dx * self.nx as f64,
                self.dy * self.ny as f64,
                self.top - self.bottom,
            ],
        }
    }

    /// The height at a point (of the cell it falls in), if inside.
    pub fn at(&self, x: f64, y: f64) -> Option<f64> {
        self.cell_at(x, y).map(|k| self.z[k] as f64)
    }

    /// The index (`j * nx + i`) of the cell a point falls in, if inside.
    pub fn cell_at(&self, x: f64, y: f64) -> Option<usize> {
        let i = ((x - self.origin[0]) / self.dx).floor();
        let j = ((y - self.origin[1]) / self.dy).floor();
        if !(i >= 0.0 && j >= 0.0 && i < self.nx as f64 && j < self.ny as f64) {
            return None;
        }
        Some(j as usize * self.nx + i as usize)
    }
}

/// Indices `k` in `0..n` with `origin + (k + 0.5) * step` in `[lo, hi]`.
fn span(lo: f64, hi: f64, origin: f64, step: f64, n: usize) -> Range<usize> {
    if !(lo <= hi) {
        return 0..0;
    }
    let a = ((lo - origin) / step - 0.5).ceil().max(0.0);
    let b = ((hi - origin) / step - 0.5).floor() + 1.0;
    let b = b.min(n as f64);
    if b <= a {
        return 0..0;
    }
    a as usize..b as usize
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_fill_the_stock() {
        let s: Stock = "100x50x20".parse().unwrap();
        let f = HeightField::new(&s, 0.3).unwrap();
        assert!((f.dx * f.nx as f64 - 100.0).abs() < 1e-9);
        assert_eq!(f.removed(), 0.0);
        assert_eq!(f.columns(0.0, 0.3 * 1.49), 0..1);
        assert_eq!(f.columns(-5.0, 200.0), 0..f.nx);
        assert_eq!(f.rows(60.0, 70.0), 0..0);
        assert!(HeightField::new(&s, 0.001).is_err());
    }

    #[test]
    fn automatic_cell_sizes() {
        let s: Stock = "200x200x20".parse().unwrap();
        assert!((HeightField::auto_cell(&s, Some(10.0)) - 0.1).abs() < 1e-12);
        assert!((HeightField::auto_cell(&s, Some(0.1)) - 0.05).abs() < 1e-12);
        assert!((HeightField::auto_cell(&s, None) - 1.0).abs() < 1e-12);
    }
}
