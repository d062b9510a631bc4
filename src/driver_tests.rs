//! The streamed reading (buffers read in place, lines across reads, UTF-8
//! checked per buffer) agrees with reading a whole decoded text.

use super::*;
use crate::dialect::builtin::builtin;
use std::io::BufReader;

/// Texts with every kind of line ending, empty lines, a last line without
/// ending, and lines that are not UTF-8 (read as Latin-1).
fn samples() -> Vec<Vec<u8>> {
    let mut latin = b"G0 X1\n(caf\xe9)\nG1 X2 Y3 F100\r\n".to_vec();
    latin.extend_from_slice(b"\xff\xfe\n\nM2");
    vec![
        b"".to_vec(),
        b"\n".to_vec(),
        b"G0 X1\nG1 Y2 F3\n".to_vec(),
        b"G0 X1\r\nG1 Y2 F3\r\n\r\nM30".to_vec(),
        "(caf\u{e9} \u{2713})\nX1\rY2\n\rZ3\r".as_bytes().to_vec(),
        latin,
        b"N10 G1 X1 X2 G999\nG2 X1 Y1\nG80 X2\nM30\n".to_vec(),
        b"\xEF\xBB\xBFG0 X1\r\nM30\r\n".to_vec(),
        b"\xEF\xBBG0 X1\n(\xe9)\n".to_vec(),
        b"G0 X1\rG1 X2 F100\rM30\r".to_vec(),
    ]
}

/// `(line, offset)` pairs as the streamed reader gives them.
fn streamed(bytes: &[u8], capacity: usize) -> Vec<(String, u64)> {
    let mut out = Vec::new();
    let mut offset = 0u64;
    for_each_line(BufReader::with_capacity(capacity, bytes), |text| {
        out.push((strip_ending(text).to_owned(), offset));
        offset += text.len() as u64;
        Ok(true)
    })
    .unwrap();
    out
}

#[test]
fn streamed_lines_match_the_decoded_text() {
    for bytes in samples() {
        let text = decode(&bytes);
        let whole: Vec<(String, u64)> = lines(&text)
            .map(|(l, o)| (l.to_owned(), o as u64))
            .collect();
        for capacity in [1, 2, 3, 5, 8, 64, 1 << 16] {
            assert_eq!(
                streamed(&bytes, capacity),
                whole,
                "capacity {capacity}, text {text:?}"
            );
        }
    }
}

#[test]
fn streamed_check_matches_whole_read() {
    let spec = builtin("linuxcnc").unwrap();
    for bytes in samples() {
        let text = decode(&bytes);
        let (program, mut whole) = read_program(&text, FileId(0), &spec);
        whole.truncate(crate::diag::MAX_KEPT);
        for capacity in [1, 3, 7, 1 << 16] {
            let mut blocks = Vec::new();
            let r = check_stream(
                BufReader::with_capacity(capacity, &bytes[..]),
                FileId(0),
                &spec,
                |b, _| blocks.push(b.clone()),
            )
            .unwrap();
            assert_eq!(r.bytes, text.len() as u64);
            assert_eq!(r.diagnostics, whole, "capacity {capacity}, text {text:?}");
            let spans: Vec<_> = program
                .blocks
                .iter()
                .map(|b| (b.span, b.stmts.len()))
                .collect();
            let got: Vec<_> = blocks.iter().map(|b| (b.span, b.stmts.len())).collect();
            assert_eq!(got, spans);
        }
    }
}

#[test]
fn lines_at_finds_lines_across_reads() {
    let bytes = b"G0 X1\r\n(caf\xe9)\nG1 X2\nM2".to_vec();
    let text = decode(&bytes);
    let offsets: Vec<u32> = (0..=text.len() as u32).collect();
    let want = lines_at(BufReader::with_capacity(1 << 16, &bytes[..]), &offsets).unwrap();
    assert_eq!(want.len(), 4);
    for capacity in [1, 2, 5] {
        let got = lines_at(BufReader::with_capacity(capacity, &bytes[..]), &offsets).unwrap();
        assert_eq!(
            got.iter()
                .map(|k| (&k.text, k.start, k.line))
                .collect::<Vec<_>>(),
            want.iter()
                .map(|k| (&k.text, k.start, k.line))
                .collect::<Vec<_>>()
        );
    }
    assert!(lines_at(BufReader::new(&bytes[..]), &[])
        .unwrap()
        .is_empty());
}
