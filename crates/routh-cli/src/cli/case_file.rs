//! `--case FILE`, the case file of the commands that take one with the built-in default case
//! when it is omitted (`simulate`, `exact`, `lyapunov`, `megno`, `section`).

use routh::case::Case;
use routh::AppResult as Result;
use std::path::PathBuf;

/// `--case`: the case file, read and validated by [`Case::load`].
#[derive(clap::Args, Debug)]
pub struct CaseFile {
    /// Case file (TOML); the built-in default case when omitted.
    #[arg(long)]
    pub case: Option<PathBuf>,
}

impl CaseFile {
    /// The case of the file, or the built-in default case ([`Case::load`]).
    pub fn load(&self) -> Result<Case> {
        Case::load(self.case.as_deref())
    }

    /// The case of the file with any contact law ([`Case::load_any_contact`]).
    pub fn load_any_contact(&self) -> Result<Case> {
        Case::load_any_contact(self.case.as_deref())
    }
}
