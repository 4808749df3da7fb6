//! Identities as property tests.
