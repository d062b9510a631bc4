//! Dialect specs built in code for the writer tests (the XML specs are
//! written elsewhere): the common codes of each dialect with their meanings.

use crate::dialect::{
    AddressDef, Capability as C, CodeDef, DialectSpec, Family, FunctionDef, IntegerLengths,
    Meaning, NumberRules,
};
use crate::ir::{Decimal, DwellUnit, Func};
use crate::span::Span;

fn d(s: &str) -> Decimal {
    Decimal::parse(s).unwrap()
}

fn code(spec: &str, meaning: &str) -> CodeDef {
    let letter = spec.chars().next().unwrap();
    CodeDef {
        letter,
        code: d(&spec[1..]),
        group: "test".into(),
        meaning: Meaning::parse(meaning).unwrap_or_else(|| panic!("meaning {meaning}")),
        requires: vec![],
        uses: vec![],
        dwell_units: vec![],
        preferred: false,
        run: Default::default(),
        shift: None,
        first_index: None,
        doc: String::new(),
        span: Span::default(),
    }
}

fn codes(list: &[(&str, &str)]) -> Vec<CodeDef> {
    list.iter().map(|(c, m)| code(c, m)).collect()
}

const WORD_COMMON: &[(&str, &str)] = &[
    ("G0", "motion.rapid"),
    ("G1", "motion.linear"),
    ("G2", "motion.arc-cw"),
    ("G3", "motion.arc-ccw"),
    ("G17", "plane.xy"),
    ("G18", "plane.zx"),
    ("G19", "plane.yz"),
    ("G20", "units.inch"),
    ("G21", "units.mm"),
    ("G28", "ref-return.1"),
    ("G30", "ref-return.2"),
    ("G40", "radius-comp.off"),
    ("G41", "radius-comp.left"),
    ("G42", "radius-comp.right"),
    ("G43", "length-comp.positive"),
    ("G49", "length-comp.cancel"),
    ("G52", "coord-shift.local"),
    ("G53", "machine-coords"),
    ("G54", "work-offset.1"),
    ("G55", "work-offset.2"),
    ("G56", "work-offset.3"),
    ("G57", "work-offset.4"),
    ("G58", "work-offset.5"),
    ("G59", "work-offset.6"),
    ("G61", "path.exact-stop"),
    ("G64", "path.continuous"),
    ("G73", "cycle.chip-break"),
    ("G80", "cycle.cancel"),
    ("G81", "cycle.drill"),
    ("G82", "cycle.drill-dwell"),
    ("G83", "cycle.peck"),
    ("G84", "cycle.tap"),
    ("G85", "cycle.bore-feed-out"),
    ("G86", "cycle.bore-stop-rapid-out"),
    ("G87", "cycle.back-bore"),
    ("G88", "cycle.bore-manual"),
    ("G89", "cycle.bore-dwell-feed-out"),
    ("G90", "distance.absolute"),
    ("G91", "distance.incremental"),
    ("G92", "coord-shift.set"),
    ("G93", "feed-mode.inverse-time"),
    ("G94", "feed-mode.per-minute"),
    ("G95", "feed-mode.per-revolution"),
    ("G96", "css.on"),
    ("G97", "css.off"),
    ("G98", "return.initial"),
    ("G99", "return.r-plane"),
    ("G10", "set-data"),
    ("M0", "stop.program"),
    ("M1", "stop.optional"),
    ("M2", "stop.end"),
    ("M3", "spindle.cw"),
    ("M4", "spindle.ccw"),
    ("M5", "spindle.stop"),
    ("M6", "tool.change"),
    ("M7", "coolant.mist"),
    ("M8", "coolant.flood"),
    ("M9", "coolant.off"),
    ("M19", "spindle.orient"),
    ("M30", "stop.end-rewind"),
    ("M98", "sub.call"),
    ("M99", "sub.return"),
];

