//! Suite `special`: hockle::special against mpmath tables, identities and
//! special cases.
//!
//! Reference tables: `tests/data/special_*.tsv`, written by
//! `python3 tests/data/gen_special.py` (mpmath, ≥ 50 digits, fixed seed).
//! Print the accuracy report with
//! `cargo test --release --test special -- --nocapture accuracy`.

#[path = "../common/mod.rs"]
mod common;

mod accuracy;
mod derivatives;
mod identities;
mod special_cases;
mod table;
