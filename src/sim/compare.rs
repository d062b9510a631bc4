//! Two cut parts compared cell by cell (`cncc diff --material`): the
//! largest difference of height, where it is, how many cells differ by
//! more than the tolerance, and the volume each removed. Both fields
//! must be over the same stock with the same cells.

use super::grid::HeightField;

/// The default tolerance, mm.
pub const TOLERANCE: f64 = 0.01;

#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The largest |height A - height B|, mm, and the cell centre where
    /// it is, with both heights there.
    pub largest: f64,
    pub at: [f64; 2],
    pub heights: [f64; 2],
    /// Cells differing by more than the tolerance, and the box round them
    /// (x min, y min, x max, y max).
    pub cells: usize,
    pub region: Option<[f64; 4]>,
    /// Volume each removed, mm³.
    pub removed: [f64; 2],
    /// Volume A left that B removed, and B left that A removed, mm³.
    pub only: [f64; 2],
}

impl Comparison {
    pub fn same(&self, tolerance: f64) -> bool {
        self.largest <= tolerance
    }
}

/// Compares two fields made over the same grid.
pub fn compare(a: &HeightField, b: &HeightField, tolerance: f64) -> Result<Comparison, String> {
    if (a.nx, a.ny) != (b.nx, b.ny) || a.origin != b.origin || a.dx != b.dx || a.dy != b.dy {
        return Err("the two parts are not on the same grid".into());
    }
    let mut c = Comparison {
        largest: 0.0,
        at: [a.origin[0], a.origin[1]],
        heights: [a.top, b.top],
        cells: 0,
        region: None,
        removed: [a.removed(), b.removed()],
        only: [0.0; 2],
    };
    let area = a.cell_area();
    for (k, (za, zb)) in a.z.iter().zip(&b.z).enumerate() {
        let d = (*za as f64 - *zb as f64).abs();
        if *za > *zb {
            c.only[1] += d * area;
        } else {
            c.only[0] += d * area;
        }
        if d <= tolerance {
            continue;
        }
        let (x, y) = a.centre(k % a.nx, k / a.nx);
        c.cells += 1;
        let r = c.region.get_or_insert([x, y, x, y]);
        *r = [r[0].min(x), r[1].min(y), r[2].max(x), r[3].max(y)];
        if d > c.largest {
            c.largest = d;
            c.at = [x, y];
            c.heights = [*za as f64, *zb as f64];
        }
    }
    Ok(c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_step_is_found() {
        let s: crate::toolpath::Stock = "10x10x5".parse().unwrap();
        let a = HeightField::new(&s, 1.0).unwrap();
        let mut b = a.clone();
        b.z[12] = -2.0;
        let c = compare(&a, &b, TOLERANCE).unwrap();
        assert_eq!((c.largest, c.at, c.cells), (2.0, [2.5, 1.5], 1));
        assert!((c.only[1] - 2.0).abs() < 1e-9);
        assert!(!c.same(TOLERANCE));
        assert!(compare(&a, &a, TOLERANCE).unwrap().same(TOLERANCE));
    }
}
