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
