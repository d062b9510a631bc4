//! Test helpers: hand-made lines and Fanuc-, LinuxCNC- and Siemens-like
//! dialect specs, standing in for the real front ends and spec files.

use crate::dialect::{
    AddressDef, Capability, CodeDef, DialectSpec, Family, IntegerLengths, Meaning, NumberRules,
};
use crate::ir::{Arena, Decimal, DwellUnit, Expr, ExprKind, Value, Var};
use crate::span::{FileId, Span, Spanned};
use crate::syntax::{Item, LineSyntax, WordSyntax};

/// One code: `def('G', "83", "cycle", "cycle.peck", "Q", "")`; `requires`
/// lists alternatives with `|` and entries with `,`.
pub fn def(
    letter: char,
    code: &str,
    group: &str,
    meaning: &str,
    requires: &str,
    uses: &str,
) -> CodeDef {
    CodeDef {
        letter,
        code: Decimal::parse(code).unwrap(),
        group: group.into(),
        meaning: Meaning::parse(meaning).unwrap_or_else(|| panic!("meaning {meaning}")),
        requires: requires
            .split(',')
            .filter(|s| !s.is_empty())
            .map(|alt| alt.split('|').map(|s| s.chars().next().unwrap()).collect())
            .collect(),
        uses: uses.chars().collect(),
        dwell_units: Vec::new(),
        preferred: false,
        run: Default::default(),
        shift: None,
        first_index: None,
        doc: String::new(),
        span: Span::default(),
    }
}

fn rules(integer_lengths: IntegerLengths) -> NumberRules {
    NumberRules {
        integer_lengths,
        increment_mm: Decimal::parse("0.001").unwrap(),
        increment_inch: Decimal::parse("0.0001").unwrap(),
        length_places_mm: 3,
        length_places_inch: 4,
        point_on_lengths: true,
        feed_places: 1,
        angle_places: 3,
        integer_digits: 8,
    }
}

fn addresses(spec: &mut DialectSpec, lengths: &str, others: &str) {
    for c in lengths.chars() {
        spec.addresses.push(AddressDef {
            letter: c,
            role: "length".into(),
            length: true,
        });
    }
    for c in others.chars() {
        spec.addresses.push(AddressDef {
            letter: c,
            role: "other".into(),
            length: false,
        });
    }
}

fn common_codes(group_cycle: &str) -> Vec<CodeDef> {
    let mut dwell = def('G', "4", "non-modal", "dwell", "", "");
    dwell.dwell_units = vec![('P', DwellUnit::Milliseconds), ('X', DwellUnit::Seconds)];
    vec![
        def('G', "0", "motion", "motion.rapid", "", ""),
        def('G', "1", "motion", "motion.linear", "", ""),
        def('G', "2", "motion", "motion.arc-cw", "", ""),
        def('G', "3", "motion", "motion.arc-ccw", "", ""),
        dwell,
        def('G', "10", "non-modal", "set-data", "L", "LPRQ"),
        def('G', "17", "plane", "plane.xy", "", ""),
        def('G', "20", "units", "units.inch", "", ""),
        def('G', "21", "units", "units.mm", "", ""),
        def('G', "28", "non-modal", "ref-return.1", "", ""),
        def('G', "41", "radius-comp", "radius-comp.left", "", "D"),
        def('G', "43", "length-comp", "length-comp.positive", "", "H"),
        def('G', "54", "work-offset", "work-offset.1", "", ""),
        def('G', "80", group_cycle, "cycle.cancel", "", ""),
        def('G', "81", group_cycle, "cycle.drill", "", ""),
        def('G', "83", group_cycle, "cycle.peck", "Q", ""),
        def('G', "90", "distance", "distance.absolute", "", ""),
        def('G', "91", "distance", "distance.incremental", "", ""),
        def('G', "92", "non-modal", "coord-shift.set", "", ""),
        def('M', "0", "stop", "stop.program", "", ""),
        def('M', "3", "spindle", "spindle.cw", "", ""),
        def('M', "5", "spindle", "spindle.stop", "", ""),
        def('M', "6", "tool", "tool.change", "", ""),
        def('M', "8", "coolant", "coolant.flood", "", ""),
        def('M', "19", "spindle", "spindle.orient", "", "R"),
        def('M', "30", "stop", "stop.end-rewind", "", ""),
        def('M', "98", "", "sub.call", "", ""),
        def('M', "99", "", "sub.return", "", ""),
    ]
}

