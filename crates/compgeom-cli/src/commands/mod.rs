//! One module per command, each with its args struct and `run`. See `cli.rs` for how a
//! command adds itself.

pub mod boolean;
pub mod cast;
pub mod delaunay;
pub mod enclose;
pub mod guard;
pub mod halfplanes;
pub mod hull;
pub mod interpolate;
pub mod intersect;
pub mod locate;
pub mod lp;
pub mod overlay;
pub mod range;
pub mod triangulate;
pub mod voronoi;
pub mod window;
