//! Tests of the Sinumerik front end: snapshots of representative lines of
//! every construct, errors with their spans, the corpus, and a property
//! test that no input panics.

use super::SinumerikFrontEnd;
use crate::diag::Diagnostic;
use crate::dialect::spec::{
    CycleSig, FunctionDef, IntegerLengths, NumberRules, ParamSig, ParamType,
};
use crate::dialect::{Capability, DialectSpec, Family};
use crate::ir::{Arena, Decimal, Expr, ExprId, ExprKind, Func, Value, Var};
use crate::span::{FileId, Span};
use crate::syntax::{FrontEnd, Item, LineInput};
use std::fmt::Write;

fn cycle(name: &str, params: &[(&str, ParamType)]) -> CycleSig {
    let params = params
        .iter()
        .map(|(n, t)| ParamSig {
            name: n.to_string(),
            ty: *t,
            doc: String::new(),
        })
        .collect();
    CycleSig {
        name: name.into(),
        kind: "drill".into(),
        params,
        doc: String::new(),
        span: Span::default(),
    }
}

/// A small Siemens spec for tests (the real one is read from XML).
pub fn spec() -> DialectSpec {
    let n = NumberRules {
        integer_lengths: IntegerLengths::Units,
        increment_mm: Decimal::parse("0.001").unwrap(),
        increment_inch: Decimal::parse("0.0001").unwrap(),
        length_places_mm: 3,
        length_places_inch: 4,
        point_on_lengths: false,
        feed_places: 1,
        angle_places: 3,
        integer_digits: 8,
    };
    let mut s = DialectSpec::new(
        "siemens840d".into(),
        "Siemens 840D".into(),
        Family::Sinumerik,
        n,
    );
    use ParamType::*;
    let r = |n: &'static str| (n, Real);
    s.cycles.push(cycle(
        "CYCLE81",
        &[
            r("RTP"),
            r("RFP"),
            r("SDIS"),
            r("DP"),
            r("DPR"),
            ("GMODE", Int),
            ("DMODE", Int),
            ("AMODE", Int),
        ],
    ));
    s.cycles.push(cycle(
        "CYCLE82",
        &[r("RTP"), r("RFP"), r("SDIS"), r("DP"), r("DPR"), r("DTB")],
    ));
    s.cycles.push(cycle(
        "HOLES1",
        &[
            r("SPCA"),
            r("SPCO"),
            r("STA1"),
            r("FDIS"),
            r("DBH"),
            ("NUM", Int),
        ],
    ));
    s.cycles.push(cycle(
        "HOLES2",
        &[
            r("CPA"),
            r("CPO"),
            r("RAD"),
            r("STA1"),
            r("INDA"),
            ("NUM", Int),
        ],
    ));
    s.cycles.push(cycle(
        "CYCLE801",
        &[
            r("SPCA"),
            r("SPCO"),
            r("STA"),
            r("DIS1"),
            r("DIS2"),
            ("NUM1", Int),
            ("NUM2", Int),
        ],
    ));
    let names: Vec<std::string::String> = (1..=25).map(|i| format!("P{i}")).collect();
    let pocket4: Vec<(&str, ParamType)> = names.iter().map(|n| (n.as_str(), Real)).collect();
    s.cycles.push(cycle("POCKET4", &pocket4));
    let mut c800: Vec<(&str, ParamType)> = vec![("FR", Int), ("TC", String)];
    c800.extend(names[2..16].iter().map(|n| (n.as_str(), Real)));
    s.cycles.push(cycle("CYCLE800", &c800));
    for (name, func, arity) in [
        ("SIN", Func::Sin, 1),
        ("COS", Func::Cos, 1),
        ("TAN", Func::Tan, 1),
        ("SQRT", Func::Sqrt, 1),
        ("TRUNC", Func::Trunc, 1),
        ("ATAN2", Func::Atan2, 2),
        ("POT", Func::Square, 1),
        ("DC", Func::PosShortest, 1),
        ("ACP", Func::PosPlus, 1),
    ] {
        s.functions.push(FunctionDef {
            name: name.into(),
            func,
            arity,
        });
    }
    s.commands = ["SOFT", "BRISK", "FFWON", "TRAORI", "SETAL", "SUPA"]
        .iter()
        .map(|c| c.to_string())
        .collect();
    for c in [
        Capability::SemicolonComments,
        Capability::RParameters,
        Capability::DefVariables,
        Capability::StructuredControl,
        Capability::NamedCycles,
        Capability::Frames,
    ] {
        s.capabilities.insert(c);
    }
    s.reindex();
    s
}

