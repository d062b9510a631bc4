//! The stock a program gives itself: a Heidenhain blank
//! `BLK FORM 0.1 Z X.. Y.. Z..` (minimum point) with `BLK FORM 0.2 X.. Y..
//! Z..` (maximum point, absolute or `IX..` from the minimum), used by
//! `cncc stepnc` when `--stock` is absent ([`Stock::from_program`]). It is
//! read from the IR statements of the program's head (the controller
//! wants the blank right after `BEGIN PGM`), not from the run: the blank
//! moves nothing, so the interpreter passes it by. A blank that cannot be
//! taken (incomplete, parameters, no volume) is a W0580 warning.

use super::Stock;
use crate::diag::{Code, Diagnostic};
use crate::dialect::DialectSpec;
use crate::ir::{Axes, DimMode, LengthUnit, StmtKind, StockCorner};
use crate::span::{FileId, Span};
use crate::toolpath::P3;
use std::io::{BufRead, Read};

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
        let mut head = Vec::new();
        if input.take(HEAD_BYTES).read_to_end(&mut head).is_err() {
            return (None, Vec::new());
        }
        if head.len() as u64 == HEAD_BYTES {
            // A line the limit cuts is not read: its numbers may be cut too.
            let whole = head.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
            head.truncate(whole);
        }
        from_head(&mut head.as_slice(), file, spec)
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

#[cfg(test)]
mod tests {
    use super::*;

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

    #[test]
    fn a_line_cut_by_the_head_limit_is_not_read() {
        let mut text = String::from("0 BEGIN PGM P MM\n1 BLK FORM 0.1 Z X+0 Y+0 Z-20\n");
        while text.len() < HEAD_BYTES as usize - 20 {
            text.push_str(";PADDING\n");
        }
        text.truncate(HEAD_BYTES as usize - 20);
        text.push_str("\n2 BLK FORM 0.2 X+100 Y+50 Z+15\n");
        let (s, d) = blank(&text);
        assert_eq!(s, None);
        assert_eq!(d.len(), 1, "0.1 without 0.2: {d:?}");
    }
}
