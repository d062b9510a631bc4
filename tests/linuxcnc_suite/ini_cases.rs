//! The suite's cases that need an INI file or a parameter file, which
//! `run.sh` lists as N/A (it runs `cncc canon` without them): run here with
//! the same files given to both, `rs274 -g [-v VAR] [-i INI]` and `cncc
//! canon --dialect linuxcnc [--var-file VAR] [--ini INI]`, each in its own
//! copy of the case's folder. A case passes when both run to the end with
//! the same calls (`canon-diff`) and, with a parameter file, write the same
//! file back; or when both stop with an error on the same source line.

use std::path::{Path, PathBuf};
use std::process::Command;

/// One run: the case id, its folder in the suite, the program, the INI
/// (if any) and the parameter-file template copied before the run (if
/// any; the run then uses it as its parameter file).
pub struct IniCase {
    pub id: &'static str,
    pub dir: &'static str,
    pub prog: &'static str,
    pub ini: Option<&'static str>,
    pub var_template: Option<&'static str>,
}

const fn case(
    id: &'static str,
    dir: &'static str,
    prog: &'static str,
    ini: Option<&'static str>,
    var_template: Option<&'static str>,
) -> IniCase {
    IniCase {
        id,
        dir,
        prog,
        ini,
        var_template,
    }
}

const G92: &str = "interp/g52/g92-offset-persistence";
const FANUC: &str = "interp/m98m99/09-disable-fanuc-subs";
const G92_VAR: Option<&str> = Some("g92_offsets.var.template");

/// The runs of the N/A cases that need only an INI or a parameter file
/// (their test.sh runs, in order).
pub const INI_CASES: &[IniCase] = &[
    case(
        "interp/g52/g92-offset-persistence:ini-persistent",
        G92,
        "g92_offsets.ngc",
        Some("persistent_g92_offset_true.ini"),
        G92_VAR,
    ),
    case(
        "interp/g52/g92-offset-persistence:no-ini",
        G92,
        "g92_offsets.ngc",
        None,
        G92_VAR,
    ),
    case(
        "interp/g52/g92-offset-persistence:ini-not-persistent",
        G92,
        "g92_offsets.ngc",
        Some("persistent_g92_offset_false.ini"),
        G92_VAR,
    ),
    case(
        "interp/m19",
        "interp/m19",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/abort-hot-comment",
        "interp/abort-hot-comment",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/iniparam",
        "interp/iniparam",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/iniparam-failassign",
        "interp/iniparam-failassign",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/nested-sub-error",
        "interp/nested-sub-error",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/nested-sub-in-file-error",
        "interp/nested-sub-in-file-error",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/sub-call-from-sub",
        "interp/sub-call-from-sub",
        "test.ngc",
        Some("test.ini"),
        None,
    ),
    case(
        "interp/m98m99/09-disable-fanuc-subs:fanuc+ini-no-fanuc",
        FANUC,
        "test-fanuc.ngc",
        Some("test-no-fanuc.ini"),
        None,
    ),
    case(
        "interp/m98m99/09-disable-fanuc-subs:rs274ngc+ini-no-fanuc",
        FANUC,
        "test-rs274ngc.ngc",
        Some("test-no-fanuc.ini"),
        None,
    ),
];

/// Whether `run.sh`'s N/A case `id` is run here.
pub fn run_here(id: &str) -> bool {
    INI_CASES
        .iter()
        .any(|c| c.id == id || c.id.split(':').next() == Some(id))
}

/// What one side did.
struct Side {
    ok: bool,
    calls: Vec<String>,
    /// The source line the error is on (rs274: the line it shows; cncc: the
    /// line of its first error's position).
    error_line: Option<String>,
    var_file: Option<String>,
}

/// Runs one case; `None` when it passes, else what differs.
pub fn run(suite: &Path, canon_diff: &Path, c: &IniCase) -> Option<String> {
    let scratch = tempfile::tempdir().expect("scratch folder");
    let rs = rs274(suite, scratch.path(), c);
    let cc = cncc(suite, scratch.path(), c);
    match (rs.ok, cc.ok) {
        (true, true) => {
            let same = same_calls(canon_diff, scratch.path(), &rs.calls, &cc.calls);
            if let Err(d) = same {
                return Some(format!("DIFFERENT: {d}"));
            }
            (rs.var_file != cc.var_file).then(|| {
                format!(
                    "the parameter files written differ:\nrs274:\n{}\ncncc:\n{}",
                    rs.var_file.unwrap_or_default(),
                    cc.var_file.unwrap_or_default()
                )
            })
        }
        (true, false) => Some(format!("CNCC-ERROR on {:?}", cc.error_line)),
        (false, true) => Some(format!(
            "cncc ACCEPTS the line rs274 rejects: {:?}",
            rs.error_line
        )),
        (false, false) => (rs.error_line != cc.error_line || rs.error_line.is_none()).then(|| {
            format!(
                "both stop, on other lines: rs274 {:?}, cncc {:?}",
                rs.error_line, cc.error_line
            )
        }),
    }
}

