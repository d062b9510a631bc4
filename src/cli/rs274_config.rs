//! `--ini FILE` and `--var-file FILE` (`cncc canon`): a LinuxCNC
//! configuration's `[RS274NGC]` settings and parameter file, read into
//! [`crate::interp::config::Rs274Config`] for a dialect whose spec has the
//! `var-and-ini-files` capability, and the parameter file written back
//! after the run as rs274 writes it.
//!
//! Which settings are applied, and how rs274 2.9 treats each (checked with
//! the installed `rs274 -i`): docs/linuxcnc-config.md.

use crate::cli::context::{Context, Failure};
use crate::diag::{Code, Diagnostic};
use crate::dialect::{Capability, DialectSpec};
use crate::interp::config::ini::{parse_integer, parse_number, Entry, Ini};
use crate::interp::config::var_file::{self, VarFile};
use crate::interp::Options;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// The section rs274 reads its settings from.
const SECTION: &str = "RS274NGC";

/// `[RS274NGC]` settings that change interpretation and that cncc does not
/// apply (the run goes on without them, W0596).
const NOT_APPLIED: &[&str] = &[
    "REMAP",
    "RETAIN_G43",
    "OWORD_NARGS",
    "NO_DOWNCASE_OWORD",
    "OWORD_WARN_ONLY",
    "HAL_PIN_VARS",
    "ON_ABORT_COMMAND",
    "RS274NGC_STARTUP_CODE",
    "USER_M_PATH",
    "CENTER_ARC_RADIUS_TOLERANCE_INCH",
    "CENTER_ARC_RADIUS_TOLERANCE_MM",
];

/// The files given on the command line.
#[derive(Clone, Copy, Debug, Default)]
pub struct ConfigFiles<'a> {
    pub ini: Option<&'a Path>,
    pub var_file: Option<&'a Path>,
}

impl ConfigFiles<'_> {
    pub fn any(&self) -> bool {
        self.ini.is_some() || self.var_file.is_some()
    }
}

/// What was loaded: the parameter file to write back (its path and the
/// numbers it had), and the diagnostics of both files.
#[derive(Debug, Default)]
pub struct Loaded {
    pub write_back: Option<(PathBuf, VarFile)>,
    pub diags: Vec<Diagnostic>,
}

/// A dialect without the `var-and-ini-files` capability refuses the
/// files (a usage error).
pub fn require(spec: &DialectSpec, files: ConfigFiles<'_>) -> Result<(), Failure> {
    if files.any() && !spec.has(Capability::VarAndIniFiles) {
        return Err(Failure(format!(
            "--ini and --var-file are read for a dialect whose spec has the `var-and-ini-files` capability (a LinuxCNC configuration); `{}` has not",
            spec.id
        )));
    }
    Ok(())
}

