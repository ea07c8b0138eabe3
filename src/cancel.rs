//! Cooperative cancellation of long computations.
//!
//! A caller that runs the library on a worker thread (the Python package,
//! which must stop a computation on `KeyboardInterrupt`) installs a flag on
//! that thread; the long loops — each rung of the precision ladder, each step
//! of the Taylor and the extrapolation integrators, each piece of the
//! spectral route and every 64 of its rows — call [`check`] and end
//! with [`crate::Error::Cancelled`] once the flag is set. The flag is per
//! thread and absent by default (the command line never installs one), so
//! nothing changes for other callers and no global state is shared.

use crate::error::{Error, Result};
use std::cell::RefCell;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

thread_local! {
    static FLAG: RefCell<Option<Arc<AtomicBool>>> = const { RefCell::new(None) };
}

/// Installs `flag` for the computations of the current thread.
pub fn install(flag: Arc<AtomicBool>) {
    FLAG.with(|f| *f.borrow_mut() = Some(flag));
}

/// This thread's flag, if one is installed: for work this thread hands to
/// others ([`install`] it there), so that they stop with it.
pub fn current() -> Option<Arc<AtomicBool>> {
    FLAG.with(|f| f.borrow().clone())
}

/// Whether this thread's flag is set (for loops that cannot return an
/// error: they end early, and their caller's next [`check`] reports it).
pub fn cancelled() -> bool {
    FLAG.with(|f| matches!(&*f.borrow(), Some(flag) if flag.load(Ordering::Relaxed)))
}

/// `Err(Error::Cancelled)` if this thread's flag is set.
pub fn check() -> Result<()> {
    FLAG.with(|f| match &*f.borrow() {
        Some(flag) if flag.load(Ordering::Relaxed) => Err(Error::Cancelled),
        _ => Ok(()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The flag handed to other threads is the one installed here (a long
    /// table's blocks computed at once stop with their caller).
    #[test]
    fn the_current_flag_is_the_installed_one() {
        std::thread::spawn(|| {
            assert!(current().is_none());
            let flag = Arc::new(AtomicBool::new(false));
            install(flag.clone());
            let got = current().expect("installed");
            assert!(Arc::ptr_eq(&got, &flag));
            flag.store(true, Ordering::Relaxed);
            std::thread::spawn(move || {
                install(got);
                assert_eq!(check(), Err(Error::Cancelled));
            })
            .join()
            .unwrap();
        })
        .join()
        .unwrap();
    }

    #[test]
    fn a_set_flag_cancels_only_its_thread() {
        assert!(check().is_ok());
        let flag = Arc::new(AtomicBool::new(false));
        install(flag.clone());
        assert!(check().is_ok());
        flag.store(true, Ordering::Relaxed);
        assert_eq!(check(), Err(Error::Cancelled));
        // another thread has no flag
        std::thread::spawn(|| assert!(check().is_ok()))
            .join()
            .unwrap();
        // a computation on this thread stops at its next check
        let m = crate::model::Ideal::paper_default(
            crate::exact::Exact::parse("theta0", "1/10", false).unwrap(),
        );
        let r = crate::oracle::Oracle::new(&m, 30).and_then(|mut o| o.separation());
        assert_eq!(r.err(), Some(Error::Cancelled));
        flag.store(false, Ordering::Relaxed);
    }
}
