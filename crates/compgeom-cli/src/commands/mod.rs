//! One module per command, each with its args struct and `run`. See `cli.rs` for how a
//! command adds itself.

pub mod boolean;
pub mod hull;
pub mod intersect;
pub mod overlay;
