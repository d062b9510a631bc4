//! Tool tables in LinuxCNC's `.tbl` format: one tool per line,
//! `T<tool> P<pocket> [X Y Z A B C U V W]<offset> D<diameter> [I J Q] ;comment`.
//! Numbers are in machine units (see [`crate::interp::Options::machine_units`]).

use crate::diag::{Code, Diagnostic};
use crate::span::{FileId, Span};

#[derive(Clone, Debug, PartialEq)]
pub struct Tool {
    pub number: i64,
    pub pocket: i64,
    /// Offsets X Y Z A B C U V W, machine units.
    pub offset: [f64; 9],
    pub diameter: f64,
    pub front_angle: f64,
    pub back_angle: f64,
    pub orientation: i64,
    pub comment: String,
}

impl Tool {
    /// Tool `number` in pocket `number`, with no offsets and no size.
    pub fn blank(number: i64, comment: String) -> Tool {
        Tool {
            number,
            pocket: number,
            offset: [0.0; 9],
            diameter: 0.0,
            front_angle: 0.0,
            back_angle: 0.0,
            orientation: 0,
            comment,
        }
    }
}

/// Tools in table order; the row (1-based) is what `CHANGE_TOOL` prints.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ToolTable {
    pub tools: Vec<Tool>,
    /// cncc's built-in table: its sizes are invented, not the shop's.
    pub invented: bool,
    /// Tools whose sizes the program itself gives (a CAM tool-list
    /// comment, TOOL DEF, $TC_DP): not invented.
    pub from_program: std::collections::BTreeSet<i64>,
    /// Tools the program lists by name only (`(T1001 - FACEMILL 63)`):
    /// in the table so the run goes on, with no size (W0592 says so).
    pub named_only: std::collections::BTreeSet<i64>,
}

/// The table used when none is given: tools 1 to 20, flat end mills and
/// drills of common inch sizes, lengths 1.1 to 3.0 in (machine units are
/// inches by default).
const BUILTIN: &str = "\
T1 P1 Z1.1 D0.0625 ;1/16 end mill
T2 P2 Z1.2 D0.125 ;1/8 end mill
T3 P3 Z1.3 D0.1875 ;3/16 end mill
T4 P4 Z1.4 D0.25 ;1/4 end mill
T5 P5 Z1.5 D0.3125 ;5/16 end mill
T6 P6 Z1.6 D0.375 ;3/8 end mill
T7 P7 Z1.7 D0.5 ;1/2 end mill
T8 P8 Z1.8 D0.625 ;5/8 end mill
T9 P9 Z1.9 D0.75 ;3/4 end mill
T10 P10 Z2.0 D1.0 ;1 in end mill
T11 P11 Z2.1 D0.201 ;#7 drill
T12 P12 Z2.2 D0.257 ;F drill
T13 P13 Z2.3 D0.136 ;#29 drill
T14 P14 Z2.4 D0.159 ;#21 drill
T15 P15 Z2.5 D0.25 ;1/4 drill
T16 P16 Z2.6 D0.5 ;1/2 drill
T17 P17 Z2.7 D0.125 ;1/8 ball end mill
T18 P18 Z2.8 D0.25 ;1/4 ball end mill
T19 P19 Z2.9 D0.5 ;spot drill
T20 P20 Z3.0 D0.5 ;chamfer mill
";

impl ToolTable {
    pub fn builtin() -> ToolTable {
        let mut t = ToolTable::parse(BUILTIN, FileId(0)).0;
        t.invented = true;
        t
    }

    /// Reads a table; lines that cannot be read are reported (LinuxCNC
    /// ignores them silently) and skipped.
    pub fn parse(text: &str, file: FileId) -> (ToolTable, Vec<Diagnostic>) {
        let mut table = ToolTable::default();
        let mut diags = Vec::new();
        let mut offset = 0usize;
        for raw in text.split_inclusive('\n') {
            let line = raw.trim_end_matches(['\n', '\r']);
            match parse_line(line) {
                Ok(Some(t)) => table.tools.push(t),
                Ok(None) => {}
                Err(msg) => diags.push(
                    Diagnostic::new(
                        Code::BadToolTable,
                        format!("tool table line not read: {msg}"),
                    )
                    .primary(Span::new(file, offset, offset + line.len()), "this line")
                    .help("write `T<tool> P<pocket> Z<length> D<diameter> ;comment`"),
                ),
            }
            offset += raw.len();
        }
        (table, diags)
    }

    /// The 1-based row of a tool number.
    pub fn row(&self, number: i64) -> Option<usize> {
        self.tools
            .iter()
            .position(|t| t.number == number)
            .map(|i| i + 1)
    }

    pub fn get(&self, number: i64) -> Option<&Tool> {
        self.tools.iter().find(|t| t.number == number)
    }
}

fn parse_line(line: &str) -> Result<Option<Tool>, String> {
    let (body, comment) = match line.find(';') {
        Some(i) => (&line[..i], line[i + 1..].trim().to_string()),
        None => (line, String::new()),
    };
    if body.trim().is_empty() {
        return Ok(None);
    }
    let mut t = Tool {
        pocket: 0,
        ..Tool::blank(-1, comment)
    };
    for word in body.split_whitespace() {
        let mut chars = word.chars();
        let letter = chars.next().unwrap_or(' ').to_ascii_uppercase();
        let value: f64 = chars
            .as_str()
            .parse()
            .map_err(|_| format!("`{word}` is not a letter and a number"))?;
        match letter {
            'T' => t.number = value as i64,
            'P' => t.pocket = value as i64,
            'D' => t.diameter = value,
            'I' => t.front_angle = value,
            'J' => t.back_angle = value,
            'Q' => t.orientation = value as i64,
            'X' | 'Y' | 'Z' | 'A' | 'B' | 'C' | 'U' | 'V' | 'W' => {
                let i = "XYZABCUVW".find(letter).unwrap_or(0);
                t.offset[i] = value;
            }
            _ => return Err(format!("unknown field `{letter}`")),
        }
    }
    if t.number < 0 {
        return Err("no T word".into());
    }
    Ok(Some(t))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_linuxcnc_tables() {
        let (t, d) = ToolTable::parse(
            "T7 P3 Z1.5 D0.25 ;a\n\nT3 P1 D.5 Z+0.1\nbad line\n",
            FileId(0),
        );
        assert_eq!(t.tools.len(), 2);
        assert_eq!(t.row(3), Some(2));
        assert_eq!(t.get(7).unwrap().offset[2], 1.5);
        assert_eq!(d.len(), 1);
        assert_eq!(ToolTable::builtin().tools.len(), 20);
    }
}
