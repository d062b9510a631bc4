//! `cncc stepnc --cc1` (raising to explicit toolpaths and writing Part 21)
//! on generated CAM programs, against `cncc canon` and LinuxCNC's `rs274`
//! on the same files.
//!
//! `cargo bench --bench stepnc` generates (or reuses) the 3 MB and 30 MB
//! programs of `benches/canon.rs` with `../shared/bench/gen_program.py`,
//! runs each command as a subprocess under `/usr/bin/time -f %M` and prints
//! seconds, MB/s of input and peak resident memory. Printed, never asserted.

#[path = "support/mod.rs"]
mod support;

use std::path::Path;
use support::{generate, measure, root, Run};

fn row(what: &str, mb: f64, m: Option<Run>) -> Option<f64> {
    let Run {
        secs,
        peak_mib: rss,
        ..
    } = m?;
    println!(
        "{what:<36} {mb:>7.1} {secs:>8.2} {:>7.1} {rss:>12.1}",
        mb / secs
    );
    Some(secs)
}

fn main() {
    let cncc = root().join("target/release/cncc");
    if !Path::new("/usr/bin/time").exists() || !cncc.exists() {
        eprintln!("note: needs /usr/bin/time and cargo build --release; benchmark skipped");
        return;
    }
    let oracle = root().join("../shared/tools/rs274-canon");
    let dir = root().join("target/bench-programs");
    std::fs::create_dir_all(&dir).expect("mkdir");
    let out = dir.join("bench-out.stp");
    println!(
        "{:<36} {:>7} {:>8} {:>7} {:>12}",
        "run", "MB", "seconds", "MB/s", "peak RSS MiB"
    );
    for (lines, name) in [(215_000u64, "cam-3MB.ngc"), (2_150_000, "cam-30MB.ngc")] {
        let path = dir.join(name);
        if !generate(lines, &[], &path) {
            return;
        }
        let mb = std::fs::metadata(&path).map_or(0.0, |m| m.len() as f64 / 1e6);
        let p = path.as_os_str();
        let raise = [
            "stepnc".as_ref(),
            p,
            "--cc1".as_ref(),
            "-o".as_ref(),
            out.as_os_str(),
        ];
        let ours = row(
            &format!("cncc stepnc --cc1 {name}"),
            mb,
            measure(&cncc, &raise),
        );
        let canon = row(
            &format!("cncc canon {name}"),
            mb,
            measure(&cncc, &["canon".as_ref(), p]),
        );
        let rs274 = if oracle.exists() {
            row(&format!("rs274 {name}"), mb, measure(&oracle, &[p]))
        } else {
            None
        };
        if let (Some(o), Some(c)) = (ours, canon) {
            println!("  stepnc / canon time: {:.1}x", o / c);
        }
        if let (Some(o), Some(r)) = (ours, rs274) {
            println!("  stepnc / rs274 time: {:.2}x", o / r);
        }
    }
    let _ = std::fs::remove_file(out);
}
