//! Tool lists that CAM posts write as comments at the top of a program,
//! read as tool data when no tool table gives the tool:
//!
//! - Fusion 360 / HSMWorks / Inventor CAM: `(T1 D=10. CR=0. - ZMIN=-5. - FLAT END MILL)`
//!   (`TAPER=118DEG`, `TAPER=90DEG` may follow CR);
//! - Mastercam: `(TOOL - 1 DIA. OFF. - 1 LEN. - 1 DIA. - 6.)`;
//! - a tool named with no size, `(T1001 - FACEMILL 63)`, as `cncc port`
//!   lists a tool called by name for a target whose tool table must hold
//!   every tool: it joins a table that lacks it, with no size.
//!
//! Sizes are in the program's units where the comment stands. A tool
//! table given with `--tool-table` wins for the tools it lists.

use super::state::MM_PER_INCH;
use super::tooltable::{Tool, ToolTable};
use crate::dialect::{DialectSpec, Meaning};
use crate::ir::LengthUnit;

/// One tool a header comment describes.
#[derive(Clone, Debug, PartialEq)]
pub struct HeaderTool {
    pub number: i64,
    pub diameter: f64,
    /// Corner radius, when the comment gives one.
    pub corner: Option<f64>,
    /// Point or taper angle, degrees (`TAPER=118DEG`), when given.
    pub taper: Option<f64>,
    /// What the comment calls it (`FLAT END MILL`).
    pub name: String,
}

/// The tool a comment describes, if it is a tool-list line.
pub fn parse(text: &str) -> Option<HeaderTool> {
    let t = text.trim();
    fusion(t).or_else(|| mastercam(t))
}

/// `T1 D=10. CR=0. - ZMIN=-5. - FLAT END MILL`
fn fusion(t: &str) -> Option<HeaderTool> {
    let rest = t.strip_prefix(['T', 't'])?;
    let digits = rest.find(|c: char| !c.is_ascii_digit())?;
    let number = rest[..digits].parse().ok()?;
    if !rest[digits..].starts_with(char::is_whitespace) {
        return None;
    }
    let mut words = rest[digits..].split_whitespace();
    let diameter = number_after(words.next()?, "D=")?;
    let corner = words.next().and_then(|w| number_after(w, "CR="));
    let taper = words
        .take_while(|w| *w != "-")
        .find_map(|w| number_after(w.trim_end_matches("DEG"), "TAPER="));
    let name = t.rsplit(" - ").next().unwrap_or("").trim().to_string();
    Some(HeaderTool {
        number,
        diameter,
        corner,
        taper,
        name,
    })
}

/// `TOOL - 1 DIA. OFF. - 1 LEN. - 1 DIA. - 6.`
fn mastercam(t: &str) -> Option<HeaderTool> {
    let upper = t.to_ascii_uppercase();
    let rest = upper.strip_prefix("TOOL")?.trim_start().strip_prefix('-')?;
    let number = rest.split_whitespace().next()?.parse().ok()?;
    let (_, dia) = upper.rsplit_once("DIA. -")?;
    let diameter = dia.split_whitespace().next()?.parse().ok()?;
    Some(HeaderTool {
        number,
        diameter,
        corner: None,
        taper: None,
        name: String::new(),
    })
}

fn number_after(word: &str, key: &str) -> Option<f64> {
    let v = word.strip_prefix(key)?;
    v.parse().ok()
}

/// Every tool a program's first lines list in comments, as written.
pub fn header_tools(head: &str) -> Vec<HeaderTool> {
    head.lines().flat_map(comments).filter_map(parse).collect()
}

/// The tools a program's first lines list in comments (a CAM header),
/// joined to `table` with their diameters in machine units, unless a real
/// tool table (not cncc's invented one) lists them already. Their numbers
/// go into `table.from_program`.
pub fn merge_header(table: &mut ToolTable, head: &str, machine: LengthUnit, spec: &DialectSpec) {
    let program = program_units(head, spec);
    for h in head.lines().flat_map(comments).filter_map(parse) {
        if h.number <= 0 || !(h.diameter.is_finite() && h.diameter >= 0.0) {
            continue;
        }
        if table.get(h.number).is_some() && !table.invented {
            continue;
        }
        let diameter = convert(h.diameter, program, machine);
        table.tools.retain(|t| t.number != h.number);
        let mut t = Tool::blank(h.number, h.name.clone());
        t.diameter = diameter;
        table.tools.push(t);
        table.from_program.insert(h.number);
    }
    for (number, name) in head.lines().flat_map(comments).filter_map(named) {
        if number > 0 && table.get(number).is_none() {
            table.tools.push(Tool::blank(number, name));
            table.named_only.insert(number);
        }
    }
}

/// `T1001 - FACEMILL 63`: a tool named with no size.
pub fn named(text: &str) -> Option<(i64, String)> {
    let rest = text.trim().strip_prefix(['T', 't'])?;
    let digits = rest.find(|c: char| !c.is_ascii_digit())?;
    let number = rest[..digits].parse().ok()?;
    let name = rest[digits..].strip_prefix(" - ")?.trim();
    (!name.is_empty()).then(|| (number, name.to_string()))
}

/// The tool-list line [`named`] reads, for tool `number` called `name`.
pub fn named_line(number: i64, name: &str) -> String {
    format!("T{number} - {}", name.trim())
}

