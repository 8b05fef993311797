//! Writing results: to standard output, or atomically to a file (a temporary file beside
//! the target, renamed into place, so a reader never sees a half-written file; devices
//! and pipes are written to as they are).

use crate::error::CliError;
use std::io::Write as _;
use std::path::Path;

/// Write `text` to `path` (atomically), or to standard output when `path` is `None` or `-`.
pub fn emit(path: Option<&Path>, text: &str) -> Result<(), CliError> {
    match path {
        Some(p) if p.as_os_str() != "-" => write_atomic(p, text.as_bytes()),
        _ => write_stdout(text),
    }
}

/// Write to standard output. A closed pipe (`compgeom … | head`) is a clean exit.
pub fn write_stdout(text: &str) -> Result<(), CliError> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(CliError::failure(format!(
            "cannot write standard output: {e}"
        ))),
    }
}

/// Write `bytes` to `path` through a temporary file in the same directory, then rename it
/// over `path`. On any error the target is untouched and the temporary file is removed.
/// A path that exists and is neither a regular file nor a directory (`/dev/null`, a named
/// pipe, a terminal) is written to directly: renaming over it would replace the device
/// or the pipe itself with a file.
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), CliError> {
    let name = path.display();
    let fail = |what: &str, e: &dyn std::fmt::Display| {
        CliError::failure(format!("cannot {what} {name}: {e}"))
    };
    if std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir()) {
        return std::fs::OpenOptions::new()
            .write(true)
            .open(path)
            .and_then(|mut f| f.write_all(bytes).and_then(|()| f.flush()))
            .map_err(|e| fail("write", &e));
    }
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let mut tmp = tempfile::Builder::new()
        .prefix(".compgeom-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(|e| fail("create a temporary file for", &e))?;
    tmp.write_all(bytes)
        .and_then(|()| tmp.flush())
        .map_err(|e| fail("write", &e))?;
    // Temporary files are created private (0600); an output file should be readable like any
    // other file the user creates.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt as _;
        let mode = std::fs::metadata(path)
            .map(|m| m.permissions().mode() & 0o7777)
            .unwrap_or(0o644);
        tmp.as_file()
            .set_permissions(std::fs::Permissions::from_mode(mode))
            .map_err(|e| fail("set permissions of", &e))?;
    }
    tmp.persist(path).map_err(|e| fail("write", &e.error))?;
    Ok(())
}

/// Geometry text ends with a newline, so shells and files look right.
pub fn with_newline(mut text: String) -> String {
    if !text.ends_with('\n') {
        text.push('\n');
    }
    text
}