const FANUC_ONLY: &[(&str, &str)] = &[
    ("G44", "length-comp.negative"),
    ("G50", "scale.off"),
    ("G51", "scale.on"),
    ("G50.1", "mirror.off"),
    ("G51.1", "mirror.on"),
    ("G54.1", "work-offset.extended"),
    ("G65", "macro.call"),
    ("G66", "macro.modal"),
    ("G67", "macro.cancel"),
    ("G68", "rotate.on"),
    ("G69", "rotate.off"),
    ("G74", "cycle.tap-left"),
    ("G76", "cycle.fine-bore"),
];

fn dwell(units: &[(char, DwellUnit)]) -> CodeDef {
    let mut c = code("G4", "dwell");
    c.dwell_units = units.to_vec();
    c
}

fn rules(increments: bool, places: (u8, u8), point: bool) -> NumberRules {
    NumberRules {
        integer_lengths: if increments {
            IntegerLengths::Increments
        } else {
            IntegerLengths::Units
        },
        increment_mm: d("0.001"),
        increment_inch: d("0.0001"),
        length_places_mm: places.0,
        length_places_inch: places.1,
        point_on_lengths: point,
        feed_places: 4,
        angle_places: 4,
        integer_digits: 8,
    }
}

fn functions(list: &[(&str, Func, usize)]) -> Vec<FunctionDef> {
    list.iter()
        .map(|(n, f, a)| FunctionDef {
            name: n.to_string(),
            func: *f,
            arity: *a,
        })
        .collect()
}

const BRACKET_FUNCS: &[(&str, Func, usize)] = &[
    ("SIN", Func::Sin, 1),
    ("COS", Func::Cos, 1),
    ("TAN", Func::Tan, 1),
    ("ASIN", Func::Asin, 1),
    ("ACOS", Func::Acos, 1),
    ("ATAN", Func::Atan, 1),
    ("ATAN", Func::Atan2, 2),
    ("SQRT", Func::Sqrt, 1),
    ("ABS", Func::Abs, 1),
    ("ROUND", Func::Round, 1),
    ("FIX", Func::Floor, 1),
    ("FUP", Func::Ceil, 1),
    ("LN", Func::Ln, 1),
    ("EXP", Func::Exp, 1),
];

fn lengths(spec: &mut DialectSpec, letters: &str) {
    for l in letters.chars() {
        spec.addresses.push(AddressDef {
            letter: l,
            role: "length".into(),
            length: true,
        });
    }
}

fn finish(mut s: DialectSpec, caps: &[C]) -> DialectSpec {
    s.capabilities = caps.iter().copied().collect();
    s.reindex();
    s
}

pub fn fanuc() -> DialectSpec {
    let mut s = DialectSpec::new(
        "fanuc".into(),
        "Fanuc".into(),
        Family::WordAddress,
        rules(true, (3, 4), true),
    );
    s.codes = codes(WORD_COMMON);
    s.codes.extend(codes(FANUC_ONLY));
    s.codes.push(dwell(&[
        ('X', DwellUnit::Seconds),
        ('P', DwellUnit::Milliseconds),
    ]));
    s.functions = functions(BRACKET_FUNCS);
    s.functions.extend(functions(&[
        ("POW", Func::Pow, 2),
        ("BIN", Func::Bin, 1),
        ("BCD", Func::Bcd, 1),
    ]));
    lengths(&mut s, "XYZABCUVWIJKRQ");
    finish(
        s,
        &[
            C::ParenComments,
            C::MacroB,
            C::NumberedPrograms,
            C::GCodeTransforms,
        ],
    )
}

pub fn haas() -> DialectSpec {
    let mut s = fanuc();
    s.id = "haas".into();
    s.name = "Haas".into();
    s.repeat_letter = 'L';
    s.codes.push(code("M97", "sub.local-call"));
    let mut g154 = code("G154", "work-offset.extended");
    g154.preferred = true;
    s.codes.push(g154);
    s.capabilities.insert(C::LocalSubprogramCall);
    s.reindex();
    s
}