/// Reads a whole text line by line; returns the rendering and diagnostics.
pub(super) fn read(text: &str) -> (String, Vec<Diagnostic>) {
    let spec = spec();
    let mut fe = SinumerikFrontEnd::new();
    let mut exprs = Arena::new();
    let mut diags = Vec::new();
    let mut out = String::new();
    let mut offset = 0u32;
    for line in text.split('\n') {
        let first = exprs.len();
        let input = LineInput {
            text: line,
            file: FileId(0),
            offset,
            spec: &spec,
        };
        let ls = fe
            .parse_line(&input, &mut exprs, &mut diags)
            .expect("a line");
        let _ = writeln!(out, "{line}");
        show_line(&mut out, &ls, &exprs, first);
        offset += line.len() as u32 + 1;
    }
    (out, diags)
}

fn show_line(out: &mut String, ls: &crate::syntax::LineSyntax, exprs: &Arena<Expr>, first: usize) {
    if let Some(s) = &ls.skip {
        let _ = writeln!(out, "  skip {} @{}..{}", s.node, s.span.start, s.span.end);
    }
    if let Some(n) = &ls.number {
        let _ = writeln!(out, "  N{} @{}..{}", n.node, n.span.start, n.span.end);
    }
    if let Some(l) = &ls.label {
        let _ = writeln!(out, "  label {} @{}..{}", l.node, l.span.start, l.span.end);
    }
    for it in &ls.items {
        match it {
            Item::Word(w) => {
                let v = value(exprs, &w.value);
                let _ = writeln!(
                    out,
                    "  word {}{}{} dim={:?} @{}..{}",
                    w.address,
                    if w.extended { "=" } else { "" },
                    v,
                    w.dim,
                    w.span.start,
                    w.span.end
                );
            }
            Item::Stmt(s) => {
                let _ = writeln!(
                    out,
                    "  stmt {} @{}..{}",
                    compact(&format!("{:?}", s.kind)),
                    s.span.start,
                    s.span.end
                );
            }
        }
    }
    for (id, e) in exprs.iter().skip(first) {
        let _ = writeln!(out, "    {:?} = {}", id, expr(exprs, id));
        let _ = e;
    }
}

/// Drops spans from Debug text to keep snapshots short.
fn compact(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(i) = rest.find("Span { file: FileId(0), start: ") {
        out.push_str(&rest[..i]);
        let tail = &rest[i + "Span { file: FileId(0), start: ".len()..];
        let close = tail.find(" }").unwrap_or(tail.len());
        out.push_str(&tail[..close].replace(", end: ", ".."));
        rest = &tail[(close + 2).min(tail.len())..];
    }
    out.push_str(rest);
    out
}

fn value(exprs: &Arena<Expr>, v: &Value) -> String {
    match v {
        Value::Number(d) => d.to_string(),
        Value::Expr(e) => format!("[{}]", expr(exprs, *e)),
    }
}

