//! Property tests standing in for fuzzing in CI: arbitrary text, and lines
//! of real programs cut and mixed, never make a reader or writer panic.
//! (The coverage-guided fuzz targets are in `fuzz/`; see the README.)

use proptest::prelude::*;

const DIALECTS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// Fragments that exercise the grammars' corners.
const PIECES: &[&str] = &[
    "G1",
    "X10.",
    "Y-2.5",
    "#1=",
    "[",
    "]",
    "#[#2]",
    "IF",
    "GOTO",
    "WHILE",
    "DO1",
    "END1",
    "(",
    ")",
    ";",
    "o100",
    "sub",
    "endsub",
    "call",
    "if",
    "endif",
    "#<a>",
    "**",
    "R1=",
    "DEF REAL",
    "IFR1>2",
    "GOTOF",
    "L:",
    "CYCLE81(",
    ",",
    ")",
    "MCALL",
    "\"",
    "AC(",
    "CR=",
    "FOR",
    "ENDFOR",
    "N10",
    "/",
    "%",
    "1.2.3",
    "M98P",
    "G65",
    "ATAN",
    "SQRT",
    "=",
    "+",
    "-",
    "*",
    "\n",
    " ",
    "\t",
    "\r\n",
    "é",
    "\u{0}",
    "BEGIN PGM",
    "END PGM",
    " MM",
    "L",
    " X+",
    "IX-",
    "Q12",
    "RQ5",
    "FMAX",
    "CC",
    "C",
    "DR+",
    "CR",
    "R+5",
    "CT",
    "RND R",
    "CHF ",
    "LP PR+",
    "PA+",
    "IPA",
    "APPR LT",
    "DEP",
    "LEN",
    "LBL ",
    "CALL LBL",
    " REP 2/2",
    "FN 9: IF +",
    " EQU ",
    "GOTO LBL",
    "FN 1: Q1 = +",
    "CYCL DEF 200",
    "CYCL DEF 7.1",
    " ~",
    "Q200=",
    ";LABEL",
    "CYCL CALL",
    "M99",
    "PATTERN DEF",
    "POS1 (",
    "TOOL CALL",
    "BLK FORM 0.1 Z",
    "INT",
    "* - ",
    "~\n",
];

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn arbitrary_text_never_panics(s in "\\PC{0,200}") {
        for d in DIALECTS {
            cncc::fuzzing::read_and_write(d, s.as_bytes());
        }
    }

    #[test]
    fn mixed_fragments_never_panic(parts in proptest::collection::vec(0..PIECES.len(), 0..60)) {
        let s: String = parts.iter().map(|&i| PIECES[i]).collect();
        for d in DIALECTS {
            cncc::fuzzing::read_and_write(d, s.as_bytes());
        }
    }

    #[test]
    fn arbitrary_bytes_never_panic(b in proptest::collection::vec(any::<u8>(), 0..300)) {
        for d in DIALECTS {
            cncc::fuzzing::read_and_write(d, &b);
        }
    }
}
