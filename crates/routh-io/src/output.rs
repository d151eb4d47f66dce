//! Writing result files safely: an error or an interrupt never leaves a half-written file at
//! the target, and never replaces something that is not a regular file.
//!
//! What `write_atomic` does depends on what the target path is:
//!
//! * `-`: the content is streamed to standard output;
//! * a device, a named pipe or a socket (`/dev/null`, a FIFO): streamed directly into it,
//!   never replaced;
//! * a symbolic link: followed (to any depth) and the rules applied to its final target, so
//!   the link stays and the file it points to is written;
//! * a regular file or a new path: the content goes to a temporary file `.NAME.tmp-PID-N` in
//!   the target's directory, which is renamed over the target only when complete (and takes
//!   the old file's permissions); on any error the temporary file is removed by a guard;
//! * a directory: refused.
//!
//! The temporary files in progress are registered, so that [`remove_temporaries_on_signal`]
//! (installed by the command-line tool) removes them on SIGINT, SIGTERM or SIGHUP before the
//! process ends with the signal's usual status. It is the process's one handler of these
//! signals: a long computation that can stop cleanly (a sweep) asks it, with
//! [`stop_on_signal`], to set a flag on the first signal instead.

use crate::error::{AppError, AppResult as Result, RouthError};
use std::fs::{File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// Temporary files being written, removed by the signal handler.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The flag the next SIGINT, SIGTERM or SIGHUP sets instead of ending the process
/// ([`stop_on_signal`]).
static STOP: Mutex<Option<Arc<AtomicBool>>> = Mutex::new(None);

/// A counter that keeps the temporary names of one process distinct.
static SERIAL: AtomicUsize = AtomicUsize::new(0);

/// The longest file name, in bytes, that the temporary names are kept within: the `NAME_MAX`
/// of Linux's file systems (ext4, XFS, Btrfs, tmpfs) and of macOS's APFS.
const NAME_MAX: usize = 255;

/// How many symbolic links are followed before giving up (the limit of Linux's `ELOOP`).
const MAX_LINK_DEPTH: usize = 40;

/// Write `path` safely (see the module documentation): `fill` writes the content. On error
/// nothing is left behind and an existing target is untouched (a device or pipe may have
/// received part of the stream).
pub fn write_atomic(path: &Path, fill: impl FnOnce(&mut dyn Write) -> Result<()>) -> Result<()> {
    if path == Path::new("-") {
        let stdout = std::io::stdout();
        return stream(path, stdout.lock(), fill);
    }
    let target = follow_links(path)?;
    let io = AppError::io(&target);
    match std::fs::metadata(&target) {
        Ok(meta) if meta.is_dir() => Err(io(std::io::Error::new(
            std::io::ErrorKind::IsADirectory,
            "is a directory, expected a file name",
        ))),
        Ok(meta) if !meta.is_file() => {
            let file = OpenOptions::new().write(true).open(&target).map_err(&io)?;
            stream(&target, file, fill)
        }
        Ok(meta) => replace(&target, Some(meta.permissions()), fill),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => replace(&target, None, fill),
        Err(e) => Err(io(e)),
    }
}

/// Whether `path` is the standard output of this process: `-`, or a file (after its links)
/// that standard output is open on (`/dev/stdout`, or the file that `> FILE` redirects it
/// to): a command that writes both its report and a file there must send one elsewhere.
pub fn is_standard_output(path: &Path) -> bool {
    use std::os::fd::AsFd;
    use std::os::unix::fs::MetadataExt;
    if path == Path::new("-") {
        return true;
    }
    let stdout = std::io::stdout();
    let same = |meta: std::fs::Metadata| -> Option<bool> {
        let open = File::from(stdout.as_fd().try_clone_to_owned().ok()?)
            .metadata()
            .ok()?;
        Some((open.dev(), open.ino()) == (meta.dev(), meta.ino()))
    };
    std::fs::metadata(path).ok().and_then(same).unwrap_or(false)
}

/// Write bytes safely (see [`write_atomic`]).
pub fn write_bytes_atomic(path: &Path, bytes: &[u8]) -> Result<()> {
    write_atomic(path, |w| w.write_all(bytes).map_err(AppError::io(path)))
}

/// Install a handler that removes the temporary files in progress on SIGINT, SIGTERM and
/// SIGHUP, then ends the process as the signal would have (exit status 128 + signal); while a
/// flag is registered with [`stop_on_signal`], the first such signal only sets it. SIGXFSZ
/// (a file size limit, `ulimit -f`) is caught too, so that the write fails with an error and
/// the temporary file is removed like on a full disk. Meant for the command-line tool; a
/// library user keeps its own signal handling.
pub fn remove_temporaries_on_signal() -> Result<()> {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM, SIGXFSZ};
    signal_hook::flag::register(
        SIGXFSZ,
        std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)),
    )
    .map_err(AppError::io(Path::new("<signal handler>")))?;
    let mut signals = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP])
        .map_err(AppError::io(Path::new("<signal handler>")))?;
    std::thread::spawn(move || {
        for signal in signals.forever() {
            let stop = STOP.lock().unwrap_or_else(|e| e.into_inner()).take();
            match stop {
                Some(flag) => flag.store(true, Ordering::SeqCst),
                None => {
                    remove_registered();
                    let _ = signal_hook::low_level::emulate_default_handler(signal);
                    std::process::exit(128 + signal);
                }
            }
        }
    });
    Ok(())
}

