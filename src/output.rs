//! Writing result files atomically: the content goes to a temporary file beside the target,
//! which is renamed over the target only when complete. An error or an interrupt never
//! leaves a half-written file at the target path.

use crate::error::{Result, RouthError};
use std::io::{BufWriter, Write};
use std::path::Path;

/// Write a file atomically: `fill` writes the content; on success the temporary file is
/// renamed to `path`, on failure it is removed and `path` is untouched.
pub fn write_atomic(path: &Path, fill: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    let io = |source| RouthError::Io {
        path: path.to_path_buf(),
        source,
    };
    let name = path.file_name().ok_or_else(|| RouthError::Option {
        name: "output path",
        value: path.display().to_string(),
        rule: "must name a file",
    })?;
    let tmp = path.with_file_name(format!(
        ".{}.tmp-{}",
        name.to_string_lossy(),
        std::process::id()
    ));
    let result = (|| {
        let file = std::fs::File::create(&tmp).map_err(io)?;
        let mut writer = BufWriter::new(file);
        fill(&mut writer)?;
        let file = writer.into_inner().map_err(|e| io(e.into_error()))?;
        file.sync_all().map_err(io)?;
        std::fs::rename(&tmp, path).map_err(io)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}

/// Write bytes atomically (see [`write_atomic`]).
pub fn write_bytes_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic(path, |w| {
        w.write_all(bytes).map_err(|source| RouthError::Io {
            path: path.to_path_buf(),
            source,
        })
    })
}
