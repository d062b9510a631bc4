//! Unit tests of the Klartext front end: lexing corners, continuation
//! lines, comments and labels, what each block becomes.

use super::lexer::{classify, lex};
use super::token::{Kw, Tok};
use crate::dialect::builtin::builtin;
use crate::driver::read_program;
use crate::ir::print::print_program;
use crate::ir::QBank;
use crate::span::FileId;

fn toks(text: &str) -> Vec<Tok> {
    let mut raw = Vec::new();
    assert!(lex(text, 0, &mut raw).is_ok(), "{text}");
    classify(raw).into_iter().map(|t| t.1).collect()
}

fn read(text: &str) -> (String, Vec<String>) {
    let spec = builtin("heidenhain").unwrap();
    let (p, d) = read_program(text, FileId(0), &spec);
    (
        print_program(&p),
        d.iter().map(|d| d.code.code().to_string()).collect(),
    )
}

#[test]
fn keywords_only_where_a_block_can_have_them() {
    assert_eq!(toks("L C+90")[0], Tok::Kw(Kw::L));
    assert_eq!(toks("L C+90")[1], Tok::Name("C".into()));
    assert_eq!(toks("CYCL DEF 7.1")[1], Tok::Kw(Kw::Def));
    assert_eq!(toks("TOOL DEF 1 L+0")[3], Tok::Name("L".into()));
}

#[test]
fn q_parameters_split_from_their_address() {
    let t = toks("RND RQ1832 FQ12 X-QL3");
    assert_eq!(t[1], Tok::Name("R".into()));
    assert_eq!(t[2], Tok::Q(QBank::Q, 1832));
    assert_eq!(t[3], Tok::Name("F".into()));
    assert_eq!(t[4], Tok::Q(QBank::Q, 12));
    assert_eq!(t[7], Tok::Q(QBank::Local, 3));
}

#[test]
fn continuation_lines_make_one_block() {
    let text = "0 BEGIN PGM A MM\n1 CYCL DEF 200 DRILLING ~\n  Q200=+2 ;SET-UP ~\n  Q201=-5 ;DEPTH\n2 END PGM A MM\n";
    let (ir, d) = read(text);
    assert!(
        ir.contains("cycle-def 200 \"DRILLING\" Q200=2 ;\"SET-UP\" Q201=-5 ;\"DEPTH\""),
        "{ir}"
    );
    assert!(d.contains(&"E0320".to_string()), "{d:?}");
}

#[test]
fn a_comment_block_continues_its_text() {
    let (ir, _) = read("3  ;first~\n second\n");
    assert!(ir.contains("comment semicolon \"first second\""), "{ir}");
}

