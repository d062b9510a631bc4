//! The cut part as an STL mesh (binary, or ASCII on request) that CAD
//! viewers open: the height field's top surface on a grid of nodes, four
//! side walls and the bottom, closed. The nodes are the cells' centres
//! (the border nodes moved out to the stock's edges); a field larger than
//! [`MAX_NODES`] a side is thinned, each node taking the lowest height of
//! the cells it stands for, so a small hole stays open. Streamed to the
//! writer: memory is the field's.

use super::grid::HeightField;
use std::io::{self, Write};

/// Most nodes along a side (a 1000 x 1000 mesh is about 100 MB binary).
pub const MAX_NODES: usize = 1000;

type V = [f32; 3];

/// The nodes along one axis: (first cell, last cell + 1, position).
fn axis(n: usize, origin: f64, step: f64) -> Vec<(usize, usize, f32)> {
    let stride = n.div_ceil(MAX_NODES).max(1);
    let mut out = Vec::new();
    let mut k = 0;
    while k < n {
        let end = (k + stride).min(n);
        let mid = (k + end) as f64 / 2.0;
        out.push((k, end, (origin + mid * step) as f32));
        k = end;
    }
    if out.len() == 1 {
        // One cell across: its two edges.
        out.push(out[0]);
    }
    if let Some(first) = out.first_mut() {
        first.2 = origin as f32;
    }
    if let Some(last) = out.last_mut() {
        last.2 = (origin + n as f64 * step) as f32;
    }
    out
}

/// Writes the mesh.
pub fn write(f: &HeightField, ascii: bool, out: &mut impl Write) -> io::Result<()> {
    let xs = axis(f.nx, f.origin[0], f.dx);
    let ys = axis(f.ny, f.origin[1], f.dy);
    let mut z = vec![0f32; xs.len() * ys.len()];
    for (b, &(j0, j1, _)) in ys.iter().enumerate() {
        for (a, &(i0, i1, _)) in xs.iter().enumerate() {
            let mut lo = f32::MAX;
            for j in j0..j1 {
                for h in &f.z[j * f.nx + i0..j * f.nx + i1] {
                    lo = lo.min(*h);
                }
            }
            z[b * xs.len() + a] = lo;
        }
    }
    let (nx, ny) = (xs.len(), ys.len());
    let bottom = f.bottom as f32;
    let node = |a: usize, b: usize| -> V { [xs[a].2, ys[b].2, z[b * nx + a]] };
    let foot = |a: usize, b: usize| -> V { [xs[a].2, ys[b].2, bottom] };
    let count = 2 * (nx - 1) * (ny - 1) + 4 * (nx - 1) + 4 * (ny - 1) + 2;
    let mut w = Writer::new(out, ascii, count)?;
    for b in 0..ny - 1 {
        for a in 0..nx - 1 {
            let (p, q, r, s) = (
                node(a, b),
                node(a + 1, b),
                node(a + 1, b + 1),
                node(a, b + 1),
            );
            w.tri(p, q, r)?;
            w.tri(p, r, s)?;
        }
    }
    // Walls, wound to face out: front (y min), back, left, right.
    for a in 0..nx - 1 {
        w.quad(foot(a, 0), foot(a + 1, 0), node(a + 1, 0), node(a, 0))?;
        let b = ny - 1;
        w.quad(foot(a + 1, b), foot(a, b), node(a, b), node(a + 1, b))?;
    }
    for b in 0..ny - 1 {
        w.quad(foot(0, b + 1), foot(0, b), node(0, b), node(0, b + 1))?;
        let a = nx - 1;
        w.quad(foot(a, b), foot(a, b + 1), node(a, b + 1), node(a, b))?;
    }
    w.quad(
        foot(0, 0),
        foot(0, ny - 1),
        foot(nx - 1, ny - 1),
        foot(nx - 1, 0),
    )?;
    w.finish()
}

struct Writer<'a, W: Write> {
    out: &'a mut W,
    ascii: bool,
}

impl<'a, W: Write> Writer<'a, W> {
    fn new(out: &'a mut W, ascii: bool, count: usize) -> io::Result<Self> {
        if ascii {
            writeln!(out, "solid cncc")?;
        } else {
            let mut header = [b' '; 80];
            let name = b"cncc simulate: the cut part";
            header[..name.len()].copy_from_slice(name);
            out.write_all(&header)?;
            out.write_all(&(count as u32).to_le_bytes())?;
        }
        Ok(Writer { out, ascii })
    }

    fn quad(&mut self, p: V, q: V, r: V, s: V) -> io::Result<()> {
        self.tri(p, q, r)?;
        self.tri(p, r, s)
    }

    fn tri(&mut self, p: V, q: V, r: V) -> io::Result<()> {
        let u = nalgebra::Vector3::new(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
        let v = nalgebra::Vector3::new(r[0] - p[0], r[1] - p[1], r[2] - p[2]);
        let n = u.cross(&v).try_normalize(1e-20).unwrap_or_default();
        if self.ascii {
            writeln!(self.out, "facet normal {} {} {}", n.x, n.y, n.z)?;
            writeln!(self.out, " outer loop")?;
            for c in [p, q, r] {
                writeln!(self.out, "  vertex {} {} {}", c[0], c[1], c[2])?;
            }
            return writeln!(self.out, " endloop\nendfacet");
        }
        for c in [[n.x, n.y, n.z], p, q, r] {
            for x in c {
                self.out.write_all(&x.to_le_bytes())?;
            }
        }
        self.out.write_all(&[0, 0])
    }

    fn finish(self) -> io::Result<()> {
        if self.ascii {
            writeln!(self.out, "endsolid cncc")?;
        }
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_closed_binary_mesh() {
        let s: crate::toolpath::Stock = "10x5x2".parse().unwrap();
        let f = HeightField::new(&s, 1.0).unwrap();
        let mut out = Vec::new();
        write(&f, false, &mut out).unwrap();
        let n = u32::from_le_bytes(out[80..84].try_into().unwrap()) as usize;
        assert_eq!(out.len(), 84 + 50 * n);
        assert_eq!(n, 2 * 9 * 4 + 4 * 9 + 4 * 4 + 2);
        let mut text = Vec::new();
        write(&f, true, &mut text).unwrap();
        let text = String::from_utf8(text).unwrap();
        assert_eq!(text.matches("facet normal").count(), n);
    }

    #[test]
    fn large_fields_are_thinned() {
        let nodes = axis(2500, 0.0, 0.1);
        assert!(nodes.len() <= MAX_NODES);
        assert_eq!(nodes.last().unwrap().1, 2500);
    }
}
