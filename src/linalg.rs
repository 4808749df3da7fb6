//! Dense and sparse linear algebra for the solvers: the only module that
//! names faer, which never appears in a public signature.
