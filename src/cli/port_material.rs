//! `cncc port --verify --material` (without `--features`): after the move
//! comparison, both programs cut the same stock and the finished parts are
//! compared cell by cell ([`crate::sim::material`]): the largest
//! deviation, where it is and the move of each program that made it, and
//! the volume difference; within 0.01 mm the parts are the same.
//!
//! The stock is `--stock`, else the source's `BLK FORM`, else a box round
//! the feed moves of both programs (said in the output). The tools cut
//! with the shapes of the source's tool data (`--tool-table`, the CAM
//! tool list, else cncc's built-in table, whose sizes are invented: said
//! too); the port's tools are the source's renumbered by `--tool-map`.

use crate::cli::context::{Context, Failure};
use crate::diag::Diagnostic;
use crate::dialect::DialectSpec;
use crate::interp::Options;
use crate::port::ToolMap;
use crate::sim::material::{self, MaterialVerdict, Side};
use crate::sim::report::StockFrom;
use crate::sim::Cutters;
use crate::span::FileId;
use crate::toolpath::{Event, Stock};
use std::path::Path;

/// `--material` without `--features`: what the material proof is given.
pub struct MaterialArgs<'a> {
    pub tool_table: Option<&'a Path>,
    pub stock: Option<&'a str>,
}

/// What the material proof knows before the runs.
pub struct Proof {
    /// `--stock`, or the source's own blank.
    pub given: Option<(Stock, StockFrom)>,
    /// The source's tools.
    pub cutters: Cutters,
    /// The tools whose sizes cncc invented (its built-in table: no
    /// `--tool-table`, not in the program's tool list).
    pub invented: std::collections::BTreeSet<i64>,
}

/// Loads `--tool-table` into `options` (the runs use it too).
pub fn load_table(
    ctx: &mut Context,
    m: &MaterialArgs<'_>,
    options: &mut Options,
) -> Result<Vec<Diagnostic>, Failure> {
    crate::cli::stats::load_tool_table(ctx, m.tool_table, options)
}

impl Proof {
    /// The stock and the source's cutters, from the options and the
    /// source's text (its CAM tool list, its `BLK FORM`).
    pub fn new(
        m: &MaterialArgs<'_>,
        options: &Options,
        text: &str,
        id: FileId,
        spec: &DialectSpec,
        diags: &mut Vec<Diagnostic>,
    ) -> Result<Proof, Failure> {
        let given = match m.stock {
            Some(s) => Some((
                s.parse::<Stock>()
                    .map_err(|e| Failure(format!("--stock: {e}")))?,
                StockFrom::Option,
            )),
            None => {
                let (b, d) = Stock::from_program(text.as_bytes(), id, spec);
                diags.extend(d);
                b.map(|b| (b, StockFrom::Blank))
            }
        };
        let head = head_of(text);
        let opts = crate::cli::check::program_tools(options, head, spec);
        let mm = crate::cli::stats::machine_mm(&opts);
        let table = &crate::sim::tool_defs::with_tool_defs(&opts.tool_table, head, spec, mm);
        Ok(Proof {
            given,
            cutters: Cutters::from_table(table, head, mm, false),
            invented: table
                .tools
                .iter()
                .map(|t| t.number)
                .filter(|n| table.invented && !table.from_program.contains(n))
                .collect(),
        })
    }

    /// The port's cutters: the source's, renumbered by `map`.
    fn port_cutters(&self, map: &ToolMap) -> Cutters {
        let mut port = Cutters::default();
        // Renumbered tools last: they take the number from a table row.
        for renumbered in [false, true] {
            for (t, c) in &self.cutters.by_tool {
                if (map.map(*t) != *t) == renumbered {
                    port.by_tool.insert(map.map(*t), *c);
                }
            }
        }
        port
    }

    /// Cuts the stock with both runs and compares the parts.
    pub fn compare(
        &self,
        source: &[Event],
        port: &[Event],
        map: &ToolMap,
    ) -> Result<(MaterialVerdict, StockFrom), String> {
        let sides = [
            Side {
                events: source,
                cutters: self.cutters.clone(),
            },
            Side {
                events: port,
                cutters: self.port_cutters(map),
            },
        ];
        let given = self.given.map(|(s, _)| s);
        let from = self.given.map_or(StockFrom::Guessed, |(_, f)| f);
        let (stock, cell) = material::grid_for(&sides, given, None)?;
        let v = material::compare_runs(sides, &stock, cell, crate::sim::compare::TOLERANCE)?;
        Ok((v, from))
    }

