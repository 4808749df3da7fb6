//! The scene: every model answers the same spring with the same type.

#[path = "../common/mod.rs"]
mod common;

mod bad_input;
mod cascade;
mod choice;
mod contact;
mod measure;
mod models;
mod scene;
mod shape;
mod stability;
mod sweep;
mod tangent;
