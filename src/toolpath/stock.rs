//! The stock (raw piece) as the command line gives it:
//! `--stock LxWxH[+X+Y+Z]`.
//!
//! `L`, `W`, `H` are the sizes along X, Y and Z in millimetres; the
//! optional `+X+Y+Z` (each written `+n` or `-n`) is the stock's lowest
//! corner in work coordinates. Without it the stock lies in the +X +Y
//! quadrant with its top at Z0 (corner at `0, 0, -H`), the usual setup
//! of a program that faces the top at Z0. Examples: `100x50x20`,
//! `100x50x20-50-25-20` (centred on X0 Y0), `4x2x1+0+0-1`.

use crate::toolpath::P3;

/// A block of stock: its lowest corner and its size (mm).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Stock {
    pub corner: P3,
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
        text.parse()
    }
}

impl std::str::FromStr for Stock {
    type Err = String;

    fn from_str(s: &str) -> Result<Stock, String> {
        let bad =
            |why: &str| format!("stock `{s}`: {why}; write LxWxH[+X+Y+Z], e.g. 100x50x20-50-25-20");
        let s = s.trim();
        // The sizes end where the first sign after them starts.
        let split = s
            .char_indices()
            .skip(1)
            .find(|&(_, c)| c == '+' || c == '-')
            .map(|(i, _)| i)
            .unwrap_or(s.len());
        let (sizes, corner) = s.split_at(split);
        let size: Vec<f64> = sizes
            .split(['x', 'X', '*'])
            .map(|v| v.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .map_err(|_| bad("the sizes are not numbers"))?;
        if size.len() != 3 {
            return Err(bad("three sizes are needed"));
        }
        if size.iter().any(|v| !v.is_finite() || *v <= 0.0) {
            return Err(bad("sizes must be positive"));
        }
        let size = [size[0], size[1], size[2]];
        let corner = if corner.is_empty() {
            [0.0, 0.0, -size[2]]
        } else {
            parse_corner(corner).ok_or_else(|| bad("the corner is not three signed numbers"))?
        };
        Ok(Stock { corner, size })
    }
}

/// `+X+Y+Z` with signs as separators.
fn parse_corner(s: &str) -> Option<P3> {
    let mut parts = Vec::new();
    let mut start = 0;
    for (i, c) in s.char_indices().skip(1) {
        if (c == '+' || c == '-') && !s[..i].ends_with(['e', 'E']) {
            parts.push(&s[start..i]);
            start = i;
        }
    }
    parts.push(&s[start..]);
    if parts.len() != 3 || !parts.iter().all(|p| p.starts_with(['+', '-'])) {
        return None;
    }
    let v: Vec<f64> = parts
        .iter()
        .map(|p| p.parse::<f64>())
        .collect::<Result<_, _>>()
        .ok()?;
    v.iter().all(|x| x.is_finite()).then(|| [v[0], v[1], v[2]])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_and_corners() {
        let s: Stock = "100x50x20".parse().unwrap();
        assert_eq!(s.corner, [0.0, 0.0, -20.0]);
        assert_eq!(s.max(), [100.0, 50.0, 0.0]);
        let s: Stock = "100x50x20-50-25-20".parse().unwrap();
        assert_eq!(s.corner, [-50.0, -25.0, -20.0]);
        let s: Stock = "4.5x2x1+0+0.5-1".parse().unwrap();
        assert_eq!((s.size, s.corner), ([4.5, 2.0, 1.0], [0.0, 0.5, -1.0]));
    }

    #[test]
    fn mistakes_are_refused() {
        for bad in [
            "",
            "100x50",
            "100x50x0",
            "axbxc",
            "100x50x20+1+2",
            "100x50x20+1+2+z",
        ] {
            assert!(bad.parse::<Stock>().is_err(), "{bad}");
        }
    }
}
