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
/// behind unless they free them ([`cylroll::numeric::ThreadCaches`], the
/// guard the Python package's worker, a table's block threads and the
/// report's workers make first): 1500 threads at 20 000 bits would leave at
/// least 3.75 MB; with the guard, half of them ending in a panic, the
/// process does not grow by half of that.
#[test]
fn a_thread_that_frees_its_caches_leaves_nothing() {
    let run = |free: bool| {
        for i in 0..1500 {
            let r = std::thread::spawn(move || {
                let _caches = free.then_some(cylroll::numeric::ThreadCaches);
                let pi = rug::Float::with_val(20_000, rug::float::Constant::Pi);
                assert!(pi > 3);
                if free && i % 2 == 1 {
                    panic!("a worker that fails");
                }
            })
            .join();
            assert_eq!(r.is_err(), free && i % 2 == 1);
        }
    };
    let Some(before) = rss() else {
        return; // not Linux: nothing to measure
    };
    // the panics are expected: not printed
    let hook = std::panic::take_hook();
    std::panic::set_hook(Box::new(|_| {}));
    run(true);
    std::panic::set_hook(hook);
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
