//! MPFR keeps caches per thread (its constants, its pool of integers) and
//! does not free them when a thread ends: the library's threads free them
//! ([`cylroll::numeric::free_thread_caches`]). A process of its own: the
//! test measures the process's resident memory.

/// Resident memory of this process, in bytes (Linux).
fn rss() -> Option<u64> {
    let s = std::fs::read_to_string("/proc/self/statm").ok()?;
    let pages: u64 = s.split_whitespace().nth(1)?.parse().ok()?;
    Some(pages * 4096)
}

/// Threads that compute π and end leave MPFR's per-thread caches
/// behind unless they free them ([`cylroll::numeric::free_thread_caches`], as the
/// Python package's worker and a table's block threads do): 1500 threads
/// at 20 000 bits would leave at least 3.75 MB; freed, the process does
/// not grow by half of that.
#[test]
fn a_thread_that_frees_its_caches_leaves_nothing() {
    let run = |free: bool| {
        for _ in 0..1500 {
            std::thread::spawn(move || {
                let pi = rug::Float::with_val(20_000, rug::float::Constant::Pi);
                assert!(pi > 3);
                if free {
                    cylroll::numeric::free_thread_caches();
                }
            })
            .join()
            .unwrap();
        }
    };
    let Some(before) = rss() else {
        return; // not Linux: nothing to measure
    };
    run(true);
    let freed = rss().unwrap_or(before).saturating_sub(before);
    assert!(
        freed < 1_800_000,
        "grew by {freed} bytes with the caches freed"
    );
    let before = rss().unwrap_or(0);
    run(false);
    let kept = rss().unwrap_or(before).saturating_sub(before);
    // the measure sees a leak where there is one
    assert!(
        kept > 3_000_000,
        "grew by only {kept} bytes without freeing"
    );
}
