//! Tests of the word-address front end: constructs as snapshots, errors
//! with their spans, the fast path against the grammar, the corpus, fuzz.

use super::*;
use crate::dialect::{Capability, DialectSpec, Family, FunctionDef, IntegerLengths, NumberRules};
use crate::ir::{Decimal, ExprKind, Func, Value};
use crate::span::FileId;
use std::fmt::Write;

/// A word-address spec with the given capabilities and the Fanuc functions.
pub fn test_spec(caps: &[Capability]) -> DialectSpec {
    let numbers = NumberRules {
        integer_lengths: IntegerLengths::Units,
        increment_mm: Decimal::parse("0.001").unwrap(),
        increment_inch: Decimal::parse("0.0001").unwrap(),
        length_places_mm: 3,
        length_places_inch: 4,
        point_on_lengths: true,
        feed_places: 1,
        angle_places: 3,
        integer_digits: 8,
    };
    let mut s = DialectSpec::new("test".into(), "Test".into(), Family::WordAddress, numbers);
    s.capabilities = caps.iter().copied().collect();
    let f = |name: &str, func, arity| FunctionDef {
        name: name.into(),
        func,
        arity,
    };
    s.functions = vec![
        f("SIN", Func::Sin, 1),
        f("COS", Func::Cos, 1),
        f("TAN", Func::Tan, 1),
        f("ASIN", Func::Asin, 1),
        f("ACOS", Func::Acos, 1),
        f("LN", Func::Ln, 1),
        f("EXP", Func::Exp, 1),
        f("SQRT", Func::Sqrt, 1),
        f("ABS", Func::Abs, 1),
        f("FIX", Func::Floor, 1),
        f("FUP", Func::Ceil, 1),
        f("ROUND", Func::Round, 1),
        f("POW", Func::Pow, 2),
    ];
    s
}

fn fanuc() -> DialectSpec {
    use Capability::*;
    test_spec(&[ParenComments, MacroB, NumberedPrograms, CommaCornerWords])
}

fn linuxcnc() -> DialectSpec {
    use Capability::*;
    test_spec(&[
        ParenComments,
        SemicolonComments,
        OWords,
        NamedParameters,
        PowerOperator,
        NumberedPrograms,
        PolarWords,
    ])
}

/// Parses lines with one front end; returns the rendered result.
fn run(spec: &DialectSpec, text: &str) -> String {
    let mut fe = WordFrontEnd::new();
    run_with(&mut fe, spec, text)
}

fn run_with(fe: &mut WordFrontEnd, spec: &DialectSpec, text: &str) -> String {
    let mut out = String::new();
    let mut offset = 0u32;
    for l in text.split('\n') {
        let mut exprs = Arena::new();
        let mut diags = Vec::new();
        let input = LineInput {
            text: l,
            file: FileId(0),
            offset,
            spec,
        };
        let line = fe.parse_line(&input, &mut exprs, &mut diags);
        writeln!(out, "> {l}").unwrap();
        if let Some(line) = line {
            render_line(&mut out, &line, &exprs);
        }
        for d in &diags {
            let s = d.span().unwrap();
            writeln!(
                out,
                "  {} {}..{} {} | {}",
                d.code.code(),
                s.start,
                s.end,
                d.message,
                d.help.clone().unwrap_or_default()
            )
            .unwrap();
        }
        offset += l.len() as u32 + 1;
    }
    out
}

fn render_line(out: &mut String, line: &LineSyntax, exprs: &Arena<Expr>) {
    if let Some(s) = &line.skip {
        writeln!(out, "  skip /{} {}..{}", s.node, s.span.start, s.span.end).unwrap();
    }
    if let Some(n) = &line.number {
        writeln!(out, "  N{} {}..{}", n.node, n.span.start, n.span.end).unwrap();
    }
    for it in &line.items {
        match it {
            Item::Word(w) => {
                let v = value(exprs, &w.value);
                writeln!(
                    out,
                    "  word {} = {v} {}..{} addr {}..{}",
                    w.address, w.span.start, w.span.end, w.address_span.start, w.address_span.end
                )
                .unwrap();
            }
            Item::Stmt(s) => {
                writeln!(out, "  stmt {:?} {}..{}", s.kind, s.span.start, s.span.end).unwrap()
            }
        }
    }
    for (h, e) in exprs.iter() {
        writeln!(
            out,
            "    {h:?} = {} {}..{}",
            expr(exprs, h),
            e.span.start,
            e.span.end
        )
        .unwrap();
    }
}

