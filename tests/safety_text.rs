//! Issue 14, point 1: any text a program or a STEP-NC file says, written by
//! any writer for any target, reads back as exactly one comment or message
//! and the same moves (never as code). Ports and posts, all five dialects;
//! comments, messages, program names and every string of a STEP-NC project.

use cncc::dialect::{builtin, DialectSpec};
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
            let numbered = |n: &str| !n.is_empty() && n.bytes().all(|b| b.is_ascii_digit());
            match l
                .strip_prefix('N')
                .map(|r| r.split_once(' ').unwrap_or((r, "")))
            {
                Some((n, rest)) if numbered(n) => rest.trim(),
                _ => l,
            }
        })
        // The name is text: at the start, and in Klartext's END PGM.
        .filter(|l| !l.is_empty() && *l != "(blank)")
        .filter(|l| !l.starts_with("program-start") && !l.starts_with("program-end name="))
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

/// Where the text goes in the program that is ported.
#[derive(Clone, Copy, Debug)]
enum Place {
    Comment(CommentStyle),
    Message,
    /// The program's name (`O1 (NAME)`, `%_N_NAME_MPF`, `BEGIN PGM NAME`).
    Name,
}

/// `base(from)` with `text` placed in it.
fn with_text(from: &str, text: &str, place: Place) -> Program {
    let (mut p, errors) = read(base(from), from);
    assert!(!errors);
    let named = p
        .blocks
        .iter_mut()
        .flat_map(|b| &mut b.stmts)
        .find_map(|s| match &mut s.kind {
            StmtKind::ProgramStart { name, .. } => Some(name),
            _ => None,
        });
    if let (Place::Name, Some(name)) = (place, named) {
        *name = Some(text.to_string());
        return p;
    }
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
    let kind = match place {
        Place::Message => StmtKind::Message(Some(text.to_string())),
        Place::Comment(style) => StmtKind::Comment {
            text: text.to_string(),
            style,
        },
        Place::Name => StmtKind::ProgramStart {
            number: None,
            name: Some(text.to_string()),
        },
    };
    let stmt = Stmt::new(kind, span);
    match place {
        // A block of its own before the first.
        Place::Name => {
            let mut b = p.blocks[0].clone();
            (b.number, b.label, b.skip, b.stmts) = (None, None, None, vec![stmt]);
            p.blocks.insert(0, b);
        }
        _ => p.blocks[at].stmts.push(stmt),
    }
    p
}

/// `p` ported from `from` to `spec` (read back as `to`): the program
/// written, and its texts and other statements read back; `None` when the
/// target has no form for something (an error, never wrong text).
fn port_back(
    p: &Program,
    from: &str,
    to: &str,
    spec: &DialectSpec,
) -> Result<Option<(String, Vec<String>, Vec<String>)>, TestCaseError> {
    let spec_from = builtin(from).unwrap();
    let (q, _) = cncc::port::port_program(p, &spec_from, spec, &Default::default());
    let Ok(out) = cncc::emit::write_program(&q, spec) else {
        return Ok(None);
    };
    let (back, errors) = read(&out, to);
    prop_assert!(!errors, "{from}->{to}:\n{out}");
    let (texts, rest) = split(&back);
    Ok(Some((out, texts, rest)))
}

/// Ports `text` as a comment, message or program name from `from` to
/// `spec` (dialect `to`) and reads the result back: as many texts as the
/// same program with a plain text there, the same statements otherwise,
/// nothing the target would run, and 7-bit text for a 7-bit target.
fn port_one(
    text: &str,
    from: &str,
    to: &str,
    spec: &DialectSpec,
    place: Place,
) -> Result<(), TestCaseError> {
    let Some((_, want_texts, want_rest)) =
        port_back(&with_text(from, "PLAIN", place), from, to, spec)?
    else {
        return Ok(());
    };
    let Some((out, texts, rest)) = port_back(&with_text(from, text, place), from, to, spec)? else {
        return Ok(());
    };
    // A name the target cannot take as a name is kept as one comment
    // beside a name of the target's own (`%_N_O1_MPF ; text`).
    let extra = texts.len().checked_sub(want_texts.len());
    let fits = match place {
        Place::Name => matches!(extra, Some(0 | 1)),
        _ => extra == Some(0),
    };
    prop_assert!(
        fits,
        "{from}->{to} {text:?} as {place:?}: {texts:?} for {want_texts:?}\n{out}"
    );
    let diff = first_difference(&rest, &want_rest);
    prop_assert!(diff.is_none(), "{from}->{to} {text:?}: {diff:?}\n{out}");
    if from != to {
        // Not active on the target: what LinuxCNC would run is neutralised.
        if let Place::Comment(_) = place {
            for t in &texts {
                prop_assert!(spec.text.active_word(t).is_none(), "{to}: {t:?}");
            }
        }
        // A port to the same dialect keeps the characters its control read.
        if spec.text.ascii {
            prop_assert!(out.is_ascii(), "{from}->{to} {text:?}:\n{out}");
        }
    }
    Ok(())
}

