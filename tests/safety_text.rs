//! Issue 14, point 1: any text a program or a STEP-NC file says, written by
//! any writer for any target, reads back as exactly one comment or message
//! and the same moves (never as code). Ports and posts, all five dialects.

use cncc::dialect::builtin;
use cncc::driver::read_program;
use cncc::ir::{CommentStyle, Program, Stmt, StmtKind};
use cncc::source::SourceMap;
use proptest::prelude::*;

const DIALECTS: &[&str] = &["fanuc", "haas", "linuxcnc", "siemens840d", "heidenhain"];

/// A small program with two moves, in each dialect.
fn base(dialect: &str) -> &'static str {
    match dialect {
        "siemens840d" => "G0 X1 Y2\nG1 X5 F100\nM30\n",
        "heidenhain" => "BEGIN PGM T MM\nL X+1 Y+2 FMAX\nL X+5 F100\nM30\nEND PGM T MM\n",
        _ => "%\nO1\nG0 X1. Y2.\nG1 X5. F100.\nM30\n%\n",
    }
}

fn read(text: &str, dialect: &str) -> (Program, bool) {
    let spec = builtin(dialect).unwrap();
    let mut files = SourceMap::default();
    let id = files.add("t", text.to_string());
    let (p, d) = read_program(text, id, &spec);
    let errors = d.iter().any(|d| d.is_error());
    (p, errors)
}

/// Comments and messages, and the printed IR of everything else.
fn split(p: &Program) -> (Vec<String>, Vec<String>) {
    let mut texts = Vec::new();
    for b in &p.blocks {
        for s in &b.stmts {
            match &s.kind {
                StmtKind::Comment { text, .. } => texts.push(text.clone()),
                StmtKind::Message(t) => texts.push(t.clone().unwrap_or_default()),
                // A title beside the program number is read as its name.
                StmtKind::ProgramStart { name: Some(n), .. } => texts.push(n.clone()),
                _ => {}
            }
        }
    }
    let mut q = p.clone();
    for b in &mut q.blocks {
        b.stmts
            .retain(|s| !matches!(s.kind, StmtKind::Comment { .. } | StmtKind::Message(_)));
    }
    // What else the text may change: the program's name, and a block left
    // empty by a comment alone.
    let rest = cncc::ir::print::print_program(&q)
        .lines()
        .map(|l| {
            // Klartext numbers every line: a comment line shifts them.
            let l = l.trim();
            match l.strip_prefix('N').and_then(|r| r.split_once(' ')) {
                Some((n, rest)) if n.bytes().all(|b| b.is_ascii_digit()) => rest.trim(),
                _ => l,
            }
        })
        .filter(|l| !l.is_empty() && *l != "(blank)" && !l.starts_with("program-start"))
        .map(String::from)
        .collect();
    (texts, rest)
}

/// The first line where two programs differ.
fn first_difference(a: &[String], b: &[String]) -> Option<String> {
    if a == b {
        return None;
    }
    let i = a.iter().zip(b).take_while(|(x, y)| x == y).count();
    Some(format!("line {i}: {:?} / {:?}", a.get(i), b.get(i)))
}