fn value(exprs: &Arena<Expr>, v: &Value) -> String {
    match v {
        Value::Number(d) => d.to_string(),
        Value::Expr(h) => format!("{h:?}{{{}}}", expr(exprs, *h)),
    }
}

/// An expression as a compact s-expression.
fn expr(exprs: &Arena<Expr>, h: crate::ir::ExprId) -> String {
    let e = |h| expr(exprs, h);
    match &exprs[h].kind {
        ExprKind::Number(d) => d.to_string(),
        ExprKind::Var(v) => match v {
            crate::ir::Var::Indirect(i) => format!("#[{}]", e(*i)),
            other => format!("{other:?}"),
        },
        ExprKind::Unary(op, a) => format!("({op:?} {})", e(*a)),
        ExprKind::Binary(op, a, b) => format!("({op:?} {} {})", e(*a), e(*b)),
        ExprKind::Call(f, args) => format!(
            "({f:?} {})",
            args.iter().map(|a| e(*a)).collect::<Vec<_>>().join(" ")
        ),
        ExprKind::AtanSlash(a, b) => format!("(AtanSlash {} {})", e(*a), e(*b)),
        other => format!("{other:?}"),
    }
}

#[test]
fn words_numbers_and_prefix() {
    insta::assert_snapshot!(run(
        &fanuc(),
        "/2 N10 G0G40X-1.25Y.5 Z10.\ng 0 x 1.5\n%\nN20 G1 X#1 Y-#2 Z-[#3+1]"
    ));
}

#[test]
fn comments_and_messages() {
    insta::assert_snapshot!(run(
        &linuxcnc(),
        "G0 (rapid) X1 ; to the start\n(MSG, Change tool)\nO1234 (PART ONE)\n(open"
    ));
}

#[test]
fn macro_b() {
    let text = "#1=#2+3*#4\n#[#2]=SIN[30]\nIF[#118EQ#116]AND[#119EQ#117]GOTO10\nIF [#1 GT 0] THEN #2=1\nWHILE[#1LT10]DO1\nEND1\nGOTO #5\nX#1 G#143 Z[#1/2]\n#3=ATAN[1]/[2]+ATAN[1,2]+FIX[#1 MOD 2]";
    insta::assert_snapshot!(run(&fanuc(), text));
}

#[test]
fn owords() {
    let text = "o100 sub\no100 endsub [1]\no<my_sub> call [1] [#2+1]\no101 if [#<x> GT 2**3]\no101 elseif [EXISTS[#<_y>]]\no101 else\no101 endif\no102 do\no102 break\no102 continue\no102 while [#1 LT 3]\no103 while [1]\no103 endwhile\no104 repeat [5]\no104 endrepeat\no100 return [#<_v>]";
    insta::assert_snapshot!(run(&linuxcnc(), text));
}

#[test]
fn precedence() {
    insta::assert_snapshot!(run(
        &linuxcnc(),
        "#1=1+2*3**2 EQ 4 AND 5 OR 6 XOR 7\n#2=-2*-#1-[1-2]"
    ));
}

#[test]
fn errors_with_spans() {
    let text = "G0 (no end\nX1.2.3 Y1234567890123456789\nG0 $ X1\nX#140/2+#142\nG1 X Y2\n#1=[1+\nIF [#1 EQ 2] FOO\nG1 X1 Y2 ]\n#1=BAR[2]\nG1 X2";
    insta::assert_snapshot!(run(&fanuc(), text));
}

