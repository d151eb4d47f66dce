//! Errors of the front ends: [`FileError`], the errors of files (case files, tables of
//! samples, figures, reading and writing), and [`AppError`], the error of the front ends
//! (case files, tables, figures, the command-line tool, the sweep), which holds a
//! [`RouthError`] of the model or a [`FileError`], so that `?` works across both.

pub use routh_ball::RouthError;

/// What can go wrong with a file: a case file, a table of samples, a figure, reading or
/// writing.
#[derive(Debug, thiserror::Error)]
pub enum FileError {
    /// A case file that cannot be read or does not follow the schema.
    #[error("case file {file}: {message}")]
    Case {
        /// The file (or `<built-in default>`).
        file: String,
        /// What is wrong, naming the key.
        message: String,
    },
    /// A table of samples (a CSV file of `routh simulate`) that cannot be used.
    #[error("{origin}: {message}")]
    Table {
        /// Where the table came from (a file, or `simulation`).
        origin: String,
        /// What is wrong, naming the line or the column.
        message: String,
    },
    /// Drawing a figure failed.
    #[error("cannot draw {figure}: {message}")]
    Plot {
        /// The figure's file name.
        figure: String,
        /// The drawing backend's message.
        message: String,
    },
    /// Reading or writing a file failed.
    #[error("{}: {source}", path.display())]
    Io {
        /// The file.
        path: std::path::PathBuf,
        /// The underlying error.
        source: std::io::Error,
    },
}

/// Any error of the front ends (case files, tables, figures, the command-line tool): an error
/// of the model or of a file, each shown with its own message.
#[derive(Debug, thiserror::Error)]
pub enum AppError {
    /// An error of the model or its numerics.
    #[error(transparent)]
    Model(#[from] RouthError),
    /// An error of a file.
    #[error(transparent)]
    File(#[from] FileError),
}

impl From<routh_integrate::IntegrateError> for AppError {
    fn from(e: routh_integrate::IntegrateError) -> Self {
        AppError::Model(e.into())
    }
}

impl AppError {
    /// For `map_err`: the error of reading or writing `path` ([`FileError::Io`]).
    pub fn io(path: &std::path::Path) -> impl Fn(std::io::Error) -> AppError + '_ {
        move |source| {
            FileError::Io {
                path: path.to_path_buf(),
                source,
            }
            .into()
        }
    }
}

/// Shorthand for results of the front ends.
pub type AppResult<T> = std::result::Result<T, AppError>;
