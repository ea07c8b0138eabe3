//! A long trajectory, computed and printed in blocks of rows so that memory
//! stays bounded: each block is verified on its own (see
//! [`oracle::trajectory_in_blocks`]) and its rows are rendered at once into
//! a spill — memory up to a few megabytes, then an unnamed temporary file —
//! and only when every block has verified is anything written: the text
//! before the rows (the events of the whole motion), the rows, the text
//! after them. A failure in any block prints nothing but the error.

use super::render::{rows_text, table_parts, RowStats};
use super::{prove, Format};
use cylroll::error::{Error, Result};
use cylroll::exact::Exact;
use cylroll::model::Model;
use cylroll::oracle::{self, Options};
use std::fs::File;
use std::io::{Read, Seek, SeekFrom, Write};

/// Rows per block: the rows of one block are held in memory at both
/// working precisions (a few kilobytes each); `CYLROLL_BLOCK_ROWS`
/// overrides it (tests use small blocks).
///
/// Errors: `CYLROLL_BLOCK_ROWS` set to anything but a whole number from 1
/// to 10^6.
fn block_rows() -> Result<usize> {
    let n = cylroll::knobs::count(
        "CYLROLL_BLOCK_ROWS",
        1_000_000,
        "the rows of a block of a long table",
    )?;
    Ok(n.unwrap_or(2000))
}

/// Rendered text held in memory up to this many bytes, then in a file.
const SPILL_BYTES: usize = 8 << 20;

/// What a command prints: one text, or a table whose rows may be in a file.
pub enum Output {
    /// The whole output.
    Text(String),
    /// A trajectory: the text before the rows, the rows, the text after.
    Table {
        head: String,
        rows: Spill,
        tail: String,
    },
}

impl Output {
    /// Writes the output to `w`.
    pub fn write_to(self, w: &mut impl Write) -> std::io::Result<()> {
        match self {
            Output::Text(s) => w.write_all(s.as_bytes()),
            Output::Table { head, rows, tail } => {
                w.write_all(head.as_bytes())?;
                rows.copy_to(w)?;
                w.write_all(tail.as_bytes())
            }
        }
    }
}

/// Text kept in memory until it grows large, then in an unnamed temporary
/// file (removed by the system when it is closed).
pub struct Spill {
    mem: String,
    file: Option<File>,
}

impl Spill {
    fn new() -> Self {
        Spill {
            mem: String::new(),
            file: None,
        }
    }

    /// Appends `s`; what is held goes to the file first when `s` would take
    /// it past [`SPILL_BYTES`], so the text in memory never outgrows that
    /// (pushed and then flushed, it doubled its buffer to twice as much).
    fn push(&mut self, s: String) -> Result<()> {
        if self.mem.is_empty() {
            // the first text kept as it is, not copied
            self.mem = s;
            return Ok(());
        }
        if self.mem.len() + s.len() > SPILL_BYTES {
            if self.file.is_none() {
                self.file = Some(temp_file()?);
            }
            if let Some(f) = self.file.as_mut() {
                f.write_all(self.mem.as_bytes()).map_err(spill_error)?;
            }
            self.mem.clear();
        }
        self.mem.push_str(&s);
        Ok(())
    }

    fn copy_to(self, w: &mut impl Write) -> std::io::Result<()> {
        if let Some(mut f) = self.file {
            f.seek(SeekFrom::Start(0))?;
            let mut buf = vec![0u8; 1 << 16];
            loop {
                let n = f.read(&mut buf)?;
                if n == 0 {
                    break;
                }
                w.write_all(&buf[..n])?;
            }
        }
        w.write_all(self.mem.as_bytes())
    }
}

fn spill_error(e: std::io::Error) -> Error {
    Error::invalid(
        "TMPDIR",
        std::env::temp_dir().display().to_string(),
        format!(
            "must be a writable directory: a long trajectory keeps its rows there until every \
             block has verified ({e})"
        ),
    )
}

/// A new temporary file, already unlinked.
fn temp_file() -> Result<File> {
    let dir = std::env::temp_dir();
    for k in 0..100u32 {
        let path = dir.join(format!("cylroll-rows-{}-{k}", std::process::id()));
        match std::fs::OpenOptions::new()
            .read(true)
            .write(true)
            .create_new(true)
            .open(&path)
        {
            Ok(f) => {
                let _ = std::fs::remove_file(&path);
                return Ok(f);
            }
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(spill_error(e)),
        }
    }
    Err(spill_error(std::io::Error::other("no free name")))
}

/// The trajectory at `times`, printed in `format`; `rigorous`: the rows of
/// the ideal models are also enclosed (`--rigorous`).
pub fn trajectory(
    model: &Model,
    times: &[Exact],
    opts: &Options,
    columns: &[String],
    rigorous: bool,
    format: Format,
) -> Result<Output> {
    let mut stats = RowStats::default();
    let mut spill = Spill::new();
    let mut rigor = prove::RowsProof::default();
    let mut head =
        oracle::trajectory_in_blocks(model, times, opts, columns, block_rows()?, |t, mut a| {
            if rigorous {
                rigor.block(model, t, &mut a);
            }
            let first = stats.rows == 0;
            stats.add(&a);
            spill.push(rows_text(&a, format, first))
        })?;
    if rigorous {
        rigor.notes(&mut head);
    }
    let (h, tail) = table_parts(&head, format, &stats);
    Ok(Output::Table {
        head: h,
        rows: spill,
        tail,
    })
}