/// LinuxCNC made 7-bit (a target that writes messages and reads ASCII
/// only: no built-in one does both).
fn linuxcnc_7_bit() -> DialectSpec {
    let mut spec = (*builtin("linuxcnc").unwrap()).clone();
    spec.text.ascii = true;
    spec
}

/// Every text a post writes from the project: its id, the workplan's,
/// every executable's, workpiece's, feature's, operation's and tool's,
/// and a message.
fn project_saying(text: &str) -> cncc::stepnc::model::Project {
    use cncc::stepnc::model::Executable as E;
    let mut project = cncc::post::fixture::ex1();
    let t = || text.to_string();
    project.id = t();
    project.main_workplan.id = t();
    for e in &mut project.main_workplan.elements {
        match e {
            E::Workingstep(w) => w.id = t(),
            E::Rapid(r) => r.id = t(),
            E::Workplan(w) => w.id = t(),
            E::ProgramStop { id } | E::OptionalStop { id } => *id = t(),
            E::DisplayMessage { id, text } => (*id, *text) = (t(), t()),
            E::Other(_) => {}
        }
    }
    project
        .main_workplan
        .elements
        .insert(0, E::DisplayMessage { id: t(), text: t() });
    project.workpieces.iter_mut().for_each(|w| w.id = t());
    project.features.iter_mut().for_each(|f| f.id = t());
    project.operations.iter_mut().for_each(|o| o.id = t());
    project.tools.iter_mut().for_each(|o| o.id = t());
    project
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
        port_one(&text, from, to, &builtin(to).unwrap(), Place::Comment(style))?;
    }

    #[test]
    fn any_message_ported_reads_back_as_one_message(
        text in hostile(),
        from in prop::sample::select(DIALECTS),
        to in prop::sample::select(DIALECTS),
    ) {
        // Fanuc, Haas and Klartext have no message: an error, skipped.
        port_one(&text, from, to, &builtin(to).unwrap(), Place::Message)?;
    }

    #[test]
    fn any_message_ported_to_a_7_bit_target_reads_back_in_ascii(
        text in hostile(),
        from in prop::sample::select(DIALECTS),
    ) {
        port_one(&text, from, "linuxcnc", &linuxcnc_7_bit(), Place::Message)?;
    }

    #[test]
    fn any_program_name_ported_reads_back_as_one_name(
        text in hostile(),
        from in prop::sample::select(DIALECTS),
        to in prop::sample::select(DIALECTS),
    ) {
        port_one(&text, from, to, &builtin(to).unwrap(), Place::Name)?;
    }

    #[test]
    fn any_stepnc_text_posted_reads_back_as_comments(
        text in hostile(),
        to in prop::sample::select(DIALECTS),
    ) {
        let spec = builtin(to).unwrap();
        let plain = cncc::post::post(&project_saying("PLAIN"), &spec);
        let posted = cncc::post::post(&project_saying(&text), &spec);
        let (Ok(plain), Ok(posted)) = (plain, posted) else { return Ok(()) };
        let (want, _) = read(&plain.text, to);
        let (back, errors) = read(&posted.text, to);
        prop_assert!(!errors, "{to} {text:?}:\n{}", posted.text);
        let (t0, r0) = split(&want);
        let (t1, r1) = split(&back);
        // As many comments as with plain text; every one still a comment.
        prop_assert_eq!(t1.len(), t0.len(), "{} {:?}:\n{}", to, text, posted.text);
        let diff = first_difference(&r0, &r1);
        prop_assert!(diff.is_none(), "{to} {text:?}: {diff:?}");
        for t in &t1 {
            prop_assert!(spec.text.active_word(t).is_none(), "{to}: {t:?}");
        }
        if spec.text.ascii {
            prop_assert!(posted.text.is_ascii(), "{to} {text:?}:\n{}", posted.text);
        }
    }
}
