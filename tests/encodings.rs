//! Every encoding real files have, in every dialect: UTF-8 with or without
//! a BOM, Latin-1, CP1250 and GBK comments (not valid UTF-8), CRLF, CR-only
//! line ends, no final newline. Each reads clean, and a round trip into
//! the same dialect (`cncc port --to` it) gives back the comment bytes.

mod common;
use common::*;

/// (dialect, extension, lines of a clean program; `{}` is the comment text).
const PROGRAMS: &[(&str, &str, &[&str])] = &[
    (
        "fanuc",
        "nc",
        &["%", "O1000 ({})", "G21 G90", "G0 X10. Y10.", "M30", "%"],
    ),
    (
        "haas",
        "nc",
        &["%", "O1000 ({})", "G20 G90", "G0 X1. Y1.", "M30", "%"],
    ),
    ("linuxcnc", "ngc", &["({})", "G21 G90", "G0 X10 Y10", "M2"]),
    (
        "siemens840d",
        "mpf",
        &["; {}", "T1 D1", "M6", "G0 X10 Y10", "M30"],
    ),
    (
        "heidenhain",
        "h",
        &[
            "0 BEGIN PGM T MM",
            "1 ; {}",
            "2 BLK FORM 0.1 Z X+0 Y+0 Z-20",
            "3 BLK FORM 0.2 X+100 Y+100 Z+0",
            "4 TOOL CALL 1 Z S1000",
            "5 L X+10 Y+10 FMAX",
            "6 END PGM T MM",
        ],
    ),
];

/// Comment texts as bytes: ASCII, UTF-8, Latin-1, CP1250 (`řez`), GBK (`刀具`).
const COMMENTS: &[&[u8]] = &[
    b"plain",
    "caf\u{e9} \u{5200}".as_bytes(),
    b"caf\xe9",
    b"\xf8ez",
    b"\xb5\xb6\xbe\xdf",
];

/// (name, BOM, line end, final line end).
const FORMS: &[(&str, bool, &str, bool)] = &[
    ("lf", false, "\n", true),
    ("bom-crlf", true, "\r\n", true),
    ("crlf-no-final", false, "\r\n", false),
    ("cr", false, "\r", true),
    ("bom-lf-no-final", true, "\n", false),
];

fn program(lines: &[&str], comment: &[u8], form: &(&str, bool, &str, bool)) -> Vec<u8> {
    let (_, bom, end, last) = *form;
    let mut out = Vec::new();
    if bom {
        out.extend_from_slice(b"\xEF\xBB\xBF");
    }
    for (i, l) in lines.iter().enumerate() {
        let (a, b) = l.split_once("{}").unwrap_or((l, ""));
        out.extend_from_slice(a.as_bytes());
        if l.contains("{}") {
            out.extend_from_slice(comment);
        }
        out.extend_from_slice(b.as_bytes());
        if i + 1 < lines.len() || last {
            out.extend_from_slice(end.as_bytes());
        }
    }
    out
}

fn dir() -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("cncc-encodings-{}", std::process::id()));
    std::fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn every_encoding_checks_clean_in_every_dialect() {
    let dir = dir();
    for (dialect, ext, lines) in PROGRAMS {
        for (ci, comment) in COMMENTS.iter().enumerate() {
            for form in FORMS {
                let path = dir.join(format!("{dialect}-{ci}-{}.{ext}", form.0));
                std::fs::write(&path, program(lines, comment, form)).unwrap();
                let p = path.to_str().unwrap();
                let o = cncc(&["check", "--dialect", dialect, p]);
                let err = stderr(&o);
                assert!(o.status.success(), "{dialect} {ci} {}:\n{err}", form.0);
                assert!(!err.contains("error"), "{dialect} {ci} {}:\n{err}", form.0);
                let cr_note = err.contains("W0006");
                assert_eq!(cr_note, form.0 == "cr", "{dialect} {}:\n{err}", form.0);
            }
        }
    }
}

#[test]
fn a_round_trip_keeps_comment_bytes_bom_and_line_ends() {
    let dir = dir();
    for (dialect, ext, lines) in PROGRAMS {
        for (ci, comment) in COMMENTS.iter().enumerate() {
            for form in FORMS.iter().filter(|f| f.3) {
                let bytes = program(lines, comment, form);
                let path = dir.join(format!("rt-{dialect}-{ci}-{}.{ext}", form.0));
                std::fs::write(&path, &bytes).unwrap();
                let p = path.to_str().unwrap();
                let o = cncc(&["port", p, "--from", dialect, "--to", dialect]);
                assert!(o.status.success(), "{dialect} {ci}: {}", stderr(&o));
                assert_eq!(
                    String::from_utf8_lossy(&o.stdout),
                    String::from_utf8_lossy(&bytes),
                    "{dialect} {ci} {}",
                    form.0
                );
                assert_eq!(o.stdout, bytes, "{dialect} {ci} {}", form.0);
            }
        }
    }
}
