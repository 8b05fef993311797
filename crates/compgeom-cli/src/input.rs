//! Reading the input named on the command line: a file or standard input, its format given
//! or detected, parsed by `compgeom::io`.

use crate::cli::InputArgs;
use crate::error::CliError;
use compgeom::io::{self, Format};
use compgeom::Point2;
use std::io::Read as _;
use std::path::Path;

/// The text of an input and the name errors use for it.
pub struct Source {
    /// The whole input.
    pub text: String,
    /// The path as given, or `<stdin>`.
    pub name: String,
    /// The format: `--input-format`, else from the extension, else from the content.
    pub format: Format,
}

impl InputArgs {
    /// True when the input is standard input.
    fn is_stdin(&self) -> bool {
        self.input.as_os_str() == "-"
    }

    /// Read the input and decide its format. A missing or unreadable file, invalid UTF-8 or
    /// an undetectable format is bad input (exit 2).
    pub fn read(&self) -> Result<Source, CliError> {
        let (text, name, path) = if self.is_stdin() {
            let mut buf = Vec::new();
            std::io::stdin()
                .lock()
                .read_to_end(&mut buf)
                .map_err(|e| CliError::bad_input(format!("cannot read standard input: {e}")))?;
            let text = String::from_utf8(buf).map_err(|e| {
                CliError::bad_input(format!("standard input is not UTF-8 text: {e}"))
            })?;
            (text, "<stdin>".to_string(), None)
        } else {
            let path: &Path = &self.input;
            let name = path.display().to_string();
            let bytes = std::fs::read(path)
                .map_err(|e| CliError::bad_input(format!("cannot read {name}: {e}")))?;
            let text = String::from_utf8(bytes)
                .map_err(|e| CliError::bad_input(format!("{name} is not UTF-8 text: {e}")))?;
            (text, name, Some(path))
        };
        let format = match self.input_format {
            Some(f) => f.into(),
            None => io::detect_format(path, &text)?,
        };
        Ok(Source { text, name, format })
    }

    /// Read points in the plane.
    pub fn read_points(&self) -> Result<Vec<Point2>, CliError> {
        let src = self.read()?;
        Ok(io::read_points(&src.text, src.format, &src.name)?)
    }
}