/// Let the next SIGINT, SIGTERM or SIGHUP set `flag` instead of ending the process (with the
/// handler of [`remove_temporaries_on_signal`]): a computation that polls it stops and keeps
/// what is done. A further signal ends the process as usual.
pub fn stop_on_signal(flag: Arc<AtomicBool>) {
    *STOP.lock().unwrap_or_else(|e| e.into_inner()) = Some(flag);
}

/// Remove every registered temporary file (the signal handler's work).
fn remove_registered() {
    let list = TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner());
    for path in list.iter() {
        let _ = std::fs::remove_file(path);
    }
}

/// Write into an already open stream (standard output, a device, a pipe).
fn stream(
    path: &Path,
    sink: impl Write,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let mut writer = BufWriter::new(sink);
    fill(&mut writer)?;
    writer.flush().map_err(AppError::io(path))
}

/// Write a temporary file beside `target` and rename it over `target` when complete.
fn replace(
    target: &Path,
    permissions: Option<std::fs::Permissions>,
    fill: impl FnOnce(&mut dyn Write) -> Result<()>,
) -> Result<()> {
    let io = AppError::io(target);
    let temporary = Temporary::register(temporary_beside(target, "output path")?);
    let file = OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(&temporary.path)
        .map_err(&io)?;
    let mut writer = BufWriter::new(file);
    fill(&mut writer)?;
    let file: File = writer.into_inner().map_err(|e| io(e.into_error()))?;
    if let Some(permissions) = permissions {
        file.set_permissions(permissions).map_err(&io)?;
    }
    file.sync_all().map_err(&io)?;
    drop(file);
    std::fs::rename(&temporary.path, target).map_err(&io)?;
    temporary.renamed();
    Ok(())
}

/// The temporary name beside `target` (the option that named it: `option`):
/// `.NAME.tmp-PID-N`, N distinct within the process, the name part cut so that the whole
/// stays within [`NAME_MAX`] bytes whatever the target's name (a name of 255 bytes is valid
/// and its temporary must be too). The cut keeps the name unique: PID and N are whole.
pub(crate) fn temporary_beside(target: &Path, option: &'static str) -> Result<PathBuf> {
    use std::os::unix::ffi::{OsStrExt, OsStringExt};
    let name = target.file_name().ok_or_else(|| RouthError::Option {
        name: option,
        value: target.display().to_string(),
        rule: "must name a file",
    })?;
    let suffix = format!(
        ".tmp-{}-{}",
        std::process::id(),
        SERIAL.fetch_add(1, Ordering::Relaxed)
    );
    let room = NAME_MAX - 1 - suffix.len();
    let kept = &name.as_bytes()[..name.len().min(room)];
    let mut temporary = Vec::with_capacity(NAME_MAX);
    temporary.push(b'.');
    temporary.extend_from_slice(kept);
    temporary.extend_from_slice(suffix.as_bytes());
    Ok(target.with_file_name(std::ffi::OsString::from_vec(temporary)))
}

/// Resolve symbolic links in the last component of `path`, to any depth, so that a link is
/// written through. A dangling link resolves to its (missing) target, which is then created.
fn follow_links(path: &Path) -> Result<PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINK_DEPTH {
        match std::fs::symlink_metadata(&current) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let link = std::fs::read_link(&current).map_err(AppError::io(&current))?;
                current = match current.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            _ => return Ok(current),
        }
    }
    Err(AppError::io(path)(std::io::Error::other(format!(
        "more than {MAX_LINK_DEPTH} symbolic links to follow"
    ))))
}

