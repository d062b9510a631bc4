//! Giving freed memory back to the system between the phases of a long
//! command. glibc keeps what a phase freed in its heap for reuse, but the
//! next phase runs on other threads, whose allocations come from arenas
//! of their own: without this the port's freed working memory would
//! count on top of the proof's in the peak.

/// Returns the heap's free pages to the system (glibc `malloc_trim`);
/// nothing elsewhere.
pub fn release_freed() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: malloc_trim only walks the allocator's own free lists.
    unsafe {
        libc::malloc_trim(0);
    }
}

/// Fixes glibc's trim and mmap thresholds (32 MB and 16 MB) for the run.
/// By default glibc raises them as it goes and gives the top of each
/// thread's heap back at every large free, so a long command faults the
/// same pages in again and again: `port --verify` of the generator's
/// 2M-line program made 320,000 page faults (1.7 s of system time, 1 GB
/// of pages cleared for a 109 MB peak); with these thresholds 40,000
/// (0.3 s), and the peak within a few per cent (`docs/speed.md`).
pub fn settle_allocator() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets the allocator's tuning parameters; it is
    // called before the command starts any thread.
    unsafe {
        libc::mallopt(libc::M_TRIM_THRESHOLD, 32 << 20);
        libc::mallopt(libc::M_MMAP_THRESHOLD, 16 << 20);
    }
}