    /// The proof, printed (`verify: material: ...`); a located E1002 in
    /// `diags` when the parts differ. True when they are the same.
    pub fn verify(
        &self,
        source: &[Event],
        port: &[Event],
        map: &ToolMap,
        diags: &mut Vec<Diagnostic>,
    ) -> bool {
        let (v, from) = match self.compare(source, port, map) {
            Ok(r) => r,
            Err(why) => {
                eprintln!("verify: material: not compared: {why}");
                return true;
            }
        };
        let stock = format!("stock: {}", from.says());
        let (_, tools) = material::feed_box(source);
        let sizes = if tools.iter().any(|t| self.invented.contains(t)) {
            "; tool sizes from cncc's built-in table where no tool data gives them (give --tool-table)"
        } else {
            ""
        };
        if v.same() {
            eprintln!(
                "verify: material: {}; {stock}{sizes}",
                material::summary(&v)
            );
            return true;
        }
        eprintln!(
            "verify: DIFFERENT by material: {}; {stock}{sizes}",
            material::summary(&v)
        );
        let mut d = material::diagnostic(&v);
        d.help = Some(
            "the port is not written; report the construct, or use --expand-cycles for cycles"
                .into(),
        );
        diags.push(d);
        false
    }
}

/// The program's first lines (where CAM tool lists stand).
pub(crate) fn head_of(text: &str) -> &str {
    let mut end = text.len().min(1 << 16);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    &text[..end]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::interp::flow::NoLoader;
    use crate::span::Span;
    use std::rc::Rc;

    const HEAD: &str = "(T1 D=10. CR=0. - FLAT END MILL)\nG21 G90 G17\nT1 M6\nS3000 M3\n";
    /// A ring round an island, and the same circle with its centre cleared.
    const RING: &str =
        "G0 X10. Y0.\nG0 Z1.\nG1 Z-5. F100.\nG3 X10. Y0. I-10. J0. F300.\nG0 Z5.\nM30\n";
    const FULL: &str =
        "G0 X0. Y0.\nG0 Z1.\nG1 Z-5. F100.\nG1 X10. F300.\nG3 X10. Y0. I-10. J0.\nG0 Z5.\nM30\n";

    fn run(text: &str, file: u32) -> Vec<Event> {
        let spec = crate::dialect::builtin::builtin("fanuc").unwrap();
        let (p, d) = crate::driver::read_program(text, FileId(file), &spec);
        assert!(!d.iter().any(Diagnostic::is_error), "{d:?}");
        let mut o = Options::default();
        o.machine_units = crate::ir::LengthUnit::Mm;
        let (ev, _) = crate::port::verify::events(Rc::new(p), &spec, &o, &mut NoLoader);
        ev
    }

    fn proof(stock: Option<&str>) -> Proof {
        let spec = crate::dialect::builtin::builtin("fanuc").unwrap();
        let mut o = Options::default();
        o.machine_units = crate::ir::LengthUnit::Mm;
        let m = MaterialArgs {
            tool_table: None,
            stock,
        };
        Proof::new(&m, &o, HEAD, FileId(0), &spec, &mut Vec::new()).unwrap()
    }

    fn line_of(text: &str, span: Span) -> &str {
        let start = text[..span.start as usize].rfind('\n').map_or(0, |k| k + 1);
        text[start..].lines().next().unwrap()
    }

    #[test]
    fn the_same_program_cuts_the_same_part() {
        let p = proof(Some("40x40x20-20-20-20"));
        assert_eq!(p.cutters.get(1).radius, 5.0);
        assert!(p.invented.is_empty() || !p.invented.contains(&1));
        let ring = run(&format!("{HEAD}{RING}"), 0);
        let again = run(&format!("{HEAD}{RING}"), 1);
        assert!(p.verify(&ring, &again, &ToolMap::default(), &mut Vec::new()));
    }

    #[test]
    fn a_ring_and_a_full_circle_differ_where_the_island_stands() {
        let full_text = format!("{HEAD}{FULL}");
        let ring = run(&format!("{HEAD}{RING}"), 0);
        let full = run(&full_text, 1);
        for stock in [Some("40x40x20-20-20-20"), None] {
            let p = proof(stock);
            let (v, from) = p.compare(&ring, &full, &ToolMap::default()).unwrap();
            assert_eq!(from == StockFrom::Guessed, stock.is_none());
            assert!(!v.same());
            assert!((v.comparison.largest - 5.0).abs() < 1e-6, "{v:?}");
            assert!(v.comparison.at[0].abs() < 5.0 && v.comparison.at[1].abs() < 5.0);
            // The ring never cut the island; the full circle's plunge did.
            assert_eq!(v.made[0], None);
            let (span, z) = v.made[1].expect("the port cut there");
            assert_eq!(span.file, FileId(1));
            assert_eq!(line_of(&full_text, span), "G1 Z-5. F100.");
            assert!((z + 5.0).abs() < 1e-6);
            let mut diags = Vec::new();
            assert!(!p.verify(&ring, &full, &ToolMap::default(), &mut diags));
            assert_eq!(diags.len(), 1);
            assert_eq!(diags[0].code.code(), "E1002");
        }
    }

    #[test]
    fn the_port_cuts_with_the_source_tool_it_was_renumbered_from() {
        let p = proof(Some("40x40x20-20-20-20"));
        let map = ToolMap::parse("1=7").unwrap();
        let ring = run(&format!("{HEAD}{RING}"), 0);
        let port = run(&format!("{}{RING}", HEAD.replace("T1 M6", "T7 M6")), 1);
        assert!(p.verify(&ring, &port, &map, &mut Vec::new()));
        assert!(!p.verify(&ring, &port, &ToolMap::default(), &mut Vec::new()));
    }
}