pub fn linuxcnc() -> DialectSpec {
    let mut s = DialectSpec::new(
        "linuxcnc".into(),
        "LinuxCNC".into(),
        Family::WordAddress,
        rules(false, (4, 5), false),
    );
    s.codes = codes(WORD_COMMON);
    s.codes.extend(codes(&[
        ("G38.2", "motion.probe-toward"),
        ("G61.1", "path.exact-path"),
        ("G43.1", "length-comp.dynamic"),
        ("G90.1", "arc-distance.absolute"),
        ("G91.1", "arc-distance.incremental"),
        ("G59.1", "work-offset.7"),
        ("G33", "aux"),
        ("G5.2", "aux"),
        ("G74", "cycle.tap-left"),
    ]));
    s.codes.push(dwell(&[('P', DwellUnit::Seconds)]));
    let orient = s
        .codes
        .iter_mut()
        .find(|c| c.letter == 'M' && c.code == d("19"))
        .unwrap();
    orient.uses = vec!['R', 'Q', 'P'];
    s.repeat_letter = 'L';
    s.functions = functions(BRACKET_FUNCS);
    finish(
        s,
        &[
            C::ParenComments,
            C::SemicolonComments,
            C::OWords,
            C::NamedParameters,
            C::PowerOperator,
            C::NumberedPrograms,
            C::PolarWords,
            C::MessageComments,
        ],
    )
}

pub fn siemens() -> DialectSpec {
    let mut s = DialectSpec::new(
        "siemens840d".into(),
        "Siemens 840D".into(),
        Family::Sinumerik,
        rules(false, (6, 6), false),
    );
    s.codes = codes(&[
        ("G0", "motion.rapid"),
        ("G1", "motion.linear"),
        ("G2", "motion.arc-cw"),
        ("G3", "motion.arc-ccw"),
        ("G17", "plane.xy"),
        ("G18", "plane.zx"),
        ("G19", "plane.yz"),
        ("G70", "units.inch"),
        ("G71", "units.mm"),
        ("G700", "units.inch-with-feeds"),
        ("G710", "units.mm-with-feeds"),
        ("G90", "distance.absolute"),
        ("G91", "distance.incremental"),
        ("G93", "feed-mode.inverse-time"),
        ("G94", "feed-mode.per-minute"),
        ("G95", "feed-mode.per-revolution"),
        ("G40", "radius-comp.off"),
        ("G41", "radius-comp.left"),
        ("G42", "radius-comp.right"),
        ("G500", "work-offset.0"),
        ("G54", "work-offset.1"),
        ("G55", "work-offset.2"),
        ("G53", "machine-coords"),
        ("G60", "path.exact-stop"),
        ("G9", "path.exact-stop-block"),
        ("G64", "path.continuous"),
        ("G74", "ref-return.1"),
        ("G96", "css.on"),
        ("G97", "css.off"),
        ("M0", "stop.program"),
        ("M1", "stop.optional"),
        ("M2", "stop.end"),
        ("M30", "stop.end-rewind"),
        ("M3", "spindle.cw"),
        ("M4", "spindle.ccw"),
        ("M5", "spindle.stop"),
        ("M6", "tool.change"),
        ("M7", "coolant.mist"),
        ("M8", "coolant.flood"),
        ("M9", "coolant.off"),
        ("M17", "sub.return"),
    ]);
    s.codes.push(dwell(&[
        ('F', DwellUnit::Seconds),
        ('S', DwellUnit::Revolutions),
    ]));
    s.functions = functions(&[
        ("SIN", Func::Sin, 1),
        ("COS", Func::Cos, 1),
        ("TAN", Func::Tan, 1),
        ("ATAN2", Func::Atan2, 2),
        ("SQRT", Func::Sqrt, 1),
        ("POT", Func::Square, 1),
        ("ABS", Func::Abs, 1),
        ("TRUNC", Func::Trunc, 1),
        ("ROUND", Func::Round, 1),
        ("ROUNDUP", Func::Ceil, 1),
        ("MINVAL", Func::Min, 2),
        ("MAXVAL", Func::Max, 2),
    ]);
    finish(
        s,
        &[
            C::SemicolonComments,
            C::RParameters,
            C::DefVariables,
            C::StructuredControl,
            C::NamedCycles,
            C::Frames,
        ],
    )
}