/// Ports `text` as a comment (or message) from `from` to `to` and reads
/// the result back.
fn port_one(
    text: &str,
    from: &str,
    to: &str,
    message: bool,
    style: CommentStyle,
) -> Result<(), TestCaseError> {
    let (mut p, errors) = read(base(from), from);
    prop_assert!(!errors);
    let (want_texts, want_rest) = {
        let spec_from = builtin(from).unwrap();
        let spec_to = builtin(to).unwrap();
        let (q, _) = cncc::port::port_program(&p, &spec_from, &spec_to, &Default::default());
        let Ok(out) = cncc::emit::write_program(&q, &spec_to) else {
            return Ok(());
        };
        split(&read(&out, to).0)
    };
    // Beside the first move.
    let at = p
        .blocks
        .iter()
        .position(|b| {
            b.stmts
                .iter()
                .any(|s| format!("{:?}", s.kind).starts_with("Motion"))
        })
        .unwrap();
    let span = p.blocks[at].stmts[0].span;
    let kind = if message {
        StmtKind::Message(Some(text.to_string()))
    } else {
        StmtKind::Comment {
            text: text.to_string(),
            style,
        }
    };
    p.blocks[at].stmts.push(Stmt::new(kind, span));
    let spec_from = builtin(from).unwrap();
    let spec_to = builtin(to).unwrap();
    let (q, _) = cncc::port::port_program(&p, &spec_from, &spec_to, &Default::default());
    // A target with no form for it says so (an error); never wrong text.
    let Ok(out) = cncc::emit::write_program(&q, &spec_to) else {
        return Ok(());
    };
    let (back, errors) = read(&out, to);
    prop_assert!(!errors, "{from}->{to} {text:?}:\n{out}");
    let (texts, rest) = split(&back);
    prop_assert_eq!(
        texts.len(),
        want_texts.len() + 1,
        "{}->{} {:?}:\n{}",
        from,
        to,
        text,
        out
    );
    let diff = first_difference(&rest, &want_rest);
    prop_assert!(diff.is_none(), "{from}->{to} {text:?}: {diff:?}\n{out}");
    // Not active on the target: what LinuxCNC would run is neutralised.
    if !message && from != to {
        for t in &texts {
            prop_assert!(spec_to.text.active_word(t).is_none(), "{to}: {t:?}");
        }
    }
    Ok(())
}

fn hostile() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<String>(),
        "[ -~]{0,40}",
        prop::collection::vec(
            prop::sample::select(vec![
                "LOGOPEN,",
                " py ,",
                "MSG,",
                "(",
                ")",
                ";",
                "%",
                "~",
                "\n",
                "\r",
                "\"",
                "'",
                "ABORT",
                "Ø",
                "é",
                " ",
                "X10",
                "G0",
                "M30",
                "*",
                "\t",
                "\u{0}",
                "probeopen",
                "LOGCLOSE",
                "debug ,",
                "END PGM",
            ]),
            0..8,
        )
        .prop_map(|v| v.concat()),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]

    #[test]
    fn any_comment_ported_reads_back_as_one_comment(
        text in hostile(),
        from in prop::sample::select(DIALECTS),
        to in prop::sample::select(DIALECTS),
        paren in any::<bool>(),
    ) {
        let style = if paren { CommentStyle::Paren } else { CommentStyle::Semicolon };
        port_one(&text, from, to, false, style)?;
    }

    #[test]
    fn any_message_ported_reads_back_as_one_message(
        text in hostile(),
        from in prop::sample::select(DIALECTS),
        to in prop::sample::select(&["linuxcnc", "siemens840d"][..]),
    ) {
        port_one(&text, from, to, true, CommentStyle::Paren)?;
    }

    #[test]
    fn any_stepnc_text_posted_reads_back_as_comments(
        text in hostile(),
        to in prop::sample::select(DIALECTS),
    ) {
        let spec = builtin(to).unwrap();
        let plain = cncc::post::post(&cncc::post::fixture::ex1(), &spec).unwrap();
        let mut project = cncc::post::fixture::ex1();
        project.id = text.clone();
        project.main_workplan.id = text.clone();
        project.main_workplan.elements.insert(0, cncc::stepnc::model::Executable::DisplayMessage {
            id: text.clone(),
            text: text.clone(),
        });
        let posted = cncc::post::post(&project, &spec);
        let Ok(posted) = posted else { return Ok(()) };
        let (want, _) = read(&plain.text, to);
        let (back, errors) = read(&posted.text, to);
        prop_assert!(!errors, "{to} {text:?}:\n{}", posted.text);
        let (t0, r0) = split(&want);
        let (t1, r1) = split(&back);
        // The message is one more comment; every line is still a comment.
        prop_assert_eq!(t1.len(), t0.len() + 1, "{} {:?}:\n{}", to, text, posted.text);
        let diff = first_difference(&r0, &r1);
        prop_assert!(diff.is_none(), "{to} {text:?}: {diff:?}");
        for t in &t1 {
            prop_assert!(spec.text.active_word(t).is_none(), "{to}: {t:?}");
        }
    }
}
