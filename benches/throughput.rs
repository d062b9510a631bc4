//! Throughput of reading and checking (`cncc check --no-run`) over large
//! generated CAM programs; `benches/canon.rs` measures the runs.
//!
//! `cargo bench --bench throughput` generates programs of about 3 MB and
//! 30 MB with `../shared/bench/gen_program.py` (the 30 MB one also with
//! `--line-numbers` and `--explicit-motion`), streams each through the
//! checker on one thread (best of three), and prints MB/s and the
//! process's peak resident memory after each, so a memory that grows with
//! the program shows. The target is 100 MB/s with flat memory. Figures are
//! printed, never asserted.

use cncc::dialect::builtin::builtin;
use cncc::driver::check_stream;
use cncc::span::FileId;
use std::io::BufReader;
use std::path::{Path, PathBuf};

#[path = "support/mod.rs"]
mod support;
use std::time::Instant;
use support::generate;

/// Peak resident set size of this process, in MiB (Linux).
fn peak_rss_mib() -> f64 {
    let status = std::fs::read_to_string("/proc/self/status").unwrap_or_default();
    status
        .lines()
        .find(|l| l.starts_with("VmHWM:"))
        .and_then(|l| l.split_whitespace().nth(1))
        .and_then(|kb| kb.parse::<f64>().ok())
        .map(|kb| kb / 1024.0)
        .unwrap_or(f64::NAN)
}

fn bench_check(path: &Path, dialect: &str) -> (f64, u64, usize) {
    let spec = builtin(dialect).expect("dialect");
    let best = (0..3)
        .map(|_| {
            let f = std::fs::File::open(path).expect("open");
            let start = Instant::now();
            let r = check_stream(
                BufReader::with_capacity(1 << 16, f),
                FileId(0),
                &spec,
                |_, _| {},
            )
            .expect("read");
            (start.elapsed().as_secs_f64(), r.bytes, r.diagnostics.len())
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap();
    best
}

fn main() {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target/bench-programs");
    std::fs::create_dir_all(&dir).expect("mkdir");
    println!(
        "{:<34} {:>8} {:>10} {:>10} {:>14}",
        "program", "MB", "seconds", "MB/s", "peak RSS MiB"
    );
    let programs: [(u64, &[&str], &str); 4] = [
        (215_000, &[], "cam-3MB.ngc"),
        (2_150_000, &[], "cam-30MB.ngc"),
        (2_150_000, &["--line-numbers"], "cam-30MB-n.ngc"),
        (2_150_000, &["--explicit-motion"], "cam-30MB-x.ngc"),
    ];
    for (lines, flags, name) in programs {
        let path = dir.join(name);
        if !generate(lines, flags, &path) {
            return;
        }
        for dialect in ["linuxcnc", "fanuc"] {
            let (secs, bytes, ndiag) = bench_check(&path, dialect);
            let mb = bytes as f64 / 1e6;
            println!(
                "{:<34} {:>8.1} {:>10.3} {:>10.1} {:>14.1}{}",
                format!("check --no-run {name} ({dialect})"),
                mb,
                secs,
                mb / secs,
                peak_rss_mib(),
                if ndiag > 0 {
                    format!("  ({ndiag} diagnostics)")
                } else {
                    String::new()
                }
            );
        }
    }
}