/// Reads the files into `options.rs274` (see [`require`] for the
/// dialect).
pub fn read(
    ctx: &mut Context,
    files: ConfigFiles<'_>,
    options: &mut Options,
) -> Result<Loaded, Failure> {
    let mut loaded = Loaded::default();
    if !files.any() {
        return Ok(loaded);
    }
    let mut var_path = files.var_file.map(Path::to_path_buf);
    if let Some(path) = files.ini {
        let (id, text) = ctx.add_side_file(path)?;
        let (ini, d) = Ini::parse(&text, id);
        loaded.diags.extend(d);
        let dir = path.parent().unwrap_or(Path::new("")).to_path_buf();
        let cfg = &mut options.rs274;
        let mut warn = |e: &Entry, why: String| loaded.diags.push(bad_setting(e, why));
        if let Some(e) = ini.get(SECTION, "SUBROUTINE_PATH") {
            for part in e.value.split(':').filter(|p| !p.trim().is_empty()) {
                let dir = relative_to(&dir, part.trim());
                if dir.is_dir() {
                    cfg.subroutine_path.push(dir);
                } else {
                    warn(
                        e,
                        format!("SUBROUTINE_PATH folder `{}` does not exist", dir.display()),
                    );
                }
            }
        }
        if let Some(e) = ini.get(SECTION, "ORIENT_OFFSET") {
            match parse_number(&e.value) {
                Some(v) => cfg.orient_offset = v,
                None => warn(e, format!("ORIENT_OFFSET `{}` is not a number", e.value)),
            }
        }
        let mut flag = |name: &str, default: bool| match ini.get(SECTION, name) {
            None => default,
            Some(e) => match parse_integer(&e.value) {
                Some(v) => v != 0,
                None => {
                    warn(
                        e,
                        format!("{name} `{}` is not an integer (write 0 or 1)", e.value),
                    );
                    default
                }
            },
        };
        // rs274 2.9 reads `#<_ini[..]>` unless INI_VARS is 0 (FEATURES
        // does not turn it off).
        let ini_vars = flag("INI_VARS", true);
        cfg.disable_g92_persistence = flag("DISABLE_G92_PERSISTENCE", false);
        cfg.disable_fanuc_subs = flag("DISABLE_FANUC_STYLE_SUB", false);
        // FEATURES bit 4 (INI_VARS) is what rs274 does anyway.
        if let Some(e) = ini.get(SECTION, "FEATURES") {
            if parse_integer(&e.value).is_none_or(|v| v & !4 != 0) {
                loaded.diags.push(not_applied(e, "FEATURES"));
            }
        }
        for name in NOT_APPLIED {
            if let Some(e) = ini.get(SECTION, name) {
                loaded.diags.push(not_applied(e, name));
            }
        }
        if var_path.is_none() {
            var_path = ini
                .get(SECTION, "PARAMETER_FILE")
                .map(|e| relative_to(&dir, e.value.trim()));
        }
        if ini_vars {
            options.rs274.ini_vars = Some(Arc::new(ini));
        }
    }
    if let Some(path) = var_path {
        // rs274 starts from 0 when the file does not exist, and creates it.
        let file = if path.exists() {
            let (id, text) = ctx.add_side_file(&path)?;
            let (file, d) = VarFile::parse(&text, id);
            loaded.diags.extend(d);
            file
        } else {
            VarFile::default()
        };
        options.rs274.parameters = Some(file.clone());
        loaded.write_back = Some((path, file));
    }
    Ok(loaded)
}

/// Writes the parameter file back with the values the run ended with (as
/// rs274 does on exit, after an error too). Nothing is written when the
/// run did not start.
pub fn write_back(loaded: &Loaded, options: &Options) -> Result<(), Failure> {
    let Some((path, file)) = &loaded.write_back else {
        return Ok(());
    };
    let Some(end) = options.rs274.final_parameters.take() else {
        return Ok(());
    };
    let text = var_file::render(&file.values, |n| end.get(&n).copied().unwrap_or(0.0));
    let fail = |e: std::io::Error| {
        Failure(format!(
            "{}: writing the parameter file: {e}",
            path.display()
        ))
    };
    let mut out = crate::cli::atomic::AtomicFile::create(path).map_err(fail)?;
    std::io::Write::write_all(out.file(), text.as_bytes()).map_err(fail)?;
    out.commit().map_err(fail)
}

/// A path from the INI file, relative to the INI's folder (LinuxCNC runs in
/// the configuration's folder [?]: rs274 alone resolves it from its
/// working folder); `~/` is the home folder.
fn relative_to(dir: &Path, p: &str) -> PathBuf {
    if let Some(rest) = p.strip_prefix("~/") {
        if let Some(home) = std::env::var_os("HOME") {
            return PathBuf::from(home).join(rest);
        }
    }
    dir.join(p)
}

fn bad_setting(e: &Entry, why: String) -> Diagnostic {
    Diagnostic::new(Code::BadIniSetting, format!("{why}: the default is kept"))
        .primary(e.span, "not taken")
        .help("write a number for ORIENT_OFFSET, 0 or 1 for the switches, existing folders for SUBROUTINE_PATH")
}

fn not_applied(e: &Entry, name: &str) -> Diagnostic {
    Diagnostic::new(
        Code::IniSettingNotApplied,
        format!("[RS274NGC]{name} is not applied by cncc: the run goes on without it"),
    )
    .primary(e.span, "ignored")
    .help("cncc applies SUBROUTINE_PATH, PARAMETER_FILE, INI_VARS, ORIENT_OFFSET, DISABLE_G92_PERSISTENCE and DISABLE_FANUC_STYLE_SUB; remaps, HAL pins and Python stay with LinuxCNC")
}
