//! The one error type of the library.

use std::fmt;

/// Where in the input something was found: a file (or other source name) and a 1-based line.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Location {
    /// File name, `-` for standard input, or another name for the source; `None` if unknown.
    pub source: Option<String>,
    /// 1-based line number, if the input is line oriented and the line is known.
    pub line: Option<usize>,
}

impl Location {
    /// A location with a source name and a line.
    pub fn new(source: impl Into<String>, line: usize) -> Self {
        Location {
            source: Some(source.into()),
            line: Some(line),
        }
    }

    /// A location naming only the source.
    pub fn source(source: impl Into<String>) -> Self {
        Location {
            source: Some(source.into()),
            line: None,
        }
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.source, self.line) {
            (Some(s), Some(l)) => write!(f, "{s}:{l}"),
            (Some(s), None) => write!(f, "{s}"),
            (None, Some(l)) => write!(f, "line {l}"),
            (None, None) => write!(f, "input"),
        }
    }
}

/// Everything that can go wrong in compgeom. Each variant says what and where.
///
/// Panics are bugs; bad input always comes back as one of these.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// An input coordinate is NaN or infinite. `what` names the element, e.g. "point 17".
    #[error("{what} has a non-finite coordinate ({value})")]
    NonFinite {
        /// The offending element, e.g. "point 17" or "segment 3".
        what: String,
        /// The value found.
        value: f64,
    },
    /// The input text could not be parsed.
    #[error("{message} ({location})")]
    Parse {
        /// What was wrong.
        message: String,
        /// Where.
        location: Location,
    },
    /// The input format is unknown or could not be detected.
    #[error("unknown or undetectable format: {0}")]
    UnknownFormat(String),
    /// The input is well-formed but not valid for the operation (say why and where).
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// A claimed result failed verification; the message names the first broken invariant.
    #[error("verification failed: {0}")]
    Verification(String),
    /// Reading or writing a file failed.
    #[error("{path}: {source}")]
    Io {
        /// The file involved.
        path: String,
        /// The underlying error.
        #[source]
        source: std::io::Error,
    },
}

impl Error {
    /// A parse error at a location.
    pub fn parse(message: impl Into<String>, location: Location) -> Self {
        Error::Parse {
            message: message.into(),
            location,
        }
    }
}

/// `Result` with [`Error`].
pub type Result<T, E = Error> = std::result::Result<T, E>;