/// A fresh copy of the case's folder (with the parameter file made from
/// its template).
fn copy_case(suite: &Path, scratch: &Path, c: &IniCase, side: &str) -> PathBuf {
    let to = scratch.join(side);
    copy_dir(&suite.join(c.dir), &to);
    if let Some(t) = c.var_template {
        std::fs::copy(to.join(t), to.join("run.var")).expect("copy the parameter file");
        let mut p = std::fs::metadata(to.join("run.var")).unwrap().permissions();
        #[allow(clippy::permissions_set_readonly_false)]
        p.set_readonly(false);
        std::fs::set_permissions(to.join("run.var"), p).unwrap();
    }
    to
}

fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).unwrap();
    for e in std::fs::read_dir(from).unwrap() {
        let e = e.unwrap();
        let target = to.join(e.file_name());
        if e.file_type().unwrap().is_dir() {
            copy_dir(&e.path(), &target);
        } else {
            std::fs::copy(e.path(), &target).unwrap();
        }
    }
}

fn rs274(suite: &Path, scratch: &Path, c: &IniCase) -> Side {
    let dir = copy_case(suite, scratch, c, "rs");
    let home = scratch.join("home");
    std::fs::create_dir_all(&home).unwrap();
    // An empty parameter file when the case has none: all parameters 0.
    let var = match c.var_template {
        Some(_) => dir.join("run.var"),
        None => {
            std::fs::write(scratch.join("empty.var"), "").unwrap();
            scratch.join("empty.var")
        }
    };
    let mut cmd = Command::new("timeout");
    cmd.arg("15").arg("rs274").arg("-g").arg("-v").arg(&var);
    if let Some(ini) = c.ini {
        cmd.args(["-i", ini]);
    }
    let out = cmd
        .args([c.prog, "rs274.canon"])
        .current_dir(&dir)
        .env_remove("INI_FILE_NAME")
        .env("HOME", &home)
        .env("TMPDIR", &home)
        .env("LC_ALL", "C")
        .stdin(std::process::Stdio::null())
        .output()
        .expect("run rs274");
    let canon = std::fs::read_to_string(dir.join("rs274.canon")).unwrap_or_default();
    let calls = canon
        .lines()
        .filter_map(|l| l.split_once("N..... ").map(|(_, c)| c.trim().to_string()))
        .collect();
    let err = String::from_utf8_lossy(&out.stderr);
    let lines: Vec<&str> = err
        .lines()
        .filter(|l| !l.trim().is_empty() && *l != "executing")
        .collect();
    let ok = out.status.success();
    Side {
        ok,
        calls,
        error_line: (!ok && lines.len() >= 2).then(|| lines[lines.len() - 1].trim().to_string()),
        var_file: c
            .var_template
            .map(|_| std::fs::read_to_string(&var).unwrap_or_default()),
    }
}

fn cncc(suite: &Path, scratch: &Path, c: &IniCase) -> Side {
    let dir = copy_case(suite, scratch, c, "cc");
    let mut cmd = Command::new(env!("CARGO_BIN_EXE_cncc"));
    cmd.args(["canon", c.prog, "--dialect", "linuxcnc"]);
    cmd.args(["--format", "json", "--color", "never"]);
    if let Some(ini) = c.ini {
        cmd.args(["--ini", ini]);
    }
    if c.var_template.is_some() {
        cmd.args(["--var-file", "run.var"]);
    }
    let out = cmd.current_dir(&dir).output().expect("run cncc");
    let calls = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| l.trim().to_string())
        .collect();
    let err = String::from_utf8_lossy(&out.stderr);
    let first_error = err
        .lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .find(|j| j["severity"] == "error");
    let error_line = first_error.and_then(|j| {
        let file = dir.join(j["file"].as_str()?);
        let n = j["line"].as_u64()? as usize;
        let text = std::fs::read_to_string(file).ok()?;
        Some(text.lines().nth(n.checked_sub(1)?)?.trim().to_string())
    });
    Side {
        ok: out.status.success(),
        calls,
        error_line,
        var_file: c
            .var_template
            .map(|_| std::fs::read_to_string(dir.join("run.var")).unwrap_or_default()),
    }
}

/// `canon-diff` of the two call lists (numbers within 1e-4; the
/// interpreter's own notes skipped).
fn same_calls(canon_diff: &Path, scratch: &Path, a: &[String], b: &[String]) -> Result<(), String> {
    let (pa, pb) = (scratch.join("calls.rs"), scratch.join("calls.cc"));
    std::fs::write(&pa, a.join("\n") + "\n").unwrap();
    std::fs::write(&pb, b.join("\n") + "\n").unwrap();
    let out = Command::new(canon_diff)
        .args(["--tol", "1.0001e-4"])
        .arg(&pa)
        .arg(&pb)
        .output()
        .expect("run canon-diff");
    if out.status.success() {
        Ok(())
    } else {
        Err(String::from_utf8_lossy(&out.stdout).into_owned())
    }
}
