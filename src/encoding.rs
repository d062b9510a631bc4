//! The bytes of a program file as text, and text back as bytes.
//!
//! Real files come in every encoding a shop's PC had: UTF-8 with or
//! without a byte order mark, Latin-1, CP1250 or GBK comments (not valid
//! UTF-8), and CRLF, LF or CR-only line ends. Reading never fails and never
//! loses a byte: a UTF-8 BOM is dropped, a line that is not valid UTF-8 is
//! read as Latin-1 (one char per byte, whatever the real code page was), and
//! a lone CR ends a line. [`SourceEncoding`] remembers what the file was so
//! that a program written back into the same dialect ([`encode`]) has the
//! same comment bytes, BOM and line ends.
//!
//! All the text offsets cncc uses (spans) are offsets in the decoded text,
//! which the whole-file ([`decode`]) and streamed readers agree on.

/// The UTF-8 byte order mark.
pub const BOM: &[u8] = b"\xEF\xBB\xBF";

/// What a file's bytes were, for writing a result the same way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SourceEncoding {
    /// The file began with a UTF-8 byte order mark.
    pub bom: bool,
    /// Some line was not valid UTF-8 and was read one char per byte.
    pub bytes: bool,
    /// How its lines ended (the first line end found).
    pub ending: LineEnding,
}

/// A file's line ends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LineEnding {
    #[default]
    Lf,
    CrLf,
    /// Classic Mac OS and some old DNC software.
    Cr,
}

impl LineEnding {
    pub fn as_str(self) -> &'static str {
        match self {
            LineEnding::Lf => "\n",
            LineEnding::CrLf => "\r\n",
            LineEnding::Cr => "\r",
        }
    }
}

/// Looks at a file's bytes: BOM, encoding, line ends.
pub fn sniff(bytes: &[u8]) -> SourceEncoding {
    let bom = bytes.starts_with(BOM);
    let ending = match bytes.iter().position(|&b| b == b'\n' || b == b'\r') {
        Some(i) if bytes[i] == b'\n' => LineEnding::Lf,
        Some(i) if bytes.get(i + 1) == Some(&b'\n') => LineEnding::CrLf,
        Some(_) => LineEnding::Cr,
        None => LineEnding::Lf,
    };
    SourceEncoding {
        bom,
        bytes: std::str::from_utf8(bytes).is_err(),
        ending,
    }
}

/// Decodes a file's bytes: UTF-8 when valid, otherwise each line that is
/// not valid UTF-8 as Latin-1 (old controllers' files), so that no byte is
/// lost. A leading UTF-8 BOM is dropped. Offsets in the result are offsets
/// in the decoded text.
pub fn decode(bytes: &[u8]) -> String {
    let bytes = bytes.strip_prefix(BOM).unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(s) => s.to_owned(),
        Err(_) => {
            let mut out = String::with_capacity(bytes.len());
            for line in bytes.split_inclusive(|&b| b == b'\n') {
                decode_line_into(line, &mut out);
            }
            out
        }
    }
}

/// Appends one line's bytes: UTF-8 if valid, else one char per byte.
pub fn decode_line_into(line: &[u8], out: &mut String) {
    match std::str::from_utf8(line) {
        Ok(s) => out.push_str(s),
        Err(_) => out.extend(line.iter().map(|&b| b as char)),
    }
}

/// Text written for a program read from a file of encoding `enc`: its
/// line ends and BOM, and, when the file was read one char per byte, every
/// char up to U+00FF as that one byte again (so a Latin-1, CP1250 or GBK
/// comment keeps its bytes). [?] A file that mixes valid UTF-8 lines with
/// non-ASCII chars and lines that are not UTF-8 gets its UTF-8 lines'
/// non-ASCII chars written as single bytes.
pub fn encode(text: &str, enc: SourceEncoding) -> Vec<u8> {
    encode_cow(text, enc).into_owned()
}

/// [`encode`], without a copy where the text already is those bytes
/// (UTF-8 without a BOM, `\n` line ends, no `\r`): a large program's
/// output is not held twice.
pub fn encode_cow(text: &str, enc: SourceEncoding) -> std::borrow::Cow<'_, [u8]> {
    let plain = !enc.bom && !enc.bytes && enc.ending.as_str() == "\n" && !text.contains('\r');
    if plain {
        return std::borrow::Cow::Borrowed(text.as_bytes());
    }
    std::borrow::Cow::Owned(encode_copy(text, enc))
}

