//! The CLI's error: a message and whether it was bad input (exit 2) or another failure (exit 1).

use std::fmt;

/// Which exit code an error maps to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// Bad input or usage: unreadable or malformed input, non-finite coordinates, unknown
    /// format. Exit code 2 (as clap uses for usage errors).
    BadInput,
    /// Anything else: writing output failed, a result failed verification. Exit code 1.
    Failure,
}

impl ErrorKind {
    /// The process exit code.
    pub fn code(self) -> u8 {
        match self {
            ErrorKind::BadInput => 2,
            ErrorKind::Failure => 1,
        }
    }
}

/// An error to report on stderr as `error: <message>`.
#[derive(Debug)]
pub struct CliError {
    /// Exit code class.
    pub kind: ErrorKind,
    /// What went wrong and where (library errors already name `file:line`).
    pub message: String,
}

impl CliError {
    /// Bad input or usage (exit 2).
    pub fn bad_input(message: impl Into<String>) -> Self {
        CliError {
            kind: ErrorKind::BadInput,
            message: message.into(),
        }
    }

    /// Another failure (exit 1).
    pub fn failure(message: impl Into<String>) -> Self {
        CliError {
            kind: ErrorKind::Failure,
            message: message.into(),
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

impl From<compgeom::Error> for CliError {
    fn from(e: compgeom::Error) -> Self {
        use compgeom::Error as E;
        let kind = match &e {
            E::NonFinite { .. } | E::Parse { .. } | E::UnknownFormat(_) | E::InvalidInput(_) => {
                ErrorKind::BadInput
            }
            // Verification failures, I/O, and whatever variants come later.
            _ => ErrorKind::Failure,
        };
        CliError {
            kind,
            message: e.to_string(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use compgeom::{Error, Location};

    #[test]
    fn library_errors_map_to_exit_codes() {
        let code = |e: Error| CliError::from(e).kind.code();
        assert_eq!(
            code(Error::parse("bad number", Location::new("a.csv", 3))),
            2
        );
        assert_eq!(
            code(Error::NonFinite {
                what: "point 1".into(),
                value: f64::NAN
            }),
            2
        );
        assert_eq!(code(Error::UnknownFormat("x".into())), 2);
        assert_eq!(code(Error::InvalidInput("x".into())), 2);
        assert_eq!(code(Error::Verification("not convex".into())), 1);
        let io = std::io::Error::new(std::io::ErrorKind::PermissionDenied, "denied");
        assert_eq!(
            code(Error::Io {
                path: "out".into(),
                source: io
            }),
            1
        );
        // The message keeps the library's "(file:line)".
        let e = CliError::from(Error::parse("bad number", Location::new("a.csv", 3)));
        assert_eq!(e.message, "bad number (a.csv:3)");
    }
}
