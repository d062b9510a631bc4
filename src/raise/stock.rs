//! The stock (raw piece) given on the command line: `--stock LxWxH[+X+Y+Z]`.
//!
//! `L`, `W`, `H` are the block's sizes along X, Y and Z in millimetres.
//! The optional tail gives the block's lowest corner (minimum X, Y, Z) in
//! work coordinates, each number with its sign (`+0+0-30`, `-60-40-25`).
//! Without it, the block sits with its top face at Z0 and its lowest
//! corner at X0 Y0 (corner `+0+0-H`), the usual "zero on the top-left
//! corner of the part" set-up. `x` and `X` both separate the sizes.
//!
//! Without `--stock`, a Heidenhain `BLK FORM` gives it: see [`super::blank`].

use crate::toolpath::P3;

/// A rectangular block of stock, mm, work coordinates.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stock {
    /// The lowest corner (minimum X, Y, Z).
    pub corner: P3,
    /// Sizes along X, Y, Z (all positive).
    pub size: P3,
}

impl Stock {
    /// The highest corner.
    pub fn max(&self) -> P3 {
        [
            self.corner[0] + self.size[0],
            self.corner[1] + self.size[1],
            self.corner[2] + self.size[2],
        ]
    }

    /// The top face's Z.
    pub fn top(&self) -> f64 {
        self.corner[2] + self.size[2]
    }

    /// Reads `LxWxH[+X+Y+Z]`; the error says what is wrong.
    pub fn parse(text: &str) -> Result<Stock, String> {
        let t = text.trim();
        let split = t.find(['+', '-']).unwrap_or(t.len());
        let (sizes, corner) = t.split_at(split);
        let size = parse_sizes(sizes)?;
        let corner = if corner.is_empty() {
            [0.0, 0.0, -size[2]]
        } else {
            parse_corner(corner)?
        };
        Ok(Stock { corner, size })
    }
}

fn parse_sizes(text: &str) -> Result<P3, String> {
    let parts: Vec<&str> = text.split(['x', 'X']).collect();
    if parts.len() != 3 {
        return Err(format!(
            "`{text}` is not three sizes `LxWxH` (for example `120x80x30`)"
        ));
    }
    let mut size = [0.0; 3];
    for (slot, part) in size.iter_mut().zip(&parts) {
        let v: f64 = part
            .trim()
            .parse()
            .map_err(|_| format!("`{part}` is not a number"))?;
        if !(v.is_finite() && v > 0.0) {
            return Err(format!("the size `{part}` must be a positive number"));
        }
        *slot = v;
    }
    Ok(size)
}

/// `+X+Y+Z`: three signed numbers, each starting with its sign.
fn parse_corner(text: &str) -> Result<P3, String> {
    let mut starts: Vec<usize> = text
        .char_indices()
        .filter(|&(i, c)| (c == '+' || c == '-') && !text[..i].ends_with(['e', 'E']))
        .map(|(i, _)| i)
        .collect();
    if starts.len() != 3 {
        return Err(format!(
            "`{text}` is not three signed numbers `+X+Y+Z` (for example `+0+0-30`)"
        ));
    }
    starts.push(text.len());
    let mut corner = [0.0; 3];
    for (i, slot) in corner.iter_mut().enumerate() {
        let part = &text[starts[i]..starts[i + 1]];
        let v: f64 = part
            .parse()
            .map_err(|_| format!("`{part}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("`{part}` is not a finite number"));
        }
        *slot = v;
    }
    Ok(corner)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_with_and_without_a_corner() {
        let s = Stock::parse("120x80x30").unwrap();
        assert_eq!(s.size, [120.0, 80.0, 30.0]);
        assert_eq!(s.corner, [0.0, 0.0, -30.0]);
        assert_eq!(s.top(), 0.0);
        let s = Stock::parse("100X50.5X20-50+0-20").unwrap();
        assert_eq!(s.corner, [-50.0, 0.0, -20.0]);
        assert_eq!(s.max(), [50.0, 50.5, 0.0]);
    }

    #[test]
    fn bad_stock_is_explained() {
        assert!(Stock::parse("120x80").unwrap_err().contains("three sizes"));
        assert!(Stock::parse("120x0x30").unwrap_err().contains("positive"));
        assert!(Stock::parse("1x2x3+1+2")
            .unwrap_err()
            .contains("three signed"));
        assert!(Stock::parse("axbxc").is_err());
        assert!(Stock::parse("").is_err());
    }
}
