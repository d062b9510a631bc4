//! The streamed port (`src/port/stream.rs`) against the whole port: every
//! program of `tests/programs/`, `../shared/corpus/` and `../shared/field/`
//! that reads cleanly is ported to each other dialect both ways, the
//! stream cut into chunks of two blocks (so every run of three or more
//! moves is chunked, far more often than the 4096-block chunks the
//! command uses), and the two texts must be the same byte for byte.
//! Where the whole port fails, the stream must give up (the command then
//! ports whole and reports it). The field part is skipped with a note
//! when `../shared` is absent.

mod common;

use cncc::dialect::builtin::builtin;
use cncc::port::stream::{port_text, Chunking};
use cncc::port::{port_program, PortOptions};
use cncc::source::SourceMap;
use std::path::Path;

const DIALECTS: [&str; 5] = ["fanuc", "haas", "heidenhain", "linuxcnc", "siemens840d"];

/// Ports `path` (read as `from`) to every other dialect both ways; the
/// differences found, and how many ports were streamed.
fn both_ways(from: &str, path: &Path, streamed: &mut (usize, usize)) -> Vec<String> {
    both_ways_in(from, path, Chunking { chunk: 2 }, streamed)
}

/// [`both_ways`] with the stream cut as `chunking` says.
fn both_ways_in(
    from: &str,
    path: &Path,
    chunking: Chunking,
    streamed: &mut (usize, usize),
) -> Vec<String> {
    let mut out = Vec::new();
    let Ok(bytes) = std::fs::read(path) else {
        return out;
    };
    let text = cncc::driver::decode(&bytes);
    let spec = builtin(from).unwrap();
    let mut files = SourceMap::new();
    let id = files.add(path.display().to_string(), text.clone());
    let (program, read) = cncc::driver::read_program(&text, id, &spec);
    if read.iter().any(|d| d.is_error()) {
        return out;
    }
    let opts = PortOptions::default();
    for to in DIALECTS.iter().filter(|t| **t != from) {
        let target = builtin(to).unwrap();
        let (ported, diags) = port_program(&program, &spec, &target, &opts);
        let whole = if diags.iter().any(|d| d.is_error()) {
            None
        } else {
            cncc::emit::write_program(&ported, &target).ok()
        };
        let stream = port_text(&text, id, &spec, &target, &opts, chunking);
        let name = format!("{} -> {to}", path.display());
        match (whole, stream) {
            (Some(w), Some(s)) => {
                streamed.0 += 1;
                streamed.1 += s.chunked;
                if let Some(d) = common::first_difference(&w, &s.text) {
                    out.push(format!("{name}: {d}"));
                }
            }
            (None, Some(_)) => {
                out.push(format!("{name}: the whole port fails, the stream does not"))
            }
            (_, None) => {}
        }
    }
    out
}

fn check_tree(root: &Path, dialect: &str, diffs: &mut Vec<String>, streamed: &mut (usize, usize)) {
    for f in common::files_in(&root.join(dialect)) {
        if f.extension().is_some_and(|e| e == "md") {
            continue;
        }
        diffs.extend(both_ways(dialect, &f, streamed));
    }
}

#[test]
fn the_streamed_port_is_the_whole_port_on_the_test_programs() {
    let (mut diffs, mut streamed) = (Vec::new(), (0, 0));
    for d in DIALECTS {
        check_tree(
            &common::root().join("tests/programs"),
            d,
            &mut diffs,
            &mut streamed,
        );
    }
    judge(&diffs, streamed, (50, 200));
}

#[test]
fn the_streamed_port_is_the_whole_port_on_real_programs() {
    let Some(shared) = common::shared() else {
        return;
    };
    let (mut diffs, mut streamed) = (Vec::new(), (0, 0));
    for top in ["corpus", "field"] {
        for d in DIALECTS {
            check_tree(&shared.join(top), d, &mut diffs, &mut streamed);
        }
    }
    judge(&diffs, streamed, (100, 10_000));
}

/// A CAM-like program of about 1.5 MB: set-up, long runs of modal moves
/// with arcs, a drilling cycle with its positions between them, tool
/// changes, the end.
fn generated() -> String {
    let mut t = String::from("%\nO1000 (STREAM TEST)\nG21 G90 G17 G40 G49 G80\nT1 M6\nG54 G0 X0 Y0 S8000 M3\nG43 H1 Z25.\n");
    for pass in 0..100 {
        t.push_str(&format!("G0 X0 Y{}.\nG1 Z-{}.5 F600\n", pass, pass % 5));
        for i in 1..1000 {
            let x = i as f64 * 0.1;
            let z = -((i % 17) as f64) * 0.01 - (pass % 5) as f64;
            t.push_str(&format!("X{x:.1} Z{z:.3}\n"));
            if i % 250 == 0 {
                t.push_str(&format!(
                    "G2 X{:.1} Y{pass}.5 I0.25 J0.25\nG1 Y{pass}.\n",
                    x + 0.5
                ));
            }
        }
        t.push_str("G0 Z25.\n");
        if pass == 50 {
            t.push_str("T2 M6\nG0 X5. Y5. S2000 M3\nG43 H2 Z25.\nG98 G81 X5. Y5. Z-10. R2. F200\n");
            for k in 0..300 {
                t.push_str(&format!("X{}. Y5.\n", 5 + k % 50));
            }
            t.push_str("G80\nT1 M6\nG0 X0 Y0 S8000 M3\nG43 H1 Z25.\n");
        }
    }
    t.push_str("M5 M9\nG91 G28 Z0.\nM30\n%\n");
    t
}

