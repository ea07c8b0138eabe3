//! The `cylroll` command: see `cylroll --help` and the README.

mod cli;

/// The command's allocator: mimalloc, for Rust's allocations and (through
/// [`cylroll::allocator::use_mimalloc_for_gmp`]) for GMP's and MPFR's.
#[global_allocator]
static GLOBAL: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() {
    // SAFETY: first thing in main, before any big number or other thread
    unsafe { cylroll::allocator::use_mimalloc_for_gmp() };
    std::process::exit(cli::main_with(std::env::args().collect()));
}
