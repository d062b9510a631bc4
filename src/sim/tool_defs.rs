//! Tool sizes a Klartext program gives itself: `TOOL DEF n L.. R..` in
//! its head, with plain numbers. The interpreter reads them as it runs,
//! but the simulation takes its cutters before the run, so they are read
//! here from the head's statements (as the blank is, see
//! [`crate::toolpath::Stock::from_program`]) into a copy of the tool
//! table; the run's own table is left as it is.

use crate::dialect::DialectSpec;
use crate::interp::tooltable::{Tool, ToolTable};
use crate::ir::{LengthUnit, StmtKind, ToolRef};
use crate::span::FileId;

/// `(tool, radius in mm)` of each `TOOL DEF` with a number and a radius.
pub fn tool_defs(head: &str, spec: &DialectSpec) -> Vec<(i64, f64)> {
    let mut scale = 1.0;
    let mut out = Vec::new();
    let mut input = head.as_bytes();
    let _ = crate::driver::check_stream_flagged(&mut input, FileId::default(), spec, |b, _, _| {
        for s in &b.stmts {
            match &s.kind {
                StmtKind::Units { unit, .. } => {
                    scale = match unit {
                        LengthUnit::Mm => 1.0,
                        LengthUnit::Inch => 25.4,
                    }
                }
                StmtKind::ToolDef {
                    tool: ToolRef::Number(n),
                    radius: Some(r),
                    ..
                } => {
                    let n = n.number().map(|d| d.to_f64());
                    let r = r.number().map(|d| d.to_f64() * scale);
                    if let (Some(n), Some(r)) = (n, r) {
                        if n.fract() == 0.0 && n > 0.0 && r.is_finite() {
                            out.push((n as i64, r.abs()));
                        }
                    }
                }
                _ => {}
            }
        }
    });
    out
}

/// `table` with the head's `TOOL DEF` radii (`mm` millimetres per table
/// unit); the tools so sized count as given by the program.
pub fn with_tool_defs(table: &ToolTable, head: &str, spec: &DialectSpec, mm: f64) -> ToolTable {
    let mut t = table.clone();
    for (n, r) in tool_defs(head, spec) {
        let d = 2.0 * r / mm;
        match t.tools.iter_mut().find(|x| x.number == n) {
            Some(x) => {
                x.diameter = d;
                // A built-in row's description is not this tool's.
                if table.invented && !table.from_program.contains(&n) {
                    x.comment.clear();
                }
            }
            None => {
                let mut x = Tool::blank(n, String::new());
                x.diameter = d;
                t.tools.push(x);
            }
        }
        t.from_program.insert(n);
    }
    t
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tool_def_radii_are_read() {
        let spec = crate::dialect::builtin::builtin("heidenhain").unwrap();
        let head = "0 BEGIN PGM P INCH\n1 TOOL DEF 3 L+0 R+0.25\n2 TOOL DEF 4 L+10\n3 TOOL DEF 5 L+0 R+Q1\n4 TOOL CALL 3 Z S1000\n";
        assert_eq!(tool_defs(head, &spec), vec![(3, 6.35)]);
        let t = with_tool_defs(&ToolTable::builtin(), head, &spec, 1.0);
        assert_eq!(t.get(3).unwrap().diameter, 12.7);
        assert!(t.from_program.contains(&3));
    }
}
