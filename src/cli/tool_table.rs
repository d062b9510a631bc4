//! Loading `--tool-table` for the commands that raise a program to
//! STEP-NC (`stepnc`, `port --features`): the table, its diagnostics, and
//! a warning when a table read in inches holds sizes that look metric.

use crate::cli::context::{Context, Failure};
use crate::diag::{Code, Diagnostic};
use crate::interp::tooltable::ToolTable;
use crate::ir::LengthUnit;
use crate::span::{FileId, Span};
use std::path::Path;

/// A tool wider than this, in mm, is taken as a sign of a unit mix-up.
const IMPLAUSIBLE_MM: f64 = 300.0;

/// Reads and parses the table; `units` are the machine units it is read in.
pub fn load(
    ctx: &mut Context,
    path: &Path,
    units: LengthUnit,
) -> Result<(ToolTable, Vec<Diagnostic>), Failure> {
    let (id, text) = ctx.add_side_file(path)?;
    let (table, mut diags) = ToolTable::parse(&text, id);
    if units == LengthUnit::Inch {
        diags.extend(looks_metric(&table, &text, id));
    }
    Ok((table, diags))
}

/// W0864 at the first tool whose diameter, read in inches, is over
/// [`IMPLAUSIBLE_MM`].
fn looks_metric(table: &ToolTable, text: &str, id: FileId) -> Option<Diagnostic> {
    let big = table
        .tools
        .iter()
        .find(|t| t.diameter * 25.4 > IMPLAUSIBLE_MM)?;
    let span = line_of_tool(text, big.number)
        .map(|(start, end)| Span::new(id, start, end))
        .unwrap_or_else(|| Span::new(id, 0, 0));
    let mm = big.diameter * 25.4;
    Some(
        Diagnostic::new(
            Code::RaiseTableLooksMetric,
            format!(
                "tool {} is {mm:.1} mm across when its D{} is read in inches",
                big.number, big.diameter
            ),
        )
        .primary(span, "read in inches (the machine units)")
        .help("if the table is in millimetres, pass `--machine-units mm`"),
    )
}

/// Byte range of the line that defines tool `number` (`T<number> ...`).
fn line_of_tool(text: &str, number: i64) -> Option<(usize, usize)> {
    let mut start = 0;
    for line in text.split_inclusive('\n') {
        let body = line.trim_end_matches(['\n', '\r']);
        let word = body.trim_start().split_whitespace().next().unwrap_or("");
        let n = word
            .strip_prefix(['T', 't'])
            .and_then(|n| n.parse::<i64>().ok());
        if n == Some(number) {
            let lead = body.len() - body.trim_start().len();
            return Some((start + lead, start + body.len()));
        }
        start += line.len();
    }
    None
}