#[test]
fn missing_capabilities() {
    let text = "o100 sub\n#<a>=2\nX[2**3]\n; text\nG0 ;";
    insta::assert_snapshot!(run(&fanuc(), text));
    let text2 = "IF [#1 EQ 2] GOTO 5\nWHILE [1] DO 1\nO1000\nX#1/2";
    insta::assert_snapshot!(run(&test_spec(&[Capability::ParenComments]), text2));
}

#[test]
fn unbracketed_with_capability() {
    let mut spec = fanuc();
    spec.capabilities.insert(Capability::UnbracketedExpressions);
    let out = run(&spec, "X#140/2+#142 Y-#1*2");
    assert!(!out.contains("E0105"), "{out}");
    assert!(
        out.contains("(Add (Div Numbered(140) 2) Numbered(142))"),
        "{out}"
    );
}

#[test]
fn fast_path_agrees() {
    let spec = fanuc();
    let lines = "N10 G1 X12.345 Y-3.2 Z-1. F500\nG0X1Y2\nn5 m3 s1000\nX+.5 Y-0.25\n\nM30\nN010 T1 M6\n(TOOL 1 ; D12)\nG0 (a)X1(MSG,b)";
    let mut fast = WordFrontEnd::new();
    let mut slow = WordFrontEnd::without_fast_path();
    for l in lines.split('\n') {
        let input = LineInput {
            text: l,
            file: FileId(0),
            offset: 7,
            spec: &spec,
        };
        assert!(fast::fast_line(&input).is_some(), "fast path refused {l:?}");
    }
    assert_eq!(
        run_with(&mut fast, &spec, lines),
        run_with(&mut slow, &spec, lines)
    );
    for l in [
        "O100", "G0 (x", "X1-2", "G 0", "X.", "GOTO1", "#1=2", "N1.5",
    ] {
        let input = LineInput {
            text: l,
            file: FileId(0),
            offset: 0,
            spec: &spec,
        };
        assert!(fast::fast_line(&input).is_none(), "fast path took {l:?}");
    }
}

/// Every corpus file parses without panic; the lines with diagnostics are
/// printed (and kept in a snapshot).
#[test]
fn corpus() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus");
    if !root.exists() {
        println!("corpus not found at {}; skipped", root.display());
        return;
    }
    let mut report = String::new();
    for (dir, spec) in [
        ("fanuc", fanuc_like()),
        ("haas", fanuc_like()),
        ("linuxcnc", linuxcnc()),
    ] {
        let mut files: Vec<_> = std::fs::read_dir(root.join(dir))
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        files.sort();
        for f in files {
            let text = String::from_utf8_lossy(&std::fs::read(&f).unwrap()).into_owned();
            let name = format!("{dir}/{}", f.file_name().unwrap().to_string_lossy());
            corpus_file(&mut report, &name, &text, &spec);
        }
    }
    insta::assert_snapshot!(report);
}

fn fanuc_like() -> DialectSpec {
    let mut s = fanuc();
    s.capabilities.insert(Capability::UnbracketedExpressions);
    s
}

fn corpus_file(report: &mut String, name: &str, text: &str, spec: &DialectSpec) {
    let mut fe = WordFrontEnd::new();
    let mut offset = 0u32;
    let mut exprs = Arena::new();
    for (n, raw) in text.split('\n').enumerate() {
        let l = raw.strip_suffix('\r').unwrap_or(raw);
        let mut diags = Vec::new();
        fe.parse_line(
            &LineInput {
                text: l,
                file: FileId(0),
                offset,
                spec,
            },
            &mut exprs,
            &mut diags,
        );
        for d in diags {
            writeln!(
                report,
                "{name}:{}: {} {} | {}",
                n + 1,
                d.code.code(),
                d.message,
                l.trim()
            )
            .unwrap();
        }
        offset += raw.len() as u32 + 1;
    }
}

