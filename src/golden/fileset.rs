//! Sets of output files that change as a whole.
//!
//! A golden data set or a report is many files; a kill between two renames
//! must not leave a new `bobbin.json` beside an old `bobbin.csv`. So a set is
//! written as a redo log:
//!
//! 1. every file is written in full to a temporary `.NAME.tmpPID` beside its
//!    final place and flushed to disk (nothing visible has changed yet);
//! 2. the journal [`JOURNAL`], listing each temporary and its final name, is
//!    written atomically — the one step that switches the set;
//! 3. each temporary is renamed over its final name, and the journal removed.
//!
//! [`recover`] finishes an interrupted switch: with a journal, the renames
//! still to do are done (every temporary it names was complete before the
//! journal existed); without one, temporaries of processes that no longer run
//! are removed, leaving the old set whole. Every writer of a set, and every
//! reader of golden data, calls it first.

use crate::error::{Error, Result};
use std::path::{Path, PathBuf};

/// The journal of a set switch in progress, in the set's directory.
pub const JOURNAL: &str = ".cylroll-set.pending";

fn write_err(path: &Path, e: std::io::Error) -> Error {
    Error::Write {
        path: path.display().to_string(),
        what: e.to_string(),
    }
}

/// The temporary name of `path` for process `pid`: `.NAME.tmpPID` beside it.
pub fn temp_name(path: &Path, pid: u32) -> PathBuf {
    let dir = path.parent().unwrap_or_else(|| Path::new("."));
    let file_name = path.file_name().and_then(|n| n.to_str()).unwrap_or("out");
    dir.join(format!(".{file_name}.tmp{pid}"))
}

/// The process id of a temporary `.NAME.tmpPID`, if `name` is one.
fn temp_pid(name: &str) -> Option<u32> {
    if !name.starts_with('.') {
        return None;
    }
    let (_, pid) = name.rsplit_once(".tmp")?;
    pid.parse().ok()
}

/// Whether process `pid` is running (Linux: `/proc/PID` exists; elsewhere
/// every process is assumed alive, so nothing is removed).
fn alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return true;
    }
    let proc = Path::new("/proc");
    !proc.is_dir() || proc.join(pid.to_string()).exists()
}

/// Writes `bytes` to `path` in full under its temporary name and flushes it.
fn stage(path: &Path, bytes: &[u8]) -> Result<PathBuf> {
    use std::io::Write;
    let dir = path.parent().unwrap_or_else(|| Path::new("."));
    std::fs::create_dir_all(dir).map_err(|e| write_err(dir, e))?;
    let tmp = temp_name(path, std::process::id());
    let mut f = std::fs::File::create(&tmp).map_err(|e| write_err(path, e))?;
    f.write_all(bytes).and_then(|_| f.sync_all()).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        write_err(path, e)
    })?;
    Ok(tmp)
}

/// Whether the set's directories can be written, creating nothing: for each
/// of `dirs` (relative to `dir`; `dir` itself for an empty path), a probe
/// file is written and removed in the directory or, where it does not exist
/// yet, in its nearest existing ancestor (which must be a directory). Called
/// before the work that computes the set, so that an unwritable destination
/// is refused at once.
///
/// Errors: [`Error::Write`] naming the directory.
pub fn check_writable(dir: &Path, dirs: &[&str]) -> Result<()> {
    for sub in dirs {
        let d = if sub.is_empty() {
            dir.to_path_buf()
        } else {
            dir.join(sub)
        };
        let mut at = d.as_path();
        while !at.exists() {
            match at.parent() {
                Some(p) if !p.as_os_str().is_empty() => at = p,
                _ => {
                    at = Path::new(".");
                    break;
                }
            }
        }
        if !at.is_dir() {
            return Err(write_err(
                &d,
                std::io::Error::other(format!("{} is not a directory", at.display())),
            ));
        }
        let probe = at.join(format!(".cylroll-probe-{}", std::process::id()));
        std::fs::File::create(&probe).map_err(|e| write_err(&d, e))?;
        let _ = std::fs::remove_file(&probe);
    }
    Ok(())
}

/// Writes `bytes` to `path` atomically: readers see the old or the new file,
/// never a partial one.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    let tmp = stage(path, bytes)?;
    std::fs::rename(&tmp, path).map_err(|e| {
        let _ = std::fs::remove_file(&tmp);
        write_err(path, e)
    })
}

/// Writes the files `(path relative to dir, bytes)` as one set: after a kill
/// at any point, [`recover`] leaves either the whole old set or the whole new
/// one (files of the directory outside the set are untouched).
///
/// Errors: [`Error::Write`] naming the file that could not be written (the
/// old set stays whole: the temporaries are removed).
pub fn write_set(dir: &Path, files: &[(PathBuf, Vec<u8>)]) -> Result<()> {
    recover(dir)?;
    let mut staged: Vec<(PathBuf, PathBuf)> = Vec::new();
    for (rel, bytes) in files {
        let path = dir.join(rel);
        match stage(&path, bytes) {
            Ok(tmp) => staged.push((tmp, path)),
            Err(e) => {
                for (tmp, _) in &staged {
                    let _ = std::fs::remove_file(tmp);
                }
                return Err(e);
            }
        }
    }
    let rel = |p: &Path| -> String {
        p.strip_prefix(dir)
            .unwrap_or(p)
            .to_string_lossy()
            .into_owned()
    };
    let journal: String = staged
        .iter()
        .map(|(tmp, path)| format!("{}\t{}\n", rel(tmp), rel(path)))
        .collect();
    // the switch: from here on the new set is the set
    write_atomic(&dir.join(JOURNAL), journal.as_bytes())?;
    recover(dir)
}

/// Finishes an interrupted [`write_set`] in `dir` (or does nothing), and
/// removes temporaries left by processes that no longer run, in `dir` and
/// its subdirectories one level down.
///
/// Errors: [`Error::Write`] when a rename or removal fails.
pub fn recover(dir: &Path) -> Result<()> {
    let journal = dir.join(JOURNAL);
    if let Ok(text) = std::fs::read_to_string(&journal) {
        for line in text.lines() {
            let Some((tmp, path)) = line.split_once('\t') else {
                continue;
            };
            let (tmp, path) = (dir.join(tmp), dir.join(path));
            if tmp.exists() {
                std::fs::rename(&tmp, &path).map_err(|e| write_err(&path, e))?;
            }
        }
        std::fs::remove_file(&journal).map_err(|e| write_err(&journal, e))?;
    }
    let mut dirs = vec![dir.to_path_buf()];
    if let Ok(rd) = std::fs::read_dir(dir) {
        dirs.extend(
            rd.filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.is_dir()),
        );
    }
    for d in dirs {
        let Ok(rd) = std::fs::read_dir(&d) else {
            continue;
        };
        for e in rd.filter_map(|e| e.ok()) {
            let name = e.file_name();
            let Some(pid) = name.to_str().and_then(temp_pid) else {
                continue;
            };
            if !alive(pid) {
                let p = e.path();
                std::fs::remove_file(&p).map_err(|e| write_err(&p, e))?;
            }
        }
    }
    Ok(())
}
