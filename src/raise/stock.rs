//! The stock (raw piece) given on the command line: `--stock LxWxH[+X+Y+Z]`.
//!
//! `L`, `W`, `H` are the block's sizes along X, Y and Z in millimetres.
//! The optional tail gives the block's lowest corner (minimum X, Y, Z) in
//! work coordinates, each number with its sign (`+0+0-30`, `-60-40-25`).
//! Without it, the block sits with its top face at Z0 and its lowest
//! corner at X0 Y0 (corner `+0+0-H`), the usual "zero on the top-left
//! corner of the part" set-up. `x` and `X` both separate the sizes.
//!
//! Without `--stock` the program may say it: a Heidenhain blank
//! `BLK FORM 0.1 Z X.. Y.. Z..` (minimum point) with `BLK FORM 0.2 X.. Y..
//! Z..` (maximum point, absolute or `IX..` from the minimum) gives the
//! stock ([`Stock::from_program`]). It is read from the IR statements of
//! the program's head (the controller wants the blank right after
//! `BEGIN PGM`), not from the run: the blank moves nothing, so the
//! interpreter passes it by.

use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::{Axes, DimMode, LengthUnit, StmtKind, StockCorner};
use crate::span::{FileId, Span};
use crate::toolpath::P3;
use std::io::{BufRead, Read};

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

/// How much of a program's text is searched for its blank: the head,
/// where `BLK FORM` stands (bounded, so large CAM files are not read twice).
pub const HEAD_BYTES: u64 = 64 * 1024;

impl Stock {
    /// The blank the program's head gives (see the module doc), with a
    /// W0580 warning for a `BLK FORM` that cannot be taken. `None` without
    /// any `BLK FORM` (every dialect but Heidenhain).
    pub fn from_program(
        input: impl Read,
        file: FileId,
        spec: &DialectSpec,
    ) -> (Option<Stock>, Vec<Diagnostic>) {
        let mut reader = std::io::BufReader::new(input.take(HEAD_BYTES));
        from_head(&mut reader, file, spec)
    }
}

/// The corners read so far, mm.
#[derive(Default)]
struct Blank {
    scale: f64,
    min: Option<(P3, Span)>,
    max: Option<(Axes, Span)>,
    bad: Option<(Span, &'static str)>,
}

fn from_head(
    input: &mut impl BufRead,
    file: FileId,
    spec: &DialectSpec,
) -> (Option<Stock>, Vec<Diagnostic>) {
    let mut blank = Blank {
        scale: 1.0,
        ..Blank::default()
    };
    let read = crate::driver::check_stream_flagged(input, file, spec, |block, _, _| {
        for st in &block.stmts {
            blank.statement(&st.kind, st.span);
        }
    });
    if read.is_err() {
        return (None, Vec::new());
    }
    blank.finish()
}

impl Blank {
    fn statement(&mut self, kind: &StmtKind, span: Span) {
        match kind {
            StmtKind::Units { unit, .. } => {
                self.scale = match unit {
                    LengthUnit::Mm => 1.0,
                    LengthUnit::Inch => 25.4,
                }
            }
            StmtKind::Stock {
                corner: StockCorner::Min,
                axes,
                ..
            } => match absolute_point(axes) {
                Some(p) => self.min = Some((p.map(|v| v * self.scale), span)),
                None => self.fail(span, "BLK FORM 0.1 needs X, Y and Z as absolute numbers"),
            },
            StmtKind::Stock {
                corner: StockCorner::Max,
                axes,
                ..
            } => self.max = Some(((**axes).clone(), span)),
            _ => {}
        }
    }

    fn fail(&mut self, span: Span, why: &'static str) {
        self.bad.get_or_insert((span, why));
    }