mod fuzz {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]
        #[test]
        fn never_panics(s in "[ -~]{0,40}") {
            let _ = run(&linuxcnc(), &s);
            let _ = run(&fanuc(), &s);
        }

        #[test]
        fn never_panics_on_code_like_text(s in "([GXYZ#\\[\\]()=+*/<>;%-]|IF|GOTO|o1|sub|while|do|END|EQ|ATAN|[0-9.]{1,3}| ){0,20}") {
            let _ = run(&linuxcnc(), &s);
            let _ = run(&fanuc(), &s);
        }

        #[test]
        fn never_panics_on_any_unicode(s in "\\PC{0,30}") {
            let _ = run(&fanuc(), &s);
        }
    }
}

fn is_comment(it: &Item) -> bool {
    matches!(it, Item::Stmt(s) if matches!(s.kind, crate::ir::StmtKind::Comment { .. } | crate::ir::StmtKind::Message(_)))
}

#[test]
fn comments_are_kept_in_order() {
    let spec = linuxcnc();
    let mut fe = WordFrontEnd::new();
    let mut exprs = Arena::new();
    let mut diags = Vec::new();
    let input = LineInput {
        text: "(a) G0 (b) X1 ;c",
        file: FileId(0),
        offset: 0,
        spec: &spec,
    };
    let line = fe.parse_line(&input, &mut exprs, &mut diags).unwrap();
    let kinds: Vec<bool> = line.items.iter().map(is_comment).collect();
    assert_eq!(kinds, vec![true, false, true, false, true]);
    assert!(diags.is_empty());
}

#[test]
fn corner_and_polar_words() {
    insta::assert_snapshot!(run(&fanuc(), "G1 X0,R#144 Y2 ,C1.5"));
    insta::assert_snapshot!(run(&linuxcnc(), "G91 G81 @1 ^[360/17] R.1\n G1 X1,R2"));
}

/// Throughput of `parse_line` over a CAM program (run in release):
/// `python3 ../shared/bench/gen_program.py --lines 200000 -o /tmp/b.nc`, then
/// `CNCC_BENCH_FILE=/tmp/b.nc cargo test --release --lib word::tests::throughput -- --ignored --nocapture`.
#[test]
#[ignore]
fn throughput() {
    let Ok(path) = std::env::var("CNCC_BENCH_FILE") else {
        println!("CNCC_BENCH_FILE not set; skipped");
        return;
    };
    let text = std::fs::read_to_string(path).unwrap();
    let spec = linuxcnc();
    for (label, fast) in [("fast path + grammar", true), ("grammar only", false)] {
        // Best of five passes: the machine is shared.
        let best = (0..5)
            .map(|_| pass(&text, &spec, fast))
            .fold(f64::MAX, f64::min);
        println!("{label}: {:.1} MB/s", text.len() as f64 / best / 1e6);
    }
}

fn pass(text: &str, spec: &DialectSpec, fast: bool) -> f64 {
    let mut fe = if fast {
        WordFrontEnd::new()
    } else {
        WordFrontEnd::without_fast_path()
    };
    let start = std::time::Instant::now();
    let (mut items, mut diags, mut exprs, mut offset) = (0usize, Vec::new(), Arena::new(), 0u32);
    for l in text.lines() {
        let input = LineInput {
            text: l,
            file: FileId(0),
            offset,
            spec,
        };
        if let Some(line) = fe.parse_line(&input, &mut exprs, &mut diags) {
            items += line.items.len();
        }
        offset += l.len() as u32 + 1;
    }
    assert!(items > 0 && diags.is_empty());
    start.elapsed().as_secs_f64()
}

#[test]
fn more_lines_and_invalid_values() {
    let text = "/ G1 X1\nN1.5 G1\nWHILE [1] DO 300\nO1234\n#1=#1.5\nGOTO [#1+1]\nX[1+2\nX.\nG1 X1 (a) (b) Y2";
    insta::assert_snapshot!(run(&fanuc(), text));
    insta::assert_snapshot!(run(
        &linuxcnc(),
        "o<Sub_A> sub\no<sub_a> endsub\no<x> call\no<x>\no100 foo"
    ));
}
