//! The stock (raw piece) given on the command line: `--stock LxWxH[+X+Y+Z]`
//! (the one parser is [`crate::toolpath::stock`], shared with `plot`).
//!
//! `L`, `W`, `H` are the block's sizes along X, Y and Z in millimetres.
//! The optional tail gives the block's lowest corner (minimum X, Y, Z) in
//! work coordinates, each number with its sign (`+0+0-30`, `-60-40-25`).
//! Without it, the block sits with its top face at Z0 and its lowest
//! corner at X0 Y0 (corner `+0+0-H`), the usual "zero on the top-left
//! corner of the part" set-up. `x` and `X` both separate the sizes.
//!
//! Without `--stock`, a Heidenhain `BLK FORM` gives it: see [`super::blank`].

pub use crate::toolpath::stock::Stock;

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