/// Fanuc-like: lengths without a point in increments, lenient words and M codes.
pub fn fanuc() -> DialectSpec {
    let mut s = DialectSpec::new(
        "fanuc".into(),
        "Fanuc-like".into(),
        Family::WordAddress,
        rules(IntegerLengths::Increments),
    );
    addresses(&mut s, "XYZABCUVWIJKRQ", "FSTDHPLNO");
    s.codes = common_codes("cycle");
    s.codes.extend([
        def('G', "54.1", "work-offset", "work-offset.extended", "", ""),
        def('G', "65", "non-modal", "macro.call", "", ""),
        def('G', "68", "rotation", "rotate.on", "", ""),
        def('G', "69", "rotation", "rotate.off", "", ""),
        def('M', "97", "", "sub.local-call", "", ""),
    ]);
    s.capabilities = [
        Capability::MacroB,
        Capability::NumberedPrograms,
        Capability::LocalSubprogramCall,
    ]
    .into();
    s.reindex();
    s
}

/// LinuxCNC-like: strict M codes and words, G80 in the motion group.
pub fn linuxcnc() -> DialectSpec {
    let mut s = DialectSpec::new(
        "linuxcnc".into(),
        "LinuxCNC-like".into(),
        Family::WordAddress,
        rules(IntegerLengths::Units),
    );
    addresses(&mut s, "XYZABCUVWIJKRQ", "FSTDHPLN");
    s.codes = common_codes("motion");
    s.codes
        .push(def('G', "64", "path", "path.continuous", "", "PQ"));
    s.capabilities = [
        Capability::StrictMCodes,
        Capability::StrictWords,
        Capability::ProgramEndRequired,
        Capability::OWords,
    ]
    .into();
    s.repeat_letter = 'L';
    s.reindex();
    s
}

/// Siemens-like: `D` is a cutting edge.
pub fn siemens() -> DialectSpec {
    let mut s = DialectSpec::new(
        "siemens840d".into(),
        "Siemens-like".into(),
        Family::Sinumerik,
        rules(IntegerLengths::Units),
    );
    addresses(&mut s, "XYZABCIJK", "FST");
    s.addresses.push(AddressDef {
        letter: 'D',
        role: "cutting-edge".into(),
        length: false,
    });
    s.codes = common_codes("motion");
    s.capabilities = [Capability::StructuredControl].into();
    s.reindex();
    s
}

/// A word token: `X10.5`, `CR=5`, `P#146`, `@2`.
fn word(tok: &str, span: Span, exprs: &mut Arena<Expr>) -> WordSyntax {
    let (address, value, extended) = match tok.split_once('=') {
        Some((a, v)) => (a.to_string(), v, true),
        None => {
            let n = tok
                .find(|c: char| !(c.is_ascii_alphabetic() || c == '@' || c == '^'))
                .unwrap_or(tok.len());
            (tok[..n].to_string(), &tok[n..], false)
        }
    };
    let value = match value.strip_prefix('#') {
        Some(n) => Value::Expr(exprs.alloc(Expr {
            kind: ExprKind::Var(Var::Numbered(n.parse().unwrap())),
            span,
        })),
        None => Value::Number(Decimal::parse(if value.is_empty() { "0" } else { value }).unwrap()),
    };
    let address_span = Span {
        end: span.start + address.len() as u32,
        ..span
    };
    WordSyntax {
        address: address.into(),
        value,
        dim: None,
        extended,
        span,
        address_span,
    }
}

/// Splits a line on spaces into words; `N10` becomes the line number.
pub fn line(text: &str, file: FileId, offset: u32, exprs: &mut Arena<Expr>) -> LineSyntax {
    let mut l = LineSyntax {
        span: Span::new(file, offset as usize, offset as usize + text.len()),
        skip: None,
        number: None,
        label: None,
        items: Vec::new(),
    };
    let mut pos = 0usize;
    for tok in text.split(' ') {
        let span = Span::new(
            file,
            offset as usize + pos,
            offset as usize + pos + tok.len(),
        );
        pos += tok.len() + 1;
        if tok.is_empty() {
            continue;
        }
        if let Some(n) = tok.strip_prefix('N').and_then(|n| n.parse().ok()) {
            l.number = Some(Spanned::new(n, span));
            continue;
        }
        l.items.push(Item::Word(word(tok, span, exprs)));
    }
    l
}
