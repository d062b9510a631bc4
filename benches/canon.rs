//! `cncc canon` against LinuxCNC's `rs274` on the same generated programs.
//!
//! `cargo bench --bench canon` generates CAM programs of about 3 MB and
//! 30 MB with `../shared/bench/gen_program.py`, runs `cncc canon` and
//! `rs274-canon` on each as subprocesses (output to /dev/null, each under
//! `/usr/bin/time -f %M` for its peak resident memory), and prints MB/s of
//! each (cncc: the best of three runs), the ratio, and the peaks.
//! Figures are printed, never asserted.
//! `cncc check` (which runs the program too) is measured the same way.

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

/// Runs a command with its output discarded; seconds, peak RSS in MiB
/// (from `/usr/bin/time -f %M`), exit code.
fn measure(program: &Path, args: &[&std::ffi::OsStr]) -> Option<(f64, f64, i32)> {
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
    Some((secs, kb / 1024.0, status.code().unwrap_or(-1)))
}

/// The fastest of `n` runs (other work on the machine only slows a run
/// down), with the largest peak memory seen.
fn best_of(n: usize, program: &Path, args: &[&std::ffi::OsStr]) -> Option<(f64, f64, i32)> {
    let runs: Vec<_> = (0..n).filter_map(|_| measure(program, args)).collect();
    let secs = runs.iter().map(|r| r.0).fold(f64::INFINITY, f64::min);
    let rss = runs.iter().map(|r| r.1).fold(0.0, f64::max);
    let code = runs.iter().map(|r| r.2).find(|c| *c != 0).unwrap_or(0);
    (!runs.is_empty()).then_some((secs, rss, code))
}

fn row(what: &str, mb: f64, m: Option<(f64, f64, i32)>) -> Option<f64> {
    let (secs, rss, code) = m?;
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
        if !generate(lines, &path) {
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
