//! An example's command line: `--help` (or `-h`) prints its usage and
//! nothing runs; an argument it does not take is an error that names it
//! and shows the usage.

/// Whether `--help` or `-h` is among the arguments; prints `usage` if so.
pub fn help(usage: &str) -> bool {
    let asked = std::env::args().skip(1).any(|a| a == "--help" || a == "-h");
    if asked {
        print!("{usage}");
    }
    asked
}

/// The error for the argument `arg` the example does not take.
pub fn unknown(arg: &str, usage: &str) -> String {
    format!("unknown argument {arg}\n{usage}")
}

/// For an example whose arguments are flags only: the first argument
/// not among `flags`, as [`unknown`]'s error.
#[allow(dead_code)] // not every example that includes this file takes flags only
pub fn only_flags(flags: &[&str], usage: &str) -> Result<(), String> {
    match std::env::args()
        .skip(1)
        .find(|a| !flags.contains(&a.as_str()))
    {
        Some(a) => Err(unknown(&a, usage)),
        None => Ok(()),
    }
}