fn var(exprs: &Arena<Expr>, v: &Var) -> String {
    let idx = |ix: &Vec<ExprId>| {
        if ix.is_empty() {
            String::new()
        } else {
            format!(
                "[{}]",
                ix.iter()
                    .map(|e| expr(exprs, *e))
                    .collect::<Vec<_>>()
                    .join(",")
            )
        }
    };
    match v {
        Var::R(n) => format!("R{n}"),
        Var::RIndirect(e) => format!("R[{}]", expr(exprs, *e)),
        Var::User(n, ix) => format!("{n}{}", idx(ix)),
        Var::System(n, ix) => format!("{n}{}", idx(ix)),
        other => format!("{other:?}"),
    }
}

fn expr(exprs: &Arena<Expr>, id: ExprId) -> String {
    match &exprs[id].kind {
        ExprKind::Number(d) => d.to_string(),
        ExprKind::Str(s) => format!("{s:?}"),
        ExprKind::Bool(b) => b.to_string(),
        ExprKind::Var(v) => var(exprs, v),
        ExprKind::Unary(op, a) => format!("{op:?}({})", expr(exprs, *a)),
        ExprKind::Binary(op, a, b) => format!("({} {op:?} {})", expr(exprs, *a), expr(exprs, *b)),
        ExprKind::Call(f, args) => format!(
            "{f:?}({})",
            args.iter()
                .map(|a| expr(exprs, *a))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        other => format!("{other:?}"),
    }
}

fn diags_text(ds: &[Diagnostic]) -> String {
    let mut out = String::new();
    for d in ds {
        let sp = d
            .span()
            .map(|s| format!("{}..{}", s.start, s.end))
            .unwrap_or_default();
        let _ = writeln!(
            out,
            "{} {} @{}: {} | {}",
            d.code.code(),
            d.code.name(),
            sp,
            d.message,
            d.help.clone().unwrap_or_default()
        );
    }
    out
}

fn snap(text: &str) -> String {
    let (out, ds) = read(text);
    format!("{out}---\n{}", diags_text(&ds))
}

#[test]
fn words_and_packed_words() {
    insta::assert_snapshot!(snap("N10 G0X10Y20 Z-5.5\nT1D1M6\nN40 Label_1: G0 X=1.2+SIN(R1) Y1\nX=AC(10) Y=IC(-5) CR=10 AR=90 TURN=2\nCIP X10 Y20 I1=5 J1=6\nCT X5 Y5\nG1 X10 CHF=2 RND=1.5\nF159.0 S1000 M3 G70 G710\nM1=3 S1=1000"));
}

#[test]
fn prefixes_and_headers() {
    insta::assert_snapshot!(snap(
        "%_N_PART1_MPF\n;$PATH=/_N_MPF_DIR\n/N10 G0 X1\n/3 N20 X2\n:100 G1\nN5 END: ;end label"
    ));
}

#[test]
fn variables_and_expressions() {
    insta::assert_snapshot!(snap("DEF REAL A, B=2.5, T[3,4]\nDEF INT N1=1000\nDEF STRING[32] S\nDEF AXIS AX\nA=B*2+R1 N1=N1 DIV 3 MOD 2\nR[R2+1]=-R3\nT[1,2]=POT(A)\nS=\"ab\" << \"cd\"\n$P_UIFR[1]=0\nR5=$AA_IW[X]\nR6=NOT (R1==1) AND B_NOT R2 B_AND 3 OR R1<>2 XOR R2>=1"));
}

#[test]
fn control_flow() {
    insta::assert_snapshot!(snap("IF R1<(90-0.5*R7) GOTOB METKA1\nGOTOF END\nIF R1==1\nELSE\nENDIF\nWHILE R1<10\nENDWHILE\nFOR R2=1 TO 10\nENDFOR\nDEF INT I\nFOR I=0 TO R1\nREPEAT\nUNTIL R1>=5\nLOOP\nENDLOOP\nCASE(R1+R2) OF 8 GOTOF L1 6 GOTOB L2 DEFAULT GOTOF L3\nREPEAT Begin P=3\nREPEAT START ENDE P=R1\nREPEATB LBL\nGOTO X1\nGOTOC NEXT"));
}

#[test]
fn calls_and_cycles() {
    insta::assert_snapshot!(snap("MCALL CYCLE81(10,0,2,-5)\nMCALL\nCYCLE81(10,0,2,,-5)\nHOLES2(CPA, CPO, RAD, STA1,0,NUM)\nCYCLE801(,,,10,15,10,5)\nL123\nL123 P3\nL140(2)\nMYSUB\nMYSUB(1,,2)\nCALL \"NAME\"\nPROC MYPROC(REAL A, INT B) SAVE DISPLOF\nA=B\nRET\nM17\nM30\nMSG(\"hello\")\nMSG()\nT=\"FACEMILL 63\"\nWORKPIECE(,,,\"BOX\",64)"));
}

#[test]
fn frames_and_commands() {
    insta::assert_snapshot!(snap("TRANS X10 Y5\nATRANS Z=R1\nROT Z45\nROT RPL=45\nAROT Y-90\nSCALE X2\nMIRROR X0\nAMIRROR Y0\nTRANS\nSOFT\nSETAL(66021)\nFFWON G64"));
}

#[test]
fn errors_have_spans() {
    insta::assert_snapshot!(snap("G0 X1.2.3\nG1 X123456789012345678901\nMSG(\"open\nG0 X?\nG0 X\nR1=(2+\nIF R1== GOTOF\nG0 X1 Y2 Z3 ) \nG1 X=R1+\nCYCLE81(10,0,2,-5,0,1,1,1,9)\nCYCLE800(\"x\",5)\nHOLES1(1,2,3,4,5,1.5)\nR1=SIN(1,2)\nX10 LBL: Y2\nG1 X10 Y20"));
}

#[test]
fn unknown_constructs_are_kept_as_text() {
    insta::assert_snapshot!(snap(
        "N150 WHENEVER $A_IN[1] DO OVR=0\nR1=FOO(3)\nMSG(\"a\" << R1)\nTRANS X1 FOO=2"
    ));
}

#[test]
fn declarations_carry_to_later_lines() {
    let (out, ds) = read("DEF REAL XA1\nXA1=5\nG0 X=XA1");
    assert!(ds.is_empty(), "{ds:?}");
    assert!(out.contains("Assign { var: User(\"XA1\""), "{out}");
    assert!(out.contains("word X=[XA1]"), "{out}");
}

#[test]
fn corpus_files_parse_without_panic() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/corpus/siemens840d");
    let Ok(entries) = std::fs::read_dir(&dir) else {
        println!("note: {} not found, corpus test skipped", dir.display());
        return;
    };
    let mut names: Vec<_> = entries.filter_map(|e| e.ok()).map(|e| e.path()).collect();
    names.sort();
    let mut report = String::new();
    for path in names {
        let bytes = std::fs::read(&path).unwrap();
        let text = String::from_utf8_lossy(&bytes);
        let (_, ds) = read(&text);
        let name = path.file_name().unwrap().to_string_lossy().to_string();
        let _ = writeln!(report, "{name}: {} diagnostics", ds.len());
        for d in &ds {
            let at = d
                .span()
                .map(|s| line_of(&text, s.start as usize))
                .unwrap_or(0);
            let _ = writeln!(report, "  line {at}: {} {}", d.code.code(), d.message);
        }
    }
    insta::assert_snapshot!(report);
}

fn line_of(text: &str, at: usize) -> usize {
    text.as_bytes()[..at.min(text.len())]
        .iter()
        .filter(|b| **b == b'\n')
        .count()
        + 1
}

proptest::proptest! {
    #[test]
    fn arbitrary_text_never_panics(s in "\\PC{0,60}") {
        let _ = read(&s);
    }

    #[test]
    fn sinumerik_like_text_never_panics(s in "[A-Z0-9=+\\-*/()\\[\\],:;$\"<>. _]{0,60}") {
        let _ = read(&s);
    }
}
