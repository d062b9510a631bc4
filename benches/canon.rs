//! `cncc canon` against LinuxCNC's `rs274` on the same generated programs.
//!
//! `cargo bench --bench canon` generates CAM programs of about 3 MB and
//! 30 MB with `../shared/bench/gen_program.py`, runs `cncc canon` and
//! `rs274-canon` on each as subprocesses (output to /dev/null, each under
//! `/usr/bin/time -f %M` for its peak resident memory), and prints MB/s of
//! each (cncc: the best of three runs), the ratio, and the peaks.
//! Figures are printed, never asserted.
//! `cncc check` (which runs the program too) is measured the same way.

#[path = "support/mod.rs"]
mod support;

use std::path::Path;
use support::{best_of, generate, measure, root, Run};

fn row(what: &str, mb: f64, m: Option<Run>) -> Option<f64> {
    let Run {
        secs,
        peak_mib: rss,
        exit: code,
    } = m?;
    let note = if code == 0 {
        String::new()
    } else {
        format!("  (exit {code})")
    };
    println!(
        "{what:<34} {mb:>8.1} {secs:>9.3} {:>9.1} {rss:>13.1}{note}",
        mb / secs
    );
    Some(mb / secs)
}

fn main() {
    if !Path::new("/usr/bin/time").exists() {
        eprintln!("note: /usr/bin/time is absent; benchmark skipped");
        return;
    }
    let cncc = root().join("target/release/cncc");
    if !cncc.exists() {
        eprintln!("note: build first: cargo build --release (benchmark skipped)");
        return;
    }
    let oracle = root().join("../shared/tools/rs274-canon");
    let table = root().join("../shared/tools/default.tbl");
    let dir = root().join("target/bench-programs");
    std::fs::create_dir_all(&dir).expect("mkdir");
    println!(
        "{:<34} {:>8} {:>9} {:>9} {:>13}",
        "run", "MB", "seconds", "MB/s", "peak RSS MiB"
    );
    for (lines, name) in [(215_000u64, "cam-3MB.ngc"), (2_150_000, "cam-30MB.ngc")] {
        let path = dir.join(name);
        if !generate(lines, &[], &path) {
            return;
        }
        let mb = std::fs::metadata(&path)
            .map(|m| m.len() as f64 / 1e6)
            .unwrap_or(0.0);
        let p = path.as_os_str();
        let ours = row(
            &format!("cncc canon {name}"),
            mb,
            best_of(
                3,
                &cncc,
                &[
                    "canon".as_ref(),
                    "--dialect".as_ref(),
                    "linuxcnc".as_ref(),
                    "--tool-table".as_ref(),
                    table.as_os_str(),
                    p,
                ],
            ),
        );
        let check = row(
            &format!("cncc check {name}"),
            mb,
            best_of(
                3,
                &cncc,
                &[
                    "check".as_ref(),
                    "--dialect".as_ref(),
                    "linuxcnc".as_ref(),
                    p,
                ],
            ),
        );
        if let Some(c) = check {
            println!(
                "{:<34} check {c:.0} MB/s (target >= 100 MB/s)",
                format!("target {name}")
            );
        }
        let theirs = if oracle.exists() {
            std::env::set_var("RS274_CANON_TIMEOUT", "600");
            row(
                &format!("rs274 {name}"),
                mb,
                measure(&oracle, &[p, table.as_os_str()]),
            )
        } else {
            eprintln!("note: rs274-canon is absent; only cncc measured");
            None
        };
        if let (Some(a), Some(b)) = (ours, theirs) {
            println!(
                "{:<34} cncc/rs274 speed ratio {:.1}x (target >= 25x)",
                format!("ratio {name}"),
                a / b
            );
        }
    }
}