#[test]
fn block_numbers_are_optional_and_may_have_gaps() {
    let (ir, d) = read("BEGIN PGM X MM\n7 L X+1 FMAX\n9 L Y+2\nEND PGM X MM\n");
    assert!(ir.contains("N7 motion rapid X=1"), "{ir}");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn trailing_continuation_at_end_of_file_is_reported() {
    let (_, d) = read("0 BEGIN PGM X MM\n1 CYCL DEF 200 DRILLING ~\n");
    assert!(d.contains(&"E0125".to_string()), "{d:?}");
}

#[test]
fn spaced_signs_and_unsigned_values_are_read() {
    let (ir, d) = read("L Z + Q13 FMAX\nL Z 25.000 FMAX\nL IZ - 2.5 F100\n");
    assert!(ir.contains("motion rapid Z=Q13"), "{ir}");
    assert!(ir.contains("motion rapid Z=25.000"), "{ir}");
    assert!(ir.contains("motion linear Z=IC(-2.5)"), "{ir}");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn fn_functions_check_their_operator() {
    let (_, d) = read("FN 1: Q1 = +Q2 - +Q3\n");
    assert_eq!(d, vec!["E0101".to_string()]);
    let (ir, d) = read("FN 11: IF +Q2 GT Q22 GOTO LBL 2\nLBL 2\n");
    assert!(ir.contains("goto either 2 if [Q2 GT Q22]"), "{ir}");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn m13_is_spindle_and_coolant() {
    let (ir, _) = read("L X+1 FMAX M13\n");
    assert!(ir.contains("spindle cw | coolant flood"), "{ir}");
}

#[test]
fn fast_path_gives_what_the_grammar_gives() {
    let spec = builtin("heidenhain").unwrap();
    for line in [
        "12 L X+10.5 Y-3 Z-1 R0 F500",
        "L Z+50 R0 FMAX M3 M8",
        "7   L IX-5 IY+10 RL F200.0",
        "L M30",
        "L",
        "100 L X-0 Y+0.000 FMAX M91",
        "L A+90 B-45 C+0 RR",
    ] {
        let fast = super::fast::line(line, 0, FileId(0)).expect(line);
        let input = crate::syntax::LineInput {
            text: line,
            file: FileId(0),
            offset: 0,
            spec: &spec,
        };
        let mut exprs = crate::ir::Arena::new();
        let mut diags = Vec::new();
        let slow = super::read_block(&[(line.to_string(), 0)], &input, &mut exprs, &mut diags);
        assert!(diags.is_empty(), "{line}: {diags:?}");
        assert_eq!(Some(fast), slow, "{line}");
    }
    for line in [
        "L X+Q1",
        "L X+1 ;c",
        "L X + 1",
        "L X+1 M99",
        "L X+1 X+2",
        "L R+5",
        "LP PR+5",
    ] {
        assert!(super::fast::line(line, 0, FileId(0)).is_none(), "{line}");
    }
}

#[test]
fn cycle_def_is_rejected_with_the_right_keyword() {
    let spec = builtin("heidenhain").unwrap();
    let text = "0 BEGIN PGM P MM\n1 CYCLE DEF 9.0 DWELL TIME\n2 END PGM P MM\n";
    let (_, d) = read_program(text, FileId(0), &spec);
    assert_eq!(d.len(), 1, "{d:?}");
    assert_eq!(d[0].code.code(), "E0120");
    assert!(
        d[0].message.contains("the keyword is `CYCL DEF`"),
        "{}",
        d[0].message
    );
    let (_, d) = read("0 BEGIN PGM P MM\n1 CYCLE CALL\n2 END PGM P MM\n");
    assert_eq!(d, ["E0120"]);
}

#[test]
fn f_max_with_a_space_is_fmax() {
    let (a, d) = read("L X+1 R0 F MAX M3\n");
    let (b, _) = read("L X+1 R0 FMAX M3\n");
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(a, b);
}

#[test]
fn block_skip_slash_before_or_after_the_number() {
    let spec = builtin("heidenhain").unwrap();
    for text in ["/69 M30\n", "69 /M30\n", "/L X+1 FMAX\n"] {
        let (p, d) = read_program(text, FileId(0), &spec);
        assert!(d.is_empty(), "{text}: {d:?}");
        assert!(p.blocks[0].skip.is_some(), "{text}");
    }
}

#[test]
fn m140_mb_is_one_retract_with_its_m_function() {
    let (ir, d) = read("M140 MB MAX F99999\nL Z+5 R0 F500 M140 MB+50\n");
    assert!(d.is_empty(), "{d:?}");
    assert_eq!(ir.matches("retract").count(), 2, "{ir}");
    assert!(!ir.contains("aux M140"), "{ir}");
    let (_, d) = read("M140 MB\n");
    assert_eq!(d, ["E0123"]);
}

#[test]
fn function_blocks_and_formula_functions() {
    let (ir, d) = read("FUNCTION TCPM F TCP AXIS POS PATHCTRL AXIS\nFUNCTION RESET TCPM\nQ1 = SGN Q2 + LOG 10 + NEG Q3\n");
    assert!(d.is_empty(), "{d:?}");
    assert!(ir.contains("function"), "{ir}");
    assert!(ir.contains("sign(Q2)"), "{ir}");
    assert!(ir.contains("log10(10)+-Q3"), "{ir}");
    let (_, d) = read("FUNCTION\n");
    assert_eq!(d, ["E0123"]);
}

#[test]
fn cycle_text_may_have_an_apostrophe() {
    let (ir, d) = read("CYCL DEF 19.0 PLAN D'USINAGE\nCYCL DEF 19.1 A+0\n");
    assert!(d.is_empty(), "{d:?}");
    assert!(ir.contains("D'USINAGE"), "{ir}");
}

#[test]
fn post_mistakes_get_located_errors() {
    let spec = builtin("heidenhain").unwrap();
    let one = |text: &str| {
        let (_, d) = read_program(text, FileId(0), &spec);
        d.into_iter()
            .next()
            .map(|d| (d.code.code().to_string(), d.message))
            .unwrap()
    };
    let (c, m) = one("L Xnan Y+1 FMAX\n");
    assert_eq!(c, "E0121");
    assert!(m.contains("`X` is `nan`"), "{m}");
    let (c, m) = one("0010 BEGIN PGM 100 IN\n");
    assert_eq!(c, "E0123");
    assert!(m.contains("INCH"), "{m}");
    let (c, m) = one("1 CYCL DEF 200 DRILLING\nQ200=2\nQ201=-5\n");
    assert_eq!(c, "E0320");
    assert!(m.contains("does not end with `~`"), "{m}");
    let (c, m) = one("% 123 G71\nN10 G0 X0\n");
    assert_eq!(c, "E0120");
    assert!(m.contains("DIN/ISO"), "{m}");
}

#[test]
fn end_pgm_naming_another_program_is_a_warning() {
    let (_, d) = read("0 BEGIN PGM CUT MM\n1 END PGM RECTIFI MM\n");
    assert_eq!(d, ["W0120"]);
    let (_, d) = read("0 BEGIN PGM CUT MM\n1 END PGM cut MM\n");
    assert!(d.is_empty(), "{d:?}");
}

#[test]
fn old_cycle_words_with_dashes_dots_and_colons() {
    let (ir, d) =
        read("CYCL DEF 32.2 HSC-MODE:0\nCYCL DEF9 .0 VARAKOZASI IDO\nCYCL DEF9.1 V.IDO5\n");
    assert!(d.is_empty(), "{d:?}");
    assert!(ir.contains("HSC-MODE:"), "{ir}");
    assert!(ir.contains("cycle-line 9.0"), "{ir}");
    assert!(ir.contains("V.IDO"), "{ir}");
}

#[test]
fn comments_keep_their_trailing_blanks() {
    let (ir, d) = read("10 ; PROJECT\t  : \r\n11 CYCL DEF 392 ATC ~\n  Q240=+0 ; TUNING MODE   ~\n  Q241=+1 ;WEIGHT MODE\n");
    assert!(ir.contains("\" PROJECT\\t  : \""), "{ir}");
    assert!(ir.contains("\" TUNING MODE\""), "{ir}");
    assert!(d.is_empty(), "{d:?}");
}
