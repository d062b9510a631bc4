//! Siemens milling cycles expanded into moves: POCKET1 and POCKET3
//! (rectangular pockets), POCKET2 and POCKET4 (circular pockets), SLOT1,
//! SLOT2 and LONGHOLE (slots on a circle), CYCLE71 (face milling).
//! CYCLE72 (contour milling) is not expanded: its contour is another
//! program and its approach and departure paths are not documented well
//! enough [?]; it keeps the W0510 warning.
//!
//! Sources: parameter lists and meanings from `reference/dialects.md` §1.7
//! (classic SINUMERIK cycle documentation [S]/[K]). The tool paths are not
//! specified there in detail; what is built here is a plain, documented
//! strategy, every choice marked `[?]`:
//! * depth: DPR (relative to RFP, unsigned) wins when given and not 0,
//!   else DP; levels from RFP down in equal steps of at most MID (0: one).
//! * stepover in the plane: the tool radius [?] (POCKET1/2 have no width
//!   infeed parameter), MIDA for CYCLE71 (0: the tool radius).
//! * the tool radius is that of the active cutting edge (D).

mod face;
mod pen;
mod pocket;
mod pocket34;
mod slots;

use crate::diag::{Code, Diagnostic};
use crate::interp::host::MotionHost;

/// Does this module expand the cycle?
pub fn expands(name: &str) -> bool {
    matches!(
        name,
        "POCKET1" | "POCKET2" | "POCKET3" | "POCKET4" | "SLOT1" | "SLOT2" | "LONGHOLE" | "CYCLE71"
    )
}

/// What became of a call.
#[derive(Debug, PartialEq)]
pub enum Outcome {
    Done,
    /// The arguments ask for a variant whose path is not defined well
    /// enough: the call is left out (W0510), for this reason.
    NotExpanded(String),
}

/// The argument list read by position; empty slots are 0.
pub struct Args<'a>(pub &'a [Option<f64>]);

impl Args<'_> {
    pub fn get(&self, i: usize) -> f64 {
        self.0.get(i).copied().flatten().unwrap_or(0.0)
    }
    pub fn opt(&self, i: usize) -> Option<f64> {
        self.0.get(i).copied().flatten()
    }
}

pub fn bad(msg: String) -> Diagnostic {
    Diagnostic::new(Code::CycleBadArgument, msg)
}

/// Most passes (levels × rings × lines) one call may produce.
pub const MAX_PASSES: f64 = 100_000.0;

/// Levels from `top` down to `bottom`, equal steps of at most `mid`.
pub fn levels(name: &str, top: f64, bottom: f64, mid: f64) -> Result<Vec<f64>, Diagnostic> {
    if bottom > top {
        return Err(bad(format!(
            "{name}: the depth {bottom} lies above the reference plane {top}"
        )));
    }
    let total = top - bottom;
    let mid = mid.abs();
    let n = if mid > 0.0 {
        (total / mid - 1e-9).ceil().max(1.0)
    } else {
        1.0
    };
    if n > MAX_PASSES {
        return Err(bad(format!("{name}: more than {MAX_PASSES} depth passes")));
    }
    let n = n as usize;
    Ok((1..=n)
        .map(|k| {
            if k == n {
                bottom
            } else {
                top - total * k as f64 / n as f64
            }
        })
        .collect())
}

/// Expands `name` (see [`expands`]); `radius` is the active tool radius
/// in program units.
pub fn run(
    host: &mut dyn MotionHost,
    name: &str,
    args: &[Option<f64>],
    radius: f64,
) -> Result<Outcome, Diagnostic> {
    let a = Args(args);
    let done = match name {
        "POCKET1" => pocket::pocket1(host, &a, radius),
        "POCKET2" => pocket::pocket2(host, &a, radius),
        "POCKET3" => return pocket34::pocket3(host, &a, radius),
        "POCKET4" => return pocket34::pocket4(host, &a, radius),
        "SLOT1" => slots::slot1(host, &a, radius),
        "SLOT2" => slots::slot2(host, &a, radius),
        "LONGHOLE" => slots::longhole(host, &a, radius),
        "CYCLE71" => face::cycle71(host, &a, radius),
        _ => Err(bad(format!(
            "{name} is not a milling cycle this interpreter expands"
        ))),
    };
    done.map(|()| Outcome::Done)
}
