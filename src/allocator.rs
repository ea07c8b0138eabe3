//! mimalloc for GMP's and MPFR's numbers, for a program that uses the
//! library (the `cylroll` command, the benchmark).
//!
//! A table of many digits allocates and frees a few hundred thousand small
//! numbers; glibc's allocator spent 15–18% of a 30-digit friction table's
//! instructions on them, mimalloc a third of that. A program takes mimalloc
//! for Rust's own allocations with `#[global_allocator] static GLOBAL:
//! mimalloc::MiMalloc = mimalloc::MiMalloc;` and for the big numbers with
//! [`use_mimalloc_for_gmp`]. The library itself sets nothing: GMP's memory
//! functions belong to the whole process (a Python interpreter may hold other
//! GMP users), so only a program's `main` may change them.

use std::ffi::c_void;

extern "C" fn gmp_alloc(size: usize) -> *mut c_void {
    // SAFETY: mi_malloc may be called with any size
    let p = unsafe { libmimalloc_sys::mi_malloc(size) };
    if p.is_null() {
        out_of_memory(size)
    }
    p
}

unsafe extern "C" fn gmp_realloc(p: *mut c_void, _old: usize, size: usize) -> *mut c_void {
    // SAFETY: p came from gmp_alloc or gmp_realloc (GMP hands back only
    // its own blocks)
    let q = unsafe { libmimalloc_sys::mi_realloc(p, size) };
    if q.is_null() {
        out_of_memory(size)
    }
    q
}

unsafe extern "C" fn gmp_free(p: *mut c_void, _size: usize) {
    // SAFETY: as gmp_realloc
    unsafe { libmimalloc_sys::mi_free(p) }
}

/// GMP's contract: an allocation function does not return on failure.
fn out_of_memory(size: usize) -> ! {
    use std::io::Write;
    // no panic from here (a failed write to stderr is ignored): abort
    let _ = writeln!(
        std::io::stderr(),
        "error: out of memory (allocating {size} bytes for a big number)"
    );
    std::process::abort()
}

/// Points GMP (and MPFR, which allocates through GMP's functions) at
/// mimalloc.
///
/// # Safety
///
/// Call it first thing in `main`, before any GMP or MPFR number exists and
/// before any other thread is started: no block GMP or MPFR allocated
/// before the call may be reallocated or freed after it (MPFR's cached
/// constants included, and numbers made by code that runs before `main`),
/// since each block must go back to the allocator it came from; and GMP's
/// memory functions are not synchronised.
pub unsafe fn use_mimalloc_for_gmp() {
    // SAFETY: the caller's contract above
    unsafe {
        gmp_mpfr_sys::gmp::set_memory_functions(Some(gmp_alloc), Some(gmp_realloc), Some(gmp_free));
    }
}
