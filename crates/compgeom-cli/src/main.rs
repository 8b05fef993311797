//! The `compgeom` command-line tool.
fn main() {}
