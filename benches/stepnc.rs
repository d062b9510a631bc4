//! `cncc stepnc --cc1` (raising to explicit toolpaths and writing Part 21)
//! on generated CAM programs, against `cncc canon` and LinuxCNC's `rs274`
//! on the same files.
//!
//! `cargo bench --bench stepnc` generates (or reuses) the 3 MB and 30 MB
//! programs of `benches/canon.rs` with `../shared/bench/gen_program.py`,
//! runs each command as a subprocess under `/usr/bin/time -f %M` and prints
//! seconds, MB/s of input and peak resident memory. Printed, never asserted.

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn generate(lines: u64, out: &Path) -> bool {
    let gen = root().join("../shared/bench/gen_program.py");
    if !gen.exists() {
        eprintln!("note: ../shared/bench/gen_program.py is absent; benchmark skipped");
        return false;
    }
    out.exists()
        || Command::new("python3")
            .arg(&gen)
            .args(["--lines", &lines.to_string(), "-o"])
            .arg(out)
            .status()
            .map(|s| s.success())
            .unwrap_or(false)
}

/// Seconds and peak RSS in MiB of one run, its output discarded.
fn measure(program: &Path, args: &[&OsStr]) -> Option<(f64, f64)> {
    let rss_file = std::env::temp_dir().join(format!("cncc-bench-rss-{}", std::process::id()));
    let start = Instant::now();
    Command::new("/usr/bin/time")
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
    Some((secs, kb / 1024.0))
}

fn row(what: &str, mb: f64, m: Option<(f64, f64)>) -> Option<f64> {
    let (secs, rss) = m?;
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
        if !generate(lines, &path) {
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
