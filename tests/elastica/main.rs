//! `elastica`: closed forms against the mpmath tables (tests/data/gen_elastica.py),
//! direct integration of the planar Kirchhoff equations, the energy
//! derivative, the series and bad input.
#[path = "../common/mod.rs"]
mod common;

mod data;
mod extremes;
mod out_of_plane;
mod physics;
mod series;
mod tables;
mod trace;
