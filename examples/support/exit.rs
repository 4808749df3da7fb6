//! How an example ends: an error is printed as a sentence (its `Display`,
//! which names the argument or value at fault), prefixed by the example's
//! name, and the process exits with code 2, instead of Rust's debug form of
//! an error returned from `main`.

use std::fmt::Display;
use std::process::ExitCode;

/// `result` of the example `name` as its exit code.
pub fn report<E: Display>(name: &str, result: Result<(), E>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("{name}: {e}");
            ExitCode::from(2)
        }
    }
}
