//! Output files written whole or not at all: a temporary file beside the
//! output, renamed into place at the end. The output gets the permissions a
//! new file gets under the user's umask (or keeps an existing file's mode);
//! the temporary file is removed on every exit path, a signal included
//! (SIGINT, SIGTERM, SIGHUP), and errors name the real output path.

use std::ffi::CString;
use std::fs::{File, OpenOptions};
use std::io::{Error, ErrorKind, Result};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicPtr, AtomicU32, Ordering};

/// Temporary files to remove if a signal ends the run: leaked C strings,
/// read by the signal handler without locking.
const SLOTS: usize = 8;
static TEMPS: [AtomicPtr<libc::c_char>; SLOTS] =
    [const { AtomicPtr::new(std::ptr::null_mut()) }; SLOTS];
static COUNTER: AtomicU32 = AtomicU32::new(0);

/// A temporary file that becomes `target` on [`AtomicFile::commit`].
pub struct AtomicFile {
    target: PathBuf,
    tmp: PathBuf,
    file: Option<File>,
    slot: Option<usize>,
}

impl AtomicFile {
    pub fn create(target: &Path) -> Result<AtomicFile> {
        let dir = match target.parent() {
            Some(p) if !p.as_os_str().is_empty() => p,
            _ => Path::new("."),
        };
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let mut last = None;
        for _ in 0..16 {
            let n = COUNTER.fetch_add(1, Ordering::Relaxed);
            let tmp = dir.join(format!(".{name}.cncc-{}-{n}.tmp", std::process::id()));
            let mut o = OpenOptions::new();
            o.write(true).create_new(true);
            #[cfg(unix)]
            {
                use std::os::unix::fs::OpenOptionsExt;
                o.mode(0o666);
            }
            match o.open(&tmp) {
                Ok(file) => {
                    let slot = register(&tmp);
                    return Ok(AtomicFile {
                        target: target.to_path_buf(),
                        tmp,
                        file: Some(file),
                        slot,
                    });
                }
                Err(e) if e.kind() == ErrorKind::AlreadyExists => last = Some(e),
                Err(e) => return Err(named(target, e)),
            }
        }
        Err(named(
            target,
            last.unwrap_or_else(|| Error::other("no temporary name")),
        ))
    }

    pub fn file(&mut self) -> &mut File {
        // Only `commit`, which consumes self, takes the file.
        self.file
            .as_mut()
            .expect("an output file is open until committed")
    }

    /// Flushes to disk and renames into place, keeping an existing
    /// output's permissions.
    pub fn commit(mut self) -> Result<()> {
        let target = self.target.clone();
        let file = self.file.take();
        let res = (|| {
            if let Some(f) = &file {
                f.sync_all()?;
                if let Ok(meta) = std::fs::metadata(&target) {
                    f.set_permissions(meta.permissions())?;
                }
            }
            drop(file);
            std::fs::rename(&self.tmp, &target)
        })();
        match res {
            Ok(()) => {
                self.release();
                Ok(())
            }
            Err(e) => Err(named(&target, e)),
        }
    }

    fn release(&mut self) {
        if let Some(i) = self.slot.take() {
            let p = TEMPS[i].swap(std::ptr::null_mut(), Ordering::SeqCst);
            if !p.is_null() {
                // SAFETY: the pointer came from CString::into_raw in register.
                drop(unsafe { CString::from_raw(p) });
            }
        }
    }
}

impl Drop for AtomicFile {
    fn drop(&mut self) {
        if self.slot.is_some() {
            self.file.take();
            let _ = std::fs::remove_file(&self.tmp);
            self.release();
        }
    }
}

/// The error with the output path in it (never the temporary one).
fn named(target: &Path, e: Error) -> Error {
    Error::new(e.kind(), format!("{}: {e}", target.display()))
}

fn register(tmp: &Path) -> Option<usize> {
    use std::os::unix::ffi::OsStrExt;
    let c = CString::new(tmp.as_os_str().as_bytes()).ok()?.into_raw();
    for (i, slot) in TEMPS.iter().enumerate() {
        if slot
            .compare_exchange(std::ptr::null_mut(), c, Ordering::SeqCst, Ordering::SeqCst)
            .is_ok()
        {
            return Some(i);
        }
    }
    // SAFETY: `c` came from into_raw just above and was not stored.
    drop(unsafe { CString::from_raw(c) });
    None
}

extern "C" fn on_signal(sig: libc::c_int) {
    for slot in &TEMPS {
        let p = slot.load(Ordering::SeqCst);
        if !p.is_null() {
            // SAFETY: unlink is async-signal-safe; p is a valid C string.
            unsafe { libc::unlink(p) };
        }
    }
    // SAFETY: restoring the default action and raising again ends the
    // process with the signal's usual status.
    unsafe {
        libc::signal(sig, libc::SIG_DFL);
        libc::raise(sig);
    }
}

/// Installs the process-wide handlers: temporary files removed on SIGINT,
/// SIGTERM and SIGHUP; a closed pipe (SIGPIPE) ends the run quietly with
/// the shell's usual status instead of a write error.
pub fn install_signal_handlers() {
    // SAFETY: setting dispositions at start-up, before any other thread.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
        for sig in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            libc::signal(
                sig,
                on_signal as extern "C" fn(libc::c_int) as libc::sighandler_t,
            );
        }
    }
}