    fn finish(mut self) -> (Option<Stock>, Vec<Diagnostic>) {
        if self.bad.is_none() {
            match (self.min, &self.max) {
                (None, None) => return (None, Vec::new()),
                (Some((min, _)), Some((axes, span))) => match max_point(axes, min, self.scale) {
                    Some(max) if (0..3).all(|i| max[i] > min[i]) => {
                        let size = [max[0] - min[0], max[1] - min[1], max[2] - min[2]];
                        return (Some(Stock { corner: min, size }), Vec::new());
                    }
                    Some(_) => self.fail(
                        *span,
                        "BLK FORM 0.2 must lie above BLK FORM 0.1 on X, Y and Z",
                    ),
                    None => self.fail(*span, "BLK FORM 0.2 needs X, Y and Z as numbers"),
                },
                (Some((_, span)), None) => self.fail(span, "BLK FORM 0.1 without BLK FORM 0.2"),
                (None, Some((_, span))) => self.fail(*span, "BLK FORM 0.2 without BLK FORM 0.1"),
            }
        }
        let (span, why) = self.bad.expect("set above");
        let d = Diagnostic::new(Code::BlankNotRead, format!("{why}: the blank is not taken as the stock"))
            .primary(span, why)
            .help("give BLK FORM 0.1 Z X.. Y.. Z.. and BLK FORM 0.2 X.. Y.. Z.. with numbers, or --stock LxWxH+X+Y+Z");
        (None, vec![d])
    }
}

/// X, Y, Z as plain absolute numbers.
fn absolute_point(axes: &Axes) -> Option<P3> {
    let mut p = [0.0; 3];
    for (slot, c) in p.iter_mut().zip([&axes.x, &axes.y, &axes.z]) {
        let c = c.as_ref()?;
        if c.dim == Some(DimMode::Incremental) {
            return None;
        }
        *slot = c.value.number()?.to_f64();
    }
    Some(p)
}

/// The maximum point: each axis absolute or incremental from `min` (mm).
fn max_point(axes: &Axes, min: P3, scale: f64) -> Option<P3> {
    let mut p = [0.0; 3];
    for (i, c) in [&axes.x, &axes.y, &axes.z].into_iter().enumerate() {
        let c = c.as_ref()?;
        let v = c.value.number()?.to_f64() * scale;
        p[i] = match c.dim {
            Some(DimMode::Incremental) => min[i] + v,
            _ => v,
        };
    }
    Some(p)
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

    fn blank(text: &str) -> (Option<Stock>, Vec<Diagnostic>) {
        let spec = crate::dialect::builtin::builtin("heidenhain").unwrap();
        Stock::from_program(text.as_bytes(), FileId::default(), &spec)
    }

    #[test]
    fn blk_form_gives_the_stock() {
        let (s, d) = blank(
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X-50 Y-40 Z-30\n2 BLK FORM 0.2 IX+100 Y+40 IZ+30\n3 END PGM P MM\n",
        );
        assert!(d.is_empty(), "{d:?}");
        let s = s.unwrap();
        assert_eq!(
            (s.corner, s.size),
            ([-50.0, -40.0, -30.0], [100.0, 80.0, 30.0])
        );
        let (s, _) = blank(
            "0 BEGIN PGM P INCH\n1 BLK FORM 0.1 Z X+0 Y+0 Z-1\n2 BLK FORM 0.2 X+4 Y+2 Z+0\n3 END PGM P INCH\n",
        );
        assert_eq!(s.unwrap().size, [101.6, 50.8, 25.4]);
        assert_eq!(blank("0 BEGIN PGM P MM\n1 L X+0 FMAX\n").0, None);
    }

    #[test]
    fn a_blank_that_cannot_be_taken_is_reported() {
        for text in [
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n",
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+50\n",
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n2 BLK FORM 0.2 X+100 Y+50 Z-30\n",
            "0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z+Q1\n2 BLK FORM 0.2 X+100 Y+50 Z+0\n",
        ] {
            let (s, d) = blank(text);
            assert_eq!(s, None, "{text}");
            assert_eq!(d.len(), 1, "{text}");
            assert_eq!(d[0].code.code(), "W0580");
        }
    }
}