fn encode_copy(text: &str, enc: SourceEncoding) -> Vec<u8> {
    let mut out = Vec::with_capacity(text.len() + 3);
    if enc.bom {
        out.extend_from_slice(BOM);
    }
    let ending = enc.ending.as_str().as_bytes();
    for piece in text.split_inclusive('\n') {
        let (body, nl) = match piece.strip_suffix('\n') {
            Some(b) => (b.strip_suffix('\r').unwrap_or(b), true),
            None => (piece, false),
        };
        if enc.bytes {
            let mut buf = [0u8; 4];
            for c in body.chars() {
                match u8::try_from(u32::from(c)) {
                    Ok(b) => out.push(b),
                    Err(_) => out.extend_from_slice(c.encode_utf8(&mut buf).as_bytes()),
                }
            }
        } else {
            out.extend_from_slice(body.as_bytes());
        }
        if nl {
            out.extend_from_slice(ending);
        }
    }
    out
}

/// Splits a piece of text that has no LF (a CR-only file, or the last
/// line of a file) at each lone CR, calling `f` with each piece with its
/// ending. A line that ends with LF is passed whole: a stray CR inside a
/// line of an LF or CR LF file (a CAM's comment) stays blank space.
pub fn split_lone_cr<'a, E>(
    text: &'a str,
    mut f: impl FnMut(&'a str, bool) -> Result<bool, E>,
) -> Result<bool, E> {
    if text.ends_with('\n') {
        return f(text, false);
    }
    let b = text.as_bytes();
    let mut start = 0;
    let mut i = 0;
    while let Some(k) = b[i..].iter().position(|&c| c == b'\r') {
        let at = i + k;
        i = at + 1;
        if b.get(at + 1) == Some(&b'\n') {
            continue;
        }
        if !f(&text[start..=at], true)? {
            return Ok(false);
        }
        start = at + 1;
    }
    if start < text.len() || start == 0 {
        return f(&text[start..], false);
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pieces(text: &str) -> Vec<(String, bool)> {
        let mut out = Vec::new();
        split_lone_cr::<()>(text, |p, cr| {
            out.push((p.to_string(), cr));
            Ok(true)
        })
        .unwrap();
        out
    }

    #[test]
    fn lone_cr_ends_a_line_crlf_does_not_split() {
        assert_eq!(pieces("G0 X1\r\n"), [("G0 X1\r\n".into(), false)]);
        assert_eq!(
            pieces("G0\rG1\rM30\r"),
            [
                ("G0\r".into(), true),
                ("G1\r".into(), true),
                ("M30\r".into(), true)
            ]
        );
        assert_eq!(pieces("a\rb\n"), [("a\rb\n".into(), false)]);
        assert_eq!(pieces("a\rb"), [("a\r".into(), true), ("b".into(), false)]);
        assert_eq!(pieces(""), [("".into(), false)]);
    }

    #[test]
    fn bom_is_dropped_and_latin1_kept_byte_for_byte() {
        assert_eq!(decode(b"\xEF\xBB\xBFG0 X1\n"), "G0 X1\n");
        let latin = b"G0 X1 (caf\xe9)\r\nM30\r\n";
        let enc = sniff(latin);
        assert!(enc.bytes && !enc.bom);
        assert_eq!(enc.ending, LineEnding::CrLf);
        assert_eq!(decode(latin), "G0 X1 (caf\u{e9})\r\nM30\r\n");
        assert_eq!(encode(&decode(latin), enc), latin);
    }

    #[test]
    fn gbk_and_cp1250_bytes_come_back_unchanged() {
        // GBK `(刀具)` and CP1250 `(řez)`: not UTF-8, read byte for byte.
        for bytes in [&b"(\xb5\xb6\xbe\xdf)\nM30\n"[..], b"(\xf8ez)\nM30\n"] {
            let enc = sniff(bytes);
            assert_eq!(encode(&decode(bytes), enc), bytes);
        }
    }

    #[test]
    fn utf8_with_bom_and_cr_only_ends_come_back() {
        let bytes = "\u{feff}(caf\u{e9})\rM30\r".as_bytes();
        let enc = sniff(bytes);
        assert!(enc.bom && !enc.bytes);
        assert_eq!(enc.ending, LineEnding::Cr);
        let text = "(caf\u{e9})\nM30\n";
        assert_eq!(encode(text, enc), bytes);
    }
}