/// A registered temporary file, removed (and unregistered) when dropped unless renamed.
struct Temporary {
    path: PathBuf,
    renamed: bool,
}

/// Put `path` on the list of temporary files that a signal removes ([`remove_temporaries_on_signal`]).
pub(crate) fn register_temporary(path: &Path) {
    TEMPORARIES
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(path.to_path_buf());
}

/// Take `path` off that list (it was renamed or removed).
pub(crate) fn unregister_temporary(path: &Path) {
    TEMPORARIES
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .retain(|p| p != path);
}

impl Temporary {
    fn register(path: PathBuf) -> Self {
        register_temporary(&path);
        Temporary {
            path,
            renamed: false,
        }
    }

    fn renamed(mut self) {
        self.renamed = true;
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        if !self.renamed {
            let _ = std::fs::remove_file(&self.path);
        }
        unregister_temporary(&self.path);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `name` in a directory of its own (the tests run in parallel).
    fn scratch(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("routh-output-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        dir.join(name)
    }

    fn leftovers(dir: &Path) -> Vec<String> {
        std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.contains(".tmp-"))
            .collect()
    }

    #[test]
    fn an_error_leaves_the_old_file_and_no_temporary() {
        let path = scratch("kept.txt");
        std::fs::write(&path, "old").unwrap();
        let result = write_atomic(&path, |w| {
            w.write_all(b"half").unwrap();
            Err(RouthError::State("stopped".into()).into())
        });
        assert!(result.is_err());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "old");
        assert!(leftovers(path.parent().unwrap()).is_empty());
        let registered = TEMPORARIES.lock().unwrap();
        assert!(!registered
            .iter()
            .any(|p| p.starts_with(path.parent().unwrap())));
    }

    #[test]
    fn a_symlink_is_written_through() {
        let target = scratch("target.txt");
        let link = target.with_file_name("link.txt");
        std::fs::write(&target, "old").unwrap();
        let _ = std::fs::remove_file(&link);
        std::os::unix::fs::symlink("target.txt", &link).unwrap();
        write_bytes_atomic(&link, b"new").unwrap();
        assert!(std::fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(std::fs::read_to_string(&target).unwrap(), "new");
    }

    #[test]
    fn a_device_is_streamed_into_not_replaced() {
        write_bytes_atomic(Path::new("/dev/null"), b"anything").unwrap();
        let meta = std::fs::metadata("/dev/null").unwrap();
        assert!(!meta.is_file(), "/dev/null must stay a device");
    }

    #[test]
    fn the_temporary_name_of_a_longest_name_fits_and_stays_unique() {
        let name = "n".repeat(NAME_MAX);
        let target = scratch("long").with_file_name(&name);
        let (a, b) = (
            temporary_beside(&target, "out").unwrap(),
            temporary_beside(&target, "out").unwrap(),
        );
        assert_ne!(a, b);
        for t in [&a, &b] {
            let n = t.file_name().unwrap().to_str().unwrap();
            assert!(n.len() <= NAME_MAX && n.starts_with(".nnn"), "{n}");
            assert!(n.contains(&format!(".tmp-{}-", std::process::id())), "{n}");
        }
        write_bytes_atomic(&target, b"long").unwrap();
        assert_eq!(std::fs::read(&target).unwrap(), b"long");
        assert!(leftovers(target.parent().unwrap()).is_empty());
        // A short name is kept whole.
        let short = temporary_beside(Path::new("dir/x.csv"), "out").unwrap();
        assert!(
            short.to_str().unwrap().starts_with("dir/.x.csv.tmp-"),
            "{short:?}"
        );
    }

    #[test]
    fn standard_output_is_recognised_by_name() {
        assert!(is_standard_output(Path::new("-")));
        assert!(!is_standard_output(&scratch("not-stdout.txt")));
    }

    #[test]
    fn a_directory_is_refused() {
        let dir = scratch("a-dir");
        std::fs::create_dir_all(&dir).unwrap();
        let e = write_bytes_atomic(&dir, b"x").unwrap_err().to_string();
        assert!(e.contains("directory"), "{e}");
    }
}