/// The comments of one line: `( ... )` parts and what follows `;`.
fn comments(line: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = line;
    while let Some(open) = rest.find('(') {
        let Some(close) = rest[open..].find(')') else {
            break;
        };
        out.push(&rest[open + 1..open + close]);
        rest = &rest[open + close + 1..];
    }
    if let Some((_, c)) = line.split_once(';') {
        out.push(c);
    }
    out
}

/// The program's units, from its first G code whose meaning in `spec` is
/// a unit (G20/G21, Siemens G70/G71), or Klartext `BEGIN PGM .. INCH`;
/// millimetres when it says neither.
fn program_units(head: &str, spec: &DialectSpec) -> LengthUnit {
    for line in head.lines() {
        let code = line
            .split('(')
            .next()
            .unwrap_or("")
            .split(';')
            .next()
            .unwrap_or("");
        let upper = code.to_ascii_uppercase();
        if upper.contains("BEGIN PGM") {
            return if upper.contains("INCH") {
                LengthUnit::Inch
            } else {
                LengthUnit::Mm
            };
        }
        for w in upper
            .split(|c: char| !c.is_ascii_alphanumeric() && c != '.')
            .flat_map(g_words)
        {
            let code = w.get(1..).and_then(|n| crate::ir::Decimal::parse(n).ok());
            if let Some(Meaning::Units { unit, .. }) =
                code.and_then(|c| spec.code('G', c)).map(|c| c.meaning)
            {
                return unit;
            }
        }
    }
    LengthUnit::Mm
}

/// `G90G21G17` → `G90`, `G21`, `G17` (without leading zeros).
fn g_words(chunk: &str) -> Vec<&str> {
    chunk
        .match_indices('G')
        .map(|(i, _)| {
            let digits = chunk[i + 1..]
                .find(|c: char| !c.is_ascii_digit())
                .map_or(chunk.len(), |e| i + 1 + e);
            &chunk[i..digits]
        })
        .collect()
}

fn convert(v: f64, from: LengthUnit, to: LengthUnit) -> f64 {
    match (from, to) {
        (LengthUnit::Inch, LengthUnit::Mm) => v * MM_PER_INCH,
        (LengthUnit::Mm, LengthUnit::Inch) => v / MM_PER_INCH,
        _ => v,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_a_fusion_tool_line() {
        let t = parse("T1 D=0.25 CR=0. - ZMIN=-0.475 - FLAT END MILL").unwrap();
        assert_eq!((t.number, t.diameter, t.corner), (1, 0.25, Some(0.0)));
        assert_eq!(t.name, "FLAT END MILL");
        let t = parse("T2 D=0.0635 CR=0. TAPER=118DEG - ZMIN=-0.4521 - DRILL").unwrap();
        assert_eq!((t.number, t.diameter), (2, 0.0635));
        assert_eq!(t.taper, Some(118.0));
    }

    #[test]
    fn reads_a_mastercam_tool_line() {
        let t = parse("TOOL - 12 DIA. OFF. - 12 LEN. - 12 DIA. - 6.35").unwrap();
        assert_eq!((t.number, t.diameter), (12, 6.35));
    }

    fn fanuc() -> std::sync::Arc<DialectSpec> {
        crate::dialect::builtin("fanuc").unwrap()
    }

    #[test]
    fn a_header_fills_an_invented_table_in_the_programs_units() {
        let head = "O1000\n(T1 D=0.5 CR=0. - ZMIN=-1. - FLAT END MILL)\n(T23 D=0.25 CR=0. - TAP)\nG20 G90\n";
        let mut t = ToolTable::builtin();
        merge_header(&mut t, head, LengthUnit::Mm, &fanuc());
        assert!((t.get(1).unwrap().diameter - 12.7).abs() < 1e-9);
        assert!((t.get(23).unwrap().diameter - 6.35).abs() < 1e-9);
        assert!(t.from_program.contains(&23));
        let mut real = ToolTable::parse("T1 P1 D3.0 Z10 ;mine\n", crate::span::FileId(0)).0;
        merge_header(&mut real, head, LengthUnit::Mm, &fanuc());
        assert_eq!(real.get(1).unwrap().diameter, 3.0, "the shop's table wins");
    }

    #[test]
    fn a_tool_named_with_no_size_joins_a_table_that_lacks_it() {
        let head = "(T1001 - FACEMILL 63)\n(T2 - DRILL)\n(T1 D=0.5 CR=0. - ZMIN=-1. - END MILL)\n";
        assert_eq!(
            named(&named_line(1001, " FACEMILL 63")),
            Some((1001, "FACEMILL 63".into()))
        );
        let mut t = ToolTable::builtin();
        let before = t.get(2).unwrap().clone();
        merge_header(&mut t, head, LengthUnit::Mm, &fanuc());
        let new = t.get(1001).unwrap();
        assert_eq!((new.diameter, new.comment.as_str()), (0.0, "FACEMILL 63"));
        assert!(t.named_only.contains(&1001) && !t.from_program.contains(&1001));
        assert_eq!(t.get(2), Some(&before), "a listed tool keeps its row");
        assert_eq!(
            named("T1 D=0.5 CR=0. - ZMIN=-1. - END MILL").map(|n| n.0),
            None
        );
        assert_eq!(named("T5 -"), None);
    }

    #[test]
    fn other_comments_are_not_tools() {
        for c in ["T1 CHANGE", "TOOL CHANGE", "T= D=", "DRILL 6 MM", "T1D=5"] {
            assert_eq!(parse(c), None, "{c}");
        }
    }
}