#[test]
fn a_large_program_streams_the_same_text_and_verifies() {
    let text = generated();
    assert!(text.len() > (1 << 20), "{} bytes", text.len());
    let spec = builtin("fanuc").unwrap();
    let mut files = SourceMap::new();
    let id = files.add("big.nc", text.clone());
    let (program, _) = cncc::driver::read_program(&text, id, &spec);
    let opts = PortOptions::default();
    for to in ["siemens840d", "heidenhain", "linuxcnc"] {
        let target = builtin(to).unwrap();
        let (ported, _) = port_program(&program, &spec, &target, &opts);
        let whole = cncc::emit::write_program(&ported, &target).unwrap();
        let s = port_text(&text, id, &spec, &target, &opts, Chunking::default())
            .unwrap_or_else(|| panic!("{to}: not streamed"));
        assert!(s.chunked > 80_000, "{to}: {} blocks in chunks", s.chunked);
        assert_eq!(common::first_difference(&whole, &s.text), None, "{to}");
    }
    let dir = std::env::temp_dir().join(format!("cncc-stream-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (src, out) = (dir.join("big.nc"), dir.join("big.h"));
    std::fs::write(&src, &text).unwrap();
    let o = common::cncc(&[
        "port",
        "--from",
        "fanuc",
        "--to",
        "heidenhain",
        "--verify",
        src.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ]);
    let err = common::stderr(&o);
    assert!(o.status.success(), "{err}");
    assert!(err.contains("verify: OK"), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// The large real programs (`../shared/field/big/`, 1.3 to 3.9 MB, the
/// dialect first in the name) as the command cuts them.
#[test]
fn the_streamed_port_is_the_whole_port_on_large_real_programs() {
    let Some(shared) = common::shared() else {
        return;
    };
    let (mut diffs, mut streamed) = (Vec::new(), (0, 0));
    for f in common::files_in(&shared.join("field/big")) {
        let name = f.file_name().unwrap().to_string_lossy().to_string();
        let from = DIALECTS
            .iter()
            .find(|d| name.starts_with(&format!("{d}_")))
            .copied()
            .unwrap_or("linuxcnc");
        diffs.extend(both_ways_in(from, &f, Chunking::default(), &mut streamed));
    }
    judge(&diffs, streamed, (4, 100_000));
}

/// No differences, and enough streamed (ports, blocks in chunks) that
/// the comparison means something.
fn judge(diffs: &[String], streamed: (usize, usize), least: (usize, usize)) {
    eprintln!(
        "{} ports streamed, {} blocks in chunks",
        streamed.0, streamed.1
    );
    assert!(
        diffs.is_empty(),
        "{} differ:\n{}",
        diffs.len(),
        diffs.join("\n")
    );
    assert!(
        streamed.0 >= least.0,
        "only {} ports were streamed",
        streamed.0
    );
    assert!(
        streamed.1 >= least.1,
        "only {} blocks were ported in chunks",
        streamed.1
    );
}

/// A run of moves `n` blocks long.
fn moves(n: usize) -> String {
    (0..n)
        .map(|i| format!("G1 X{}. Y{}.\n", i % 50, i % 7))
        .collect()
}

/// Streams `text` (read as `from`) to the 840D in chunks of two blocks.
fn stream_of(from: &str, text: &str) -> Option<cncc::port::stream::StreamedPort> {
    let spec = builtin(from).unwrap();
    let target = builtin("siemens840d").unwrap();
    let mut files = SourceMap::new();
    let id = files.add("t", text.to_string());
    port_text(
        text,
        id,
        &spec,
        &target,
        &PortOptions::default(),
        Chunking { chunk: 2 },
    )
}

#[test]
fn a_program_with_a_loop_streams_and_one_that_jumps_to_a_number_goes_whole() {
    // Jumps to an o-word land on its labelled block, never in a run.
    let looped = format!(
        "%\nG21 G90 G17 F500\n#1=0\no100 while [#1 LT 2]\n#1=[#1+1]\no100 endwhile\n{}M2\n%\n",
        moves(40)
    );
    let s = stream_of("linuxcnc", &looped).expect("a program with a loop streams");
    assert!(s.chunked > 30, "only {} blocks chunked", s.chunked);
    // `GOTO 10` may land on a numbered move inside a run: ported whole.
    let jumps = format!(
        "%\nO1\nG21 G90 G17 F500\n#1=0\n{}N10 G1 X1. Y1.\n{}#1=#1+1\nIF [#1 LT 2] GOTO 10\nM30\n%\n",
        moves(20),
        moves(20)
    );
    assert!(stream_of("fanuc", &jumps).is_none());
}
