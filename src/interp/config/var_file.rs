//! LinuxCNC's parameter file (`.var`, rs274 `-v`, `[RS274NGC]
//! PARAMETER_FILE`): the numbered parameters that outlive a run, one
//! `NUMBER VALUE` line each, numbers ascending.
//!
//! Read as rs274 2.9 reads it (checked with the installed rs274): a line
//! whose first two words are not an integer and a number is skipped
//! (W0593 here), anything after them is ignored; a number outside
//! 1..=5601 or not above the line before stops rs274 before the run
//! ("Parameter number out of range", "Parameter file out of order": E0593
//! here). Every parameter the file gives is loaded, not only the
//! persistent ones.
//!
//! Written as rs274 writes it when it exits, after an error too: every
//! number the file had, and the persistent ones ([`PERSISTENT`]) whether
//! it had them or not, ascending, as `NUMBER<TAB>VALUE` with six decimals.
//! rs274 keeps the old file as `NAME.bak`; cncc writes a temporary file
//! beside it and renames it over the old one (`cli::atomic`), so the file
//! is whole or unchanged.

use crate::diag::{Code, Diagnostic};
use crate::span::{FileId, Span};
use std::collections::BTreeMap;

/// The largest parameter number rs274 has (RS274NGC_MAX_PARAMETERS - 1).
pub const MAX_PARAMETER: u32 = 5601;

/// The parameters rs274 writes whether the file had them or not: G28 and
/// G30 positions (#5161-#5169, #5181-#5189), the G92 flag and offsets
/// (#5210-#5219), the active work offset (#5220) and the nine work offsets
/// with their rotations (#5221-#5230 ... #5381-#5390).
pub fn persistent() -> impl Iterator<Item = u32> {
    let work = (0..9).flat_map(|k| (5221 + 20 * k)..=(5230 + 20 * k));
    (5161..=5169)
        .chain(5181..=5189)
        .chain(5210..=5220)
        .chain(work)
}

/// A parameter file as read.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct VarFile {
    /// Every parameter the file gives.
    pub values: BTreeMap<u32, f64>,
}

impl VarFile {
    /// Reads `text` (file `id`). An error (E0593) means rs274 would not
    /// start; skipped lines are warnings.
    pub fn parse(text: &str, id: FileId) -> (VarFile, Vec<Diagnostic>) {
        let mut file = VarFile::default();
        let mut diags = Vec::new();
        let mut last: Option<u32> = None;
        let mut at = 0;
        for raw in text.split_inclusive('\n') {
            let line = raw.trim_end_matches(['\n', '\r']);
            let start = at;
            at += raw.len();
            let body = line.trim();
            if body.is_empty() {
                continue;
            }
            let lead = line.len() - line.trim_start().len();
            let span = Span::new(id, start + lead, start + lead + body.len());
            let mut words = body.split_whitespace();
            let number = words.next().and_then(|w| w.parse::<i64>().ok());
            let value = words
                .next()
                .and_then(|w| w.parse::<f64>().ok())
                .filter(|v| v.is_finite());
            let (Some(number), Some(value)) = (number, value) else {
                diags.push(
                    Diagnostic::new(
                        Code::ParameterLineSkipped,
                        "a parameter file line that is not `NUMBER VALUE`: LinuxCNC skips it",
                    )
                    .primary(span, "skipped")
                    .help("each line of a .var file is a parameter number and its value, e.g. `5221 10.000000`"),
                );
                continue;
            };
            if !(1..=MAX_PARAMETER as i64).contains(&number) {
                diags.push(bad_file(
                    span,
                    format!("parameter number {number} out of range"),
                    format!("parameter numbers run from 1 to {MAX_PARAMETER}"),
                ));
                break;
            }
            let number = number as u32;
            if last.is_some_and(|l| number <= l) {
                diags.push(bad_file(
                    span,
                    format!(
                        "parameter file out of order: #{number} after #{}",
                        last.unwrap_or(0)
                    ),
                    "rs274 reads the numbers in ascending order, each once: sort the lines".into(),
                ));
                break;
            }
            last = Some(number);
            file.values.insert(number, value);
        }
        (file, diags)
    }
}

fn bad_file(span: Span, msg: String, help: String) -> Diagnostic {
    Diagnostic::new(Code::BadParameterFile, msg)
        .primary(span, "here")
        .note("rs274 does not start with this file")
        .help(help)
}

/// The text rs274 writes: the file's numbers and the persistent ones,
/// ascending, each with its value from `value`.
pub fn render(listed: &BTreeMap<u32, f64>, value: impl Fn(u32) -> f64) -> String {
    let mut numbers: Vec<u32> = listed.keys().copied().chain(persistent()).collect();
    numbers.sort_unstable();
    numbers.dedup();
    let mut out = String::new();
    for n in numbers {
        let v = value(n);
        // rs274 prints `%f`: a negative zero stays "-0.000000" [?].
        out.push_str(&format!("{n}\t{v:.6}\n"));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_as_rs274_reads() {
        let (f, d) = VarFile::parse(
            "31\t7.5\n100 2 trailing\nhello\n5161 x\n5221 3\n",
            FileId(0),
        );
        assert_eq!(f.values.len(), 3);
        assert_eq!(f.values[&5221], 3.0);
        assert_eq!(d.len(), 2);
        assert!(d.iter().all(|d| d.code == Code::ParameterLineSkipped));
    }

    #[test]
    fn out_of_order_and_out_of_range_are_errors() {
        for t in ["5221 3\n5161 1\n", "5161 1\n5161 2\n", "0 5\n", "5602 1\n"] {
            let (_, d) = VarFile::parse(t, FileId(0));
            assert_eq!(d.len(), 1, "{t}");
            assert_eq!(d[0].code, Code::BadParameterFile, "{t}");
        }
        assert!(VarFile::parse("5601 1\n", FileId(0)).1.is_empty());
    }

    #[test]
    fn renders_the_file_and_the_persistent_numbers() {
        let listed: BTreeMap<u32, f64> = [(31, 1.0), (5390, 0.0)].into();
        let text = render(&listed, |n| if n == 31 { 9.0 } else { 0.0 });
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines[0], "31\t9.000000");
        assert_eq!(lines[1], "5161\t0.000000");
        assert_eq!(lines.len(), 1 + 9 + 9 + 11 + 90);
        assert_eq!(*lines.last().unwrap(), "5390\t0.000000");
    }
}
