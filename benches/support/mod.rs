//! What the subprocess benchmarks share: the crate root, generated CAM
//! programs from `../shared/bench/gen_program.py`, and one timed run of a
//! command under `/usr/bin/time -f %M` for its peak resident memory.

#![allow(dead_code)] // each bench uses its own subset

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The crate's root directory.
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Generates a program of about `lines` lines at `out` (kept between
/// runs); false, with a note, when the generator is absent or fails.
pub fn generate(lines: u64, flags: &[&str], out: &Path) -> bool {
    let gen = root().join("../shared/bench/gen_program.py");
    if !gen.exists() {
        eprintln!("note: ../shared/bench/gen_program.py is absent; benchmark skipped");
        return false;
    }
    out.exists()
        || Command::new("python3")
            .arg(&gen)
            .args(["--lines", &lines.to_string()])
            .args(flags)
            .arg("-o")
            .arg(out)
            .status()
            .map(|s| s.success())
            .unwrap_or(false)
}

/// One run, its output discarded.
#[derive(Clone, Copy, Debug)]
pub struct Run {
    pub secs: f64,
    pub peak_mib: f64,
    pub exit: i32,
}

/// Runs `program args` under `/usr/bin/time`; None when it cannot start
/// or its peak memory cannot be read.
pub fn measure(program: &Path, args: &[&OsStr]) -> Option<Run> {
    let rss_file = std::env::temp_dir().join(format!("cncc-bench-rss-{}", std::process::id()));
    let start = Instant::now();
    let status = Command::new("/usr/bin/time")
        .arg("-o")
        .arg(&rss_file)
        .args(["-f", "%M"])
        .arg(program)
        .args(args)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .ok()?;
    let secs = start.elapsed().as_secs_f64();
    let text = std::fs::read_to_string(&rss_file).ok()?;
    let kb: f64 = text.lines().rev().find_map(|l| l.trim().parse().ok())?;
    Some(Run {
        secs,
        peak_mib: kb / 1024.0,
        exit: status.code().unwrap_or(-1),
    })
}

/// The fastest of `n` runs (other work on the machine only slows a run
/// down), with the largest peak memory and the first failing exit code.
pub fn best_of(n: usize, program: &Path, args: &[&OsStr]) -> Option<Run> {
    let runs: Vec<Run> = (0..n).filter_map(|_| measure(program, args)).collect();
    let first = *runs.first()?;
    Some(Run {
        secs: runs.iter().map(|r| r.secs).fold(f64::INFINITY, f64::min),
        peak_mib: runs.iter().map(|r| r.peak_mib).fold(0.0, f64::max),
        exit: runs
            .iter()
            .map(|r| r.exit)
            .find(|c| *c != 0)
            .unwrap_or(first.exit),
    })
}
