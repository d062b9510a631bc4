//! Entry points for fuzz targets and property tests: whatever the input,
//! reading, checking and writing must not panic, hang or blow up memory.

use crate::dialect::builtin::builtin;
use crate::driver::{decode, read_program};
use crate::emit::write_program;
use crate::span::FileId;

/// Reads `data` as a program of `dialect`; if it reads without errors,
/// writes it back and reads the result again.
pub fn read_and_write(dialect: &str, data: &[u8]) {
    let Some(spec) = builtin(dialect) else { return };
    let text = decode(data);
    let (program, diags) = read_program(&text, FileId(0), &spec);
    if diags.iter().any(|d| d.is_error()) {
        return;
    }
    if let Ok(out) = write_program(&program, &spec) {
        let _ = read_program(&out, FileId(1), &spec);
    }
}
